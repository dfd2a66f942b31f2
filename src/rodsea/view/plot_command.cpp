#include "rodsea/view/plot_command.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <ostream>

#include "rodsea/cli/arguments.hpp"
#include "rodsea/cli/exit_codes.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

const CommandSpec& plot_command_spec() {
    static const CommandSpec spec{
        "plot",
        "INPUT -o DIR [--dpi D] [--only F,..] [--quiet]",
        "the paper's figure types, drawn with matplotlib",
        "Draws the paper's figure types as PNG files in DIR (created if needed) with matplotlib, "
        "from\n"
        "  one run's analysis  RUN_DIR, RUN_DIR/analysis or its analysis.json (`rodsea analyze "
        "RUN_DIR`): order_parameters, autocorrelation (C(t), C2(t) and their D_r fits), "
        "flocks_time, flock_sizes, g_r_theta and G_r_theta (polar heat maps in the corotating "
        "frame with the 70 % contour), pair_correlation, segregation, medium_velocity\n"
        "  a table of runs     T.csv from `rodsea analyze RUN1 RUN2 ... --table T.csv` (or a "
        "run's summary.csv): P and Sigma vs phi_a and vs D_r with error bars, the phase diagram "
        "(ordered P > 0.5 vs disordered in the (phi_a, D_r) plane), and S, sigma_f, N_m, N_avg, "
        "D_r vs phi_a\n"
        "What the input cannot give (a run without polar rods has no g(r,theta)) is skipped with "
        "a note. Every input is checked before the first figure is drawn; each PNG is written "
        "under a temporary name and renamed, so none is ever half-written. Prints the PNG files, "
        "one per line. Figures and what they mirror in the paper: docs/plots.md.",
        {{"-o,--output", "DIR", "where the PNG files go"},
         {"--dpi", "D",
          "pixels per inch, 20 to 600 (default 150: a 6.5 x 4.5 in figure is 975 x 675)"},
         {"--only", "F,..",
          "only these figures, by file name (.png optional): --only g_r_theta,G_r_theta"},
         {"--quiet", "", "no notes on what was skipped"}},
        "Runs /usr/bin/python3 (env RODSEA_PYTHON overrides) on rodsea_plot.py in the source "
        "tree's scripts/ (env RODSEA_SCRIPTS_DIR overrides the folder); needs Debian's "
        "python3-matplotlib, python3-numpy and python3-h5py: ./scripts/install-deps.sh installs "
        "them.\nExit codes: 0 done; 1 Python or one of its modules missing; 2 bad input (nothing "
        "written); 74 a file could not be read or written."};
    return spec;
}

namespace {

namespace fs = std::filesystem;

constexpr const char* kInstall = "install it with ./scripts/install-deps.sh";

std::string environment_or(const char* name, const char* fallback) {
    const char* value = std::getenv(name);
    return value != nullptr && *value != '\0' ? std::string(value) : std::string(fallback);
}

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

// Runs argv[0] with `argv` (no shell), its stdout and stderr forwarded to `out` and `err`.
// Returns its exit code, or 128 + the signal that ended it.
int run_child(std::vector<std::string> argv_words, std::ostream& out, std::ostream& err) {
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
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(out_pipe[1], STDOUT_FILENO);
        ::dup2(err_pipe[1], STDERR_FILENO);
        ::execv(argv[0], argv.data());
        static const char message[] = "rodsea plot: the Python interpreter could not be started\n";
        [[maybe_unused]] const ssize_t ignored =
            ::write(STDERR_FILENO, message, sizeof message - 1);
        ::_exit(kExitFailure);
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

}  // namespace

int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    const std::optional<Arguments> parsed = arguments_or_help(args, plot_command_spec(), out);
    if (!parsed) return kExitOk;
    const Arguments& a = *parsed;
    if (a.positional.size() != 1)
        throw InvalidParameter("INPUT", std::to_string(a.positional.size()) + " given",
                               "exactly one: a run's analysis directory, its analysis.json or a "
                               "table CSV (see rodsea plot --help)");
    const std::string input = a.positional[0];
    const auto output = a.value("--output");
    if (!output || output->empty())
        throw InvalidParameter("-o", output ? "''" : "missing",
                               "the directory for the PNG files: rodsea plot INPUT -o DIR");
    const long long dpi = parse_count("--dpi", a.value("--dpi").value_or("150"), 20, 600);
    std::error_code ec;
    if (!fs::exists(input, ec)) throw FileError(input, "no such file or directory");

    const std::string python = environment_or("RODSEA_PYTHON", "/usr/bin/python3");
    const fs::path script =
        fs::path(environment_or("RODSEA_SCRIPTS_DIR", RODSEA_SCRIPTS_DIR)) / "rodsea_plot.py";
    if (::access(python.c_str(), X_OK) != 0) {
        err << "rodsea plot: the Python interpreter " << python << " is missing or not executable; "
            << kInstall
            << " (Debian's python3, python3-matplotlib, python3-numpy, python3-h5py), or set "
               "RODSEA_PYTHON to a Python 3 that has them\n";
        return kExitFailure;
    }
    if (!fs::is_regular_file(script, ec)) {
        err << "rodsea plot: the plot script " << script.string()
            << " is missing; set RODSEA_SCRIPTS_DIR to the scripts/ folder of the rodsea "
               "source tree\n";
        return kExitFailure;
    }
    std::string output_flag = "--output=";
    output_flag += *output;
    std::vector<std::string> argv{python,      "-B",    script.string(),
                                  output_flag, "--dpi", std::to_string(dpi)};
    if (const auto only = a.value("--only")) {
        std::string only_flag = "--only=";
        only_flag += *only;
        argv.push_back(only_flag);
    }
    if (a.has("--quiet")) argv.emplace_back("--quiet");
    argv.emplace_back("--");  // INPUT is never taken for an option, whatever its name
    argv.push_back(input);
    return run_child(std::move(argv), out, err);
}

}  // namespace rodsea
