// The GPU backend's algorithm (engine/parallel/), run here by the host executor and, where a
// device is usable, by CUDA: the contact list is the CPU's, the colouring keeps contacts of one
// colour apart, runs repeat bit for bit, and the statistics of a dense noisy mixture are the
// CPU's within their noise. The physics tests with analytic answers (collisions, free flight, the
// elastic gas, the dense monolayer) run on every backend in their own files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>
#include <vector>

#include "each_backend.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/parallel/contact_colouring.hpp"
#include "rodsea/engine/parallel/host_executor.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

// Polar rods in a dense medium of apolar rods with noise, thrown about as a shaken layer is
// (in-plane speeds up to 100 mm/s, vertical 30 mm/s, spins 100 rad/s): every stage has work
// from the first step.
Scene shaken(Scene scene, std::uint64_t seed) {
    SplitMix64 rng(seed);
    for (size_t b = 0; b < scene.bodies.size(); ++b) {
        scene.bodies.velocity[b] = {rng.uniform(-100, 100), rng.uniform(-100, 100),
                                    rng.uniform(-30, 30)};
        scene.bodies.spin[b] = {rng.uniform(-100, 100), rng.uniform(-100, 100),
                                rng.uniform(-100, 100)};
    }
    return scene;
}

Scene noisy_dense_mixture(std::uint64_t seed) {
    Scene scene = polar_in_apolar_mixture(0.10, 2.5, 0.55, 20.0, seed);
    scene.params.noise_epsilon = 0.05;
    return shaken(std::move(scene), seed);
}

BackendOptions on(BackendKind kind, int threads = 1) {
    BackendOptions o;
    o.backend = kind;
    o.threads = threads;
    return o;
}

// A contact's every number, for comparing lists as sets.
auto key_of(const Contact& c) {
    return std::make_tuple(c.a, c.b, c.arm_a.x, c.arm_a.y, c.arm_a.z, c.arm_b.x, c.arm_b.y,
                           c.arm_b.z, c.normal.x, c.normal.y, c.normal.z, c.overlap, c.friction,
                           c.restitution);
}

class GpuAlgorithm : public testing::EachBackend {};

// Both backends fly the bodies with the same functions, so from one state the next step's search
// sees the same spheres: the cell list must find exactly the Verlet list's contacts (as a set:
// the order within a sphere's partners differs), to the last bit. Checked at every step of a
// shaken dense mixture, each from the CPU's state before it.
TEST_P(GpuAlgorithm, FindsExactlyTheCpuContacts) {
    if (GetParam() == BackendKind::cpu) GTEST_SKIP() << "the reference itself";
    const Scene scene = noisy_dense_mixture(7);
    Simulation cpu(scene.params, scene.bodies, on(BackendKind::cpu));
    std::size_t body_contacts = 0, plate_contacts = 0;
    for (int s = 0; s < 600; ++s) {
        Simulation other =
            Simulation::resume(scene.params, cpu.bodies(), cpu.step_count(), options());
        cpu.step();
        other.step();
        const StepStatistics &want = cpu.last_step(), &got = other.last_step();
        ASSERT_EQ(got.body_contacts, want.body_contacts) << "step " << cpu.step_count();
        ASSERT_EQ(got.plate_contacts, want.plate_contacts) << "step " << cpu.step_count();
        EXPECT_EQ(got.max_overlap_fraction, want.max_overlap_fraction);
        EXPECT_EQ(got.max_planar_speed, want.max_planar_speed);
        std::multiset<decltype(key_of(Contact{}))> a, b;
        for (const Contact& c : cpu.contacts())
            a.insert(key_of(c));
        for (const Contact& c : other.contacts())
            b.insert(key_of(c));
        ASSERT_TRUE(a == b) << "step " << cpu.step_count();
        body_contacts += want.body_contacts;
        plate_contacts += want.plate_contacts;
    }
    std::printf("[ measured ] %zu body and %zu plate contacts compared\n", body_contacts,
                plate_contacts);
    EXPECT_GT(body_contacts, 50u);
    EXPECT_GT(plate_contacts, 50u);
}

