#pragma once
// `rodsea run`: builds the initial state, steps it, writes the trajectory, the time series and
// checkpoints, and stops cleanly (with a checkpoint) on SIGINT, SIGTERM or a failing disk.
//
// A run directory holds:
//   config.toml       the full resolved config (every key), for people to read
//   trajectory.h5     H5MD trajectory and time series (io/trajectory_file.hpp)
//   timeseries.csv    the same time series as CSV
//   checkpoint.h5     the latest checkpoint (io/checkpoint.hpp), replaced atomically
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <vector>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/step_backend.hpp"
#include "rodsea/run/run_files.hpp"

namespace rodsea {

struct RunOptions {
    std::filesystem::path out_dir;
    bool overwrite = false;  // replace the run files of an existing directory
    bool quiet = false;      // no plan, no progress; errors still go to the error stream
    // Resume only: extend (or shorten, not below the time done) the run to this duration, s,
    // and/or change its stop-when-steady sample count; the stored config says the new values.
    std::optional<double> duration;
    std::optional<long long> steady_samples;
    // Resume only: continue on this backend instead of the stored run.backend, for this session
    // (the stored config keeps saying how the run started).
    std::optional<BackendKind> backend;
    // Step on this many threads instead of the largest run.threads, for this session (the
    // trajectory does not depend on threads; the stored configs keep theirs).
    std::optional<int> threads;
    // Every message of a run begins with its directory, also when it runs alone (as it does
    // among several): a campaign runner sorts one error stream into each run's log.
    bool name_runs_in_messages = false;
};

// A new run: its plan and the directory it writes.
struct NewRun {
    RunPlan plan;
    std::filesystem::path dir;
};

// How runs stepped together step: every run's backend (they must agree, as it decides the
// trajectory; InvalidParameter naming two that differ, by their `dirs`) on the largest
// run.threads among them (which does not); options.backend and options.threads replace either.
BackendOptions ensemble_options(const std::vector<RunPlan>& plans,
                                const std::vector<std::filesystem::path>& dirs,
                                const RunOptions& options);

// Starts a new run of `plan` in options.out_dir. Everything about the input (packing, output
// directory) is checked before any work; problems throw InvalidParameter or FileError.
// Returns an ExitCode; messages go to `out` (plan, progress) and `err` (what went wrong).
int start_run(const RunPlan& plan, const RunOptions& options, std::ostream& out, std::ostream& err,
              bool progress_is_terminal = false);

// Continues the run in `dir` from its checkpoint, bit for bit as if it had never stopped; with
// options.duration or options.steady_samples, with that run length (also when it had completed),
// bit for bit the run that had been given it from the start.
int resume_run(const std::filesystem::path& dir, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal = false);

// Several runs stepped together as one Ensemble (engine/ensemble.hpp): on a GPU they share its
// kernels. Each writes its own directory (runs[i].dir; options.out_dir is not used) exactly as
// it would alone, and each directory resumes alone or with others. Every run is checked before
// any work (a problem with one starts none); they must agree on run.backend and step on the
// largest run.threads among them (the trajectory does not depend on threads). A run that ends
// (its duration, a steady window, a blow-up, a failed write) leaves the ensemble and the others
// go on. Returns kExitOk when every run ended well, otherwise the exit code of the first run, in
// the order given, that did not.
int start_runs(const std::vector<NewRun>& runs, const RunOptions& options, std::ostream& out,
               std::ostream& err, bool progress_is_terminal = false);
// The same for resumed runs; options.duration and options.steady_samples apply to each, and
// a run already complete is said so and left alone.
int resume_runs(const std::vector<std::filesystem::path>& dirs, const RunOptions& options,
                std::ostream& out, std::ostream& err, bool progress_is_terminal = false);
// resume_runs with every run's exit code, in the order given (kExitOk for one already complete).
std::vector<int> resume_each(const std::vector<std::filesystem::path>& dirs,
                             const RunOptions& options, std::ostream& out, std::ostream& err,
                             bool progress_is_terminal = false);

// start_runs up to each run's first frame and checkpoint, without stepping: resume_each then
// steps them, with others, bit for bit as start_runs would have (a campaign's ensemble steps
// its new and its interrupted runs together). Checks as start_runs; returns each run's exit
// code (kExitIoError when its first frame or checkpoint could not be written).
std::vector<int> create_runs(const std::vector<NewRun>& runs, const RunOptions& options,
                             std::ostream& out, std::ostream& err);

}  // namespace rodsea
