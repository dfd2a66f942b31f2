#pragma once
// Progress of work counted in items (movie frames, exported frames): a bar redrawn in place on
// a terminal, a line every 10 % otherwise, nothing when quiet. Unlike ProgressReporter it knows
// nothing of simulated time.
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <string>

#include "rodsea/cli/progress.hpp"

namespace rodsea {

class CountProgress {
  public:
    CountProgress(std::ostream& out, ProgressStyle style, std::size_t total, std::string unit);
    void update(std::size_t done);  // draws at most every 0.2 s
    void finish();

  private:
    void draw(std::size_t done, bool final);

    std::ostream& out_;
    ProgressStyle style_;
    std::size_t total_;
    std::string unit_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    int next_log_percent_ = 10;
};

}  // namespace rodsea
