#include "rodsea/run/checkpoint_checks.hpp"

#include <algorithm>
#include <sstream>

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_files.hpp"
#include "rodsea/run/run_session.hpp"
#include "rodsea/run/series_recorder.hpp"
#include "rodsea/run/steady_stop.hpp"
#include "rodsea/text_file.hpp"

namespace rodsea {

namespace {

// The first line where two config texts differ, as "`a` here, `b` there".
std::string first_difference(const std::string& here, const std::string& there) {
    std::istringstream a(here), b(there);
    std::string la, lb;
    while (true) {
        const bool more_a = static_cast<bool>(std::getline(a, la));
        const bool more_b = static_cast<bool>(std::getline(b, lb));
        if (!more_a && !more_b) return "they differ";
        if (!more_a) la = "(nothing)";
        if (!more_b) lb = "(nothing)";
        if (la != lb || !more_a || !more_b) return "`" + la + "` against `" + lb + "`";
    }
}

}  // namespace

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

void check_checkpoint_belongs(const std::filesystem::path& dir, const Checkpoint& c,
                              const RunPlan& plan) {
    const std::filesystem::path checkpoint = dir / kCheckpointFile,
                                trajectory = dir / kTrajectoryFile, config = dir / kConfigFile;
    if (!std::filesystem::exists(trajectory))
        throw FileError(trajectory.string(),
                        "missing: the checkpoint continues the frames it holds (start the run "
                        "again with rodsea run CONFIG --out DIR --overwrite)");
    const std::string id = read_run_id(trajectory);
    if (id != c.run_id)
        throw FileError(checkpoint.string(),
                        "belongs to another run: its run id is " +
                            (c.run_id.empty() ? std::string("none (an older rodsea)") : c.run_id) +
                            ", trajectory.h5's is " + (id.empty() ? std::string("none") : id) +
                            " (copied from another run directory?); nothing was changed");
    const std::string mine = config_fingerprint(c.config_toml);
    const auto check_config = [&](const std::filesystem::path& file, const std::string& text) {
        const std::string theirs = config_fingerprint(text);
        if (theirs == mine || (!c.extending_from.empty() && theirs == c.extending_from)) return;
        throw FileError(file.string(),
                        "holds another config than the checkpoint (" +
                            first_difference(text, c.config_toml) +
                            "): a run resumes with the config it started with (extend it with "
                            "--duration T); restore the file or start again with --overwrite");
    };
    check_config(trajectory.string() + ":/parameters/rodsea/config",
                 read_stored_config(trajectory));
    if (std::filesystem::exists(config)) check_config(config, read_text_file(config));
    // A continuation's file holds the run's frames from its first_frame on.
    const TrajectoryReader reader(trajectory);
    if (reader.species() != c.bodies.species)
        throw FileError(trajectory.string(),
                        "holds other bodies (/particles/bodies/species) than the checkpoint: a "
                        "run resumes with the bodies it started with");
    const std::uint64_t first = read_first_frame(trajectory);
    if (first > c.frames_written || reader.frames() < c.frames_written - first) {
        const std::string held = first == 0
                                     ? std::to_string(reader.frames()) + " frames"
                                     : "the run's frames " + std::to_string(first) + " to " +
                                           std::to_string(first + reader.frames()) + " (exclusive)";
        throw FileError(trajectory.string(), "holds " + held + " but the checkpoint counts " +
                                                 std::to_string(c.frames_written) +
                                                 " (the file was replaced or damaged)");
    }
    if (c.frames_written > first) {
        const std::uint64_t k = c.frames_written - 1;
        const std::uint64_t expected = std::min(k * plan.steps_per_output(), plan.total_steps());
        const std::int64_t stored = reader.steps()[k - first];
        if (stored != static_cast<std::int64_t>(expected))
            throw FileError(trajectory.string(),
                            "frame " + std::to_string(k) + " is at step " + std::to_string(stored) +
                                " where the checkpoint's config puts it at step " +
                                std::to_string(expected));
    }
    check_checkpoint_state(c, plan, checkpoint);
}

}  // namespace rodsea
