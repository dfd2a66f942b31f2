#include "rodsea/text_file.hpp"

#include <fstream>
#include <sstream>

#include "rodsea/error.hpp"

namespace rodsea {

std::string read_text_file(const std::filesystem::path& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) throw FileError(path.string(), "no such file");
    if (std::filesystem::is_directory(path, ec))
        throw FileError(path.string(), "is a directory, not a file");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw FileError(path.string(), "cannot be opened for reading");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw FileError(path.string(), "read failed");
    return text.str();
}

}  // namespace rodsea
