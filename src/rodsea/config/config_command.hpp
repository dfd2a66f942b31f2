#pragma once
// `rodsea config --defaults | --reference`: the key table as a starting config or as docs.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& config_command_spec();
int config_command(const std::vector<std::string>& words, std::ostream& out, std::ostream& err);

}  // namespace rodsea
