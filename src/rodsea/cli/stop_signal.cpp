#include "rodsea/cli/stop_signal.hpp"

#include <time.h>

#include <csignal>

namespace rodsea {

namespace {

volatile std::sig_atomic_t received = 0;
// When the first stop signal came (CLOCK_MONOTONIC, ns). One request to stop often reaches a run
// twice: Ctrl-C signals the terminal's whole process group, a campaign runner and its runs, and
// the runner passes it on to each run; `pkill rodsea` and SLURM's scancel signal every process
// too. Killed by the repeat, a run would lose everything since its last checkpoint. So a repeat
// within a second is that same request; a later one is a second Ctrl-C, which kills as usual for
// when the clean stop is not wanted. Written before `received`, with the other stop signals
// blocked in the handler; a 64-bit store is one instruction on the machines rodsea runs on.
volatile long long first_stop_ns = 0;
constexpr long long kRepeatWindowNs = 1'000'000'000;
// Guards nest (a campaign runner steps its runs through `rodsea run`'s own code): only the
// outermost installs and restores the handlers, so that a signal that came between an inner
// guard's end and the next one's start is not forgotten.
int depth = 0;
struct sigaction previous_int, previous_term, previous_hup, previous_xfsz;

long long monotonic_nanoseconds() {
    timespec now{};
    clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe (POSIX)
    return static_cast<long long>(now.tv_sec) * 1'000'000'000 + now.tv_nsec;
}

extern "C" void on_stop_signal(int signal) {
    const long long now = monotonic_nanoseconds();
    if (received == 0) {
        first_stop_ns = now;
        received = signal;
        return;
    }
    if (now - first_stop_ns < kRepeatWindowNs) return;
    ::signal(signal, SIG_DFL);
    ::raise(signal);
}

}  // namespace

StopSignalGuard::StopSignalGuard() {
    if (depth++ > 0) return;
    received = 0;
    struct sigaction action {};
    action.sa_handler = on_stop_signal;
    action.sa_flags = 0;
    // One handler at a time in a thread, so that a repeat sees the first one recorded.
    sigemptyset(&action.sa_mask);
    sigaddset(&action.sa_mask, SIGINT);
    sigaddset(&action.sa_mask, SIGTERM);
    sigaddset(&action.sa_mask, SIGHUP);
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
