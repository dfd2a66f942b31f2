#include "rodsea/run/run_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "rodsea/error.hpp"

namespace rodsea {

RunDirectoryLock::RunDirectoryLock(const std::filesystem::path& dir) {
    const std::filesystem::path path = dir / ".rodsea.lock";
    fd_ = ::open(path.c_str(), O_CREAT | O_RDWR | O_CLOEXEC, 0644);
    if (fd_ < 0)
        throw FileError(path.string(),
                        std::string("cannot create the run's lock file: ") + std::strerror(errno));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
        const int error = errno;
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

}  // namespace rodsea
