#pragma once
// RunPlan::choices: the docs/model.md CHOICEs in force in a plan, one line each.
#include <string>
#include <vector>

#include "rodsea/config/config_values.hpp"
#include "rodsea/config/run_plan.hpp"

namespace rodsea::config {

// One line per CHOICE key with its value, saying whether it is the CHOICE default or overrides
// it, plus the choices of docs/model.md that are not keys (the sphere-chain construction).
// `values` must be resolved (resolve.hpp).
std::vector<std::string> list_choices(const ConfigValues& values, const RunPlan& plan);

}  // namespace rodsea::config
