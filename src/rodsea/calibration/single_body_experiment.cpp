#include "rodsea/calibration/single_body_experiment.hpp"

#include <cmath>
#include <numbers>

#include "rodsea/analysis/statistics.hpp"
#include "rodsea/builder/placement.hpp"
#include "rodsea/cli/stop_signal.hpp"
#include "rodsea/engine/ensemble.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

namespace {

// Far above every body: a copy is alone, and the box only has to hold its periodic image away.
constexpr double kBoxSide = 20.0;  // mm
// Lags fitted for D_r stop where C(t) falls below this (as `rodsea analyze`'s fit floor).
constexpr double kFitFloor = 0.2;

// Copies are independent: the standard error of their mean is the block error with one copy
// per block.
MeanAndError mean_and_error(const std::vector<double>& values) {
    double mean = 0.0;
    for (double v : values)
        mean += v / static_cast<double>(values.size());
    return {mean, estimate_from_blocks(mean, values).error};
}

// ⟨cos(θ(t + τ) − θ(t))⟩ over time origins, summed (not averaged) into `sum` with its counts.
void add_correlation(const std::vector<double>& angle, std::size_t max_lag,
                     std::vector<double>& sum, std::vector<double>& count) {
    for (std::size_t lag = 0; lag <= max_lag && lag < angle.size(); ++lag)
        for (std::size_t t = 0; t + lag < angle.size(); ++t) {
            sum[lag] += std::cos(angle[t + lag] - angle[t]);
            count[lag] += 1.0;
        }
}

std::vector<double> correlation_of(const std::vector<const SingleBodyTrace*>& traces,
                                   std::size_t max_lag) {
    std::vector<double> sum(max_lag + 1, 0.0), count(max_lag + 1, 0.0);
    for (const SingleBodyTrace* t : traces)
        add_correlation(t->angle, max_lag, sum, count);
    for (std::size_t lag = 0; lag <= max_lag; ++lag)
        sum[lag] = count[lag] > 0 ? sum[lag] / count[lag] : std::nan("");
    return sum;
}

}  // namespace

namespace {

// Copy `index` of an experiment as a Simulation, before its warm-up.
Simulation single_body_copy(const SingleBodyExperiment& e, int index,
                            const BackendOptions& options) {
    SplitMix64 rng(e.seed * 0x9e3779b97f4a7c15ULL + static_cast<std::uint64_t>(index) + 1);
    // A small tilt and a slow spin: a perfectly flat, still rod is a mirror-symmetric start that
    // the vibration alone takes long to leave. No initial translation, which would coast.
    const Quat tipped = tipped_orientation(0.0, rng.uniform(-0.1, 0.1));
    const Quat turn =
        Quat::from_axis_angle({0.0, 0.0, 1.0}, rng.uniform(-std::numbers::pi, std::numbers::pi));
    const Quat q = normalized(turn * tipped);
    const Vec3 spin{0.0, 0.0, rng.uniform(-2.0, 2.0)};
    EngineParameters params;
    params.box = {kBoxSide, kBoxSide};
    params.species = {e.species};
    params.drive = e.drive;
    params.dt = e.dt;
    params.noise_epsilon = e.epsilon;
    params.noise_mode = e.noise_mode;
    params.seed = e.seed + 7919ULL * static_cast<std::uint64_t>(index);
    BodyState body;
    body.add(0, {0.5 * kBoxSide, 0.5 * kBoxSide, resting_height(e.species.shape, q, e.drive)}, q,
             {}, spin);
    return Simulation(params, body, options);
}

// A copy's steps per drive period, and its warm-up and measured periods.
struct CopySchedule {
    std::uint64_t steps_per_period, warmup_periods;
    std::size_t periods;
};
CopySchedule schedule_of(const SingleBodyExperiment& e) {
    const double period = 2.0 * std::numbers::pi / e.drive.angular_frequency;
    return {static_cast<std::uint64_t>(std::llround(period / e.dt)),
            static_cast<std::uint64_t>(std::llround(e.warmup / period)),
            static_cast<std::size_t>(std::llround(e.duration / period))};
}

// Samples a copy at the end of each measured period.
class SingleBodyTracer {
  public:
    explicit SingleBodyTracer(const Vec3& start) : last_(start) {}

