#pragma once
// `rodsea campaign plan|run|status|collect CAMPAIGN`: a figure's grid of runs with one command.
#include <iosfwd>
#include <string>
#include <vector>

#include "rodsea/cli/arguments.hpp"

namespace rodsea {

const CommandSpec& campaign_command_spec();
int campaign_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace rodsea
