#include "rodsea/campaign/ensemble_executor.hpp"

#include <unistd.h>

#include <chrono>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <streambuf>

#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/campaign/campaign_runner.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/run/run_driver.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

// Writes to two stream buffers: the runner's error output, and the text each run's failure
// record and log are taken from.
class TeeBuffer : public std::streambuf {
  public:
    TeeBuffer(std::streambuf* first, std::streambuf* second) : first_(first), second_(second) {}

  protected:
    int overflow(int c) override {
        if (c == traits_type::eof()) return traits_type::not_eof(c);
        const char ch = traits_type::to_char_type(c);
        first_->sputc(ch);
        second_->sputc(ch);
        return c;
    }
    std::streamsize xsputn(const char* text, std::streamsize n) override {
        first_->sputn(text, n);
        second_->sputn(text, n);
        return n;
    }
    int sync() override { return first_->pubsync() == 0 && second_->pubsync() == 0 ? 0 : -1; }

  private:
    std::streambuf* first_;
    std::streambuf* second_;
};

// A run's log is the campaign's record of its sessions, not the run's output (its directory
// holds that): a log that cannot be written (a full disk, its path taken) is named and the runs go
// on, rather than the runner failing after the ensemble's round, with the round's ends unrecorded.
void append_to_log(const CampaignPaths& paths, const CampaignRun& run, const std::string& text,
                   std::ostream& err) {
    std::ofstream log(paths.log(run), std::ios::app);
    log << text;
    log.close();
    if (log) return;
    err << "rodsea: campaign: " << paths.log(run).string()
        << " cannot be written; the run goes on, its session not logged there" << std::endl;
}

// The messages of the error output about the run in `dir`: each message starts with a line
// "rodsea: ..." that names its run's directory followed by a colon (RunOptions::
// name_runs_in_messages; "seed1:" is not "seed10:") and goes on with indented lines.
std::string messages_of(const std::string& text, const fs::path& dir) {
    const std::string name = dir.string() + ":";
    std::istringstream lines(text);
    std::string line, mine;
    bool in_mine = false;
    while (std::getline(lines, line)) {
        if (line.rfind("rodsea: ", 0) == 0) in_mine = line.find(name) != std::string::npos;
        if (in_mine) mine += line + "\n";
    }
    return mine;
}

// A run with no checkpoint (never started, or killed before its first) starts from its config as
// `rodsea run CONFIG --out DIR --overwrite --threads T [--backend B]` would.
NewRun new_run(const CampaignPaths& paths, const CampaignRun& run, const RunnerOptions& o) {
    const fs::path config = paths.config(run);
    RunPlan plan = load_config_file(config.string(), calibration_table_lookup());
    plan = with_threads(plan.config_toml, config.string(), o.threads);
    if (o.backend) plan = with_backend(plan.config_toml, config.string(), *o.backend);
    return {std::move(plan), paths.run_dir(run)};
}

}  // namespace

