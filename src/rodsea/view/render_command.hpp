#pragma once
// `rodsea render`: see render_command_spec() and docs/visualisation.md.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& render_command_spec();

// `args` are the words after `rodsea render`. Checks all input before writing anything; throws
// InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int render_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
