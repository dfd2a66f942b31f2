#pragma once
// One body alone in the vibrated cell, measured over many independent copies (each its own
// simulation with its own start and noise seed, so that copies never interact): how fast and in
// which direction it travels along its axis, how its axis diffuses. This is the evidence that
// ties the model to the experiment (docs/model.md §7) and the ε → D_r map the paper's control
// parameter needs (docs/model.md §3).
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/step_backend.hpp"

namespace rodsea {

struct SingleBodyExperiment {
    Species species;
    DriveParameters drive;
    double dt = EngineParameters{}.dt;  // s
    double epsilon = 0.0;               // 1/mm, the noise amplitude (polar rods only)
    physics::NoiseMode noise_mode = physics::NoiseMode::add;
    int copies = 8;         // independent bodies
    double warmup = 0.2;    // s discarded after the start (coasting, settling)
    double duration = 2.0;  // s measured per copy
    std::uint64_t seed = 1;
};

struct MeanAndError {
    double mean = 0.0;
    double error = 0.0;  // one standard error
};

// What one copy did, sampled once per drive period after the warm-up.
struct SingleBodyTrace {
    std::vector<double> axial;       // mm, in-plane displacement along the axis in each period
    std::vector<double> transverse;  // mm, across it
    std::vector<double> angle;       // rad, in-plane axis angle at each period's end, unwrapped
    std::uint64_t unresolved = 0;    // contacts left unresolved
};

struct SingleBodyResult {
    double period = 0.0;                // s, the drive period (the sampling interval)
    MeanAndError axial_speed;           // mm/s along body +x: thick → thin for a polar rod
    MeanAndError transverse_speed;      // mm/s
    MeanAndError rotational_diffusion;  // rad²/s, from C(t) = exp(−D_r t) (jackknife error)
    double forward_fraction = 0.0;      // copies travelling toward body +x
    std::vector<double> period_speeds;  // mm/s, axial speed of every period of every copy
    std::vector<double> correlation;    // C(t) at lags of 0, 1, 2, ... periods, over all copies
    std::uint64_t unresolved = 0;
};

// Runs copy `index` (start angle, tilt, spin and noise seed drawn from experiment.seed and
// index) on `options`' backend. Throws InvalidParameter for parameters the engine refuses.
// Returns early, with a partial trace, once a stop signal (cli/stop_signal.hpp) has arrived.
SingleBodyTrace run_single_body_copy(const SingleBodyExperiment& experiment, int index,
                                     const BackendOptions& options = {});

// Runs copies 0 .. copies − 1 of every experiment as one Ensemble (engine/ensemble.hpp) on
// `options`' backend: on a GPU, every copy in the same kernels. Each copy's trace is the one
// run_single_body_copy gives on that backend, bit for bit. The experiments must share dt, the
// drive frequency, the warm-up and the duration (they step in lockstep, sampled each period);
// InvalidParameter otherwise. traces[point][copy]; none once a stop signal has arrived;
// `on_period` (may be empty) is called after each drive period with the fraction done.
std::optional<std::vector<std::vector<SingleBodyTrace>>> run_single_body_copies_together(
    const std::vector<SingleBodyExperiment>& experiments, int copies, const BackendOptions& options,
    const std::function<void(double)>& on_period = {});

// Combines the copies' traces. `period` is the sampling interval, s.
SingleBodyResult combine_single_body_traces(const std::vector<SingleBodyTrace>& traces,
                                            double period);

// D_r from C(t) = exp(−D_r t): the slope of −ln C through the origin over the lags down to
// C = 0.2 (as `rodsea analyze`). 0 when C never falls below 1.
double rotational_diffusion_from_correlation(const std::vector<double>& correlation,
                                             double interval);

}  // namespace rodsea
