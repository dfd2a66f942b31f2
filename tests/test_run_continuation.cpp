// rodsea run --continue: a run continued from its checkpoint alone, in a new directory, is the
// same run: its frames, series rows and end state are those of the run that was never stopped,
// bit for bit, from the checkpoint on; it resumes and continues again like any run; and every
// refusal comes before anything is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <optional>
#include <sstream>

#include "child_process.hpp"
#include "hdf5_poke.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/run/run_continuation.hpp"
#include "run_comparison.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

int continue_quietly(const std::filesystem::path& checkpoint, const std::filesystem::path& out,
                     std::optional<double> duration = std::nullopt,
                     std::optional<long long> steady_samples = std::nullopt,
                     bool overwrite = false) {
    RunOptions options;
    options.out_dir = out;
    options.overwrite = overwrite;
    options.quiet = true;
    options.duration = duration;
    options.steady_samples = steady_samples;
    std::ostringstream log, err;
    return continue_run(checkpoint, options, log, err);
}

// `part` holds the frames of `whole` (the same config and seed, never stopped) from its
// trajectory's first_frame on, and ends where it ends: the same steps, states and series rows,
// bit for bit. It keeps the id of the run it continues, `run_id`.
void expect_continuation_of(const std::filesystem::path& part, const std::filesystem::path& whole,
                            std::uint64_t first_frame, const std::string& run_id) {
    const Checkpoint end_part = read_checkpoint(part / kCheckpointFile);
    const Checkpoint end_whole = read_checkpoint(whole / kCheckpointFile);
    EXPECT_TRUE(end_part.complete);
    EXPECT_EQ(end_part.step, end_whole.step);
    EXPECT_EQ(end_part.frames_written, end_whole.frames_written);
    EXPECT_TRUE(same_bits(end_part.bodies, end_whole.bodies));
    EXPECT_EQ(end_part.interval_accumulators, end_whole.interval_accumulators);
    EXPECT_EQ(end_part.config_toml, end_whole.config_toml);
    EXPECT_EQ(read_text(part / kConfigFile), read_text(whole / kConfigFile));

    EXPECT_EQ(read_first_frame(part / kTrajectoryFile), first_frame);
    EXPECT_EQ(read_run_id(part / kTrajectoryFile), run_id);
    EXPECT_EQ(end_part.run_id, run_id);
    const TrajectoryReader tp(part / kTrajectoryFile), tw(whole / kTrajectoryFile);
    ASSERT_EQ(tp.frames() + first_frame, tw.frames());
    for (std::uint64_t f = 0; f < tp.frames(); ++f) {
        EXPECT_EQ(tp.steps()[f], tw.steps()[first_frame + f]) << "frame " << f;
        EXPECT_EQ(tp.times()[f], tw.times()[first_frame + f]) << "frame " << f;
        EXPECT_TRUE(same_bits(tp.frame(f), tw.frame(first_frame + f))) << "frame " << f;
    }
    for (const char* column : {"polar_order_polar", "nematic_order_medium", "segregation",
                               "largest_flock", "max_overlap_fraction", "impulses_per_step"}) {
        const std::vector<double> p = tp.series(column), w = tw.series(column);
        ASSERT_EQ(p.size() + first_frame, w.size()) << column;
        EXPECT_TRUE(std::equal(p.begin(), p.end(), w.begin() + static_cast<long>(first_frame)))
            << column;
    }
    EXPECT_EQ(line_count(part / kSeriesFile) + first_frame, line_count(whole / kSeriesFile));
    // Analysis reads it as any run: its frames, at their own times.
    EXPECT_EQ(open_stored_run(part).frames(), tp.frames());
}

