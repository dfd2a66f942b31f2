#pragma once
// `rodsea calibrate CONFIG`: single-body experiments over a grid of noise amplitudes ε, gaps w
// and time steps dt (see calibrate_command_spec()), run in parallel, written as one table.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& calibrate_command_spec();

// `args` are the words after `rodsea calibrate`. Checks the whole config before any run;
// throws InvalidParameter (exit 2) or FileError (exit 74); returns the exit code otherwise.
int calibrate_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
