// The rotational noise (docs/model.md §3): per polar rod and plate it hit, ε |u_n| η with |u_n| its
// fastest approach to that plate in the step, added to ω_z (noise.mode = add) or imposed as ω_z
// (set; two plates in one step impose their sum). Checked against a direct evaluation of that
// rule, on a hit list long enough to be split over threads, and on constructed collisions.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>

#include "each_backend.hpp"
#include "rodsea/builder/placement.hpp"
#include "rodsea/engine/cpu/plate_noise.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

struct NoiseCase {
    BodyState bodies;
    std::vector<cpu::PlateHit> hits;
};

// 3000 bodies, every third a bead; 4000 hits in island-like (unsorted) order, several per body
// and plate, many bodies on both plates.
NoiseCase many_hits() {
    NoiseCase c;
    for (std::uint32_t b = 0; b < 3000; ++b)
        c.bodies.add(b % 3 == 2 ? 1 : 0, {}, Quat{}, {}, {0.1 * b, 0.0, 0.01 * b});
    std::uint64_t h = 7;
    for (int i = 0; i < 4000; ++i) {
        h = splitmix64(h);
        const auto body = static_cast<std::uint32_t>(h % 3000);
        const std::uint32_t plate = (h >> 20) % 2 ? kBasePlate : kLidPlate;
        c.hits.push_back({body, plate, 1.0 + static_cast<double>((h >> 32) % 1000) * 0.05});
    }
    return c;
}

// The rule evaluated directly, without the stage's sorting or threads: the fastest approach per
// (body, plate), and each polar body's terms in plate order (the lid, numbered lower, first).
std::vector<double> direct_spin_z(const NoiseCase& start, physics::NoiseMode mode, double epsilon,
                                  std::uint64_t seed, std::uint64_t step, size_t& kicks) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, double> fastest;
    for (const cpu::PlateHit& hit : start.hits) {
        double& f = fastest[{hit.body, hit.plate}];
        f = std::max(f, hit.approach_speed);
    }
    std::vector<double> spin_z(start.bodies.size());
    for (size_t b = 0; b < start.bodies.size(); ++b)
        spin_z[b] = start.bodies.spin[b].z;
    std::map<std::uint32_t, double> imposed;
    kicks = 0;
    for (const auto& [key, speed] : fastest) {
        if (start.bodies.species[key.first] != 0) continue;  // beads get no kick
        const double term =
            epsilon * speed * physics::noise_sign(seed, step, key.first, key.second);
        if (mode == physics::NoiseMode::add)
            spin_z[key.first] += term;
        else
            imposed[key.first] += term;
        ++kicks;
    }
    for (const auto& [body, value] : imposed)
        spin_z[body] = value;
    return spin_z;
}

void expect_the_direct_rule(physics::NoiseMode mode, double epsilon) {
    const std::uint64_t seed = 11, step = 123;
    const NoiseCase start = many_hits();
    size_t expected_kicks = 0;
    const std::vector<double> expected_spin_z =
        direct_spin_z(start, mode, epsilon, seed, step, expected_kicks);
    ASSERT_GT(start.hits.size(), 1024u);  // long enough to be split over threads
    ASSERT_GT(expected_kicks, 1000u);

    EngineParameters params;
    params.species = {polar_rod_species(), bead_species()};
    params.noise_epsilon = epsilon;
    params.noise_mode = mode;
    params.seed = seed;
    const SpeciesTable species = SpeciesTable::from(params);
    for (int threads : {1, 2, 3}) {
        NoiseCase c = start;
        const size_t kicks = cpu::apply_plate_noise(c.hits, c.bodies.view(), species,
                                                    step_context(params, step), threads);
        EXPECT_EQ(kicks, expected_kicks) << threads << " threads";
        for (size_t b = 0; b < c.bodies.size(); ++b) {
            // Bit for bit: a body with two terms sums them in plate order, as the direct sum does.
            ASSERT_EQ(c.bodies.spin[b].z, expected_spin_z[b]) << "body " << b << ", " << threads;
            ASSERT_EQ(c.bodies.spin[b].x, start.bodies.spin[b].x);
        }
    }
}

TEST(PlateNoise, AddGivesEachPolarRodOneKickPerPlateFromItsFastestApproachOnAnyThreadCount) {
    expect_the_direct_rule(physics::NoiseMode::add, 0.02);
}

TEST(PlateNoise, SetImposesTheKicksOnEachPolarRodThatHitAPlateOnAnyThreadCount) {
    expect_the_direct_rule(physics::NoiseMode::set, 2.0);
}

