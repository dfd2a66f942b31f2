// The rotational noise (MODEL.md §3): one kick ω_z += ε |u_n| η per polar rod and plate it hit,
// |u_n| its fastest approach to that plate in the step. Checked against a direct evaluation of
// that rule, on a hit list long enough to be split over threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>

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

TEST(PlateNoise, EachPolarRodGetsOneKickPerPlateFromItsFastestApproachOnAnyThreadCount) {
    const double epsilon = 0.02;
    const std::uint64_t seed = 11, step = 123;
    const NoiseCase start = many_hits();

    // Direct evaluation: the fastest approach per (body, plate).
    std::map<std::pair<std::uint32_t, std::uint32_t>, double> fastest;
    for (const cpu::PlateHit& hit : start.hits) {
        double& f = fastest[{hit.body, hit.plate}];
        f = std::max(f, hit.approach_speed);
    }
    std::vector<double> expected_spin_z(start.bodies.size());
    size_t expected_kicks = 0;
    for (size_t b = 0; b < start.bodies.size(); ++b)
        expected_spin_z[b] = start.bodies.spin[b].z;
    for (const auto& [key, speed] : fastest) {
        if (start.bodies.species[key.first] != 0) continue;  // beads get no kick
        expected_spin_z[key.first] +=
            epsilon * speed * physics::noise_sign(seed, step, key.first, key.second);
        ++expected_kicks;
    }
    ASSERT_GT(start.hits.size(), 1024u);  // long enough to be split over threads
    ASSERT_GT(expected_kicks, 1000u);

    EngineParameters params;
    params.species = {polar_rod_species(), bead_species()};
    params.noise_epsilon = epsilon;
    params.seed = seed;
    const SpeciesTable species = SpeciesTable::from(params);
    for (int threads : {1, 2, 3}) {
        NoiseCase c = start;
        const size_t kicks = cpu::apply_plate_noise(c.hits, c.bodies.view(), species,
                                                    step_context(params, step), threads);
        EXPECT_EQ(kicks, expected_kicks) << threads << " threads";
        for (size_t b = 0; b < c.bodies.size(); ++b) {
            // Bit for bit: a body with two kicks adds them in plate order, as the direct sum does.
            ASSERT_EQ(c.bodies.spin[b].z, expected_spin_z[b]) << "body " << b << ", " << threads;
            ASSERT_EQ(c.bodies.spin[b].x, start.bodies.spin[b].x);
        }
    }
}

}  // namespace
}  // namespace rodsea
