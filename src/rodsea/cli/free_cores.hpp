#pragma once
// How many cores other processes leave free. OpenMP threads that wait for each other spin; on a
// core another process also wants, a spinning thread steals the time its partner needs, and a
// run with more threads than free cores went 36–900× slower than on one thread
// (docs/performance.md, "Threads and determinism"). A passive wait policy is no cure: on this
// machine it makes two threads 18× slower even on idle cores. So the run measures what is free and
// steps on that many threads (the trajectory does not depend on it).
//
// Linux: the CPU time of the whole machine (/proc/stat) less this process's own (getrusage),
// between two samples. Elsewhere: every core counts as free.
#include <cstdint>

namespace rodsea {

class FreeCoreMonitor {
  public:
    FreeCoreMonitor();  // the first sample
    // Cores this process may run on (its CPU affinity).
    int usable() const { return usable_; }
    // Cores left free by other processes since the previous sample (or construction), in
    // [0, usable()]; usable() when the interval was too short to tell (< 50 ms).
    double sample();

  private:
    struct Reading {
        std::uint64_t busy_ticks = 0, total_ticks = 0;
        double own_cpu_seconds = 0.0;
    };
    static Reading read();
    int usable_ = 1;
    int machine_cores_ = 1;
    Reading last_;
};

// The threads to step on: the requested number, or fewer when fewer cores are free (rounded so
// that a core shared half and half with another process counts as taken). At least 1.
int threads_for_free_cores(int requested, double free_cores);

}  // namespace rodsea
