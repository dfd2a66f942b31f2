#include "rodsea/engine/cpu/free_flight.hpp"

#include <cmath>

#include "rodsea/engine/physics/free_flight.hpp"

namespace rodsea::cpu {

double advance_free_flight(BodyView bodies, const SpeciesTable& species, const StepContext& step,
                           int threads) {
    const double drop = step.drop();
    const auto n = static_cast<std::ptrdiff_t>(bodies.size());
    // The largest squared speed in the plane of a centre of mass, and of a sphere about it
    // (mm²/s²): the sum of their roots bounds every sphere centre's speed in the plane, with no
    // square root per body.
    double fastest_drift2 = 0.0, fastest_turn2 = 0.0;
    // clang-format off
#pragma omp parallel for schedule(static) num_threads(threads) if (threads > 1) \
    reduction(max : fastest_drift2, fastest_turn2)
    // clang-format on
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const std::uint32_t k = bodies.species[i];
        physics::fly_freely(bodies.position[i], bodies.velocity[i], bodies.orientation[i],
                            bodies.spin[i], species.rotor[k], species.reach2[k], step, drop,
                            fastest_drift2, fastest_turn2);
    }
    return std::sqrt(fastest_drift2) + std::sqrt(fastest_turn2);
}

}  // namespace rodsea::cpu
