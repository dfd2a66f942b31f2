#include "rodsea/io/atomic_file.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "rodsea/error.hpp"

namespace rodsea {

void sync_file(const std::filesystem::path& path) {
    const int fd = ::open(path.c_str(), O_RDONLY);
    if (fd < 0) throw FileError(path.string(), std::string("cannot open: ") + std::strerror(errno));
    const int status = ::fsync(fd);
    const int error = errno;
    ::close(fd);
    if (status != 0) throw FileError(path.string(), std::string("fsync: ") + std::strerror(error));
}

void replace_file_atomically(const std::filesystem::path& path,
                             const std::function<void(const std::filesystem::path&)>& write) {
    // Unique per process: runners that write the same file at the same moment (the tasks of a
    // job array preparing one campaign directory) must not truncate each other's temporary.
    const std::filesystem::path tmp = path.string() + ".tmp." + std::to_string(::getpid());
    try {
        write(tmp);
        sync_file(tmp);
        std::error_code ec;
        std::filesystem::rename(tmp, path, ec);
        if (ec) throw FileError(path.string(), "cannot rename into place: " + ec.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(tmp, ignored);
        throw;
    }
}

int remove_stale_temporaries(const std::filesystem::path& dir) {
    int removed = 0;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
        const std::string name = entry.path().filename().string();
        const std::size_t at = name.rfind(".tmp.");
        if (at == std::string::npos || !entry.is_regular_file(ec)) continue;
        const std::string pid = name.substr(at + 5);
        if (pid.empty() || pid.find_first_not_of("0123456789") != std::string::npos ||
            pid.size() > 9)
            continue;
        // A live writer's temporary is its own business (kill(pid, 0) fails with ESRCH only
        // for a process that does not exist).
        if (::kill(static_cast<pid_t>(std::stol(pid)), 0) == 0 || errno != ESRCH) continue;
        if (std::filesystem::remove(entry.path(), ec)) ++removed;
    }
    return removed;
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
    replace_file_atomically(path, [&](const std::filesystem::path& tmp) {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out)
            throw FileError(tmp.string(), std::string("cannot create: ") + std::strerror(errno));
        out << text;
        out.flush();
        if (!out)
            throw FileError(tmp.string(), std::string("write failed: ") + std::strerror(errno));
    });
}

}  // namespace rodsea