TEST(PlateNoise, SetAtZeroEpsilonStopsEveryPolarRodThatHitAPlateAndNoOther) {
    const NoiseCase start = many_hits();
    std::vector<bool> hit(start.bodies.size(), false);
    for (const cpu::PlateHit& h : start.hits)
        hit[h.body] = true;
    EngineParameters params;
    params.species = {polar_rod_species(), bead_species()};
    params.noise_mode = physics::NoiseMode::set;
    const SpeciesTable species = SpeciesTable::from(params);
    NoiseCase c = start;
    cpu::apply_plate_noise(c.hits, c.bodies.view(), species, step_context(params, 5), 2);
    size_t stopped = 0, kept = 0;
    for (size_t b = 0; b < c.bodies.size(); ++b) {
        const bool polar_hit = hit[b] && c.bodies.species[b] == 0;
        if (polar_hit) {
            ASSERT_EQ(c.bodies.spin[b].z, 0.0) << "body " << b;
            stopped += start.bodies.spin[b].z != 0.0 ? 1 : 0;
        } else {
            ASSERT_EQ(c.bodies.spin[b].z, start.bodies.spin[b].z) << "body " << b;
            ++kept;
        }
    }
    EXPECT_GT(stopped, 1000u);
    EXPECT_GT(kept, 1000u);  // beads that hit, and bodies that hit nothing
}

// One polar rod lying flat 0.01 µm above the base and falling onto it at 20 mm/s (0.025 µm a
// step), spinning about z;
// another mid-gap, touching nothing, spinning too.
struct FallingRod {
    EngineParameters params;
    BodyState bodies;
};

FallingRod falling_rod(physics::NoiseMode mode, double epsilon, double spin_z) {
    FallingRod f;
    f.params.box = {20.0, 20.0};
    f.params.species = {polar_rod_species()};
    f.params.noise_mode = mode;
    f.params.noise_epsilon = epsilon;
    f.params.seed = 3;
    const Shape& shape = f.params.species[0].shape;
    const Quat flat = flat_orientation(0.3);
    f.bodies.add(0, {5.0, 5.0, resting_height(shape, flat, f.params.drive, 1e-5)}, flat,
                 {0.0, 0.0, -20.0}, {0.0, 0.0, spin_z});
    const double mid_gap = f.params.drive.amplitude() + 0.5 * f.params.drive.gap;
    f.bodies.add(0, {15.0, 15.0, mid_gap}, flat_orientation(1.0), {}, {0.0, 0.0, spin_z});
    return f;
}

class PlateNoiseOnEachBackend : public testing::EachBackend {};

// After the step in which it hits the base, the rod's ω_z is ε |u_n| η whatever it spun before:
// the same number from either starting spin, and the add rule's kick (add at ε minus add at 0,
// which differ only by it). At ε = 0, set stops the spin exactly; the rod touching nothing keeps
// its spin under every rule.
TEST_P(PlateNoiseOnEachBackend, ARodHittingTheBaseLeavesWithTheSetSpinExactly) {
    const auto omega_after = [&](physics::NoiseMode mode, double epsilon, double spin_z,
                                 double* untouched = nullptr) {
        const FallingRod f = falling_rod(mode, epsilon, spin_z);
        Simulation sim(f.params, f.bodies, options());
        sim.step();
        EXPECT_EQ(sim.last_step().noise_kicks,
                  epsilon == 0.0 && mode == physics::NoiseMode::add ? 0u : 1u);
        if (untouched) *untouched = sim.bodies().spin[1].z;
        return sim.bodies().spin[0].z;
    };
    const double epsilon = 0.4;  // within both rules' ranges
    // The untouched rod's spin after its free flight alone: noise of no rule may change it.
    double free_flight = 0.0, untouched = 0.0;
    const double unkicked = omega_after(physics::NoiseMode::add, 0.0, 7.0, &free_flight);
    const double set = omega_after(physics::NoiseMode::set, epsilon, 7.0, &untouched);
    EXPECT_EQ(untouched, free_flight);
    EXPECT_NEAR(free_flight, 7.0, 1e-12);
    EXPECT_EQ(omega_after(physics::NoiseMode::set, epsilon, -3.0), set);
    const double kick = omega_after(physics::NoiseMode::add, epsilon, 7.0, &untouched) - unkicked;
    EXPECT_EQ(untouched, free_flight);
    // The two add runs share every impulse; only the kick and one rounding of ω_z differ.
    EXPECT_NEAR(kick, set, 1e-12 * std::abs(set));
    // |u_n|: the 20 mm/s fall, gravity's 0.01 mm/s in a step and the base's motion (AΩ = 54.6
    // mm/s at most, near 0 at t = 0), so positive and below 20 + 55 mm/s.
    EXPECT_GT(std::abs(set) / epsilon, 0.0);
    EXPECT_LT(std::abs(set) / epsilon, 75.0);
    EXPECT_EQ(omega_after(physics::NoiseMode::set, 0.0, 7.0, &untouched), 0.0);
    EXPECT_EQ(untouched, free_flight);
}

RODSEA_ON_EACH_STEP(PlateNoiseOnEachBackend);

}  // namespace
}  // namespace rodsea
