// A program of one's own on the installed rodsea libraries: builds the initial state of a config,
// steps it 1000 times and prints the state's hash (FNV-1a over every bit), the one that Python's
// rodsea.Simulation(rodsea.load_config(path)).run(steps=1000) then state_hash() gives.
#include <cstdio>
#include <exception>

#include "rodsea/builder/initial_state.hpp"
#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/simulation.hpp"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: one_rod CONFIG.toml\n");
        return 2;
    }
    try {
        const rodsea::RunPlan plan =
            rodsea::load_config_file(argv[1], rodsea::calibration_table_lookup());
        rodsea::Simulation sim(
            plan.engine,
            rodsea::build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed));
        sim.run(1000);
        std::printf("%016llx\n", static_cast<unsigned long long>(sim.state_hash()));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "one_rod: %s\n", e.what());
        return 2;
    }
}