// Same state, parameters and seed: the same bits, in one piece or two and, on the host, on any
// number of threads.
TEST_P(GpuAlgorithm, RepeatsBitForBit) {
    const Scene scene = noisy_dense_mixture(3);
    Simulation a(scene.params, scene.bodies, options(1));
    Simulation b(scene.params, scene.bodies, options(2));
    a.run(1500);
    b.run(500);
    b.run(1000);
    EXPECT_GT(a.totals().noise_kicks, 0u);
    EXPECT_GT(a.totals().impulses, 1000u);
    EXPECT_EQ(a.state_hash(), b.state_hash());
}

// The GPU resolves impulses in colour order, the CPU in list order: the trajectories part, but
// they are the same physics. Over 3000 steps (15 ms, three drive periods) of a dense noisy
// mixture, the collision counts agree within their counting noise (3 standard deviations of
// the difference of two Poisson counts), no contact is left unresolved, and the kinetic
// energies agree within 20 % (the mixture's energy swings by a factor of ~2 over a period,
// in phase with the drive, and both runs see the same drive).
TEST_P(GpuAlgorithm, DenseMixtureHasTheCpuStatistics) {
    if (GetParam() == BackendKind::cpu) GTEST_SKIP() << "the reference itself";
    const Scene scene = noisy_dense_mixture(11);
    Simulation cpu(scene.params, scene.bodies, on(BackendKind::cpu));
    Simulation other(scene.params, scene.bodies, options());
    double body_cpu = 0, body_other = 0, plate_cpu = 0, plate_other = 0;
    for (int s = 0; s < 3000; ++s) {
        cpu.step();
        other.step();
        body_cpu += static_cast<double>(cpu.last_step().body_collisions);
        body_other += static_cast<double>(other.last_step().body_collisions);
        plate_cpu += static_cast<double>(cpu.last_step().plate_collisions);
        plate_other += static_cast<double>(other.last_step().plate_collisions);
    }
    std::printf(
        "[ measured ] body collisions cpu %.0f, %s %.0f; plate collisions %.0f, %.0f; "
        "states %s\n",
        body_cpu, to_string(GetParam()), body_other, plate_cpu, plate_other,
        cpu.state_hash() == other.state_hash() ? "equal" : "different");
    ASSERT_GT(body_cpu, 100.0);
    EXPECT_LT(std::abs(body_other - body_cpu), 3.0 * std::sqrt(body_cpu + body_other));
    EXPECT_LT(std::abs(plate_other - plate_cpu), 3.0 * std::sqrt(plate_cpu + plate_other));
    EXPECT_EQ(other.totals().unresolved, 0u);
    EXPECT_NEAR(other.kinetic_energy() / cpu.kinetic_energy(), 1.0, 0.2);
}

// An ensemble of unlike systems (rods with noise, a denser medium without, beads in another box
// and with another seed) steps each of them to the same bits as it steps alone on the same
// backend: nothing a system computes depends on its neighbours in the kernels. One of them is
// resumed from a later step, so the systems are at different times too.
TEST_P(GpuAlgorithm, AnEnsembleStepsEachSystemAsItStepsAlone) {
    std::vector<Scene> scenes = {
        noisy_dense_mixture(21), noisy_dense_mixture(22),
        shaken(monolayer({{polar_rod_species(), 6}, {bead_species(), 150}}, {14.0, 17.0}, 23), 23)};
    scenes[1].params.noise_epsilon = 0.0;
    scenes[2].params.seed = 99;
    scenes[2].params.max_sweeps = 7;
    const std::uint64_t starts[] = {0, 0, 250};
    const auto system = [&](std::size_t m) {
        return Simulation::resume(scenes[m].params, scenes[m].bodies, starts[m], options());
    };
    std::vector<Simulation> members;
    for (std::size_t m = 0; m < scenes.size(); ++m)
        members.push_back(system(m));
    Ensemble ensemble(std::move(members), options());
    ensemble.run(600);
    for (std::size_t m = 0; m < scenes.size(); ++m) {
        Simulation alone = system(m);
        alone.run(600);
        SCOPED_TRACE("system " + std::to_string(m));
        EXPECT_EQ(ensemble.step_count(m), starts[m] + 600);
        EXPECT_EQ(ensemble.state_hash(m), alone.state_hash());
        EXPECT_EQ(ensemble.totals(m).impulses, alone.totals().impulses);
        EXPECT_EQ(ensemble.totals(m).noise_kicks, alone.totals().noise_kicks);
        EXPECT_EQ(ensemble.totals(m).max_sweeps, alone.totals().max_sweeps);
        EXPECT_EQ(ensemble.last_step(m).max_planar_speed, alone.last_step().max_planar_speed);
        EXPECT_GT(ensemble.totals(m).impulses, 10u);  // each system has impulses to get right
    }
    EXPECT_GT(ensemble.totals(0).noise_kicks, 0u);
    EXPECT_EQ(ensemble.totals(1).noise_kicks, 0u);
}

