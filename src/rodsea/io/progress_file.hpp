#pragma once
// DIR/progress.txt: where a run stands, rewritten (atomically) every few seconds of wall time
// while it runs and when it stops, so that `rodsea campaign status`, a cluster's monitoring or
// `cat` can read it without touching the HDF5 files the run is writing. Lines of `key = value`.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

namespace rodsea {

inline const char* const kProgressFile = "progress.txt";

struct RunProgress {
    std::string state = "running";  // running, done, steady (stopped when steady), stopped,
                                    // blown_up, failed
    std::uint64_t step = 0, total_steps = 0;
    double time = 0.0, duration = 0.0;  // simulated, s
    double steps_per_second = 0.0;      // this session
    double wall_seconds = 0.0;          // over every session
    double updated = 0.0;               // Unix time of the update, s
    double fraction() const {
        return total_steps ? static_cast<double>(step) / static_cast<double>(total_steps) : 0.0;
    }
    // Seconds of wall time to the end at this session's rate; negative when unknown.
    double eta_seconds() const {
        return steps_per_second > 0
                   ? static_cast<double>(total_steps - std::min(step, total_steps)) /
                         steps_per_second
                   : -1.0;
    }
};

// Throws FileError naming the file.
void write_progress_file(const std::filesystem::path& run_dir, const RunProgress& progress);
// None when the file is missing or unreadable (a run that has not started, or an older run).
std::optional<RunProgress> read_progress_file(const std::filesystem::path& run_dir);

double unix_time_now();

}  // namespace rodsea
