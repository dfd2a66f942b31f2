// The run workflow end to end: the driver's trajectory is the engine's, an interrupted and
// resumed run is bit-identical to an uninterrupted one, a full disk stops with a usable
// checkpoint, and bad input changes nothing.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "child_process.hpp"
#include "rodsea/analysis/steady_state.hpp"
#include "rodsea/builder/initial_state.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_driver.hpp"
#include "rodsea/run/steady_stop.hpp"
#include "run_comparison.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

// The driver adds output, not physics: its final state is the engine's after the same steps
// from the same built state, bit for bit, and it writes one frame per interval plus the first.
TEST(RunWorkflow, DriverStateIsTheEnginesAndFramesFollowTheCadence) {
    const ScratchDir dir("run-basic");
    const RunPlan plan = load_config_string(small_config(0.01, 0.001), "test");
    RunOptions options;
    options.out_dir = dir.path() / "out";
    options.quiet = true;
    std::ostringstream out, err;
    ASSERT_EQ(start_run(plan, options, out, err), kExitOk) << err.str();

    Simulation reference(
        plan.engine, build_initial_state(plan.engine, plan.counts, plan.builder, plan.engine.seed));
    reference.run(plan.total_steps());
    const Checkpoint last = read_checkpoint(options.out_dir / kCheckpointFile);
    EXPECT_TRUE(last.complete);
    EXPECT_EQ(last.step, plan.total_steps());
    EXPECT_TRUE(same_bits(last.bodies, reference.bodies()));

    const TrajectoryReader t(options.out_dir / kTrajectoryFile);
    const std::uint64_t expected = plan.total_steps() / plan.steps_per_output() + 1;
    ASSERT_EQ(t.frames(), expected);
    ASSERT_EQ(last.frames_written, expected);
    for (std::uint64_t f = 0; f < t.frames(); ++f) {
        EXPECT_EQ(t.steps()[f], static_cast<std::int64_t>(f * plan.steps_per_output()));
        EXPECT_DOUBLE_EQ(t.times()[f], static_cast<double>(t.steps()[f]) * plan.engine.dt);
    }
    // The last frame holds the final state in single precision.
    const BodyState final_frame = t.frame(t.frames() - 1);
    for (size_t i = 0; i < final_frame.size(); ++i)
        EXPECT_NEAR(final_frame.position[i].x, reference.bodies().position[i].x, 1e-5);
    // One CSV row per frame after the two header lines, and the same P as the HDF5 series.
    EXPECT_EQ(line_count(options.out_dir / kSeriesFile), 2 + expected);
    EXPECT_EQ(t.series("polar_order_polar").size(), expected);
    EXPECT_EQ(load_config_string(read_text(options.out_dir / kConfigFile), "stored").config_toml,
              plan.config_toml);
    // The medium's mean velocity in the last row is that of the final state (summed in body
    // order, as here, so to the last bit).
    double vx = 0.0, vy = 0.0, n = 0.0;
    for (size_t i = 0; i < reference.bodies().size(); ++i) {
        if (reference.bodies().species[i] != 1) continue;
        vx += reference.bodies().velocity[i].x;
        vy += reference.bodies().velocity[i].y;
        n += 1.0;
    }
    EXPECT_EQ(t.series("mean_velocity_x_medium").back(), vx / n);
    EXPECT_EQ(t.series("mean_velocity_y_medium").back(), vy / n);
}