RODSEA_ON_EACH_BACKEND(GpuAlgorithm);

// The colouring on a random contact graph much denser than a monolayer's: every contact gets a
// colour, no two contacts of a colour share a body, and there are no more colours than the most
// contacts around one contact plus one (the greedy bound).
TEST(ContactColouring, ContactsOfOneColourShareNoBody) {
    using Exec = parallel::HostExecutor;
    Exec exec(2);
    const std::uint32_t bodies = 300, body_contacts = 1200, plate_contacts = 500;
    SplitMix64 rng(5);
    std::vector<Contact> list;
    for (std::uint32_t k = 0; k < body_contacts; ++k) {
        Contact c;
        c.a = static_cast<std::uint32_t>(rng.next() % bodies);
        do {
            c.b = static_cast<std::uint32_t>(rng.next() % bodies);
        } while (c.b == c.a);
        list.push_back(c);
    }
    for (std::uint32_t k = 0; k < plate_contacts; ++k) {
        Contact c;
        c.a = static_cast<std::uint32_t>(rng.next() % bodies);
        c.b = k % 2 ? kBasePlate : kLidPlate;
        list.push_back(c);
    }
    const auto count = static_cast<std::uint32_t>(list.size());
    Exec::Array<Contact> contacts;
    exec.upload(contacts, list);
    std::vector<std::uint32_t> rank(count);  // one system: a contact's rank is its index
    std::iota(rank.begin(), rank.end(), 0u);
    parallel::ContactColouring<Exec> colouring;
    colouring.colour(exec, contacts, rank.data(), count, body_contacts, bodies);

    std::vector<int> colour;
    exec.download(colouring.colour_of(), count, colour);
    std::vector<std::vector<std::uint32_t>> touching(bodies);
    for (std::uint32_t k = 0; k < count; ++k) {
        touching[list[k].a].push_back(k);
        if (!list[k].with_plate()) touching[list[k].b].push_back(k);
    }
    std::size_t most_neighbours = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
        ASSERT_GE(colour[k], 0);
        std::size_t neighbours = touching[list[k].a].size() - 1;
        if (!list[k].with_plate()) neighbours += touching[list[k].b].size() - 1;
        most_neighbours = std::max(most_neighbours, neighbours);
    }
    for (const auto& around : touching)
        for (std::size_t i = 0; i < around.size(); ++i)
            for (std::size_t j = i + 1; j < around.size(); ++j)
                ASSERT_NE(colour[around[i]], colour[around[j]])
                    << "contacts " << around[i] << " and " << around[j] << " share a body";
    EXPECT_LE(static_cast<std::size_t>(colouring.colours()), most_neighbours + 1);
    // The ranges cover every contact once, each in its colour.
    std::vector<int> seen(count, 0);
    for (int c = 0; c < colouring.colours(); ++c) {
        const auto r = colouring.range(c);
        for (std::uint32_t i = r.first; i < r.first + r.count; ++i) {
            const std::uint32_t k = colouring.order()[i];
            EXPECT_EQ(colour[k], c);
            ++seen[k];
        }
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(count));
}

// Asking for the GPU where this build or machine has none is refused before any work, naming
// the backend and saying why (and how to build one).
TEST(GpuBackend, IsRefusedWhereNoDeviceCanRunIt) {
    const GpuAvailability gpu = gpu_availability();
    if (gpu.usable) GTEST_SKIP() << "a GPU is usable here: " << gpu.description;
    EXPECT_FALSE(gpu.description.empty());
    const Scene scene = noisy_dense_mixture(1);
    try {
        Simulation sim(scene.params, scene.bodies, on(BackendKind::gpu));
        FAIL() << "a GPU simulation was built without a usable GPU";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "backend");
        EXPECT_NE(std::string(e.what()).find(gpu.description), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace rodsea
