#include "rodsea/campaign/campaign_runner.hpp"

#include <csignal>
#include <ostream>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/io/run_lock.hpp"

namespace rodsea {

namespace {

std::string last_line(const std::string& text) {
    const std::size_t end = text.find_last_not_of("\n ");
    if (end == std::string::npos) return "";
    const std::size_t start = text.rfind('\n', end);
    const std::size_t from = start == std::string::npos ? 0 : start + 1;
    return text.substr(from, end - from + 1);
}

}  // namespace

std::optional<RunClaim> take_run(const CampaignPaths& paths, const CampaignRun& run,
                                 int max_failures, RunnerTally& tally, bool quiet,
                                 std::ostream& out) {
    RunClaim claim(paths, run);
    if (!claim.held()) {
        ++tally.elsewhere;
        if (!quiet) out << "campaign: " << run.id << " is run by another runner" << std::endl;
        return std::nullopt;
    }
    if (run_status(paths, run, max_failures).state == RunState::done) {
        ++tally.done;  // finished by another runner since this one looked
        return std::nullopt;
    }
    // Resuming it would fail (one process per run directory) and count as the run's failure.
    if (run_directory_in_use(paths.run_dir(run))) {
        ++tally.elsewhere;
        if (!quiet)
            out << "campaign: " << run.id << " is being run by another rodsea process (rodsea run "
                << "--resume?); left to it" << std::endl;
        return std::nullopt;
    }
    return claim;
}

bool judge_failure(const CampaignPaths& paths, const CampaignRun& run, int code,
                   const std::string& message, int max_failures, bool quiet, std::ostream& out) {
    record_failure(paths, run, code, message);
    const RunStatus s = run_status(paths, run, max_failures);
    const bool retry = s.failures < max_failures && code != kExitBlownUp;
    if (!quiet)
        out << "campaign: " << run.id << " failed (exit " << code << "): " << last_line(message)
            << "\n  log: " << paths.log(run).string()
            << (retry                  ? "; retrying once"
                : code == kExitBlownUp ? "; it blew up: change the config"
                                       : "")
            << std::endl;
    return retry;
}

int finish_runner(const CampaignPaths& paths, const CampaignGrid& grid, const RunnerTally& tally,
                  double seconds, int stop_signal, bool quiet, std::ostream& out) {
    if (!quiet) {
        out << "campaign: " << tally.done << "/" << tally.mine << " runs done after "
            << format_duration(seconds);
        if (tally.elsewhere) out << "; " << tally.elsewhere << " run by another process";
        out << std::endl;
        for (const std::size_t i : tally.failed)
            out << "campaign: FAILED " << grid.runs[i].id << " (log "
                << paths.log(grid.runs[i]).string()
                << "); fix the cause, then re-run with --retry-failed" << std::endl;
    }
    if (stop_signal) return 128 + (stop_signal == SIGHUP ? SIGTERM : stop_signal);
    return tally.failed.empty() ? kExitOk : kExitFailure;
}

}  // namespace rodsea
