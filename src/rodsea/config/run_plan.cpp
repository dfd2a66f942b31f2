#include "rodsea/config/run_plan.hpp"

#include <algorithm>
#include <cmath>

namespace rodsea {

std::uint64_t RunPlan::total_steps() const {
    return static_cast<std::uint64_t>(std::max(0LL, std::llround(control.duration / engine.dt)));
}

double RunPlan::frame_interval() const {
    return static_cast<double>(steps_per_output()) * engine.dt;
}

std::uint64_t RunPlan::steps_per_output() const {
    // Validation keeps the interval >= dt; the floor of 1 guards plans built by hand.
    return static_cast<std::uint64_t>(
        std::max(1LL, std::llround(control.output_interval / engine.dt)));
}

}  // namespace rodsea
