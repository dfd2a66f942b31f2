#pragma once
// The local executor: a campaign's runs on this machine, `jobs` at a time, each a `rodsea run`
// child process on `threads` threads. Re-running it continues the campaign: finished runs are
// skipped, interrupted ones resume from their checkpoints, a run killed before its first
// checkpoint starts again, a failed run is retried once and then reported; a run another runner
// holds is left to it. SIGINT or SIGTERM is passed on to every run, which writes its checkpoint.
#include <filesystem>
#include <iosfwd>

#include "rodsea/campaign/campaign_runner.hpp"

namespace rodsea {

struct LocalExecutorOptions : RunnerOptions {
    int jobs = 1;
    std::filesystem::path executable;  // rodsea itself; empty: this process's executable
};

// Returns an ExitCode: 0 when every run is done, 130/143 when stopped by a signal, 1 when some
// failed (each named, with its log).
int run_campaign_locally(const CampaignPaths& paths, const CampaignGrid& grid,
                         const LocalExecutorOptions& options, std::ostream& out);

}  // namespace rodsea
