#pragma once
// `rodsea analyze`: a run directory in, the paper's numbers out. prepare_run checks everything
// (the file is a rodsea trajectory, the steady window lies inside the run, each requested
// observable has the species it needs, every option fits the box) before any frame is read;
// analyze_run then reads each frame once and hands it to every observable.
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/analysis/steady_state.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea {

struct AnalyzeRequest {
    std::vector<std::string> observables;  // empty: every one that applies
    std::optional<double> from;            // s; none: chosen automatically
    std::optional<double> to;              // s; none: the run's last frame
    AnalysisOptions options;
};

struct SteadyWindow {
    std::size_t first_frame = 0;
    double from = 0.0;                // s, time of the first steady frame
    bool automatic = false;           // chosen by latest_steady_start() rather than --from
    bool to_given = false;            // ended by --to rather than at the run's last frame
    std::string basis;                // the series whose steady start decided the automatic choice
    std::vector<SeriesStart> series;  // every order series: its own start, n_eff, drift
};

struct PreparedRun {
    std::filesystem::path run_dir, trajectory;
    std::vector<std::filesystem::path> parts;  // every trajectory read, `trajectory` the last
    RunPlan plan;
    AnalysisSetup setup;
    AnalysisOptions options;  // resolved for this run
    SteadyWindow window;
    std::vector<double> times;      // s, every frame analysed (to --to)
    std::size_t stored_frames = 0;  // the run's frames on the output grid, analysed or not
    double stored_last_time = 0.0;  // s, the last of them
    std::vector<std::string> observables, skipped;
    // Non-empty while a rodsea process still writes the run (its directory's lock is held):
    // where it stands, so that nobody takes an analysis of part of a run for the whole.
    std::string still_running;
    // What the analysis depends on: the trajectory (its run id, frames and last step), the
    // observables, the window and every option, and rodsea's version. Equal keys give equal
    // analyses; empty for a trajectory without a run id (written before rodsea kept one).
    std::string cache_key;
};

struct RunAnalysis {
    PreparedRun run;
    std::vector<ObservableResults> results;
    double seconds = 0.0;
};

// Accepts a run directory or its trajectory.h5. Throws FileError (not a rodsea trajectory,
// unreadable or truncated file) or InvalidParameter (window, observable, option).
PreparedRun prepare_run(const std::filesystem::path& run, const AnalyzeRequest& request);
// A run kept in several directories (its first and its continuations), analysed as one
// (io/stored_run.hpp); its output goes to the latest part's directory.
PreparedRun prepare_run(const std::vector<std::filesystem::path>& parts,
                        const AnalyzeRequest& request);

// Prints what it will do to `log`, then a progress line every 10 % of the frames (unless quiet).
RunAnalysis analyze_run(const PreparedRun& run, std::ostream& log, bool quiet);

// Throws FileError when `out_dir` exists and is not an earlier analysis (a directory holding
// analysis.json, or empty): an analysis replaces its own output only.
void check_analysis_output_directory(const std::filesystem::path& out_dir);

// analysis.json, one CSV per table, analysis.h5 (maps, labels) and summary.csv in `out_dir`,
// written into a staging directory and swapped in whole. Returns the files.
std::vector<std::filesystem::path> write_run_analysis(const RunAnalysis& analysis,
                                                      const std::filesystem::path& out_dir);

// The analysis already in `out_dir` when its analysis.json records this run's cache_key (the
// same trajectory, observables, window, options and version): the run with the scalars read
// back (tables and maps stay on disk). None when there is none, it differs or cannot be read.
std::optional<RunAnalysis> reuse_run_analysis(const PreparedRun& run,
                                              const std::filesystem::path& out_dir);

// Runs that differ only in their seed are replicates of one state point: each scalar's mean over
// them with the error from their spread, and chi²/dof of that spread against the runs' own
// errors (statistics.hpp combine_replicates).
struct ReplicateScalar {
    std::string name, unit;
    ReplicateEstimate estimate;
};
struct ReplicateSummary {
    std::vector<std::filesystem::path> runs;
    std::vector<std::uint64_t> seeds;
    std::vector<ReplicateScalar> scalars;
};
std::vector<ReplicateSummary> replicate_summaries(const std::vector<RunAnalysis>& runs);
// Runs whose config and seed are an earlier run's (its trajectory again, so not a replicate:
// replicate_summaries counts it once), each with that earlier run: (later, earlier).
std::vector<std::pair<std::filesystem::path, std::filesystem::path>> same_seed_runs(
    const std::vector<RunAnalysis>& runs);
// The same for runs already known to be replicates (a campaign point's seeds).
ReplicateSummary summarise_replicates(const std::vector<const RunAnalysis*>& runs);

// One CSV row per run: its parameters, then every scalar and its error bar; then one row per
// group of replicates (the mean, the error from their spread, chi²/dof).
std::string summary_table_csv(const std::vector<RunAnalysis>& runs);

}  // namespace rodsea
