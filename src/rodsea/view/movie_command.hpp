#pragma once
// `rodsea movie`: see movie_command_spec() and docs/visualisation.md.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& movie_command_spec();

// `args` are the words after `rodsea movie`. Checks all input before writing anything; throws
// InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int movie_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
