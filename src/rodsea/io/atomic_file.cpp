#include "rodsea/io/atomic_file.hpp"

#include <fcntl.h>
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
