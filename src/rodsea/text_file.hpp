#pragma once
// Reading a whole text file, with the errors every command gives for it.
#include <filesystem>
#include <string>

namespace rodsea {

// The file's bytes. Throws FileError naming the path for a missing file, a directory, or one
// that cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace rodsea
