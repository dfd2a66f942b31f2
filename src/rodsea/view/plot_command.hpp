#pragma once
// `rodsea plot`: the paper's figure types from `rodsea analyze` output, drawn by the matplotlib
// scripts in scripts/ (rodsea_plot.py); see plot_command_spec() and docs/plots.md.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& plot_command_spec();

// `args` are the words after `rodsea plot`. Checks the arguments and that INPUT exists (throws
// InvalidParameter, exit 2, or FileError, exit 74), then runs the Python script, which checks the
// input's content before writing anything, with its output forwarded to `out` and `err`. Returns
// the script's exit code (1 when Python or the script is missing, with a message on `err`).
int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
