#pragma once
// `rodsea run` and `rodsea info`: a config in, a run directory out (run_driver.hpp), or what the
// run would be, without running it (plan_report.hpp).
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& run_command_spec();
const CommandSpec& info_command_spec();

// `words` are the words after the command name. Throw InvalidParameter (exit 2) or FileError
// (exit 74) for bad input before any work; return the exit code otherwise.
int run_command(const std::vector<std::string>& words, std::ostream& out, std::ostream& err);
int info_command(const std::vector<std::string>& words, std::ostream& out, std::ostream& err);

}  // namespace rodsea
