#include "rodsea/cli/count_progress.hpp"

#include <algorithm>
#include <ostream>

namespace rodsea {

CountProgress::CountProgress(std::ostream& out, ProgressStyle style, std::size_t total,
                             std::string unit)
    : out_(out),
      style_(style),
      total_(std::max<std::size_t>(total, 1)),
      unit_(std::move(unit)),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

void CountProgress::update(std::size_t done) {
    if (style_ == ProgressStyle::quiet || done >= total_) return;  // finish() draws the end
    const auto now = std::chrono::steady_clock::now();
    if (style_ == ProgressStyle::bar) {
        if (now - last_draw_ < std::chrono::milliseconds(200)) return;
    } else if (static_cast<int>(100 * done / total_) < next_log_percent_) {
        return;
    }
    last_draw_ = now;
    draw(done, false);
}

void CountProgress::finish() {
    if (style_ != ProgressStyle::quiet) draw(total_, true);
}

void CountProgress::draw(std::size_t done, bool final) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double fraction = static_cast<double>(done) / static_cast<double>(total_);
    const int percent = static_cast<int>(100.0 * fraction);
    std::string line = std::to_string(done) + "/" + std::to_string(total_) + " " + unit_ + " " +
                       std::to_string(percent) + " %, " + format_duration(elapsed);
    if (final) {
        line += " in all";
    } else if (done > 0) {
        line += " elapsed, ETA " + format_duration(elapsed * (1.0 - fraction) / fraction);
    }
    if (style_ == ProgressStyle::bar) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(kWidth * fraction);
        out_ << "\r  [" << std::string(static_cast<std::size_t>(filled), '#')
             << std::string(static_cast<std::size_t>(kWidth - filled), ' ') << "] " << line << "   "
             << (final ? "\n" : "") << std::flush;
    } else {
        out_ << "  " << line << "\n" << std::flush;
        while (next_log_percent_ <= percent)
            next_log_percent_ += 10;
    }
}

}  // namespace rodsea
