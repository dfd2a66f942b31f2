#pragma once
// The `rodsea analyze` command line: options parsed and checked for every run before any frame
// is read, then each run analysed and written, then the table across runs.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& analyze_command_spec();

// `args` are the words after `rodsea analyze`. Throws InvalidParameter / FileError; returns 0.
int analyze_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& log);

}  // namespace rodsea