    void add_period(const BodyState& body) {
        const PeriodicBox2D box{kBoxSide, kBoxSide};
        const Vec3 now = body.position[0];
        const Vec3 d = box.minimum_image(now - last_);
        last_ = now;
        const Vec3 axis = rotate(body.orientation[0], Vec3{1.0, 0.0, 0.0});
        const double angle = std::atan2(axis.y, axis.x);
        const double in_plane = std::hypot(axis.x, axis.y);
        const double ux = axis.x / in_plane, uy = axis.y / in_plane;
        trace_.axial.push_back(d.x * ux + d.y * uy);
        trace_.transverse.push_back(-d.x * uy + d.y * ux);
        // Unwrapped: a turn of less than π per period (D_r of 10³ rad²/s would be needed to
        // break this) is taken as the short way round.
        double unwrapped = angle;
        if (!trace_.angle.empty()) {
            double step = angle - previous_angle_;
            step -= 2.0 * std::numbers::pi * std::round(step / (2.0 * std::numbers::pi));
            unwrapped = trace_.angle.back() + step;
        }
        previous_angle_ = angle;
        trace_.angle.push_back(unwrapped);
    }
    SingleBodyTrace finish(std::uint64_t unresolved) {
        trace_.unresolved = unresolved;
        return std::move(trace_);
    }

  private:
    Vec3 last_;
    double previous_angle_ = 0.0;
    SingleBodyTrace trace_;
};

}  // namespace

SingleBodyTrace run_single_body_copy(const SingleBodyExperiment& e, int index,
                                     const BackendOptions& options) {
    Simulation sim = single_body_copy(e, index, options);
    const CopySchedule plan = schedule_of(e);
    // A stop signal ends the copy within a drive period (its partial trace is then discarded by
    // the caller), so that Ctrl-C answers in well under a second, not after the copy.
    for (std::uint64_t p = 0; p < plan.warmup_periods; ++p) {
        if (stop_signal_received() != 0) return {};
        sim.run(plan.steps_per_period);
    }
    SingleBodyTracer tracer(sim.bodies().position[0]);
    for (std::size_t p = 0; p < plan.periods; ++p) {
        if (stop_signal_received() != 0) return tracer.finish(0);
        sim.run(plan.steps_per_period);
        tracer.add_period(sim.bodies());
    }
    return tracer.finish(sim.totals().unresolved);
}

std::optional<std::vector<std::vector<SingleBodyTrace>>> run_single_body_copies_together(
    const std::vector<SingleBodyExperiment>& experiments, int copies, const BackendOptions& options,
    const std::function<void(double)>& on_period) {
    if (experiments.empty() || copies < 1) return std::vector<std::vector<SingleBodyTrace>>{};
    const CopySchedule plan = schedule_of(experiments.front());
    for (const SingleBodyExperiment& e : experiments) {
        const CopySchedule other = schedule_of(e);
        if (e.dt != experiments.front().dt || other.steps_per_period != plan.steps_per_period ||
            other.warmup_periods != plan.warmup_periods || other.periods != plan.periods)
            throw InvalidParameter("experiments", "different dt, drive periods or lengths",
                                   "one schedule for every copy stepped together");
    }
    std::vector<Simulation> systems;
    for (const SingleBodyExperiment& e : experiments)
        for (int c = 0; c < copies; ++c)
            systems.push_back(single_body_copy(e, c, {}));
    Ensemble ensemble(std::move(systems), options);
    const std::size_t total_periods = plan.warmup_periods + plan.periods;
    const auto report = [&](std::size_t done) {
        if (on_period) on_period(static_cast<double>(done) / static_cast<double>(total_periods));
    };
    for (std::uint64_t p = 0; p < plan.warmup_periods; ++p) {
        if (stop_signal_received() != 0) return std::nullopt;
        ensemble.run(plan.steps_per_period);
        report(p + 1);
    }
    std::vector<SingleBodyTracer> tracers;
    for (std::size_t m = 0; m < ensemble.size(); ++m)
        tracers.emplace_back(ensemble.bodies(m).position[0]);
    for (std::size_t p = 0; p < plan.periods; ++p) {
        if (stop_signal_received() != 0) return std::nullopt;
        ensemble.run(plan.steps_per_period);
        for (std::size_t m = 0; m < ensemble.size(); ++m)
            tracers[m].add_period(ensemble.bodies(m));
        report(plan.warmup_periods + p + 1);
    }
    std::vector<std::vector<SingleBodyTrace>> traces(experiments.size());
    for (std::size_t m = 0; m < ensemble.size(); ++m)
        traces[m / static_cast<std::size_t>(copies)].push_back(
            tracers[m].finish(ensemble.totals(m).unresolved));
    return traces;
}