int run_campaign_as_ensemble(const CampaignPaths& paths, const CampaignGrid& grid,
                             const RunnerOptions& o, std::ostream& out, std::ostream& err) {
    StopSignalGuard signals;
    const int max_failures = o.retry_failed ? 4 : 2;
    const CampaignWork work = campaign_work(paths, grid, o.only, max_failures);
    RunnerTally tally{.mine = work.mine.size(), .done = work.done, .failed = work.failed};
    const std::string backend =
        o.backend ? to_string(*o.backend) : std::string("each run's run.backend");
    if (!o.quiet)
        out << "campaign " << paths.dir.string() << ": " << tally.mine << " runs, " << tally.done
            << " done, " << work.to_run.size() << " to run, " << tally.failed.size()
            << " failed; as one ensemble on " << backend << ", " << o.threads << " thread"
            << (o.threads > 1 ? "s" : "") << std::endl;
    const auto started = Clock::now();
    RunOptions options;
    options.quiet = o.quiet;
    options.overwrite = true;  // a run killed before its first checkpoint starts again
    options.backend = o.backend;
    options.threads = o.threads;
    options.name_runs_in_messages = true;
    std::vector<std::size_t> queue = work.to_run;
    int stop_signal = 0;
    // A round steps every queued run as one ensemble; the runs to retry make the next.
    while (!queue.empty() && stop_signal == 0) {
        std::vector<std::size_t> taken;
        std::vector<RunClaim> claims;
        for (const std::size_t i : queue) {
            std::optional<RunClaim> claim =
                take_run(paths, grid.runs[i], max_failures, tally, o.quiet, out);
            if (!claim) continue;
            taken.push_back(i);
            claims.push_back(std::move(*claim));
        }
        queue.clear();
        if (taken.empty()) break;

        std::vector<NewRun> fresh;
        std::vector<std::size_t> fresh_runs, stepped_runs;
        std::vector<fs::path> dirs;
        RunOptions round = options;
        for (const std::size_t i : taken) {
            const CampaignRun& run = grid.runs[i];
            std::error_code ec;
            const bool resumes = fs::exists(paths.run_dir(run) / kCheckpointFile, ec);
            if (resumes) {
                dirs.push_back(paths.run_dir(run));
                stepped_runs.push_back(i);
                // A campaign extended since the run ended or stopped: on to the campaign's
                // duration, which an extension (--extend takes --duration) gives every run.
                const std::optional<RunProgress> progress = read_progress_file(dirs.back());
                if (progress && ends_before(*progress, run.duration)) round.duration = run.duration;
            } else {
                fresh.push_back(new_run(paths, run, o));
                fresh_runs.push_back(i);
            }
            if (!o.quiet)
                out << "campaign: " << (resumes ? "resume " : "start ") << run.id << std::endl;
            std::ostringstream header;
            header << "=== campaign run --ensemble (pid " << ::getpid() << ") at "
                   << exact_number(unix_time_now()) << ": " << (resumes ? "resumed" : "started")
                   << " with " << taken.size() - 1 << " other runs on " << backend << ", "
                   << o.threads << " threads; their progress is in the runner's output\n";
            append_to_log(paths, run, header.str(), err);
        }

        std::ostringstream captured;
        TeeBuffer tee(err.rdbuf(), captured.rdbuf());
        std::ostream messages(&tee);
        std::map<std::size_t, int> code_of;
        if (!fresh.empty()) {
            const std::vector<int> codes = create_runs(fresh, options, out, messages);
            for (std::size_t k = 0; k < fresh.size(); ++k) {
                if (codes[k] != kExitOk) {
                    code_of[fresh_runs[k]] = codes[k];
                    continue;
                }
                dirs.push_back(fresh[k].dir);
                stepped_runs.push_back(fresh_runs[k]);
            }
        }
        if (!dirs.empty()) {
            const auto round_started = Clock::now();
            const std::vector<int> codes = resume_each(dirs, round, out, messages);
            for (std::size_t k = 0; k < dirs.size(); ++k)
                code_of[stepped_runs[k]] = codes[k];
            if (!o.quiet)
                out << "campaign: the ensemble of " << dirs.size() << " runs stepped for "
                    << format_duration(
                           std::chrono::duration<double>(Clock::now() - round_started).count())
                    << std::endl;
        }
        messages.flush();

        for (const std::size_t i : taken) {
            const CampaignRun& run = grid.runs[i];
            const int code = code_of.at(i);
            const std::string message = messages_of(captured.str(), paths.run_dir(run));
            append_to_log(paths, run, message + "=== exit " + std::to_string(code) + "\n", err);
            if (code == kExitOk) {
                ++tally.done;
                if (!o.quiet)
                    out << "campaign: done " << run.id << " (" << tally.done << "/" << tally.mine
                        << " done)" << std::endl;
            } else if (code == kExitInterrupted || code == kExitTerminated) {
                stop_signal = code - 128;
                if (!o.quiet)
                    out << "campaign: stopped " << run.id << " (checkpoint written)" << std::endl;
            } else {
                const bool retry =
                    judge_failure(paths, run, code, message, max_failures, o.quiet, out);
                if (retry)
                    queue.push_back(i);
                else
                    tally.failed.push_back(i);
            }
        }
        if (const int s = stop_signal_received(); s != 0) stop_signal = s;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    return finish_runner(paths, grid, tally, seconds, stop_signal, o.quiet, out);
}

}  // namespace rodsea
