#pragma once
// One writer per run directory: two processes resuming the same run, or --overwrite on a run
// that is still going, would interleave their writes. The lock is an flock on DIR/.rodsea.lock,
// held for the life of this object and released by the OS if the process dies.
#include <filesystem>

namespace rodsea {

class RunDirectoryLock {
  public:
    // Throws InvalidParameter naming the directory when another process holds it (for longer
    // than a moment: run_directory_in_use's probe holds it for microseconds).
    explicit RunDirectoryLock(const std::filesystem::path& dir);
    ~RunDirectoryLock();
    RunDirectoryLock(const RunDirectoryLock&) = delete;
    RunDirectoryLock& operator=(const RunDirectoryLock&) = delete;

  private:
    int fd_ = -1;
};

// Whether a rodsea process holds DIR's lock now (a run going in it, started by a campaign or by
// hand): what `campaign status` and a campaign runner must know before they call a run with a
// checkpoint interrupted and resume it.
bool run_directory_in_use(const std::filesystem::path& dir);

}  // namespace rodsea
