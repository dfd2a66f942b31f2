// The golden determinism test (Box2D's test_determinism.c): a fixed system, seed and number of
// steps, and the hash of the final state compared with a committed value. Any change to the
// physics or to the order of its floating-point operations changes the hash, so a silent change
// fails here. Changing kGoldenHash is a deliberate commit that says why the trajectory changed.
//
// The system is built here, not by the builder or the scenario library, so that a new initial
// state there does not move the golden value: only the step can.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"

namespace rodsea {
namespace {

// The engine's hash after kGoldenSteps steps of golden_system(), recorded at commit "Golden
// determinism test" with the engine of fd22886 (0x48a50052003b8eb2), unchanged by every refactor
// until beads got their own torque-free rotation (ω kept, one turn about it, instead of the
// symmetric body's ω → L → ω round trip: the beads' round-off changed, nothing else; with that
// path switched off the old hash returned).
constexpr std::uint64_t kGoldenHash = 0x1d2c76e1cb4aabd5ULL;
constexpr std::uint64_t kGoldenSteps = 6000;  // 7.5 ms: one and a half drive periods

// An asymmetric body (three unequal principal moments): the general torque-free rotation path,
// which no rod or bead takes.
Species bent_body() {
    const SphereList spheres{
        {{0.0, 0.0, 0.0}, 0.3}, {{0.7, 0.0, 0.0}, 0.3}, {{0.7, 0.65, 0.0}, 0.25}};
    return {"bent", BodyKind::apolar_rod, make_shape(spheres, 0.15, "bent"), {0.02, 0.4}};
}

// Every kind of body the engine moves, packed in rows close enough to collide within a drive
// period, with random in-plane velocities, spins that tip them, and rotational noise: every
// stage of the step (free flight on both rotation paths, contacts between bodies and with both
// plates, impulses, the projection out of the plates, the noise) runs many times.
EngineParameters golden_parameters() {
    EngineParameters p;
    p.box = {24.0, 24.0};
    p.species = {polar_rod_species(), apolar_rod_species(2.0), bead_species(), bent_body()};
    p.noise_epsilon = 0.05;
    p.seed = 20261123;
    return p;
}

BodyState golden_bodies(const EngineParameters& p) {
    SplitMix64 rng(7);
    BodyState bodies;
    const double row = 1.45;  // mm between rows: the widest body (1.375 mm) plus a little
    const double base = p.drive.amplitude();  // base height at t = 0
    for (int r = 0; r * row + row < p.box.ly; ++r) {
        const auto species = static_cast<std::uint32_t>(r % 4);
        const Shape& shape = p.species[species].shape;
        const double pitch = shape.extent + 0.05;
        for (int i = 0; (i + 1) * pitch < p.box.lx; ++i) {
            const double angle = rng.uniform() < 0.5 ? 0.0 : std::numbers::pi;
            // The definition frame flat (a bent body's spheres in a horizontal plane), turned.
            const Quat q =
                Quat::from_axis_angle({0, 0, 1}, angle) * conjugate(shape.definition_to_body);
            // Somewhere in the room its largest sphere leaves between the plates.
            const double room = p.drive.gap - 2.0 * shape.max_radius;
            const double z = base + shape.max_radius + room * (0.1 + 0.8 * rng.uniform());
            const Vec3 v{rng.uniform(-40.0, 40.0), rng.uniform(-40.0, 40.0),
                         rng.uniform(-5.0, 5.0)};
            const Vec3 w{rng.uniform(-30.0, 30.0), rng.uniform(-30.0, 30.0),
                         rng.uniform(-30.0, 30.0)};
            bodies.add(species, {(i + 0.5) * pitch, (r + 0.5) * row, z}, q, v, w);
        }
    }
    return bodies;
}

struct GoldenRun {
    Simulation sim;
    std::uint64_t body_contacts = 0;  // summed over the steps
};

// The coasting step's own golden value (BackendOptions::coasting: bodies in free flight left
// alone and jumped to where they may touch something). Its trajectory equals the per-step one to
// round-off, not to the bit, so it has a hash of its own; recorded when it was added, with the
// engine of 6865238.
constexpr std::uint64_t kCoastingGoldenHash = 0x3a1949d6f7fcbb5cULL;

GoldenRun golden_run(int threads, bool coasting = false) {
    const EngineParameters p = golden_parameters();
    // Neighbouring rods start overlapping (rows are packed by extent, not by shape), deeper than
    // the blow-up guard allows: the scene and its hash predate the guard, which never changes a
    // trajectory, only stops one.
    GoldenRun run{Simulation(p, golden_bodies(p),
                             {.threads = threads, .stop_on_blow_up = false, .coasting = coasting})};
    for (std::uint64_t k = 0; k < kGoldenSteps; ++k) {
        run.sim.step();
        run.body_contacts += run.sim.last_step().body_contacts;
    }
    return run;
}

TEST(Golden, TheFinalStateHashIsTheCommittedOne) {
    const GoldenRun run = golden_run(1);
    const Simulation& sim = run.sim;
    // The system does what it was built for: bodies collide, polar rods get kicks, and the
    // bent body takes the general rotation path (its three moments differ).
    EXPECT_GT(sim.totals().impulses, 10000u);
    EXPECT_GT(sim.totals().noise_kicks, 100u);
    const Vec3 bent = sim.parameters().species[3].shape.principal_inertia;
    EXPECT_GT(
        std::min({std::abs(bent.x - bent.y), std::abs(bent.y - bent.z), std::abs(bent.x - bent.z)}),
        1e-3 * bent.x);
    char hex[32];
    std::snprintf(hex, sizeof hex, "0x%016llxULL",
                  static_cast<unsigned long long>(sim.state_hash()));
    EXPECT_EQ(sim.state_hash(), kGoldenHash)
        << "the golden trajectory changed: its hash is now " << hex
        << ". If the change is deliberate, commit the new value with the reason.";
}

TEST(Golden, TwoThreadsGiveTheGoldenHashToo) {
    EXPECT_EQ(golden_run(2).sim.state_hash(), kGoldenHash);
}

TEST(Golden, TheCoastingStepHasItsOwnCommittedHashOnAnyThreadCount) {
    for (const int threads : {1, 2}) {
        const std::uint64_t hash = golden_run(threads, true).sim.state_hash();
        char hex[32];
        std::snprintf(hex, sizeof hex, "0x%016llxULL", static_cast<unsigned long long>(hash));
        EXPECT_EQ(hash, kCoastingGoldenHash)
            << threads << " threads: the coasting golden trajectory changed: its hash is now "
            << hex << ". If the change is deliberate, commit the new value with the reason.";
    }
}

}  // namespace
}  // namespace rodsea