// Ctrl-C in the middle, then --resume: the same final state, bit for bit, as a run that was
// never stopped, and the same frames, none lost and none twice.
TEST(RunWorkflow, InterruptedAndResumedRunIsBitIdentical) {
    const ScratchDir dir("run-resume");
    const auto config = write_config(dir, small_config(0.12, 0.004));
    const auto a = dir.path() / "interrupted", b = dir.path() / "straight";

    ChildOptions interrupt;
    interrupt.interrupt_when = [&] {
        return std::filesystem::exists(a / kSeriesFile) && line_count(a / kSeriesFile) >= 2 + 5;
    };
    const ChildResult first =
        run_rodsea({"run", config.string(), "--out", a.string(), "--quiet"}, dir.path(), interrupt);
    ASSERT_TRUE(first.interrupted);
    ASSERT_EQ(first.exit_code, kExitInterrupted) << first.err;
    EXPECT_NE(first.err.find("--resume"), std::string::npos) << first.err;
    const Checkpoint stopped = read_checkpoint(a / kCheckpointFile);
    ASSERT_FALSE(stopped.complete) << "the run finished before SIGINT arrived";

    const ChildResult resumed = run_rodsea({"run", "--resume", a.string(), "--quiet"}, dir.path());
    ASSERT_EQ(resumed.exit_code, kExitOk) << resumed.err;
    const ChildResult straight =
        run_rodsea({"run", config.string(), "--out", b.string(), "--quiet"}, dir.path());
    ASSERT_EQ(straight.exit_code, kExitOk) << straight.err;

    const Checkpoint end_a = read_checkpoint(a / kCheckpointFile);
    const Checkpoint end_b = read_checkpoint(b / kCheckpointFile);
    EXPECT_TRUE(end_a.complete);
    EXPECT_EQ(end_a.step, end_b.step);
    EXPECT_TRUE(same_bits(end_a.bodies, end_b.bodies));

    const TrajectoryReader ta(a / kTrajectoryFile), tb(b / kTrajectoryFile);
    ASSERT_EQ(ta.frames(), tb.frames());
    EXPECT_EQ(ta.steps(), tb.steps());
    for (std::uint64_t f = 0; f < ta.frames(); f += 7)
        EXPECT_TRUE(same_bits(ta.frame(f), tb.frame(f))) << "frame " << f;
    EXPECT_EQ(ta.series("nematic_order_medium"), tb.series("nematic_order_medium"));
    EXPECT_EQ(ta.series("max_overlap_fraction"), tb.series("max_overlap_fraction"));
    EXPECT_EQ(line_count(a / kSeriesFile), line_count(b / kSeriesFile));

    // Resuming a finished run does nothing and says so.
    const ChildResult again = run_rodsea({"run", "--resume", a.string()}, dir.path());
    EXPECT_EQ(again.exit_code, kExitOk);
    EXPECT_NE(again.out.find("already complete"), std::string::npos) << again.out;
}

int extend_quietly(const std::filesystem::path& dir, std::optional<double> duration,
                   std::optional<long long> samples = std::nullopt) {
    RunOptions options;
    options.quiet = true;
    options.duration = duration;
    options.steady_samples = samples;
    std::ostringstream log, err;
    return resume_run(dir, options, log, err);
}

TEST(RunExtension, AFinishedRunExtendedIsTheLongerRunBitForBit) {
    // Ending on the output grid (0.02 s, frames every 2 ms) and off it (0.021 s: a last frame at
    // 0.021 s that the 0.04 s run does not have, and an interval cut short).
    const ScratchDir dir("run-extend");
    const auto longer = dir.path() / "longer";
    ASSERT_EQ(run_quietly(small_config(0.04, 0.002), longer), kExitOk);
    for (const double first : {0.02, 0.021}) {
        const auto extended = dir.path() / ("extended-" + std::to_string(first));
        ASSERT_EQ(run_quietly(small_config(first, 0.002), extended), kExitOk);
        ASSERT_TRUE(read_checkpoint(extended / kCheckpointFile).complete);
        ASSERT_EQ(extend_quietly(extended, 0.04), kExitOk);
        SCOPED_TRACE("extended from " + std::to_string(first) + " s");
        expect_same_run(extended, longer);
        EXPECT_EQ(load_config_string(read_text(extended / kConfigFile), "c").control.duration,
                  0.04);
    }
}

