#include "rodsea/io/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <thread>

#include "rodsea/error.hpp"

namespace rodsea {

namespace {

constexpr const char* kLockFile = ".rodsea.lock";

}  // namespace

RunDirectoryLock::RunDirectoryLock(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / kLockFile;
    fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw FileError(path.string(),
                        std::string("cannot create the run's lock file: ") + std::strerror(errno));
    // A probe (run_directory_in_use) holds the lock for microseconds: a few tries over a second
    // tell it from a run that holds it for hours.
    int tries = 0;
    while (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
        if (error == EWOULDBLOCK && ++tries < 50) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            continue;
        }
        ::close(fd_);
        fd_ = -1;
        if (error == EWOULDBLOCK)
            throw InvalidParameter("run directory", dir.string(), "one rodsea process at a time",
                                   "another rodsea process is running in it");
        throw FileError(path.string(), std::string("cannot lock: ") + std::strerror(error));
    }
}

RunDirectoryLock::~RunDirectoryLock() {
    if (fd_ >= 0) ::close(fd_);
}

bool run_directory_in_use(const std::filesystem::path& dir) {
    const int fd = ::open((dir / kLockFile).c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return false;  // no run has started in it
    const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0 && errno == EWOULDBLOCK;
    ::close(fd);  // closing releases the probe's shared lock
    return held;
}

}  // namespace rodsea
