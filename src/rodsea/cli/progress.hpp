#pragma once
// Progress of a long run. On a terminal: one bar redrawn in place (simulated time, ETA, steps/s,
// the current P). Otherwise (batch jobs, logs): a plain line every few percent. Quiet: nothing.
#include <chrono>
#include <cstdint>
#include <iosfwd>
#include <string>

namespace rodsea {

enum class ProgressStyle { bar, log_lines, quiet };

// The style for this process: quiet when asked, a bar when `stream_is_terminal`.
ProgressStyle choose_progress_style(bool quiet, bool stream_is_terminal);

class ProgressReporter {
  public:
    // `first_step` is where this session starts (non-zero on resume); the rate and ETA count
    // only the steps run in this session.
    ProgressReporter(std::ostream& out, ProgressStyle style, std::uint64_t first_step,
                     std::uint64_t total_steps, double dt, double log_every_percent = 5.0);

    // Cheap enough to call every step: it reads the clock only every 64 steps.
    void update(std::uint64_t step, double polar_order);
    void finish(std::uint64_t step, double polar_order);

    double steps_per_second() const;  // this session so far

  private:
    void draw(std::uint64_t step, double polar_order, bool final);

    std::ostream& out_;
    ProgressStyle style_;
    std::uint64_t first_step_, total_steps_;
    double dt_;
    double log_every_;
    double next_log_percent_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    std::uint64_t last_step_ = 0;
};

// "1h02m", "3m05s", "12s": durations for humans.
std::string format_duration(double seconds);

}  // namespace rodsea
