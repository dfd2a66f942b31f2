#pragma once
// Process exit codes of every command (`rodsea --help` lists them).

namespace rodsea {

enum ExitCode : int {
    kExitOk = 0,
    kExitFailure = 1,        // anything unexpected
    kExitBadInput = 2,       // bad config, option or run directory: nothing was done
    kExitBlownUp = 3,        // the simulation blew up: last good frame checkpointed
    kExitIoError = 74,       // a file could not be written (disk full, permissions): checkpointed
    kExitInterrupted = 130,  // SIGINT: checkpointed, resume with --resume
    kExitTerminated = 143,   // SIGTERM: checkpointed, resume with --resume
};

}  // namespace rodsea
