// `rodsea movie`: the MP4 holds exactly the frames asked for, in a format browsers play
// (H.264, yuv420p), as ffprobe reads it; without a working ffmpeg nothing is left behind.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "child_process.hpp"
#include "constructed_run.hpp"
#include "rodsea/config/config_file.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

// Writes an executable shell script standing in for ffmpeg.
fs::path fake_ffmpeg(const fs::path& path, const std::string& body) {
    std::ofstream(path) << "#!/bin/sh\n" << body;
    fs::permissions(path, fs::perms::owner_all);
    return path;
}

class MovieCli : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("movie");
        // Seven frames of two rods turning and drifting, 0.01 s apart.
        const RunPlan plan = load_config_string(
            "[box]\nside = 16.0\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\n"
            "count = 2\n",
            "test");
        std::vector<BodyState> frames;
        for (int k = 0; k < 7; ++k) {
            BodyState f;
            add_flat_body(f, plan, 0, 4.0 + 0.5 * k, 8.0, 0.3 * k);
            add_flat_body(f, plan, 0, 12.0, 4.0 + 0.5 * k, -0.2 * k);
            frames.push_back(f);
        }
        write_constructed_run(run(), plan, frames, 0.01);
        // The same rods written every 0.02 s (frames 0, 2, 4, 6), and a run that stops at 0.03 s.
        write_constructed_run(path("every_other"), plan,
                              {frames[0], frames[2], frames[4], frames[6]}, 0.02);
        write_constructed_run(path("short"), plan, {frames[0], frames[1], frames[2], frames[3]},
                              0.01);
    }
    static void TearDownTestSuite() { delete scratch_; }
    static fs::path run() { return scratch_->path() / "run"; }
    static fs::path path(const std::string& name) { return scratch_->path() / name; }

    // Entries of the scratch directory besides the run, the children's captured output and
    // `keep`: what a command left behind.
    static std::vector<std::string> leftovers(const std::string& keep = "") {
        std::vector<std::string> found;
        for (const auto& e : fs::directory_iterator(scratch_->path())) {
            const std::string name = e.path().filename().string();
            if (name != "run" && name != "every_other" && name != "short" && name != keep &&
                name.rfind("child.", 0) != 0 && name != "fake-ffmpeg")
                found.push_back(name);
        }
        return found;
    }
    static ScratchDir* scratch_;
};
ScratchDir* MovieCli::scratch_ = nullptr;

TEST_F(MovieCli, HoldsEveryRequestedFrameAsBrowserReadyH264) {
    const fs::path mp4 = path("every2.mp4");
    // Frames 0, 2, 4, 6 of the seven: four video frames.
    const ChildResult r = run_rodsea({"movie", run().string(), "-o", mp4.string(), "--every", "2",
                                      "--size", "320", "--fps", "10"},
                                     scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("4 frames"), std::string::npos) << r.out;  // the plan says so first
    const std::string probe = shell_output(
        "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
        "stream=codec_name,pix_fmt,width,height,nb_read_frames,avg_frame_rate -of "
        "default=noprint_wrappers=1 '" +
        mp4.string() + "'");
    EXPECT_NE(probe.find("codec_name=h264"), std::string::npos) << probe;
    EXPECT_NE(probe.find("pix_fmt=yuv420p"), std::string::npos) << probe;
    EXPECT_NE(probe.find("width=320"), std::string::npos) << probe;
    // The 320 px view plus the annotation strips above and below it, in all an even height.
    const std::size_t at = probe.find("height=");
    ASSERT_NE(at, std::string::npos) << probe;
    const int height = std::stoi(probe.substr(at + 7));
    EXPECT_GT(height, 320);
    EXPECT_EQ(height % 2, 0);
    EXPECT_NE(probe.find("avg_frame_rate=10/1"), std::string::npos) << probe;
    EXPECT_NE(probe.find("nb_read_frames=4"), std::string::npos) << probe;
    EXPECT_TRUE(leftovers("every2.mp4").empty());
    fs::remove(mp4);
}