double rotational_diffusion_from_correlation(const std::vector<double>& c, double interval) {
    std::vector<double> t, y;
    for (std::size_t lag = 1; lag < c.size() && c[lag] >= kFitFloor; ++lag) {
        t.push_back(interval * static_cast<double>(lag));
        y.push_back(-std::log(std::min(1.0, c[lag])));
    }
    // No lag above the floor: C(t) fell below it within one period (D_r far beyond the fit's
    // reach) or there was no lag at all; not a D_r of 0.
    return t.empty() ? std::nan("") : slope_through_origin(t, y);
}

SingleBodyResult combine_single_body_traces(const std::vector<SingleBodyTrace>& traces,
                                            double period) {
    SingleBodyResult r;
    r.period = period;
    std::vector<double> axial, transverse;
    std::size_t shortest = traces.empty() ? 0 : traces.front().angle.size();
    for (const SingleBodyTrace& t : traces) {
        double a = 0.0, c = 0.0;
        for (std::size_t p = 0; p < t.axial.size(); ++p) {
            a += t.axial[p];
            c += t.transverse[p];
            r.period_speeds.push_back(t.axial[p] / period);
        }
        const double span = period * static_cast<double>(t.axial.size());
        axial.push_back(a / span);
        transverse.push_back(c / span);
        if (a > 0.0) r.forward_fraction += 1.0 / static_cast<double>(traces.size());
        r.unresolved += t.unresolved;
        shortest = std::min(shortest, t.angle.size());
    }
    r.axial_speed = mean_and_error(axial);
    r.transverse_speed = mean_and_error(transverse);

    // C(t) up to a quarter of a copy's length (longer lags have too few time origins), and D_r
    // with a jackknife error over copies: each copy left out in turn.
    const std::size_t max_lag = shortest / 4;
    std::vector<const SingleBodyTrace*> all;
    for (const SingleBodyTrace& t : traces)
        all.push_back(&t);
    r.correlation = correlation_of(all, max_lag);
    r.rotational_diffusion.mean = rotational_diffusion_from_correlation(r.correlation, period);
    const std::size_t n = traces.size();
    if (n >= 2) {
        std::vector<double> leave_one_out;
        for (std::size_t k = 0; k < n; ++k) {
            std::vector<const SingleBodyTrace*> rest;
            for (std::size_t j = 0; j < n; ++j)
                if (j != k) rest.push_back(&traces[j]);
            leave_one_out.push_back(
                rotational_diffusion_from_correlation(correlation_of(rest, max_lag), period));
        }
        double mean = 0.0, var = 0.0;
        for (double v : leave_one_out)
            mean += v / static_cast<double>(n);
        for (double v : leave_one_out)
            var += (v - mean) * (v - mean);
        r.rotational_diffusion.error =
            std::sqrt(static_cast<double>(n - 1) / static_cast<double>(n) * var);
    } else {
        r.rotational_diffusion.error = std::nan("");
    }
    return r;
}

}  // namespace rodsea
