#pragma once
// The built-in default scene run by `rodsea demo`: polar rods in a medium of apolar rods, small
// enough to finish in seconds, written as CSV for scripts/plot_snapshot.py.
#include <cstdint>
#include <iosfwd>
#include <string>

namespace rodsea {

struct DemoOptions {
    double drive_periods = 40.0;  // length of the run, in drive periods (5 ms each by default)
    double box_side = 30.0;       // mm
    double phi_polar = 0.05;
    double phi_apolar = 0.30;
    double apolar_length = 2.5;  // mm
    double noise_epsilon = 0.0;  // 1/mm
    std::uint64_t seed = 1;
    std::string out_dir = "out/demo";
    bool quiet = false;
};

// Prints the plan, runs, writes out_dir/{bodies,shapes,timeseries}.csv atomically. Returns the
// process exit code. Throws InvalidParameter for bad options before any work starts.
int run_demo(const DemoOptions& options, std::ostream& log);

}  // namespace rodsea