// The run's first directory is gone but for its checkpoint; extended from there to 0.04 s in a
// new directory, it is the 0.04 s run from the checkpoint on. Ending on the output grid (0.02 s)
// and off it (0.021 s, whose extra last frame the longer run does not have): either way the
// continuation's first frame is the run's frame 0.02 s / 2 ms + 1 = 11.
TEST(RunContinuation, AFinishedRunContinuedElsewhereIsTheLongerRunBitForBit) {
    const ScratchDir dir("run-continue");
    const auto longer = dir.path() / "longer";
    ASSERT_EQ(run_quietly(small_config(0.04, 0.002), longer), kExitOk);
    for (const double first : {0.02, 0.021}) {
        SCOPED_TRACE("first part to " + std::to_string(first) + " s");
        const std::string name = std::to_string(first);
        const auto first_dir = dir.path() / ("first-" + name),
                   kept = dir.path() / ("kept-" + name + ".h5"),
                   continued = dir.path() / ("continued-" + name);
        ASSERT_EQ(run_quietly(small_config(first, 0.002), first_dir), kExitOk);
        std::filesystem::copy_file(first_dir / kCheckpointFile, kept);
        std::filesystem::remove_all(first_dir);
        ASSERT_EQ(continue_quietly(kept, continued, 0.04), kExitOk);
        expect_continuation_of(continued, longer, 11, read_checkpoint(kept).run_id);
    }
}

// From the command line: a continuation interrupted mid-way resumes in its directory, and its
// mid-run checkpoint continues again elsewhere; both end as the run that never stopped.
TEST(RunContinuation, AnInterruptedContinuationResumesAndContinuesAgain) {
    const ScratchDir dir("run-continue-cli");
    const auto straight = dir.path() / "straight", first = dir.path() / "first",
               continued = dir.path() / "continued", again = dir.path() / "again";
    ASSERT_EQ(run_quietly(small_config(0.12, 0.004), straight), kExitOk);
    ASSERT_EQ(run_quietly(small_config(0.02, 0.004), first), kExitOk);
    // 0.02 s / 4 ms + 1 frames before the continuation's first.
    const std::uint64_t first_frame = 6;

    const ChildResult missing_out =
        run_rodsea({"run", "--continue", (first / kCheckpointFile).string()}, dir.path());
    EXPECT_EQ(missing_out.exit_code, kExitBadInput);
    EXPECT_NE(missing_out.err.find("--out"), std::string::npos) << missing_out.err;

    ChildOptions interrupt;
    interrupt.interrupt_when = [&] {
        return std::filesystem::exists(continued / kSeriesFile) &&
               line_count(continued / kSeriesFile) >= 2 + 5;
    };
    const ChildResult stopped = run_rodsea(
        {"run", "--continue", first.string(), "--out", continued.string(), "--duration", "0.12"},
        dir.path(), interrupt);
    ASSERT_TRUE(stopped.interrupted);
    ASSERT_EQ(stopped.exit_code, kExitInterrupted) << stopped.err;
    EXPECT_NE(stopped.out.find("from frame 6"), std::string::npos) << stopped.out;
    const Checkpoint mid = read_checkpoint(continued / kCheckpointFile);
    ASSERT_FALSE(mid.complete) << "the continuation finished before SIGINT arrived";

    const ChildResult elsewhere =
        run_rodsea({"run", "--continue", (continued / kCheckpointFile).string(), "--out",
                    again.string(), "--quiet"},
                   dir.path());
    ASSERT_EQ(elsewhere.exit_code, kExitOk) << elsewhere.err;
    const ChildResult resumed =
        run_rodsea({"run", "--resume", continued.string(), "--quiet"}, dir.path());
    ASSERT_EQ(resumed.exit_code, kExitOk) << resumed.err;

    const std::string run_id = read_run_id(first / kTrajectoryFile);
    expect_continuation_of(continued, straight, first_frame, run_id);
    expect_continuation_of(again, straight, mid.frames_written, run_id);
}

