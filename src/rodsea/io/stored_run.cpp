#include "rodsea/io/stored_run.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/trajectory_file.hpp"

namespace rodsea {

namespace fs = std::filesystem;

namespace {

fs::path trajectory_of(const fs::path& run) {
    const fs::path path = fs::is_directory(run) ? run / "trajectory.h5" : run;
    if (!fs::exists(path))
        throw FileError(path.string(),
                        "no such file (give a directory written by `rodsea run`, or its "
                        "trajectory.h5)");
    return path;
}

}  // namespace

long long StoredRun::total_bodies() const {
    long long n = 0;
    for (long long c : plan.counts)
        n += c;
    return n;
}

std::size_t StoredRun::grid_frames() const {
    const std::size_t n = frames();
    const auto per = static_cast<std::int64_t>(plan.steps_per_output());
    return n > 1 && reader.steps()[n - 1] % per != 0 ? n - 1 : n;
}

BodyState StoredRun::frame(std::size_t k) const {
    BodyState bodies = reader.frame(k);
    if (static_cast<long long>(bodies.size()) != total_bodies())
        throw FileError(trajectory.string(),
                        "frame " + std::to_string(k) + " holds " + std::to_string(bodies.size()) +
                            " bodies, the stored config " + std::to_string(total_bodies()));
    const double time = reader.times()[k];
    if (const auto p = find_state_problem(plan.engine, bodies, time, StateOrigin::stored_frame)) {
        const std::string field = p->field.substr(0, p->field.find('.'));
        const std::string dataset = field == "species" ? "/particles/bodies/species"
                                                       : "/particles/bodies/" + field + "/value";
        // A joined run's frame is named in the part that holds it, by that file's own index.
        const TrajectoryReader::FrameSource source = reader.source_of(k);
        const std::string run_frame =
            source.index == k ? "" : "the run's frame " + std::to_string(k) + ", ";
        throw FileError(source.file.string(),
                        dataset + ", frame " + std::to_string(source.index) + " (" + run_frame +
                            "t = " + format_number(time) + " s), body " + std::to_string(p->body) +
                            ": " + p->field + " " + p->value + "; allowed: " + p->allowed +
                            (p->detail.empty() ? "" : " (" + p->detail + ")"));
    }
    return bodies;
}

StoredRun open_stored_run(const fs::path& run) {
    const fs::path trajectory = trajectory_of(run);
    TrajectoryReader reader(trajectory);
    std::string config;
    try {
        config = read_stored_config(trajectory);
    } catch (const FileError&) {
        throw FileError(trajectory.string(),
                        "not a rodsea trajectory (no /parameters/rodsea/config)");
    }
    RunPlan plan = load_config_string(config, trajectory.string() + ":/parameters/rodsea/config");
    if (reader.frames() == 0) throw FileError(trajectory.string(), "holds no frames yet");
    if (const auto problem = find_species_count_problem(reader.species(), plan.counts))
        throw FileError(trajectory.string(), "/particles/bodies/species holds " + *problem);
    // Frame k's time is its step × dt; anything beyond rounding is not what rodsea wrote.
    const double dt = plan.engine.dt;
    for (std::size_t k = 0; k < reader.frames(); ++k) {
        const double expected = static_cast<double>(reader.steps()[k]) * dt;
        if (std::abs(reader.times()[k] - expected) > 1e-9 * std::max(expected, dt))
            throw FileError(trajectory.string(),
                            "/particles/bodies/position/time, frame " + std::to_string(k) + ": " +
                                format_number(reader.times()[k]) + " s, but its step " +
                                std::to_string(reader.steps()[k]) + " × dt is " +
                                format_number(expected) + " s");
    }
    const fs::path dir = fs::is_directory(run)              ? run
                         : trajectory.parent_path().empty() ? fs::path(".")
                                                            : trajectory.parent_path();
    return StoredRun{dir, trajectory, {trajectory}, std::move(plan), std::move(reader)};
}

StoredRun open_stored_run(const std::vector<fs::path>& given) {
    if (given.size() == 1) return open_stored_run(given.front());
    if (given.empty()) throw std::logic_error("open_stored_run: no parts");
    struct Part {
        fs::path trajectory;
        std::uint64_t first_frame = 0;
    };
    std::vector<Part> parts;
    std::string id;
    for (const fs::path& run : given) {
        const fs::path trajectory = trajectory_of(run);
        const std::string its = read_run_id(trajectory);
        if (its.empty() || (!id.empty() && its != id))
            throw FileError(trajectory.string(),
                            "is not a part of the run in " + given.front().string() + " (run id " +
                                (its.empty() ? std::string("none") : its) +
                                "): only a run's directories and its continuations read as one");
        id = its;
        parts.push_back({trajectory, read_first_frame(trajectory)});
    }
    std::sort(parts.begin(), parts.end(),
              [](const Part& a, const Part& b) { return a.first_frame < b.first_frame; });
    std::vector<StoredRun> stored;
    for (const Part& part : parts)
        stored.push_back(open_stored_run(part.trajectory));
    // A run's parts differ at most in their length (a continuation given --duration).
    const RunControl& last = stored.back().plan.control;
    const auto normalised = [&](const StoredRun& r) {
        return with_run_length(r.plan.config_toml, r.trajectory.string(), last.duration,
                               last.steady_samples)
            .config_toml;
    };
    const std::string config = normalised(stored.back());
    std::vector<TrajectoryReader> readers;
    std::vector<std::uint64_t> keep;
    std::vector<fs::path> paths;
    for (std::size_t k = 0; k < stored.size(); ++k) {
        const std::string where = parts[k].trajectory.string();
        if (normalised(stored[k]) != config)
            throw FileError(where, "holds another config than " + parts.back().trajectory.string() +
                                       " beyond the run's length: not a part of the same run");
        std::uint64_t frames = stored[k].frames();
        if (k + 1 < stored.size()) {
            const std::uint64_t next = parts[k + 1].first_frame;
            if (next == parts[k].first_frame)
                throw FileError(where, "starts at the run's frame " + std::to_string(next) +
                                           ", as " + parts[k + 1].trajectory.string() +
                                           " does: give each part of the run once");
            if (next > parts[k].first_frame + frames)
                throw FileError(where, "ends at the run's frame " +
                                           std::to_string(parts[k].first_frame + frames - 1) +
                                           " and the next part, " +
                                           parts[k + 1].trajectory.string() + ", starts at frame " +
                                           std::to_string(next) +
                                           ": the frames between are in none of the parts given");
            frames = next - parts[k].first_frame;
        }
        keep.push_back(frames);
        readers.push_back(std::move(stored[k].reader));
        paths.push_back(parts[k].trajectory);
    }
    StoredRun& latest = stored.back();
    return StoredRun{latest.run_dir, latest.trajectory, std::move(paths), std::move(latest.plan),
                     TrajectoryReader::joined(std::move(readers), keep)};
}

std::vector<std::vector<fs::path>> group_run_parts(const std::vector<fs::path>& runs) {
    struct Group {
        std::string id;
        std::vector<std::uint64_t> first_frames;
    };
    std::vector<std::vector<fs::path>> groups;
    std::vector<Group> keys;
    for (const fs::path& run : runs) {
        const fs::path trajectory = trajectory_of(run);
        const std::string id = read_run_id(trajectory);
        const std::uint64_t first = read_first_frame(trajectory);
        // Two directories of one run that start at the same frame are copies, or two
        // continuations of one checkpoint: each is read apart, not joined.
        const auto joins = [&](const Group& g) {
            return !id.empty() && g.id == id &&
                   std::find(g.first_frames.begin(), g.first_frames.end(), first) ==
                       g.first_frames.end();
        };
        const auto same = std::find_if(keys.begin(), keys.end(), joins);
        if (same != keys.end()) {
            groups[static_cast<std::size_t>(same - keys.begin())].push_back(run);
            same->first_frames.push_back(first);
            continue;
        }
        groups.push_back({run});
        keys.push_back({id, {first}});
    }
    return groups;
}

std::size_t select_frame(const StoredRun& run, std::optional<long long> frame,
                         std::optional<double> time) {
    const std::size_t n = run.frames();
    const long long count = static_cast<long long>(n);
    if (frame && time)
        throw InvalidParameter("--frame", std::to_string(*frame), "either --frame or --time",
                               "not both");
    if (frame) {
        const long long k = *frame < 0 ? count + *frame : *frame;
        if (k < 0 || k >= count)
            throw InvalidParameter("--frame", std::to_string(*frame),
                                   "[0, " + std::to_string(count - 1) + "] (or -1 … -" +
                                       std::to_string(count) + " from the end)",
                                   "the run holds " + std::to_string(count) + " frames");
        return static_cast<std::size_t>(k);
    }
    if (time) {
        const std::vector<double>& t = run.times();
        const double interval = n > 1 ? (t.back() - t.front()) / static_cast<double>(n - 1) : 0.0;
        // Half an output interval of slack at each end: the nearest frame is still meaningful.
        if (!std::isfinite(*time) || *time < t.front() - 0.5 * interval ||
            *time > t.back() + 0.5 * interval)
            throw InvalidParameter(
                "--time", format_number(*time) + " s",
                "[" + format_number(t.front()) + ", " + format_number(t.back()) + "] s",
                "the run's frames span that time");
        std::size_t best = 0;
        for (std::size_t k = 1; k < n; ++k)
            if (std::abs(t[k] - *time) < std::abs(t[best] - *time)) best = k;
        return best;
    }
    return n - 1;
}

FrameSpan select_frame_span(const std::vector<double>& t, double interval,
                            std::optional<double> from, std::optional<double> to) {
    // Rounding slack only: --from 0.5 takes the frame stored at 0.49999999999 s, and --from
    // 0.515 the first frame at or after it, not the one at 0.51 (--to alike).
    const double slack = 1e-6 * interval;
    std::string span("the run's frames span ");
    span.append(format_number(t.front())).append(" to ").append(format_number(t.back()));
    span.append(" s");
    const auto range = [](double lo, double hi) {
        std::string r(1, '[');
        r.append(format_number(lo)).append(", ").append(format_number(hi)).append("] s");
        return r;
    };
    // Before the first frame is allowed: a continuation's directory starts late, and its run
    // still starts at 0.
    if (from && (!std::isfinite(*from) || *from < 0.0 || *from > t.back() + slack))
        throw InvalidParameter("--from", format_number(*from) + " s", range(0.0, t.back()), span);
    // Past the last frame is refused, not clamped: a --to the run has not reached is a typo or
    // a run still being written, and a window silently shorter than asked is worse than either.
    if (to && (!std::isfinite(*to) || *to < t.front() - slack || *to > t.back() + slack))
        throw InvalidParameter("--to", format_number(*to) + " s", range(t.front(), t.back()), span);
    const double lo = from.value_or(t.front()), hi = to.value_or(t.back());
    if (hi < lo - slack)
        throw InvalidParameter("--to", format_number(hi) + " s",
                               "at least --from (" + format_number(lo) + " s)");
    FrameSpan s;
    while (s.first < t.size() && t[s.first] < lo - slack)
        ++s.first;
    s.end = s.first;
    while (s.end < t.size() && t[s.end] <= hi + slack)
        ++s.end;
    if (s.end == s.first)
        throw InvalidParameter("--from", format_number(lo) + " s to " + format_number(hi) + " s",
                               "a window that holds at least one frame",
                               "frames are " + format_number(interval) + " s apart; " + span);
    return s;
}

std::vector<std::size_t> select_frame_window(const StoredRun& run, std::optional<double> from,
                                             std::optional<double> to, long long every) {
    const FrameSpan span = select_frame_span(run.times(), run.plan.frame_interval(), from, to);
    std::vector<std::size_t> frames;
    for (std::size_t k = span.first; k < span.end; k += static_cast<std::size_t>(every))
        frames.push_back(k);
    return frames;
}

}  // namespace rodsea
