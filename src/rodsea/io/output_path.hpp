#pragma once
// Checks, before any work starts, that a command will be able to write its output file: a
// long movie or export must not fail at its end because of a typo in the directory name.
#include <filesystem>
#include <string>

namespace rodsea {

// Throws InvalidParameter (naming `flag`) when `path` does not end in `extension` (".png"; ""
// for any name) or is an existing directory, and FileError when its directory does not exist or is
// not writable.
void check_output_file(const std::string& flag, const std::filesystem::path& path,
                       const std::string& extension);

}  // namespace rodsea