// A run's first directory and its continuation, read together, are the run that never stopped:
// every frame once, in order (the first directory's off-grid last frame, which the longer run
// does not have, left out), and analysed as one they give its numbers to the last bit. Parts
// with frames missing between them, or given twice, are refused; other runs are not joined.
TEST(RunContinuation, ARunAndItsContinuationReadAndAnalyseAsTheWholeRun) {
    const ScratchDir dir("run-continue-join");
    const auto straight = dir.path() / "straight", first = dir.path() / "first",
               continued = dir.path() / "continued", later = dir.path() / "later";
    ASSERT_EQ(run_quietly(small_config(0.06, 0.004), straight), kExitOk);
    ASSERT_EQ(run_quietly(small_config(0.021, 0.004), first), kExitOk);
    ASSERT_EQ(continue_quietly(first, continued, 0.06), kExitOk);
    ASSERT_EQ(continue_quietly(continued, later, 0.08), kExitOk);

    const StoredRun whole = open_stored_run(straight);
    const StoredRun joined = open_stored_run(std::vector<std::filesystem::path>{continued, first});
    EXPECT_EQ(joined.run_dir, continued);
    ASSERT_EQ(joined.parts.size(), 2u);
    EXPECT_EQ(joined.parts.front(), first / kTrajectoryFile);
    ASSERT_EQ(joined.frames(), whole.frames());  // 0.06 s / 4 ms + 1
    EXPECT_EQ(joined.reader.steps(), whole.reader.steps());
    EXPECT_EQ(joined.times(), whole.times());
    for (std::size_t f = 0; f < whole.frames(); ++f)
        EXPECT_TRUE(same_bits(joined.frame(f), whole.frame(f))) << "frame " << f;
    EXPECT_EQ(joined.reader.series("polar_order_polar"), whole.reader.series("polar_order_polar"));

    AnalyzeRequest request;
    request.observables = {"order"};
    request.from = 0.02;
    std::ostringstream log;
    const RunAnalysis a = analyze_run(
        prepare_run(std::vector<std::filesystem::path>{first, continued}, request), log, true);
    const RunAnalysis b = analyze_run(prepare_run(straight, request), log, true);
    ASSERT_EQ(a.results.size(), b.results.size());
    ASSERT_FALSE(a.results[0].scalars.empty());
    for (std::size_t k = 0; k < a.results[0].scalars.size(); ++k) {
        EXPECT_EQ(a.results[0].scalars[k].estimate.mean, b.results[0].scalars[k].estimate.mean);
        EXPECT_EQ(a.results[0].scalars[k].estimate.error, b.results[0].scalars[k].estimate.error);
    }

    const auto groups = group_run_parts({first, straight, continued, later});
    ASSERT_EQ(groups.size(), 2u);
    EXPECT_EQ(groups[0], (std::vector<std::filesystem::path>{first, continued, later}));
    EXPECT_EQ(groups[1], (std::vector<std::filesystem::path>{straight}));
    // A directory of the run given twice (as a copy would be) is read apart, not joined.
    EXPECT_EQ(group_run_parts({first, continued, continued}).size(), 2u);
    EXPECT_THROW(open_stored_run(std::vector<std::filesystem::path>{first, later}), FileError);
    EXPECT_THROW(open_stored_run(std::vector<std::filesystem::path>{first, continued, continued}),
                 FileError);
    EXPECT_THROW(open_stored_run(std::vector<std::filesystem::path>{first, straight}), FileError);
    EXPECT_EQ(open_stored_run(std::vector<std::filesystem::path>{first, continued, later}).frames(),
              21u);  // 0.08 s / 4 ms + 1
}

