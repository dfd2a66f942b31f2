#include "rodsea/engine/cpu/free_flight.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/engine/physics/free_flight.hpp"

namespace rodsea::cpu {

double advance_free_flight(BodyView bodies, const SpeciesTable& species, const StepContext& step,
                           int threads) {
    const double dt = step.dt, gravity = step.gravity, drop = step.drop();
    const PeriodicBox2D box = step.box;
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
        const physics::Rotor& rotor = species.rotor[k];
        const physics::PlanarSpeed2 s = physics::planar_speed2(
            bodies.velocity[i], bodies.orientation[i], bodies.spin[i], rotor, species.reach2[k]);
        fastest_drift2 = std::max(fastest_drift2, s.drift2);
        fastest_turn2 = std::max(fastest_turn2, s.turn2);
        physics::fly_freely(bodies.position[i], bodies.velocity[i], bodies.orientation[i],
                            bodies.spin[i], rotor, dt, gravity, drop, box);
    }
    return std::sqrt(fastest_drift2) + std::sqrt(fastest_turn2);
}

}  // namespace rodsea::cpu
