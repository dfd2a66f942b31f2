#include "rodsea/run/checkpoint_checks.hpp"

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/run/run_session.hpp"
#include "rodsea/run/series_recorder.hpp"
#include "rodsea/run/steady_stop.hpp"

namespace rodsea {

void check_checkpoint_bodies(const Checkpoint& c, const RunPlan& plan,
                             const std::filesystem::path& path) {
    std::uint64_t expected = 0;
    for (long long n : plan.counts)
        expected += static_cast<std::uint64_t>(n);
    if (c.bodies.size() != expected)
        throw FileError(path.string(), "holds " + std::to_string(c.bodies.size()) +
                                           " bodies but its config asks for " +
                                           std::to_string(expected));
    if (const auto problem = find_species_count_problem(c.bodies.species, plan.counts))
        throw FileError(path.string(), "damaged: dataset species holds " + *problem);
}

void check_checkpoint(const Checkpoint& c, const RunPlan& plan, const std::filesystem::path& path) {
    check_checkpoint_bodies(c, plan, path);
    const std::string interval = SeriesRecorder(plan).interval_problem(c.interval_accumulators);
    if (!interval.empty())
        throw FileError(
            path.string(),
            "damaged: dataset interval_accumulators (the time series' open interval): " + interval);
}

void check_checkpoint_state(const Checkpoint& c, const RunPlan& plan,
                            const std::filesystem::path& path) {
    const double time = static_cast<double>(c.step) * plan.engine.dt;
    std::optional<StateProblem> problem =
        find_state_problem(plan.engine, c.bodies, time, StateOrigin::resumed);
    if (!problem) problem = find_gross_overlap(plan.engine, c.bodies);
    if (problem) {
        const std::string dataset = problem->field.substr(0, problem->field.find('.'));
        throw FileError(path.string(),
                        "impossible state: dataset " + dataset + ", body " +
                            std::to_string(problem->body) + " at step " + std::to_string(c.step) +
                            ": " + problem->field + " " + problem->value +
                            "; allowed: " + problem->allowed +
                            (problem->detail.empty() ? "" : " (" + problem->detail + ")"));
    }
}

// The plan of a run given a new length (--duration, --steady-samples), checked against what the
// run has done.
RunPlan extended_plan(const Checkpoint& c, std::optional<double> duration,
                      std::optional<long long> steady_samples, const std::filesystem::path& path) {
    RunPlan plan =
        with_run_length(c.config_toml, path.string() + " [config]", duration, steady_samples);
    check_steady_series(plan);
    if (plan.total_steps() < c.step)
        throw InvalidParameter("--duration", format_number(plan.control.duration) + " s",
                               "at least the " +
                                   format_number(static_cast<double>(c.step) * plan.engine.dt) +
                                   " s already simulated");
    return plan;
}

void check_frames_counted(const Checkpoint& c, const RunPlan& plan, bool extending,
                          const std::filesystem::path& path) {
    const std::uint64_t due = frames_due(plan, c.step);
    // An extension of a complete run that ended off the output grid drops that last frame.
    const bool extra_last_frame = extending && c.complete && c.frames_written == due + 1;
    if (c.step > plan.total_steps() ||
        (c.frames_written != due && c.frames_written + 1 != due && !extra_last_frame))
        throw FileError(path.string(), "counts " + std::to_string(c.frames_written) +
                                           " frames at step " + std::to_string(c.step) +
                                           ", where the run writes " + std::to_string(due) +
                                           ": not a checkpoint of this run's config");
}

void refuse_steady_stop(const RunPlan& plan, const std::string& where) {
    if (plan.control.steady_samples == 0) return;
    throw InvalidParameter(
        "time.steady_samples", std::to_string(plan.control.steady_samples) + " (" + where + ")",
        "0 in a continued run",
        "stopping when steady judges the run's whole time series, and a continuation holds only "
        "its frames from the checkpoint on: give --steady-samples 0 (run to time.duration) and "
        "choose the steady window afterwards with rodsea analyze");
}

}  // namespace rodsea
