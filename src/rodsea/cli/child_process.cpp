#include "rodsea/cli/child_process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <ostream>

#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

namespace {

// Copies what the child writes to `fd` into `to` until the child closes it.
bool forward(int fd, std::ostream& to) {
    char buffer[4096];
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n > 0) {
        to.write(buffer, n);
        to.flush();
        return true;
    }
    return n < 0 && errno == EINTR;
}

}  // namespace

int run_program(std::vector<std::string> argv_words, std::ostream& out, std::ostream& err,
                int exec_failure) {
    std::vector<char*> argv;
    for (std::string& word : argv_words)
        argv.push_back(word.data());
    argv.push_back(nullptr);
    int out_pipe[2], err_pipe[2];
    if (::pipe2(out_pipe, O_CLOEXEC) != 0) throw FileError("pipe", "cannot be created");
    if (::pipe2(err_pipe, O_CLOEXEC) != 0) {
        ::close(out_pipe[0]), ::close(out_pipe[1]);
        throw FileError("pipe", "cannot be created");
    }
    out.flush();
    err.flush();
    // Made before fork: the child only calls async-signal-safe functions.
    const std::string failure = "rodsea: " + argv_words[0] + " could not be started\n";
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(out_pipe[1], STDOUT_FILENO);
        ::dup2(err_pipe[1], STDERR_FILENO);
        ::execvp(argv[0], argv.data());
        [[maybe_unused]] const ssize_t ignored =
            ::write(STDERR_FILENO, failure.data(), failure.size());
        ::_exit(exec_failure);
    }
    ::close(out_pipe[1]);
    ::close(err_pipe[1]);
    if (pid < 0) {
        ::close(out_pipe[0]), ::close(err_pipe[0]);
        throw FileError(argv_words[0], "cannot be started (fork failed)");
    }
    pollfd fds[2] = {{out_pipe[0], POLLIN, 0}, {err_pipe[0], POLLIN, 0}};
    std::ostream* sinks[2] = {&out, &err};
    int open_pipes = 2;
    while (open_pipes > 0) {
        if (::poll(fds, 2, -1) < 0) {
            if (errno == EINTR) continue;
            break;
        }
        for (int k = 0; k < 2; ++k) {
            if (fds[k].fd < 0 || fds[k].revents == 0) continue;
            if (!forward(fds[k].fd, *sinks[k])) {
                ::close(fds[k].fd);
                fds[k].fd = -1;
                --open_pipes;
            }
        }
    }
    for (const pollfd& p : fds)
        if (p.fd >= 0) ::close(p.fd);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return kExitFailure;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace rodsea
