#pragma once
// The ensemble executor: a campaign's runs stepped together in this process as one Ensemble
// (run/run_driver.hpp: create_runs, resume_each), on a GPU in the same kernels, each run writing
// its own directory exactly as `rodsea run` would alone. It keeps the local executor's promises:
// finished runs are skipped, interrupted ones resume from their checkpoints (the new ones start
// beside them, in the same ensemble), a failed run is retried once (in a second, smaller
// ensemble) and then reported, a run another runner holds is left to it, and SIGINT or SIGTERM
// makes every run write its checkpoint.
//
// One process writes every run's messages: the runner's output has them all (each naming its
// run); each run's log (runs/<point>/seed<k>.log) gets a line per session and that run's own
// error messages, and its .failed file what made it fail. A log that cannot be written is named in
// the runner's error output and its run goes on: the log is a record, not the run's output.
#include <iosfwd>

#include "rodsea/campaign/campaign_runner.hpp"

namespace rodsea {

// Returns an ExitCode: 0 when every run is done, 130/143 when stopped by a signal, 1 when some
// failed (each named, with its log). Input problems (a checkpoint that cannot be read, runs on
// different backends) throw before any run is stepped.
int run_campaign_as_ensemble(const CampaignPaths& paths, const CampaignGrid& grid,
                             const RunnerOptions& options, std::ostream& out, std::ostream& err);

}  // namespace rodsea
