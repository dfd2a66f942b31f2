#pragma once
// What a config file resolves to: everything `rodsea run` and `rodsea info` need, in the engine's
// units (mm, s), with every default and CHOICE already applied and every key validated.
#include <cstdint>
#include <string>
#include <vector>

#include "rodsea/builder/builder_options.hpp"
#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

// The run's length and cadences.
struct RunControl {
    double duration = 1.0;              // simulated time, s
    double output_interval = 0.05;      // simulated time between trajectory frames and rows, s
    double checkpoint_interval = 30.0;  // wall-clock minutes between checkpoints
    int threads = 1;
    BackendKind backend = BackendKind::cpu;  // run.backend
    // Stop when steady: with steady_samples > 0 the run ends at the first frame whose steady
    // window (steady_state.hpp, from every order series) holds at least that many independent
    // samples of steady_series ("all": of every order series), none of those drifting; the
    // duration is then the longest it may run.
    long long steady_samples = 0;
    std::string steady_series = "all";
};

struct RunPlan {
    EngineParameters engine;        // species, box, drive, coefficients, dt, ε, seed
    std::vector<long long> counts;  // bodies per species, same order as engine.species
    // The area fraction each species was asked for, or a negative value when it was given as
    // an explicit count.
    std::vector<double> requested_area_fraction;
    BuilderOptions builder;
    RunControl control;
    std::string config_toml;           // the full resolved config, every key, as TOML
    std::vector<std::string> choices;  // each docs/model.md CHOICE in force, one line each

    std::uint64_t total_steps() const;       // round(duration / dt)
    std::uint64_t steps_per_output() const;  // round(output_interval / dt), >= 1
    // steps_per_output() × dt, s: the time between stored frames, which output_interval only
    // approximates when it is not a whole number of steps.
    double frame_interval() const;
};

}  // namespace rodsea
