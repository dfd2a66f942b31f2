// Same parameters, seed and thread count: the same state, bit for bit.
#include <gtest/gtest.h>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

Simulation noisy_mixture(std::uint64_t seed) {
    Scene scene = polar_in_apolar_mixture(0.10, 2.5, 0.40, 20.0, seed);
    scene.params.noise_epsilon = 0.05;
    return Simulation(scene.params, scene.bodies);
}

TEST(Determinism, RepeatedRunsGiveTheSameStateHash) {
    Simulation a = noisy_mixture(3), b = noisy_mixture(3);
    a.run(3000);
    b.run(1000);  // stepping in pieces changes nothing either
    b.run(2000);
    EXPECT_GT(a.totals().noise_kicks, 0u);
    EXPECT_EQ(a.state_hash(), b.state_hash());
    EXPECT_EQ(a.kinetic_energy(), b.kinetic_energy());

    Simulation c = noisy_mixture(4);  // the hash does see the state: another seed differs
    c.run(3000);
    EXPECT_NE(a.state_hash(), c.state_hash());
}

}  // namespace
}  // namespace rodsea
