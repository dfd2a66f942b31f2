#pragma once
// Runs the rodsea executable as a child process, the way a user or a batch system does: with its
// output captured, optionally a file-size limit (a stand-in for a disk that fills up), and
// optionally SIGINT sent once a condition holds (Ctrl-C in the middle of a run).
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "scratch_dir.hpp"

namespace rodsea {

struct ChildResult {
    int exit_code = -1;  // the process's exit status, or 128 + signal when killed
    std::string out, err;
    bool interrupted = false;  // whether SIGINT was sent
};

struct ChildOptions {
    long long file_size_limit = -1;        // bytes, RLIMIT_FSIZE; < 0 for none
    std::function<bool()> interrupt_when;  // polled every 10 ms; a signal once it returns true
    int interrupt_signal = SIGINT;         // the signal interrupt_when sends
    // To the child's process group, as Ctrl-C at a terminal signals every process of the
    // foreground job (a campaign runner and the runs it started), rather than to the child alone.
    bool interrupt_group = false;
    double timeout_seconds = 120.0;
};

inline ChildResult run_rodsea(const std::vector<std::string>& args,
                              const std::filesystem::path& scratch,
                              const ChildOptions& options = {}) {
    const auto out_path = scratch / "child.out", err_path = scratch / "child.err";
    std::vector<std::string> argv_storage{RODSEA_EXECUTABLE};
    argv_storage.insert(argv_storage.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (std::string& a : argv_storage)
        argv.push_back(a.data());
    argv.push_back(nullptr);

    const pid_t pid = fork();
    if (pid < 0) throw std::runtime_error("fork failed");
    if (pid == 0) {
        if (options.interrupt_group) ::setpgid(0, 0);
        if (!std::freopen(out_path.c_str(), "w", stdout) ||
            !std::freopen(err_path.c_str(), "w", stderr))
            _exit(125);
        if (options.file_size_limit >= 0) {
            const rlimit limit{static_cast<rlim_t>(options.file_size_limit),
                               static_cast<rlim_t>(options.file_size_limit)};
            setrlimit(RLIMIT_FSIZE, &limit);
        }
        execv(argv[0], argv.data());
        _exit(126);
    }
    // Here too, so that the group exists before any signal is sent to it.
    if (options.interrupt_group) ::setpgid(pid, pid);
    ChildResult result;
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    // Whatever happens in this process, the child does not outlive the test.
    struct Reaper {
        pid_t pid;
        bool group;  // and the processes it started, when it leads a group of its own
        bool done = false;
        ~Reaper() {
            if (done) return;
            kill(group ? -pid : pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
    } reaper{pid, options.interrupt_group};
    while (waitpid(pid, &status, WNOHANG) == 0) {
        if (options.interrupt_when && !result.interrupted && options.interrupt_when()) {
            kill(options.interrupt_group ? -pid : pid, options.interrupt_signal);
            result.interrupted = true;
        }
        if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >
            options.timeout_seconds) {
            throw std::runtime_error("rodsea did not finish within the test's timeout");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    reaper.done = true;
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    result.out = read_text(out_path);
    result.err = read_text(err_path);
    return result;
}

// A shell command's standard output (tools such as ffprobe and Debian's python3 in tests).
inline std::string shell_output(const std::string& command) {
    std::string out;
    if (FILE* pipe = ::popen(command.c_str(), "r")) {
        char buffer[512];
        while (std::fgets(buffer, sizeof buffer, pipe) != nullptr)
            out += buffer;
        ::pclose(pipe);
    }
    return out;
}

// Sets an environment variable (inherited by child processes) until the end of the scope,
// then restores what was there.
class ScopedEnv {
  public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        ::setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() { old_.empty() ? ::unsetenv(name_) : ::setenv(name_, old_.c_str(), 1); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

  private:
    const char* name_;
    std::string old_;
};

}  // namespace rodsea