TEST(RunExtension, RefusesToShortenBelowTheTimeDoneAndChangesNothing) {
    const ScratchDir dir("run-extend-bad");
    const auto run = dir.path() / "run";
    ASSERT_EQ(run_quietly(small_config(0.01, 0.002), run), kExitOk);
    const std::string checkpoint = read_text(run / kCheckpointFile);
    const std::string config = read_text(run / kConfigFile);
    try {
        extend_quietly(run, 0.005);
        ADD_FAILURE() << "shortened a finished run";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "--duration");
        EXPECT_NE(std::string(e.what()).find("0.01 s already simulated"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(read_text(run / kCheckpointFile), checkpoint);
    EXPECT_EQ(read_text(run / kConfigFile), config);
    // The same duration again: nothing to do.
    EXPECT_EQ(extend_quietly(run, 0.01), kExitOk);
    EXPECT_EQ(read_text(run / kCheckpointFile), checkpoint);
    // --duration belongs to --resume.
    const auto file = write_config(dir, small_config(0.01, 0.002));
    const ChildResult r =
        run_rodsea({"run", file.string(), "--out", (dir.path() / "x").string(), "--duration", "1"},
                   dir.path());
    EXPECT_EQ(r.exit_code, kExitBadInput);
    EXPECT_NE(r.err.find("--duration"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "x"));
}

// The stop rule as the run applies it, recomputed from the stored series: the window from every
// order series holds at least `samples` independent samples of `counted`, which does not drift.
bool steady_enough(const std::vector<NamedSeries>& series, const std::string& counted,
                   double samples) {
    if (series[0].values.size() < kSteadyMinimumFrames) return false;
    for (const SeriesStart& s : latest_steady_start(series).series)
        if (s.name == counted) return !s.drifting && s.n_eff >= samples;
    return false;
}

TEST(RunExtension, StopsWhenSteadyAndExtendsPastThatWithMoreSamples) {
    // At most 1 s, stopping once the medium's S has 8 independent samples in the steady window
    // (measured: at 0.134 s; 16 samples at 0.332 s).
    const ScratchDir dir("run-steady");
    const auto run = dir.path() / "run";
    std::string text = small_config(1.0, 0.002);
    text.replace(text.find("[output]"), 0,
                 "steady_samples = 8\nsteady_series = \"nematic_order_medium\"\n");
    ASSERT_EQ(run_quietly(text, run), kExitOk);
    const Checkpoint end = read_checkpoint(run / kCheckpointFile);
    ASSERT_TRUE(end.complete);
    const RunPlan plan = load_config_string(end.config_toml, "c");
    std::printf("[ measured ] stopped when steady at t = %g s of at most 1 s\n",
                static_cast<double>(end.step) * plan.engine.dt);
    EXPECT_LT(end.step, plan.total_steps()) << "did not stop early";
    EXPECT_EQ(end.step % plan.steps_per_output(), 0u);  // at a frame
    std::vector<NamedSeries> series;
    {
        const TrajectoryReader reader(run / kTrajectoryFile);  // closed before the run reopens it
        for (const char* c : {"polar_order_polar", "nematic_order_polar", "nematic_order_medium",
                              "segregation", "largest_flock"})
            series.push_back({c, reader.series(c)});
    }
    // Satisfied at the last frame, not at the one before (else it would have stopped there).
    EXPECT_TRUE(steady_enough(series, "nematic_order_medium", 8.0));
    std::vector<NamedSeries> earlier = series;
    for (NamedSeries& s : earlier)
        s.values.pop_back();
    EXPECT_FALSE(steady_enough(earlier, "nematic_order_medium", 8.0));

    // More samples asked for: it goes on from where it stopped, and stops later.
    ASSERT_EQ(extend_quietly(run, std::nullopt, 16), kExitOk);
    const Checkpoint later = read_checkpoint(run / kCheckpointFile);
    EXPECT_TRUE(later.complete);
    std::printf("[ measured ] with 16 samples at t = %g s\n",
                static_cast<double>(later.step) * plan.engine.dt);
    EXPECT_GT(later.step, end.step);
    EXPECT_EQ(load_config_string(later.config_toml, "c").control.steady_samples, 16);
}

TEST(RunExtension, AnUnknownSteadySeriesIsRefusedBeforeAnyWork) {
    const ScratchDir dir("run-steady-bad");
    std::string text = small_config(0.01, 0.002);
    text.replace(text.find("[output]"), 0, "steady_samples = 5\nsteady_series = \"P\"\n");
    try {
        run_quietly(text, dir.path() / "run");
        ADD_FAILURE() << "ran with an unknown series";
    } catch (const InvalidParameter& e) {
        EXPECT_EQ(e.name(), "time.steady_series");
        EXPECT_NE(std::string(e.what()).find("polar_order_polar"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "run"));
}

// A file-size limit makes the trajectory's writes fail part way, as a full disk does: the run
// stops with exit code 74, a message naming the file, and a checkpoint from which the run
// resumes (limit lifted) to the same end state as a run that never failed.
TEST(RunWorkflow, FullDiskStopsWithACheckpointThatResumes) {
    const ScratchDir dir("run-disk");
    const auto config = write_config(dir, small_config(0.08, 0.002));
    const auto a = dir.path() / "full", b = dir.path() / "straight";
    ASSERT_EQ(
        run_rodsea({"run", config.string(), "--out", b.string(), "--quiet"}, dir.path()).exit_code,
        kExitOk);
    // The finished file cannot grow by the run's reserve (two frames and 64 kB) under a limit of
    // its own final size, so the run must stop before its end; the start (file metadata, frame
    // 0 and the reserve) fits, and so does the ~20 kB checkpoint, a separate file.
    ChildOptions limited;
    limited.file_size_limit =
        static_cast<long long>(std::filesystem::file_size(b / kTrajectoryFile));
    const ChildResult failed =
        run_rodsea({"run", config.string(), "--out", a.string(), "--quiet"}, dir.path(), limited);
    ASSERT_EQ(failed.exit_code, kExitIoError) << failed.out << failed.err;
    EXPECT_NE(failed.err.find("trajectory.h5"), std::string::npos) << failed.err;
    EXPECT_NE(failed.err.find("checkpoint written"), std::string::npos) << failed.err;
    const Checkpoint stopped = read_checkpoint(a / kCheckpointFile);
    EXPECT_FALSE(stopped.complete);
    EXPECT_GT(stopped.frames_written, 1u);
    // What was written is intact: the file opens and holds every frame the checkpoint counts.
    EXPECT_GE(TrajectoryReader(a / kTrajectoryFile).frames(), stopped.frames_written);

    ASSERT_EQ(run_rodsea({"run", "--resume", a.string(), "--quiet"}, dir.path()).exit_code,
              kExitOk);
    EXPECT_TRUE(same_bits(read_checkpoint(a / kCheckpointFile).bodies,
                          read_checkpoint(b / kCheckpointFile).bodies));
    const TrajectoryReader ta(a / kTrajectoryFile), tb(b / kTrajectoryFile);
    EXPECT_EQ(ta.steps(), tb.steps());
    EXPECT_TRUE(same_bits(ta.frame(ta.frames() - 1), tb.frame(tb.frames() - 1)));
    // The frame that failed is rewritten on resume with the interval it was to close.
    for (const char* column :
         {"max_overlap_fraction", "max_sweeps", "impulses_per_step", "body_collision_rate",
          "plate_collision_rate", "unresolved_contacts", "polar_order_polar"})
        EXPECT_EQ(ta.series(column), tb.series(column)) << column;
}

// Checkpoints come every output.checkpoint_interval of wall time while the run goes, not only
// at the end: watched from outside, the checkpoint's step advances several times.
TEST(RunWorkflow, CheckpointsFollowTheWallClockInterval) {
    const ScratchDir dir("run-wallclock");
    const auto config = write_config(
        dir, small_config(0.2, 0.1, "checkpoint_interval = 0.001\n"));  // minutes: 60 ms
    const auto out = dir.path() / "out";
    std::set<std::uint64_t> seen;
    ChildOptions watch;
    watch.interrupt_when = [&] {
        if (std::filesystem::exists(out / kCheckpointFile)) {
            try {
                seen.insert(read_checkpoint(out / kCheckpointFile).step);
            } catch (const FileError&) {
                // replaced between exists() and open(): read it next time
            }
        }
        return false;
    };
    const ChildResult r =
        run_rodsea({"run", config.string(), "--out", out.string(), "--quiet"}, dir.path(), watch);
    ASSERT_EQ(r.exit_code, kExitOk) << r.err;
    seen.erase(0);  // the first checkpoint, before any step
    seen.erase(read_checkpoint(out / kCheckpointFile).step);  // the final one
    // ~1 s of running with a checkpoint every 60 ms; frames come only at 0, 0.1 and 0.2 s, so
    // these checkpoints were written between frames, by the wall clock.
    EXPECT_GE(seen.size(), 2u);
}

TEST(RunWorkflow, AnExistingOutputDirectoryIsRefusedAndLeftAlone) {
    const ScratchDir dir("run-exists");
    const auto config = write_config(dir, small_config(0.002, 0.001));
    const auto out = dir.path() / "out";
    std::filesystem::create_directories(out);
    std::ofstream(out / "notes.txt") << "mine";
    const ChildResult r = run_rodsea({"run", config.string(), "--out", out.string()}, dir.path());
    EXPECT_EQ(r.exit_code, kExitBadInput);
    EXPECT_NE(r.err.find(out.string()), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("--overwrite"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(out / "notes.txt"), "mine");
    EXPECT_FALSE(std::filesystem::exists(out / kTrajectoryFile));

    // --overwrite replaces the run files and keeps the user's own.
    const ChildResult o = run_rodsea(
        {"run", config.string(), "--out", out.string(), "--overwrite", "--quiet"}, dir.path());
    EXPECT_EQ(o.exit_code, kExitOk) << o.err;
    EXPECT_EQ(read_text(out / "notes.txt"), "mine");
    EXPECT_TRUE(std::filesystem::exists(out / kTrajectoryFile));
}

TEST(RunWorkflow, UnwritableOutputAndMissingInputsNameThePath) {
    const ScratchDir dir("run-paths");
    const auto config = write_config(dir, small_config(0.002, 0.001));
    // A directory inside a regular file cannot be created, whoever runs the test (root too).
    const auto blocker = dir.path() / "a-file";
    std::ofstream(blocker) << "x";
    const auto inside = blocker / "out";
    const ChildResult r =
        run_rodsea({"run", config.string(), "--out", inside.string()}, dir.path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.err.find(inside.string()), std::string::npos) << r.err;

    const auto missing = dir.path() / "missing.toml";
    const ChildResult m = run_rodsea({"info", missing.string()}, dir.path());
    EXPECT_NE(m.exit_code, 0);
    EXPECT_NE(m.err.find(missing.string()), std::string::npos) << m.err;

    const ChildResult c = run_rodsea({"run", "--resume", dir.path().string()}, dir.path());
    EXPECT_NE(c.exit_code, 0);
    EXPECT_NE(c.err.find("checkpoint"), std::string::npos) << c.err;

    const ChildResult u = run_rodsea({"run", config.string(), "--outt", "x"}, dir.path());
    EXPECT_EQ(u.exit_code, kExitBadInput);
    EXPECT_NE(u.err.find("--outt"), std::string::npos) << u.err;
}

TEST(RunWorkflow, BadConfigStopsBeforeAnyOutput) {
    const ScratchDir dir("run-badconfig");
    const auto config = write_config(dir, small_config(0.002, 0.001) + "[drive]\ngama = 7\n");
    const auto out = dir.path() / "out";
    const ChildResult r = run_rodsea({"run", config.string(), "--out", out.string()}, dir.path());
    EXPECT_EQ(r.exit_code, kExitBadInput);
    EXPECT_NE(r.err.find("drive.gama"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("gamma"), std::string::npos) << r.err;  // did you mean
    EXPECT_FALSE(std::filesystem::exists(out));
}

// Batch jobs get a line every 5 %: 0.01 s of 8000 steps logs at 5, 10, ..., 100 %. The loop
// steps in runs of at most 1 % of the steps, so each threshold prints once, near its step.
TEST(RunProgress, LogLinesEveryFivePercentAndNothingWhenQuiet) {
    const ScratchDir dir("run-progress");
    const RunPlan plan = load_config_string(small_config(0.01, 0.005), "test");
    RunOptions options;
    options.out_dir = dir.path() / "log";
    std::ostringstream out, err;
    ASSERT_EQ(start_run(plan, options, out, err, false), kExitOk) << err.str();
    std::istringstream lines(out.str());
    int progress_lines = 0;
    for (std::string l; std::getline(lines, l);)
        if (l.rfind("rodsea: ", 0) == 0 && l.find("%  t = ") != std::string::npos) ++progress_lines;
    EXPECT_GE(progress_lines, 18);  // 19 thresholds below 100 %, one may share a run
    EXPECT_LE(progress_lines, 20);  // plus the final line
    EXPECT_EQ(out.str().find('\r'), std::string::npos);

    options.out_dir = dir.path() / "bar";
    std::ostringstream bar;
    ASSERT_EQ(start_run(plan, options, bar, err, true), kExitOk);
    EXPECT_NE(bar.str().find("\r["), std::string::npos);
    EXPECT_NE(bar.str().find("steps/s  P = "), std::string::npos);

    options.out_dir = dir.path() / "quiet";
    options.quiet = true;
    std::ostringstream quiet;
    ASSERT_EQ(start_run(plan, options, quiet, err, true), kExitOk);
    EXPECT_EQ(quiet.str(), "");
}

// `rodsea info` for the paper's largest system: Table S1's counts, A = Γg/Ω² = 43.486 µm, the
// step count of one simulated second, the frame size (13 float32 per body), and every CHOICE.
TEST(RunInfo, ReportsTheLargestSystemOfThePaper) {
    const ScratchDir dir("run-info");
    const auto config = std::filesystem::path(RODSEA_SOURCE_DIR) / "examples" / "largest.toml";
    const ChildResult r = run_rodsea({"info", config.string()}, dir.path());
    ASSERT_EQ(r.exit_code, kExitOk) << r.err;
    for (const char* expected :
         {" 101070 ", " 800 ", "101870 bodies, 111470 spheres", "A = 43.486 um", "800000 steps",
          "5.3 MB", "packing  feasible", "backend  cpu, 1 thread (run.threads)"})
        EXPECT_NE(r.out.find(expected), std::string::npos) << expected << " in\n" << r.out;
    for (const std::string& choice : load_config_file(config).choices)
        EXPECT_NE(r.out.find(choice), std::string::npos) << choice;
}

// --threads takes the range run.threads takes, on every command: a run started on more threads
// than its stored config allows would then be refused by everything that reads it.
TEST(RunThreads, EveryThreadsFlagTakesTheConfigsRange) {
    const ScratchDir dir("run-threads");
    const auto config = write_config(dir, small_config(0.01, 0.002));
    const auto run = dir.path() / "run";
    const ChildResult started =
        run_rodsea({"run", config.string(), "--out", run.string(), "--threads", "300"}, dir.path());
    EXPECT_EQ(started.exit_code, kExitBadInput);
    EXPECT_NE(started.err.find("--threads = '300'"), std::string::npos) << started.err;
    EXPECT_NE(started.err.find("256"), std::string::npos) << started.err;
    EXPECT_FALSE(std::filesystem::exists(run));
    ASSERT_EQ(run_rodsea({"run", config.string(), "--out", run.string(), "--quiet"}, dir.path())
                  .exit_code,
              kExitOk);
    const std::string checkpoint = read_text(run / kCheckpointFile);
    const ChildResult resumed = run_rodsea(
        {"run", "--resume", run.string(), "--duration", "0.02", "--threads", "257"}, dir.path());
    EXPECT_EQ(resumed.exit_code, kExitBadInput);
    EXPECT_NE(resumed.err.find("--threads = '257'"), std::string::npos) << resumed.err;
    EXPECT_EQ(read_text(run / kCheckpointFile), checkpoint);
}

// A run resumes on the backend --backend names, for that session; the stored config keeps what
// the run started with. Where no GPU can run, asking for one is refused before any work, naming
// the key or flag and saying why, and leaves every file as it was.
TEST(RunBackend, ResumesOnTheBackendAskedForAndRefusesAnUnusableGpu) {
    const ScratchDir dir("run-backend");
    const auto config = write_config(dir, small_config(0.01, 0.002));
    const auto run = dir.path() / "run";
    ASSERT_EQ(run_rodsea({"run", config.string(), "--out", run.string(), "--quiet"}, dir.path())
                  .exit_code,
              kExitOk);
    const std::string config_text = read_text(run / kConfigFile);
    EXPECT_EQ(load_config_string(config_text, "c").control.backend, BackendKind::cpu);
    const ChildResult cpu = run_rodsea(
        {"run", "--resume", run.string(), "--duration", "0.02", "--backend", "cpu"}, dir.path());
    ASSERT_EQ(cpu.exit_code, kExitOk) << cpu.err;
    EXPECT_EQ(cpu.out.find("for this session"), std::string::npos) << cpu.out;  // no change

    const ChildResult bad =
        run_rodsea({"run", "--resume", run.string(), "--backend", "tpu"}, dir.path());
    EXPECT_EQ(bad.exit_code, kExitBadInput);
    EXPECT_NE(bad.err.find("--backend = tpu: allowed cpu or gpu"), std::string::npos) << bad.err;

    const GpuAvailability gpu = gpu_availability();
    if (gpu.usable) GTEST_SKIP() << "a GPU is usable here: " << gpu.description;
    const std::string checkpoint = read_text(run / kCheckpointFile);
    const ChildResult resumed = run_rodsea(
        {"run", "--resume", run.string(), "--duration", "0.03", "--backend", "gpu"}, dir.path());
    EXPECT_EQ(resumed.exit_code, kExitBadInput);
    EXPECT_NE(resumed.err.find("invalid --backend = gpu"), std::string::npos) << resumed.err;
    EXPECT_NE(resumed.err.find(gpu.description), std::string::npos) << resumed.err;
    EXPECT_EQ(read_text(run / kCheckpointFile), checkpoint);
    const auto fresh = dir.path() / "fresh";
    const ChildResult started = run_rodsea(
        {"run", config.string(), "--out", fresh.string(), "--backend", "gpu"}, dir.path());
    EXPECT_EQ(started.exit_code, kExitBadInput);
    EXPECT_NE(started.err.find("invalid run.backend = gpu"), std::string::npos) << started.err;
    EXPECT_FALSE(std::filesystem::exists(fresh));
    const ChildResult info = run_rodsea({"info", config.string()}, dir.path());
    ASSERT_EQ(info.exit_code, kExitOk);
    EXPECT_NE(info.out.find("backend  cpu"), std::string::npos) << info.out;
}

}  // namespace
}  // namespace rodsea