// A damaged frame of a run read with its continuation is named in the file that holds it, by
// that file's own index, whichever part it is in: the file to repair or discard.
TEST(RunContinuation, ADamagedFrameOfAJoinedRunIsNamedInItsOwnFile) {
    const ScratchDir dir("run-continue-damaged");
    const auto first = dir.path() / "first", continued = dir.path() / "continued";
    ASSERT_EQ(run_quietly(small_config(0.02, 0.004), first), kExitOk);
    ASSERT_EQ(continue_quietly(first, continued, 0.04), kExitOk);
    const std::uint64_t offset = read_first_frame(continued / kTrajectoryFile);
    const std::uint64_t values_per_frame =
        3 * TrajectoryReader(first / kTrajectoryFile).frame(0).size();
    poke_hdf5((first / kTrajectoryFile).string(), "/particles/bodies/position/value",
              2 * values_per_frame, std::numeric_limits<float>::quiet_NaN());
    poke_hdf5((continued / kTrajectoryFile).string(), "/particles/bodies/position/value",
              values_per_frame, std::numeric_limits<float>::quiet_NaN());

    const StoredRun run = open_stored_run(std::vector<std::filesystem::path>{first, continued});
    const auto message_of = [&run](std::size_t frame) {
        try {
            (void)run.frame(frame);
        } catch (const FileError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string in_first = message_of(2), in_continued = message_of(offset + 1);
    EXPECT_NE(in_first.find((first / kTrajectoryFile).string()), std::string::npos) << in_first;
    EXPECT_NE(in_first.find("position/value, frame 2 (t = "), std::string::npos) << in_first;
    EXPECT_NE(in_continued.find((continued / kTrajectoryFile).string()), std::string::npos)
        << in_continued;
    EXPECT_NE(in_continued.find("position/value, frame 1 (the run's frame " +
                                std::to_string(offset + 1) + ", t = "),
              std::string::npos)
        << in_continued;
    EXPECT_NO_THROW((void)run.frame(offset));  // the frames around them read as they were
}

// Refused before anything is written: a complete run without a longer --duration, a stop when
// steady (it judges the whole series, which stays behind), the checkpoint's own directory, an
// occupied one or one where a run is going as --out, no checkpoint.
TEST(RunContinuation, RefusalsComeBeforeAnyFileIsWritten) {
    const ScratchDir dir("run-continue-bad");
    const auto first = dir.path() / "first", out = dir.path() / "out";
    ASSERT_EQ(run_quietly(small_config(0.01, 0.002), first), kExitOk);
    const auto checkpoint = first / kCheckpointFile;
    const std::string before = read_text(checkpoint);

    const auto refused_as = [&](const std::string& key, const auto& attempt) {
        try {
            attempt();
            ADD_FAILURE() << "continued; expected a refusal naming " << key;
        } catch (const InvalidParameter& e) {
            EXPECT_EQ(e.name(), key) << e.what();
        }
    };
    refused_as("--continue", [&] { continue_quietly(checkpoint, out); });
    EXPECT_FALSE(std::filesystem::exists(out));
    refused_as("time.steady_samples", [&] { continue_quietly(checkpoint, out, 0.02, 100); });
    EXPECT_FALSE(std::filesystem::exists(out));
    refused_as("--duration", [&] { continue_quietly(checkpoint, out, 0.005); });
    EXPECT_FALSE(std::filesystem::exists(out));

    // Into its own directory, even with --overwrite, it would delete the frames it continues.
    refused_as("--out", [&] { continue_quietly(checkpoint, first, 0.02, std::nullopt, true); });
    EXPECT_EQ(TrajectoryReader(first / kTrajectoryFile).frames(), 6u);  // 0.01 s / 2 ms + 1

    // --overwrite of a directory where a run is still going: refused by its lock, before any of
    // its files is removed.
    const auto busy = dir.path() / "busy";
    ASSERT_EQ(run_quietly(small_config(0.01, 0.002), busy), kExitOk);
    {
        const RunDirectoryLock running(busy);
        EXPECT_THROW(continue_quietly(checkpoint, busy, 0.02, std::nullopt, true),
                     InvalidParameter);
    }
    EXPECT_EQ(TrajectoryReader(busy / kTrajectoryFile).frames(), 6u);
    EXPECT_TRUE(std::filesystem::exists(busy / kCheckpointFile));

    std::filesystem::create_directories(out);
    std::ofstream(out / "notes.txt") << "mine\n";
    refused_as("--out", [&] { continue_quietly(checkpoint, out, 0.02); });
    EXPECT_EQ(read_text(out / "notes.txt"), "mine\n");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(out), {}), 1);

    EXPECT_THROW(continue_quietly(dir.path() / "nowhere.h5", dir.path() / "other", 0.02),
                 FileError);
    EXPECT_FALSE(std::filesystem::exists(dir.path() / "other"));
    EXPECT_EQ(read_text(checkpoint), before);
}

}  // namespace
}  // namespace rodsea
