// The GPU backend's algorithm (engine/parallel/), run here by the host executor and, where a
// device is usable, by CUDA: the contact list is the CPU's, the islands are the connected
// components, runs repeat bit for bit, an ensemble steps each system as alone (on the CPU too,
// its systems side by side), and a dense noisy mixture runs the CPU's trajectory (to the bit on
// the host). The physics tests with analytic
// answers (collisions, free flight, the elastic gas, the dense monolayer) run on every backend in
// their own files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <tuple>
#include <vector>

#include "each_backend.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/parallel/host_executor.hpp"
#include "rodsea/engine/parallel/island_kernels.hpp"
#include "rodsea/engine/parallel/parallel_ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/state_check.hpp"
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

// Two beads started 0.24 mm (60 % of a radius) inside each other: deeper than impulses can undo,
// so the first step blows up.
Simulation doomed_beads() {
    EngineParameters p;
    p.box = {10.0, 10.0};
    p.species = {bead_species()};
    BodyState beads;
    const double z = 0.4 + p.drive.amplitude() + 0.01;
    beads.add(0, {5.0, 5.0, z}, Quat{});
    beads.add(0, {5.0 + 0.8 - 0.24, 5.0, z}, Quat{});
    return Simulation::resume(p, beads, 0);
}

// System 0 the healthy scene, system 1 the doomed beads.
Ensemble beside_doomed_beads(const Scene& healthy, const BackendOptions& options) {
    std::vector<Simulation> systems;
    systems.push_back(Simulation(healthy.params, healthy.bodies));
    systems.push_back(doomed_beads());
    return Ensemble(std::move(systems), options);
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
// sees the same spheres: the cell list must give exactly the Verlet list's contact list, in the
// same order, to the last bit. Checked at every step of a shaken dense mixture, each from the
// CPU's state before it.
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
        ASSERT_EQ(cpu.contacts().size(), other.contacts().size());
        for (std::size_t k = 0; k < cpu.contacts().size(); ++k)
            ASSERT_TRUE(key_of(cpu.contacts()[k]) == key_of(other.contacts()[k]))
                << "step " << cpu.step_count() << ", contact " << k;
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
    Simulation c(scene.params, scene.bodies, options(1));
    a.run(1500);
    b.run(500);
    b.run(1000);
    for (int k = 0; k < 1500; ++k)  // a device's runs of one step each
        c.step();
    EXPECT_GT(a.totals().noise_kicks, 0u);
    EXPECT_GT(a.totals().impulses, 1000u);
    EXPECT_EQ(a.state_hash(), b.state_hash());
    EXPECT_EQ(a.state_hash(), c.state_hash());
    EXPECT_EQ(a.totals().impulses, c.totals().impulses);
    EXPECT_EQ(a.totals().steps, 1500u);
}

// The GPU's algorithm is the CPU's: the same contact list, the same islands, each swept in list
// order by the same function. Run by the host executor it gives the CPU's trajectory bit for bit
// over 3000 steps (15 ms, three drive periods) of a dense noisy mixture. On a device the
// arithmetic may round differently (the build forbids fused multiply-adds, the one known cause),
// so there the collision counts must agree within their counting noise (3 standard deviations of
// the difference of two Poisson counts), no contact is left unresolved, and the kinetic energies
// agree within 20 % (the mixture's energy swings by a factor of ~2 over a period, in phase with
// the drive, and both runs see the same drive); whether the bits agree too is reported.
TEST_P(GpuAlgorithm, DenseMixtureRunsTheCpuTrajectory) {
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
    const bool same_bits = cpu.state_hash() == other.state_hash();
    std::printf(
        "[ measured ] body collisions cpu %.0f, %s %.0f; plate collisions %.0f, %.0f; "
        "states %s\n",
        body_cpu, to_string(GetParam()), body_other, plate_cpu, plate_other,
        same_bits ? "equal to the bit" : "different");
    ASSERT_GT(body_cpu, 100.0);
    if (GetParam() == BackendKind::gpu_on_host) {
        EXPECT_TRUE(same_bits);
        EXPECT_EQ(other.totals().impulses, cpu.totals().impulses);
        EXPECT_EQ(other.totals().noise_kicks, cpu.totals().noise_kicks);
        EXPECT_EQ(other.totals().max_sweeps, cpu.totals().max_sweeps);
    }
    EXPECT_LT(std::abs(body_other - body_cpu), 3.0 * std::sqrt(body_cpu + body_other));
    EXPECT_LT(std::abs(plate_other - plate_cpu), 3.0 * std::sqrt(plate_cpu + plate_other));
    EXPECT_EQ(other.totals().unresolved, 0u);
    EXPECT_NEAR(other.kinetic_energy() / cpu.kinetic_energy(), 1.0, 0.2);
}

