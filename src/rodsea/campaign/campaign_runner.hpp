#pragma once
// What the two executors of this machine (one process per run, local_executor.hpp; one ensemble,
// ensemble_executor.hpp) share: the tally of a runner's runs, taking a run, what a failure
// means for it, and the runner's last words.
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "rodsea/campaign/campaign_store.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

// What every runner of this machine is told.
struct RunnerOptions {
    int threads = 1;                     // of each run (local), of the ensemble (ensemble)
    std::optional<BackendKind> backend;  // every run's (--backend); none: its run.backend
    bool retry_failed = false;           // give runs that failed twice two more tries
    bool quiet = false;
    std::optional<std::vector<std::size_t>> only;  // these runs (indices into grid.runs); none: all
};

struct RunnerTally {
    std::size_t mine = 0;             // the runs this runner was given
    std::size_t done = 0;             // of those, done (before or by it)
    std::size_t elsewhere = 0;        // left to another runner or process that holds them
    std::vector<std::size_t> failed;  // failed for good (indices into grid.runs)
};

// The run's claim when this runner may step it; none when another runner, or a rodsea process in
// its directory, holds it (counted in `tally.elsewhere` and said) or it was finished since the
// runner looked (counted done).
std::optional<RunClaim> take_run(const CampaignPaths& paths, const CampaignRun& run,
                                 int max_failures, RunnerTally& tally, bool quiet,
                                 std::ostream& out);

// A run that ended with `code`, neither done nor stopped by a signal: records the failure with
// its `message` (the run's own output) and says so. Returns whether to retry it: a run that
// failed fewer than `max_failures` times, unless it blew up (it would do the same steps again).
bool judge_failure(const CampaignPaths& paths, const CampaignRun& run, int code,
                   const std::string& message, int max_failures, bool quiet, std::ostream& out);

// The runner's last lines (runs done, the time, each run failed for good with its log); returns
// the runner's exit code: 128 + the signal that stopped it, 1 if some run failed, else 0.
int finish_runner(const CampaignPaths& paths, const CampaignGrid& grid, const RunnerTally& tally,
                  double seconds, int stop_signal, bool quiet, std::ostream& out);

}  // namespace rodsea
