#pragma once
// `rodsea plot`: see kPlotHelp and docs/visualisation.md.
#include <iosfwd>
#include <string>
#include <vector>

namespace rodsea {

extern const char* const kPlotHelp;

// `args` are the words after `rodsea plot`. Checks all input before writing anything; throws
// InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
