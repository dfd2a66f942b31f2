// Opening a run and choosing its frames, as every read-side command does: --frame counts from 0
// or from the end, --time takes the nearest frame, --from/--to include the frames at their ends
// (up to rounding), --every counts within the window; damaged frames are refused.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "constructed_run.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/stored_run.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

// Seven frames of one polar rod, 0.01 s apart: t = 0, 0.01, …, 0.06 s.
class FrameSelection : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("stored-run");
        const RunPlan plan = load_config_string(
            "[box]\nside = 10.0\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 1\n"
            "[output]\ninterval = 0.01\n",
            "test");
        std::vector<BodyState> frames(7);
        for (std::size_t k = 0; k < frames.size(); ++k)
            add_flat_body(frames[k], plan, 0, 5.0, 5.0, 0.1 * static_cast<double>(k));
        write_constructed_run(scratch_->path() / "run", plan, frames, 0.01);
        write_constructed_run(scratch_->path() / "one", plan, {frames[0]}, 0.01);
    }
    static void TearDownTestSuite() { delete scratch_; }
    static StoredRun open(const std::string& name) {
        return open_stored_run(scratch_->path() / name);
    }
    static ScratchDir* scratch_;
};
ScratchDir* FrameSelection::scratch_ = nullptr;

TEST_F(FrameSelection, FrameIndexCountsFromEitherEnd) {
    const StoredRun run = open("run");
    EXPECT_EQ(run.frames(), 7u);
    EXPECT_EQ(select_frame(run, std::nullopt, std::nullopt), 6u);  // default: the last
    EXPECT_EQ(select_frame(run, 0, std::nullopt), 0u);
    EXPECT_EQ(select_frame(run, 6, std::nullopt), 6u);
    EXPECT_EQ(select_frame(run, -1, std::nullopt), 6u);
    EXPECT_EQ(select_frame(run, -7, std::nullopt), 0u);
    EXPECT_THROW(select_frame(run, 7, std::nullopt), InvalidParameter);
    EXPECT_THROW(select_frame(run, -8, std::nullopt), InvalidParameter);
    EXPECT_THROW(select_frame(run, 1, 0.01), InvalidParameter);  // not both
}

TEST_F(FrameSelection, TimeTakesTheNearestFrameWithinHalfAnInterval) {
    const StoredRun run = open("run");
    EXPECT_EQ(select_frame(run, std::nullopt, 0.0), 0u);
    EXPECT_EQ(select_frame(run, std::nullopt, 0.031), 3u);
    EXPECT_EQ(select_frame(run, std::nullopt, 0.0249), 2u);
    EXPECT_EQ(select_frame(run, std::nullopt, 0.064), 6u);  // past the end, nearer than 0.005 s
    EXPECT_THROW(select_frame(run, std::nullopt, 0.0651), InvalidParameter);
    EXPECT_THROW(select_frame(run, std::nullopt, -0.0051), InvalidParameter);
}

TEST_F(FrameSelection, WindowIncludesItsEndsAndCountsEveryWithinIt) {
    const StoredRun run = open("run");
    using Frames = std::vector<std::size_t>;
    EXPECT_EQ(select_frame_window(run, std::nullopt, std::nullopt, 1),
              (Frames{0, 1, 2, 3, 4, 5, 6}));
    // Stored times are sums of dt and differ from 0.02 and 0.05 by rounding only.
    EXPECT_EQ(select_frame_window(run, 0.02, 0.05, 1), (Frames{2, 3, 4, 5}));
    EXPECT_EQ(select_frame_window(run, 0.015, 0.049, 1), (Frames{2, 3, 4}));
    // --every starts at the window's first frame, not at frame 0.
    EXPECT_EQ(select_frame_window(run, 0.01, std::nullopt, 2), (Frames{1, 3, 5}));
    EXPECT_EQ(select_frame_window(run, std::nullopt, std::nullopt, 10), (Frames{0}));
    EXPECT_THROW(select_frame_window(run, 0.07, std::nullopt, 1), InvalidParameter);
    EXPECT_THROW(select_frame_window(run, 0.04, 0.02, 1), InvalidParameter);
    EXPECT_THROW(select_frame_window(run, 0.011, 0.019, 1), InvalidParameter);  // no frame in it
    // A --to the run has not reached is refused, as analyze refuses it, not clamped to 0.06 s.
    EXPECT_THROW(select_frame_window(run, std::nullopt, 0.07, 1), InvalidParameter);
}

TEST_F(FrameSelection, SpanIsTheWindowAnalyzeAndExportShare) {
    const StoredRun run = open("run");
    const double interval = run.plan.control.output_interval;
    const FrameSpan all = select_frame_span(run.times(), interval, std::nullopt, std::nullopt);
    EXPECT_EQ(all.first, 0u);
    EXPECT_EQ(all.end, 7u);
    // Both ends included, within rounding of the stored sums of dt.
    const FrameSpan mid = select_frame_span(run.times(), interval, 0.02, 0.05);
    EXPECT_EQ(mid.first, 2u);
    EXPECT_EQ(mid.end, 6u);
    // A continuation's frames start late; a --from before them starts at its first frame.
    const std::vector<double> late{1.0, 1.01, 1.02};
    const FrameSpan cont = select_frame_span(late, 0.01, 0.5, std::nullopt);
    EXPECT_EQ(cont.first, 0u);
    EXPECT_EQ(cont.end, 3u);
    EXPECT_THROW(select_frame_span(late, 0.01, std::nullopt, 0.5), InvalidParameter);
    // Within rounding of an end, a one-sided window still holds that end's frame.
    const FrameSpan first_only = select_frame_span(late, 0.01, std::nullopt, 1.0 - 1e-10);
    EXPECT_EQ(first_only.first, 0u);
    EXPECT_EQ(first_only.end, 1u);
    const FrameSpan last_only = select_frame_span(late, 0.01, 1.02 + 1e-10, std::nullopt);
    EXPECT_EQ(last_only.first, 2u);
    EXPECT_EQ(last_only.end, 3u);
    EXPECT_THROW(select_frame_span(late, 0.01, -0.1, std::nullopt), InvalidParameter);
}

TEST_F(FrameSelection, OneFrameRun) {
    const StoredRun run = open("one");
    EXPECT_EQ(select_frame(run, -1, std::nullopt), 0u);
    EXPECT_EQ(select_frame(run, std::nullopt, 0.0), 0u);
    EXPECT_THROW(select_frame(run, std::nullopt, 0.001), InvalidParameter);
    EXPECT_EQ(select_frame_window(run, std::nullopt, std::nullopt, 3),
              (std::vector<std::size_t>{0}));
}

TEST_F(FrameSelection, FramesThatDisagreeWithTheConfigAreRefused) {
    // A trajectory whose frames hold two bodies under a config for one.
    const RunPlan one = load_config_string(
        "[box]\nside = 10.0\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 1\n",
        "test");
    const RunPlan two = load_config_string(
        "[box]\nside = 10.0\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 2\n",
        "test");
    BodyState bodies;
    add_flat_body(bodies, two, 0, 2.0, 2.0, 0.0);
    add_flat_body(bodies, two, 0, 7.0, 7.0, 0.0);
    RunPlan mismatched = two;
    mismatched.config_toml = one.config_toml;
    write_constructed_run(scratch_->path() / "bad", mismatched, {bodies}, 0.01);
    // Refused as the run is opened, by its species, before any frame is read.
    try {
        open("bad");
        FAIL() << "a trajectory of two bodies opened under a config for one";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find(
                      "species holds 2 bodies of species 0, but the config asks for 1"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace rodsea
