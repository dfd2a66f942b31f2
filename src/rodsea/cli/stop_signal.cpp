#include "rodsea/cli/stop_signal.hpp"

#include <csignal>

namespace rodsea {

namespace {

volatile std::sig_atomic_t received = 0;
// Guards nest (a campaign runner steps its runs through `rodsea run`'s own code): only the
// outermost installs and restores the handlers, so that a signal that came between an inner
// guard's end and the next one's start is not forgotten.
int depth = 0;
struct sigaction previous_int, previous_term, previous_hup, previous_xfsz;

extern "C" void on_stop_signal(int signal) {
    received = signal;
}

}  // namespace

StopSignalGuard::StopSignalGuard() {
    if (depth++ > 0) return;
    received = 0;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    // A second Ctrl-C kills as usual, for when the clean stop is not wanted.
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
    sigaction(SIGHUP, &action, &previous_hup);  // the terminal closed, or an ssh session died
    struct sigaction ignore {};
    ignore.sa_handler = SIG_IGN;
    sigemptyset(&ignore.sa_mask);
    sigaction(SIGXFSZ, &ignore, &previous_xfsz);
}

StopSignalGuard::~StopSignalGuard() {
    if (--depth > 0) return;
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
    sigaction(SIGHUP, &previous_hup, nullptr);
    sigaction(SIGXFSZ, &previous_xfsz, nullptr);
}

int stop_signal_received() {
    return received;
}

int StopRequested::exit_code() const {
    return 128 + (signal == SIGHUP ? SIGTERM : signal);
}

}  // namespace rodsea
