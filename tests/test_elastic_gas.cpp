// An elastic, frictionless gas of rods between fixed plates without gravity keeps its kinetic
// energy: every impulse with e = 1, μ = 0 conserves energy exactly and so does the free flight
// of axisymmetric bodies, so only round-off remains.
#include <gtest/gtest.h>

#include "each_backend.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

class ElasticGas : public testing::EachBackend {};

TEST_P(ElasticGas, KeepsKineticEnergyOverTenThousandSteps) {
    const Box box{20.0, 20.0};
    Scene scene = monolayer(
        {{polar_rod_species(), 20}, {apolar_rod_species(2.5), 80}, {bead_species(), 40}}, box, 5);
    scene.params.drive.gamma = 0.0;
    scene.params.drive.gravity = 0.0;
    // The scene rests every body on the driven base, at z = A = 43 µm at t = 0; with the base
    // held at 0 the polar rods' thick ends reach 1.42 mm, so the lid goes up a little.
    scene.params.drive.gap = 1.5;
    scene.params.dt = 5e-6;  // s: 10 000 steps are 50 ms, long enough for > 1000 collisions
    scene.params.body_body = {0.0, 1.0};
    for (Species& s : scene.params.species)
        s.plate = {0.0, 1.0};
    SplitMix64 rng(99);
    for (size_t b = 0; b < scene.bodies.size(); ++b) {
        scene.bodies.velocity[b] = {rng.uniform(-150, 150), rng.uniform(-150, 150),
                                    rng.uniform(-60, 60)};
        scene.bodies.spin[b] = {rng.uniform(-100, 100), rng.uniform(-100, 100),
                                rng.uniform(-100, 100)};
    }
    Simulation sim(scene.params, scene.bodies, options());
    const double e0 = sim.kinetic_energy();
    sim.run(10000);
    EXPECT_NEAR(sim.kinetic_energy(), e0, 1e-9 * e0);
    EXPECT_EQ(sim.totals().unresolved, 0u);
    // The test means something only if the gas actually collided, with plates and each other.
    EXPECT_GT(sim.totals().impulses, 1000u);
}

RODSEA_ON_EACH_STEP(ElasticGas);

}  // namespace
}  // namespace rodsea
