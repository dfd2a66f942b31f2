#include "rodsea/io/output_path.hpp"

#include <unistd.h>

#include <cerrno>

#include "rodsea/error.hpp"

namespace rodsea {

namespace fs = std::filesystem;

void check_output_file(const std::string& flag, const fs::path& path,
                       const std::string& extension) {
    const std::string wanted =
        extension.empty() ? "a file name" : "a file name ending in " + extension;
    if (!extension.empty() && path.extension() != extension)
        throw InvalidParameter(flag, path.string(), wanted);
    if (fs::is_directory(path))
        throw InvalidParameter(flag, path.string(), wanted, "it is a directory");
    const fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    if (!fs::is_directory(dir))
        throw FileError(path.string(),
                        "cannot be written: its directory " + dir.string() + " does not exist");
    if (::access(dir.c_str(), W_OK | X_OK) != 0)
        throw FileError(path.string(), errno == EROFS ? "cannot be written: " + dir.string() +
                                                            " is on a read-only file system"
                                                      : "cannot be written: no write permission "
                                                        "in " +
                                                            dir.string());
}

}  // namespace rodsea
