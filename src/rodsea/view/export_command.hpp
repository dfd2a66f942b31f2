#pragma once
// `rodsea export`: see kExportHelp and docs/export.md.
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsea {

extern const char* const kExportHelp;

// `args` are the words after `rodsea export`. Checks all input before writing anything; throws
// InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int export_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