// The set rule on the same mixture, at an ε that turns the rods as fast as the add rule's 0.05 /mm
// and at ε = 0, where every plate hit stops a rod's spin: the host twin takes the CPU's
// trajectory to the bit and counts the same noise events.
TEST_P(GpuAlgorithm, TheSetNoiseRuleRunsTheCpuTrajectory) {
    if (GetParam() != BackendKind::gpu_on_host) GTEST_SKIP() << "the host twin's bits";
    for (const double epsilon : {2.0, 0.0}) {
        Scene scene = noisy_dense_mixture(12);
        scene.params.noise_mode = physics::NoiseMode::set;
        scene.params.noise_epsilon = epsilon;
        Simulation cpu(scene.params, scene.bodies, on(BackendKind::cpu));
        Simulation other(scene.params, scene.bodies, options());
        cpu.run(1500);
        other.run(1500);
        EXPECT_EQ(other.state_hash(), cpu.state_hash()) << "epsilon " << epsilon;
        EXPECT_GT(cpu.totals().noise_kicks, 100u);
        EXPECT_EQ(other.totals().noise_kicks, cpu.totals().noise_kicks);
    }
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

// A system of an ensemble that blows up (two beads started 60 % of a radius inside each other:
// deeper than impulses can undo) is reported by its index, after every system has taken the
// step, as Simulation::step reports its own.
TEST_P(GpuAlgorithm, AnEnsembleNamesTheSystemThatBlewUp) {
    const Scene healthy = noisy_dense_mixture(31);
    Ensemble ensemble = beside_doomed_beads(healthy, options());
    try {
        ensemble.step();
        FAIL() << "no blow-up";
    } catch (const BlowUpError& e) {
        EXPECT_EQ(e.blow_up().what.rfind("system 1: ", 0), 0u) << e.blow_up().what;
        EXPECT_EQ(e.step(), 1u);
    }
    EXPECT_EQ(ensemble.step_count(0), 1u);  // the healthy system took its step too
    EXPECT_EQ(ensemble.step_count(1), 1u);
    EXPECT_FALSE(ensemble.blow_up(0));
    ASSERT_TRUE(ensemble.blow_up(1));
    EXPECT_EQ(ensemble.blow_up(1)->what.rfind("system", 0), std::string::npos)
        << "the system's own description, as Simulation gives it";
    // Without the broken system the healthy one steps on as it would alone.
    ensemble.retire({1});
    ensemble.run(50);
    Simulation alone(healthy.params, healthy.bodies, options());
    alone.run(51);
    EXPECT_EQ(ensemble.state_hash(0), alone.state_hash());
}

// A system that leaves an ensemble (its run ended) takes nothing with it: the others step on to
// the bits they reach alone, renumbered in their order, on a data-parallel stepper rebuilt
// without it.
TEST_P(GpuAlgorithm, AnEnsembleWithoutARetiredSystemStepsTheOthersOn) {
    const std::vector<Scene> scenes = {noisy_dense_mixture(41), noisy_dense_mixture(42),
                                       noisy_dense_mixture(43)};
    std::vector<Simulation> members;
    for (const Scene& scene : scenes)
        members.emplace_back(scene.params, scene.bodies);
    Ensemble ensemble(std::move(members), options());
    ensemble.run(200);
    EXPECT_THROW(ensemble.retire({3}), InvalidParameter);
    ensemble.retire({1});
    ASSERT_EQ(ensemble.size(), 2u);
    ensemble.set_threads(2);  // the bits do not depend on it
    ensemble.run(300);
    for (const auto& [m, scene] : {std::pair{0, 0}, std::pair{1, 2}}) {
        Simulation alone(scenes[scene].params, scenes[scene].bodies, options());
        alone.run(500);
        SCOPED_TRACE("system " + std::to_string(m) + " (first " + std::to_string(scene) + ")");
        EXPECT_EQ(ensemble.step_count(m), 500u);
        EXPECT_EQ(ensemble.state_hash(m), alone.state_hash());
        EXPECT_EQ(ensemble.totals(m).impulses, alone.totals().impulses);
    }
    ensemble.retire({0, 1});
    EXPECT_EQ(ensemble.size(), 0u);
    ensemble.step();  // nothing left to step: nothing happens
}

// A system that blows up within a run of steps stops after that step, the others' steps go on:
// on a device to the run's end (the same run for all), on the CPU they stop with it. Either way
// the ensemble names it, and without it the healthy system steps on to the bits it reaches alone.
TEST_P(GpuAlgorithm, ABlowUpWithinARunStopsThatSystemThere) {
    const Scene healthy = noisy_dense_mixture(33);
    Ensemble ensemble = beside_doomed_beads(healthy, options());
    EXPECT_THROW(ensemble.run(40), BlowUpError);
    const std::uint64_t others = GetParam() == BackendKind::cpu ? 1u : 40u;
    EXPECT_EQ(ensemble.step_count(0), others);
    EXPECT_EQ(ensemble.step_count(1), 1u);
    EXPECT_EQ(ensemble.last_run(0).steps, others);
    EXPECT_FALSE(ensemble.blow_up(0));
    ASSERT_TRUE(ensemble.blow_up(1));
    ensemble.retire({1});
    ensemble.run(60 - others);
    Simulation alone(healthy.params, healthy.bodies, options());
    alone.run(60);
    EXPECT_EQ(ensemble.state_hash(0), alone.state_hash());
    EXPECT_EQ(ensemble.totals(0).impulses, alone.totals().impulses);
}

// The neighbour list is rebuilt when the spheres may have moved half its skin, not every step:
// a shaken dense mixture (in-plane speeds up to 100 mm/s, 0.125 µm per step) needs one every
// ~200 steps at most by that bound. The CPU's list measures the actual moves and so lasts longer.
TEST_P(GpuAlgorithm, TheNeighbourListLastsManySteps) {
    const Scene scene = noisy_dense_mixture(17);
    Simulation sim(scene.params, scene.bodies, options());
    sim.run(2000);
    std::printf("[ measured ] %s: %llu builds in 2000 steps\n", to_string(GetParam()),
                static_cast<unsigned long long>(sim.pair_list_builds()));
    EXPECT_GE(sim.pair_list_builds(), 1u);
    EXPECT_LE(sim.pair_list_builds(), 100u);
}

RODSEA_ON_EACH_BACKEND(GpuAlgorithm);

// A run whose lists outgrow their room (here one partner per sphere, one sphere per cell and one
// contact per step to start with) is taken again from its start with more room: the bits are those
// of a stepper that had the room from the start, run by run.
TEST(DataParallelRuns, ARunThatOutgrowsItsRoomIsTakenAgainToTheSameBits) {
    const Scene scene = noisy_dense_mixture(9);
    const SpeciesTable species = SpeciesTable::from(scene.params);
    const auto stepper = [&](parallel::Room room) {
        std::vector<parallel::EnsembleMember> members;
        members.push_back(ensemble_member(species, scene.bodies));
        return parallel::ParallelEnsemble<parallel::HostExecutor>(
            std::move(members), kGrossOverlapFraction, parallel::HostExecutor(1), room);
    };
    auto roomy = stepper({});
    auto cramped = stepper({1, 1, 1});
    std::vector<StepsDone> roomy_done, cramped_done;
    StageProfile profile;
    std::uint64_t step = 0;
    for (int run = 0; run < 3; ++run) {
        std::vector<StepContext> contexts;
        for (int k = 0; k < 200; ++k)
            contexts.push_back(step_context(scene.params, ++step));
        roomy.run(contexts, 200, nullptr, roomy_done, profile);
        cramped.run(contexts, 200, nullptr, cramped_done, profile);
        SCOPED_TRACE("run " + std::to_string(run));
        EXPECT_EQ(cramped_done[0].tally.impulses, roomy_done[0].tally.impulses);
        EXPECT_EQ(cramped_done[0].last.body_contacts, roomy_done[0].last.body_contacts);
        EXPECT_EQ(state_hash(cramped.bodies(0), step), state_hash(roomy.bodies(0), step));
    }
    EXPECT_GT(roomy_done[0].tally.impulses, 100u);
    EXPECT_EQ(cramped.contacts(0).size(), roomy.contacts(0).size());
}

// On the CPU an ensemble steps its systems side by side, min(threads, systems) at a time on one
// thread each, or, with two threads or more per system, in turn on all of them. Three unlike
// systems (two sizes, so the workers' shares are uneven) on 1 to 4 threads, and two on 4 (in
// turn), reach the bits each reaches alone on one thread; a retired system changes the sharing
// and nothing else.
TEST(CpuEnsemble, SystemsSideBySideStepAsTheyStepAlone) {
    std::vector<Scene> scenes = {noisy_dense_mixture(51), noisy_dense_mixture(52),
                                 shaken(polar_in_apolar_mixture(0.10, 2.5, 0.55, 30.0, 53), 53)};
    std::vector<std::uint64_t> alone_hashes;
    for (const Scene& scene : scenes) {
        Simulation alone(scene.params, scene.bodies);
        alone.run(300);
        alone_hashes.push_back(alone.state_hash());
    }
    const auto ensemble_of = [&](std::size_t systems, int threads) {
        std::vector<Simulation> members;
        for (std::size_t m = 0; m < systems; ++m)
            members.emplace_back(scenes[m].params, scenes[m].bodies);
        return Ensemble(std::move(members), on(BackendKind::cpu, threads));
    };
    for (const auto& [systems, threads] :
         {std::pair{3, 1}, std::pair{3, 2}, std::pair{3, 3}, std::pair{3, 4}, std::pair{2, 4}}) {
        SCOPED_TRACE(std::to_string(systems) + " systems on " + std::to_string(threads) +
                     " threads");
        Ensemble ensemble = ensemble_of(static_cast<std::size_t>(systems), threads);
        ensemble.run(300);
        for (std::size_t m = 0; m < ensemble.size(); ++m)
            EXPECT_EQ(ensemble.state_hash(m), alone_hashes[m]) << "system " << m;
    }
    Ensemble ensemble = ensemble_of(3, 2);
    ensemble.run(100);
    ensemble.retire({0});  // two systems left on two threads: one each instead of a shared one
    ensemble.run(200);
    EXPECT_EQ(ensemble.state_hash(0), alone_hashes[1]);
    EXPECT_EQ(ensemble.state_hash(1), alone_hashes[2]);
}

// Side by side, the systems are dealt to the workers again by what their steps cost, every 1000
// steps (ensemble.cpp): a system may change workers mid-run, and its bits do not change. Three
// unlike systems on two threads over three such looks.
TEST(CpuEnsemble, SystemsDealtAgainByCostStepAsTheyStepAlone) {
    const std::vector<Scene> scenes = {
        noisy_dense_mixture(71), shaken(polar_in_apolar_mixture(0.05, 2.5, 0.15, 30.0, 72), 72),
        shaken(polar_in_apolar_mixture(0.10, 1.0, 0.60, 20.0, 73), 73)};
    constexpr std::uint64_t kSteps = 3100;
    std::vector<Simulation> members;
    for (const Scene& scene : scenes)
        members.emplace_back(scene.params, scene.bodies);
    Ensemble ensemble(std::move(members), on(BackendKind::cpu, 2));
    ensemble.run(kSteps);
    for (std::size_t m = 0; m < scenes.size(); ++m) {
        Simulation alone(scenes[m].params, scenes[m].bodies);
        alone.run(kSteps);
        EXPECT_EQ(ensemble.state_hash(m), alone.state_hash()) << "system " << m;
    }
}

// A blow-up on one worker while the other steps a healthy system: reported by its index after
// both took the step, as when the systems step one after another.
TEST(CpuEnsemble, ABlowUpSideBySideNamesItsSystem) {
    const Scene healthy = noisy_dense_mixture(61);
    std::vector<Simulation> systems;
    systems.push_back(doomed_beads());
    systems.push_back(Simulation(healthy.params, healthy.bodies));
    Ensemble ensemble(std::move(systems), on(BackendKind::cpu, 2));
    try {
        ensemble.step();
        FAIL() << "no blow-up";
    } catch (const BlowUpError& e) {
        EXPECT_EQ(e.blow_up().what.rfind("system 0: ", 0), 0u) << e.blow_up().what;
    }
    EXPECT_EQ(ensemble.step_count(1), 1u);
    EXPECT_FALSE(ensemble.blow_up(1));
    ensemble.retire({0});
    ensemble.run(50);
    Simulation alone(healthy.params, healthy.bodies);
    alone.run(51);
    EXPECT_EQ(ensemble.state_hash(0), alone.state_hash());
}

// Joins each body contact's two islands (the contact search does it as it writes them).
struct JoinEach {
    const Contact* contacts;
    std::uint32_t* parent;
    void operator()(std::uint32_t k) const {
        parallel::join_islands(parent, contacts[k].a, contacts[k].b);
    }
};

// The islands on a random contact graph much denser than a monolayer's, joined and listed by two
// threads: every contact is on the list of the smallest body of its connected component (found
// here by a plain search), once, whatever order the joins ran in.
TEST(Islands, EveryContactIsListedAtTheSmallestBodyOfItsComponent) {
    using Exec = parallel::HostExecutor;
    Exec exec(2);
    const std::uint32_t bodies = 6000, body_contacts = 5000, plate_contacts = 800;
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
    Exec::Array<std::uint32_t> parent, island_count, island_head, next;
    exec.upload(contacts, list);
    std::vector<std::uint32_t> itself(bodies);
    std::iota(itself.begin(), itself.end(), 0u);
    exec.upload(parent, itself);  // free flight's start: every body its own island
    island_count.resize(bodies);
    island_head.resize(bodies);
    exec.fill(island_count, bodies, 0u);
    exec.fill(island_head, bodies, parallel::kNoContact);
    next.resize(count);
    exec.launch(body_contacts, JoinEach{contacts.data(), parent.data()});
    exec.launch(count, parallel::ListIslands{contacts.data(), parent.data(), island_count.data(),
                                             island_head.data(), next.data()});
    std::vector<std::uint32_t> counted, head, after;
    exec.download(island_count, bodies, counted);
    exec.download(island_head, bodies, head);
    exec.download(next, count, after);

    // The components by a breadth-first search over the body–body contacts.
    std::vector<std::vector<std::uint32_t>> around(bodies);
    for (std::uint32_t k = 0; k < body_contacts; ++k) {
        around[list[k].a].push_back(list[k].b);
        around[list[k].b].push_back(list[k].a);
    }
    std::vector<std::uint32_t> smallest(bodies, bodies);
    for (std::uint32_t start = 0; start < bodies; ++start) {
        if (smallest[start] != bodies) continue;
        std::vector<std::uint32_t> queue{start};
        smallest[start] = start;  // bodies are visited in order: the first is the smallest
        for (std::size_t q = 0; q < queue.size(); ++q)
            for (const std::uint32_t next_body : around[queue[q]])
                if (smallest[next_body] == bodies) {
                    smallest[next_body] = start;
                    queue.push_back(next_body);
                }
    }
    // Each root's list holds exactly its island's contacts, as many as it counted, every
    // contact once.
    std::vector<int> seen(count, 0);
    std::size_t joined = 0;
    for (std::uint32_t root = 0; root < bodies; ++root) {
        std::uint32_t k = head[root];
        for (std::uint32_t i = 0; i < counted[root]; ++i, k = after[k]) {
            ASSERT_LT(k, count) << "root " << root;
            ASSERT_EQ(smallest[list[k].a], root) << "contact " << k;
            ++seen[k];
            if (root != list[k].a) ++joined;
        }
        EXPECT_EQ(k, parallel::kNoContact) << "root " << root << "'s list is longer than counted";
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(count));
    EXPECT_GT(joined, count / 2);  // the graph does join most contacts into larger islands
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
