#pragma once
// What Python holds for a config: the resolved plan and where it came from.
#include <string>

#include "rodsea/config/run_plan.hpp"

namespace rodsea::python {

struct Config {
    RunPlan plan;
    std::string source;
};

}  // namespace rodsea::python