TEST_F(MovieCli, SeveralRunsSideBySideShowTheSameTimeInEveryPanel) {
    const fs::path mp4 = path("grid.mp4");
    const auto probe = [&](const std::string& entries) {
        return shell_output(
            "ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=" +
            entries + " -of csv=p=0 '" + mp4.string() + "'");
    };
    // Two panels of 160 px side by side, over the 0 … 0.03 s that both runs have: 4 frames.
    ChildResult r = run_rodsea({"movie", run().string(), path("short").string(), "-o", mp4.string(),
                                "--size", "160", "--labels", "φ_a = 0.05,short"},
                               scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("4 frames (t = 0 to 0.03 s"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("2 × 1 panels"), std::string::npos) << r.out;
    const std::string size = probe("width,height,nb_read_frames");
    EXPECT_EQ(size.substr(0, 4), "320,") << size;
    EXPECT_EQ(std::stoi(size.substr(4)) % 2, 0) << size;
    EXPECT_NE(size.find(",4\n"), std::string::npos) << size;
    fs::remove(mp4);

    // Frames every 0.01 s against frames every 0.02 s are not in step; with --every 2 they are.
    r = run_rodsea({"movie", run().string(), path("every_other").string(), "-o", mp4.string(),
                    "--size", "160", "--quiet"},
                   scratch_->path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("no frame at t = 0.01 s"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(mp4));
    r = run_rodsea({"movie", run().string(), path("every_other").string(), "-o", mp4.string(),
                    "--size", "160", "--every", "2", "--columns", "1", "--quiet"},
                   scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::string stacked = probe("width,nb_read_frames");
    EXPECT_EQ(stacked, "160,4\n") << stacked;
    fs::remove(mp4);

    // Refused before anything is drawn: a label missing, no -o for several runs, a grid option
    // for one run.
    for (const std::vector<std::string>& bad :
         {std::vector<std::string>{"movie", run().string(), path("short").string(), "-o",
                                   mp4.string(), "--labels", "one"},
          std::vector<std::string>{"movie", run().string(), path("short").string()},
          std::vector<std::string>{"movie", run().string(), "-o", mp4.string(), "--columns",
                                   "1"}}) {
        r = run_rodsea(bad, scratch_->path());
        EXPECT_EQ(r.exit_code, 2) << r.err;
        EXPECT_FALSE(fs::exists(mp4));
    }
    EXPECT_TRUE(leftovers().empty());
}

TEST_F(MovieCli, TimeWindowSelectsItsFrames) {
    const fs::path mp4 = path("window.mp4");
    // t = 0.02 … 0.05 s: frames 2, 3, 4, 5.
    const ChildResult r = run_rodsea({"movie", run().string(), "-o", mp4.string(), "--from", "0.02",
                                      "--to", "0.05", "--size", "160", "--quiet"},
                                     scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(shell_output("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
                           "stream=nb_read_frames -of csv=p=0 '" +
                           mp4.string() + "'"),
              "4\n");
    fs::remove(mp4);
}

TEST_F(MovieCli, MissingOrFailingFfmpegLeavesNoFile) {
    const fs::path mp4 = path("none.mp4");
    {
        const ScopedEnv env("RODSEA_FFMPEG", (scratch_->path() / "no-ffmpeg").string());
        const ChildResult r =
            run_rodsea({"movie", run().string(), "-o", mp4.string()}, scratch_->path());
        EXPECT_NE(r.exit_code, 0);
        EXPECT_NE(r.err.find("RODSEA_FFMPEG=" + (scratch_->path() / "no-ffmpeg").string()),
                  std::string::npos)
            << r.err;
    }
    {
        // No ffmpeg anywhere on PATH (rodsea itself is started by its full path).
        const ScopedEnv env("PATH", (scratch_->path() / "empty-bin").string());
        const ChildResult r =
            run_rodsea({"movie", run().string(), "-o", mp4.string()}, scratch_->path());
        EXPECT_NE(r.exit_code, 0);
        EXPECT_NE(r.err.find("ffmpeg not found on PATH"), std::string::npos) << r.err;
        EXPECT_NE(r.err.find("install-deps"), std::string::npos) << r.err;
    }
    {
        // An "ffmpeg" that reads a little and dies: the failure is reported with its message,
        // and neither the partial movie nor the log is left.
        const ScopedEnv env(
            "RODSEA_FFMPEG",
            fake_ffmpeg(path("fake-ffmpeg"),
                        "head -c 1000 > /dev/null\necho 'encoder exploded' >&2\nexit 3\n")
                .string());
        const ChildResult r =
            run_rodsea({"movie", run().string(), "-o", mp4.string(), "--quiet"}, scratch_->path());
        EXPECT_EQ(r.exit_code, 74) << r.err;
        EXPECT_NE(r.err.find("encoder exploded"), std::string::npos) << r.err;
    }
    EXPECT_FALSE(fs::exists(mp4));
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

TEST_F(MovieCli, FfmpegFailingAfterTheLastFrameLeavesNoFile) {
    // Reads every frame, then fails while "finishing" the file: the error comes from the wait
    // for ffmpeg, not from a broken pipe.
    const ScopedEnv env("RODSEA_FFMPEG",
                        fake_ffmpeg(path("fake-ffmpeg"),
                                    "cat > /dev/null\necho 'moov atom not written' >&2\nexit 5\n")
                            .string());
    const fs::path mp4 = path("late.mp4");
    const ChildResult r =
        run_rodsea({"movie", run().string(), "-o", mp4.string(), "--quiet"}, scratch_->path());
    EXPECT_EQ(r.exit_code, 74) << r.err;
    EXPECT_NE(r.err.find("exit status 5"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("moov atom not written"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(mp4.string() + ":"), std::string::npos) << "names the user's file";
    EXPECT_FALSE(fs::exists(mp4));
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

TEST_F(MovieCli, CtrlCStopsCleanlyAndLeavesNoFile) {
    // An ffmpeg that is slow to start reading: rodsea is blocked writing the first frame (a
    // 2.5 MB frame does not fit the pipe) when Ctrl-C arrives.
    const fs::path started = path("ffmpeg-started");
    const ScopedEnv env("RODSEA_FFMPEG", fake_ffmpeg(path("fake-ffmpeg"),
                                                     "touch '" + started.string() +
                                                         "'\nsleep 2\ncat > /dev/null\nexit 0\n")
                                             .string());
    const fs::path mp4 = path("stopped.mp4");
    ChildOptions options;
    options.interrupt_when = [&] { return fs::exists(started); };
    const ChildResult r = run_rodsea({"movie", run().string(), "-o", mp4.string(), "--quiet"},
                                     scratch_->path(), options);
    ASSERT_TRUE(r.interrupted);
    fs::remove(started);  // the test's own marker
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_FALSE(fs::exists(mp4));
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

TEST_F(MovieCli, BadInputIsRefusedBeforeAnyFrameIsDrawn) {
    const std::string mp4 = path("bad.mp4").string();
    struct Case {
        std::vector<std::string> args;
        int exit_code;
        std::string message;
    };
    const std::vector<Case> cases{
        {{"--size", "321"}, 2, "even"},
        {{"--fps", "0"}, 2, "--fps"},
        {{"--every", "0"}, 2, "--every"},
        {{"--from", "0.5"}, 2, "--from"},
        {{"--from", "0.04", "--to", "0.02"}, 2, "--to"},
        {{"--colour", "sepia"}, 2, "direction, flock or uniform"},
        {{"--crf", "99"}, 2, "--crf"},
    };
    for (const Case& c : cases) {
        std::vector<std::string> args{"movie", run().string(), "-o", mp4};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const ChildResult r = run_rodsea(args, scratch_->path());
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args[0] << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    const ChildResult r =
        run_rodsea({"movie", run().string(), "-o", (path("missing-dir") / "m.mp4").string()},
                   scratch_->path());
    EXPECT_EQ(r.exit_code, 74);
    EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
    EXPECT_TRUE(leftovers().empty()) << leftovers().front();
}

}  // namespace
}  // namespace rodsea
