#include "rodsea/campaign/local_executor.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <deque>
#include <fstream>
#include <map>
#include <ostream>
#include <sstream>
#include <thread>
#include <vector>

#include "rodsea/campaign/campaign_runner.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/cli/progress.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/error.hpp"
#include "rodsea/number_text.hpp"
#include "rodsea/run/run_driver.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

struct ActiveRun {
    std::size_t run = 0;
    RunClaim claim;
    Clock::time_point started;
    std::streamoff log_start = 0;  // where this session's output begins in the log
};

// The words of the `rodsea run` that continues `run` from what its directory holds.
std::vector<std::string> run_words(const CampaignPaths& paths, const CampaignRun& run,
                                   const LocalExecutorOptions& o, std::string& what) {
    const fs::path dir = paths.run_dir(run);
    std::error_code ec;
    std::vector<std::string> words;
    if (fs::exists(dir / kCheckpointFile, ec)) {
        what = "resume";
        // On this command's --threads, whatever the run started on: threads change the speed,
        // never the trajectory. Not --quiet (nor below): the log is the run's only record of
        // its plan, of how its start was built and of its rate, a progress line every 5 %.
        words = {"run", "--resume", dir.string(), "--threads", std::to_string(o.threads)};
        // A campaign extended since the run ended or stopped: on to the campaign's duration.
        const std::optional<RunProgress> progress = read_progress_file(dir);
        if (progress && ends_before(*progress, run.duration))
            words.insert(words.end(), {"--duration", exact_number(run.duration)});
    } else {
        // Killed before its first checkpoint (or never started): from the start.
        what = fs::exists(dir, ec) ? "restart (no checkpoint yet)" : "start";
        words = {"run",       paths.config(run).string(), "--out", dir.string(), "--overwrite",
                 "--threads", std::to_string(o.threads)};
    }
    if (o.backend) words.insert(words.end(), {"--backend", to_string(*o.backend)});
    return words;
}

pid_t spawn(const fs::path& executable, const std::vector<std::string>& words,
            const fs::path& log) {
    const int fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd < 0) throw FileError(log.string(), "cannot be opened for the run's output");
    std::vector<std::string> storage{executable.string()};
    storage.insert(storage.end(), words.begin(), words.end());
    std::vector<char*> argv;
    for (std::string& w : storage)
        argv.push_back(w.data());
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(fd, STDOUT_FILENO);
        ::dup2(fd, STDERR_FILENO);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    ::close(fd);
    if (pid < 0) throw FileError(executable.string(), "cannot be started (fork failed)");
    return pid;
}

bool is_stop_signal(int signal) {
    return signal == SIGINT || signal == SIGTERM || signal == SIGHUP;
}

std::string log_since(const fs::path& log, std::streamoff from) {
    std::ifstream in(log, std::ios::binary);
    in.seekg(from);
    std::ostringstream s;
    s << in.rdbuf();
    std::string text = s.str();
    // The last lines say what went wrong; the whole log stays on disk.
    constexpr std::size_t kTail = 2000;
    return text.size() > kTail ? text.substr(text.size() - kTail) : text;
}

}  // namespace

int run_campaign_locally(const CampaignPaths& paths, const CampaignGrid& grid,
                         const LocalExecutorOptions& o, std::ostream& out) {
    StopSignalGuard signals;
    const fs::path executable =
        o.executable.empty() ? fs::read_symlink("/proc/self/exe") : o.executable;
    const int max_failures = o.retry_failed ? 4 : 2;
    const CampaignWork work = campaign_work(paths, grid, o.only, max_failures);
    std::deque<std::size_t> queue(work.to_run.begin(), work.to_run.end());
    RunnerTally tally{.mine = work.mine.size(), .done = work.done, .failed = work.failed};
    if (!o.quiet)
        out << "campaign " << paths.dir.string() << ": " << tally.mine << " runs, " << tally.done
            << " done, " << queue.size() << " to run, " << tally.failed.size() << " failed; "
            << o.jobs << " at a time on " << o.threads << " thread" << (o.threads > 1 ? "s" : "")
            << " each" << std::endl;
    const auto started = Clock::now();
    std::map<pid_t, ActiveRun> active;
    int stop_signal = 0;
    while (!queue.empty() || !active.empty()) {
        if (const int s = stop_signal_received(); s != 0 && stop_signal == 0) {
            stop_signal = s;
            queue.clear();
            for (const auto& [pid, a] : active)
                ::kill(pid, s);
            if (!o.quiet)
                out << "campaign: stopping; each run writes its checkpoint (re-run the same "
                       "command to continue)"
                    << std::endl;
        }
        while (stop_signal == 0 && static_cast<int>(active.size()) < o.jobs && !queue.empty()) {
            const std::size_t i = queue.front();
            queue.pop_front();
            const CampaignRun& run = grid.runs[i];
            std::optional<RunClaim> claim = take_run(paths, run, max_failures, tally, o.quiet, out);
            if (!claim) continue;
            std::string what;
            const std::vector<std::string> words = run_words(paths, run, o, what);
            const fs::path log = paths.log(run);
            std::error_code ec;
            const std::streamoff log_start =
                fs::exists(log, ec) ? static_cast<std::streamoff>(fs::file_size(log, ec)) : 0;
            const pid_t pid = spawn(executable, words, log);
            active.emplace(pid, ActiveRun{i, std::move(*claim), Clock::now(), log_start});
            if (!o.quiet) out << "campaign: " << what << " " << run.id << std::endl;
        }
        int status = 0;
        const pid_t pid = ::waitpid(-1, &status, WNOHANG);
        if (pid <= 0) {
            std::this_thread::sleep_for(std::chrono::milliseconds(50));
            continue;
        }
        const auto it = active.find(pid);
        if (it == active.end()) continue;
        const CampaignRun& run = grid.runs[it->second.run];
        // A run exits 130 or 143 itself once its checkpoint is written; killed by the signal, it
        // did not write one, and 128 + the signal is the same number.
        const bool killed = WIFSIGNALED(status);
        const int code = killed ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
        const double seconds =
            std::chrono::duration<double>(Clock::now() - it->second.started).count();
        if (code == kExitOk) {
            ++tally.done;
            if (!o.quiet)
                out << "campaign: done " << run.id << " in " << format_duration(seconds) << " ("
                    << tally.done << "/" << tally.mine << " done)" << std::endl;
        } else if (!killed && (code == kExitInterrupted || code == kExitTerminated)) {
            if (!o.quiet)
                out << "campaign: stopped " << run.id << " (checkpoint written)" << std::endl;
        } else if (killed && stop_signal != 0 && is_stop_signal(WTERMSIG(status))) {
            // Stopping was asked for, so it is no failure; only the checkpoint is older.
            if (!o.quiet)
                out << "campaign: " << run.id << " was killed by signal " << WTERMSIG(status)
                    << " before it wrote its checkpoint; the next `campaign run` resumes it from "
                       "its last checkpoint"
                    << std::endl;
        } else {
            const std::string message = log_since(paths.log(run), it->second.log_start);
            const bool retry = judge_failure(paths, run, code, message, max_failures, o.quiet, out);
            // Once stopping, a first failure waits for the next command's retry.
            if (!retry)
                tally.failed.push_back(it->second.run);
            else if (stop_signal == 0)
                queue.push_back(it->second.run);
        }
        active.erase(it);
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
    return finish_runner(paths, grid, tally, seconds, stop_signal, o.quiet, out);
}

}  // namespace rodsea
