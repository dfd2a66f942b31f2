// Same parameters, seed and thread count: the same state, bit for bit.
#include <gtest/gtest.h>

#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/scenes/scenes.hpp"

namespace rodsea {
namespace {

Simulation noisy_mixture(std::uint64_t seed, int threads = 1) {
    Scene scene = polar_in_apolar_mixture(0.10, 2.5, 0.40, 20.0, seed);
    scene.params.noise_epsilon = 0.05;
    return Simulation(scene.params, scene.bodies, {.threads = threads});
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

namespace rodsea {
namespace {

// The Verlet list is rebuilt only now and then, so a resumed run (which builds it afresh at its
// first step) has a younger list than the run that never stopped. Contacts come in the order of
// their sphere pairs, not of the list, so the two runs still agree bit for bit.
TEST(Determinism, AResumedRunMatchesTheUninterruptedOneWhateverTheAgeOfTheVerletList) {
    // Stop 50 steps after the uninterrupted run's first rebuild (a list of the same age from
    // the start would be no test), and check that it did not rebuild at the stop either.
    Simulation whole = noisy_mixture(5);
    while (whole.pair_list_builds() < 2)
        whole.step();
    whole.run(50);
    const std::uint64_t stop = whole.step_count();
    whole.step();
    ASSERT_EQ(whole.pair_list_builds(), 2u);
    whole.run(799);

    Simulation first_part = noisy_mixture(5);
    first_part.run(stop);
    Simulation resumed =
        Simulation::resume(first_part.parameters(), first_part.bodies(), first_part.step_count());
    resumed.run(800);
    EXPECT_EQ(whole.state_hash(), resumed.state_hash());
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

// Every parallel stage writes its chunks where the serial loop would, and islands of contacts are
// resolved independently: 1, 2 and 3 threads give the same state, bit for bit. (3 does not divide
// the work evenly, and on a 2-core machine oversubscribes it: neither may change the result.)
TEST(Determinism, AnyNumberOfThreadsGivesTheSameStateHash) {
    std::uint64_t hash[3] = {};
    for (int threads = 1; threads <= 3; ++threads) {
        Simulation sim = noisy_mixture(6, threads);
        sim.run(1500);
        EXPECT_GT(sim.totals().noise_kicks, 0u);
        hash[threads - 1] = sim.state_hash();
    }
    EXPECT_EQ(hash[0], hash[1]);
    EXPECT_EQ(hash[0], hash[2]);
}

// One range of threads, [1, kMaxThreads], whatever asks: OpenMP aborts the process when asked
// for a team it cannot start (5000 threads did), so the range is checked before it is asked.
TEST(Determinism, RefusesThreadsOutsideOneRange) {
    EXPECT_THROW(noisy_mixture(6, 0), InvalidParameter);
    try {
        noisy_mixture(6, kMaxThreads + 1);
        ADD_FAILURE() << "accepted " << kMaxThreads + 1 << " threads";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "threads");
        EXPECT_NE(std::string(e.what()).find("[1, 256]"), std::string::npos) << e.what();
    }
    Simulation sim = noisy_mixture(6, 1);
    EXPECT_THROW(sim.set_threads(1'000'000), InvalidParameter);
    EXPECT_EQ(sim.options().threads, 1);  // refused: nothing changed
}

}  // namespace
}  // namespace rodsea
