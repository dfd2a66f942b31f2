#include "rodsea/cli/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace rodsea {

namespace {
constexpr double kRedrawSeconds = 0.25;
constexpr int kBarWidth = 24;
}  // namespace

ProgressStyle choose_progress_style(bool quiet, bool stream_is_terminal) {
    if (quiet) return ProgressStyle::quiet;
    return stream_is_terminal ? ProgressStyle::bar : ProgressStyle::log_lines;
}

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    const auto s = static_cast<long long>(std::llround(seconds));
    char text[64];
    if (s >= 86400)
        std::snprintf(text, sizeof text, "%lldd%02lldh", s / 86400, (s % 86400) / 3600);
    else if (s >= 3600)
        std::snprintf(text, sizeof text, "%lldh%02lldm", s / 3600, (s % 3600) / 60);
    else if (s >= 60)
        std::snprintf(text, sizeof text, "%lldm%02llds", s / 60, s % 60);
    else
        std::snprintf(text, sizeof text, "%llds", s);
    return text;
}

ProgressReporter::ProgressReporter(std::ostream& out, ProgressStyle style, std::uint64_t first_step,
                                   std::uint64_t total_steps, double dt, double log_every_percent)
    : out_(out),
      style_(style),
      first_step_(first_step),
      total_steps_(total_steps),
      dt_(dt),
      log_every_(log_every_percent),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_),
      last_step_(first_step) {
    const double done = total_steps == 0 ? 100.0
                                         : 100.0 * static_cast<double>(first_step) /
                                               static_cast<double>(total_steps);
    next_log_percent_ = (std::floor(done / log_every_) + 1.0) * log_every_;
}

double ProgressReporter::steps_per_second() const {
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    return wall > 0.0 ? static_cast<double>(last_step_ - first_step_) / wall : 0.0;
}

void ProgressReporter::update(std::uint64_t step, double polar_order) {
    last_step_ = step;  // the rate is wanted in the time series even when quiet
    // The last step is finish()'s to report, once.
    if (style_ == ProgressStyle::quiet || step >= total_steps_) return;
    const double percent = 100.0 * static_cast<double>(step) /
                           static_cast<double>(std::max<std::uint64_t>(total_steps_, 1));
    if (style_ == ProgressStyle::log_lines) {
        if (percent >= next_log_percent_) {
            draw(step, polar_order, false);
            next_log_percent_ = (std::floor(percent / log_every_) + 1.0) * log_every_;
        }
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (std::chrono::duration<double>(now - last_draw_).count() < kRedrawSeconds) return;
    last_draw_ = now;
    draw(step, polar_order, false);
}

void ProgressReporter::finish(std::uint64_t step, double polar_order) {
    last_step_ = step;
    if (style_ == ProgressStyle::quiet) return;
    draw(step, polar_order, true);
}

void ProgressReporter::draw(std::uint64_t step, double polar_order, bool final) {
    const double fraction =
        static_cast<double>(step) / static_cast<double>(std::max<std::uint64_t>(total_steps_, 1));
    const double rate = steps_per_second();
    const double eta = rate > 0.0 ? static_cast<double>(total_steps_ - step) / rate : NAN;
    char line[256];
    std::snprintf(
        line, sizeof line, "t = %.4g / %.4g s  %s %s  %.0f steps/s  P = %.3f",
        static_cast<double>(step) * dt_, static_cast<double>(total_steps_) * dt_,
        final ? "took" : "ETA",
        format_duration(
            final ? std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count()
                  : eta)
            .c_str(),
        rate, polar_order);
    if (style_ == ProgressStyle::bar) {
        const int filled = static_cast<int>(std::lround(fraction * kBarWidth));
        out_ << "\r[" << std::string(static_cast<size_t>(filled), '#')
             << std::string(static_cast<size_t>(kBarWidth - filled), '.') << "] ";
        char percent[16];
        std::snprintf(percent, sizeof percent, "%5.1f%%  ", 100.0 * fraction);
        out_ << percent << line << "\033[K";
        if (final) out_ << '\n';
    } else {
        char percent[16];
        std::snprintf(percent, sizeof percent, "%5.1f%%  ", 100.0 * fraction);
        out_ << "rodsea: " << percent << line << '\n';
    }
    out_.flush();
}

}  // namespace rodsea
