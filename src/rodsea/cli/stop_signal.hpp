#pragma once
// SIGINT, SIGTERM and SIGHUP ask a run to stop at the end of the current step (the handler only
// sets a flag; the run loop writes the checkpoint). Another one within a second is the same
// request delivered twice (to a terminal's process group, passed on by a campaign runner) and is
// ignored; a later one kills the process, as the default action does. SIGXFSZ is ignored so that
// a file-size limit shows up as a failed write, handled like a full disk, instead of killing the
// process.
namespace rodsea {

// Installs the handlers for its lifetime and restores the previous ones afterwards. Guards nest:
// an inner one (a run stepped by a campaign runner) leaves the outer one's handlers and flag.
class StopSignalGuard {
  public:
    StopSignalGuard();
    ~StopSignalGuard();
    StopSignalGuard(const StopSignalGuard&) = delete;
    StopSignalGuard& operator=(const StopSignalGuard&) = delete;
};

// The signal number received since the outermost guard was installed, or 0.
int stop_signal_received();

// Thrown by commands that stop between units of work (movie frames, export frames) when a stop
// signal arrived: it unwinds through replace_file_atomically, which removes the unfinished file.
struct StopRequested {
    int signal = 0;
    // 130 for SIGINT, 143 for SIGTERM and SIGHUP (both mean "the session is going away")
    int exit_code() const;
};

}  // namespace rodsea
