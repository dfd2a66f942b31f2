// `rodsea run A.toml B.toml ...`: several runs stepped as one ensemble. Each directory must hold
// exactly the run it holds when run alone (the ensemble adds no physics and no coupling), runs
// of different lengths leave the ensemble without disturbing the others, resumes go alone or
// together, and one bad input starts none of them.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "each_backend.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/run/run_driver.hpp"
#include "run_comparison.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

// A few polar rods in a sparse or a denser medium of a 20 mm box: unlike systems, each a
// fraction of a second of wall time per 0.01 s simulated.
std::string member_config(double medium_fraction, int seed, double duration,
                          const std::string& extra = "") {
    std::ostringstream s;
    s << "[box]\nside = 20.0\n"
      << "[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 4\n"
      << "[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
      << "area_fraction = " << medium_fraction << "\n"
      << "[noise]\nepsilon = 0.02\n"
      << "[time]\nduration = " << duration << "\n"
      << "[output]\ninterval = 0.002\n"
      << "[run]\nseed = " << seed << "\n"
      << extra;
    return s.str();
}

RunOptions quiet_options() {
    RunOptions options;
    options.quiet = true;
    return options;
}

RunPlan on_backend(const std::string& config, BackendKind backend) {
    RunPlan plan = load_config_string(config, "test");
    plan.control.backend = backend;
    return plan;
}

class RunEnsemble : public testing::EachBackend {};

// Three unlike runs: a sparse one, a denser one with two threads, and a short one that ends off
// the output grid (0.013 s with frames every 2 ms) and leaves first. Each directory equals the
// same config run alone on the same backend, bit for bit, frame for frame.
TEST_P(RunEnsemble, EachRunIsTheRunItIsAlone) {
    const ScratchDir dir("run-ensemble");
    const std::vector<std::string> configs = {member_config(0.15, 11, 0.03),
                                              member_config(0.35, 12, 0.02, "threads = 2\n"),
                                              member_config(0.10, 13, 0.013)};
    std::vector<NewRun> together;
    for (std::size_t r = 0; r < configs.size(); ++r)
        together.push_back(
            {on_backend(configs[r], GetParam()), dir.path() / "together" / std::to_string(r)});
    std::ostringstream out, err;
    ASSERT_EQ(start_runs(together, quiet_options(), out, err), kExitOk) << err.str();
    for (std::size_t r = 0; r < configs.size(); ++r) {
        RunOptions alone = quiet_options();
        alone.out_dir = dir.path() / "alone" / std::to_string(r);
        ASSERT_EQ(start_run(on_backend(configs[r], GetParam()), alone, out, err), kExitOk)
            << err.str();
        SCOPED_TRACE("run " + std::to_string(r));
        expect_same_run(together[r].dir, alone.out_dir);
    }
}

// Two finished runs extended together (--resume A B --duration T) are the runs given that
// duration from the start; a third, already at T, is left alone and said so.
TEST_P(RunEnsemble, RunsExtendedTogetherAreTheLongerRuns) {
    const ScratchDir dir("run-ensemble-extend");
    const auto a = dir.path() / "a", b = dir.path() / "b", done = dir.path() / "done";
    std::ostringstream out, err;
    const auto start = [&](const std::string& config, const std::filesystem::path& to) {
        RunOptions options = quiet_options();
        options.out_dir = to;
        return start_run(on_backend(config, GetParam()), options, out, err);
    };
    ASSERT_EQ(start(member_config(0.15, 21, 0.01), a), kExitOk) << err.str();
    ASSERT_EQ(start(member_config(0.30, 22, 0.013), b), kExitOk) << err.str();
    ASSERT_EQ(start(member_config(0.20, 23, 0.024), done), kExitOk) << err.str();
    RunOptions extend;
    extend.duration = 0.024;
    std::ostringstream said;
    ASSERT_EQ(resume_runs({a, b, done}, extend, said, err), kExitOk) << err.str();
    EXPECT_NE(said.str().find("already complete"), std::string::npos) << said.str();
    ASSERT_EQ(start(member_config(0.15, 21, 0.024), dir.path() / "a-straight"), kExitOk);
    ASSERT_EQ(start(member_config(0.30, 22, 0.024), dir.path() / "b-straight"), kExitOk);
    expect_same_run(a, dir.path() / "a-straight");
    expect_same_run(b, dir.path() / "b-straight");
}

// A run that blows up stops with its last good frame, as alone; the run beside it goes on to
// its end and is the run it is alone; the exit code is the blow-up's.
TEST_P(RunEnsemble, ABlowUpStopsOnlyItsOwnRun) {
    const ScratchDir dir("run-ensemble-blowup");
    RunPlan wild = on_backend(member_config(0.15, 31, 0.02), GetParam());
    wild.engine.noise_epsilon = 10.0;  // beyond the config's range: the engine's guard decides
    const RunPlan calm = on_backend(member_config(0.25, 32, 0.02), GetParam());
    std::ostringstream out, err;
    const std::vector<NewRun> runs = {{wild, dir.path() / "wild"}, {calm, dir.path() / "calm"}};
    ASSERT_EQ(start_runs(runs, quiet_options(), out, err), kExitBlownUp) << err.str();
    // Among several runs on one stream, the message names its run.
    EXPECT_NE(
        err.str().find("rodsea: " + (dir.path() / "wild").string() + ": the simulation blew up"),
        std::string::npos)
        << err.str();
    EXPECT_FALSE(read_checkpoint(dir.path() / "wild" / kCheckpointFile).complete);
    RunOptions alone = quiet_options();
    alone.out_dir = dir.path() / "calm-alone";
    ASSERT_EQ(start_run(calm, alone, out, err), kExitOk) << err.str();
    expect_same_run(dir.path() / "calm", alone.out_dir);
}

RODSEA_ON_EACH_BACKEND(RunEnsemble);

// Every run is checked before any starts: a packing that cannot fit, two runs into one
// directory, or runs on different backends refuse the whole command, naming the problem, and
// leave no directory behind.
TEST(RunEnsembleInput, OneBadRunStartsNone) {
    const ScratchDir dir("run-ensemble-refused");
    const RunPlan good = load_config_string(member_config(0.15, 41, 0.01), "good");
    RunPlan too_many = good;
    too_many.counts[1] = 5000;  // 5000 apolar rods in 400 mm²: a packing fraction far above 1
    std::ostringstream out, err;
    const auto first = dir.path() / "first", second = dir.path() / "second";
    EXPECT_THROW(start_runs({{good, first}, {too_many, second}}, quiet_options(), out, err),
                 InvalidParameter);
    try {
        start_runs({{good, first}, {good, dir.path() / "." / "first"}}, quiet_options(), out, err);
        ADD_FAILURE() << "one directory for two runs was accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("first"), std::string::npos) << e.what();
    }
    RunPlan elsewhere = good;
    elsewhere.control.backend = BackendKind::gpu_on_host;
    try {
        start_runs({{good, first}, {elsewhere, second}}, quiet_options(), out, err);
        ADD_FAILURE() << "runs on two backends were accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_NE(std::string(e.what()).find("run.backend"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(first));
    EXPECT_FALSE(std::filesystem::exists(second));
}

// The command line: several configs with --out DIR write DIR/<config name> each, and
// --resume with several directories extends them together.
TEST(RunEnsembleCli, SeveralConfigsWriteOneDirectoryEach) {
    const ScratchDir dir("run-ensemble-cli");
    const auto sparse = dir.path() / "sparse.toml", dense = dir.path() / "dense.toml";
    std::ofstream(sparse) << member_config(0.10, 51, 0.006);
    std::ofstream(dense) << member_config(0.30, 52, 0.004);
    // `rodsea info` with both: the ensemble's line per run and its totals, then each plan; the
    // ensemble's bodies are the sum of each plan's.
    const ChildResult info = run_rodsea({"info", sparse.string(), dense.string()}, dir.path());
    ASSERT_EQ(info.exit_code, kExitOk) << info.err;
    const auto bodies_after = [&](const std::string& marker, std::size_t from) {
        const std::size_t at = info.out.find(marker, from);
        EXPECT_NE(at, std::string::npos) << marker << "\n" << info.out;
        return at == std::string::npos ? 0ull : std::stoull(info.out.substr(at + marker.size()));
    };
    const std::size_t sparse_plan = info.out.find("rodsea info " + sparse.string());
    const std::size_t dense_plan = info.out.find("rodsea info " + dense.string());
    ASSERT_NE(sparse_plan, std::string::npos) << info.out;
    ASSERT_NE(dense_plan, std::string::npos) << info.out;
    EXPECT_EQ(bodies_after("total    ", 0), bodies_after("         total ", sparse_plan) +
                                                bodies_after("         total ", dense_plan))
        << info.out;
    EXPECT_NE(info.out.find("out/sparse"), std::string::npos) << info.out;

    const auto out = dir.path() / "out";
    const ChildResult started =
        run_rodsea({"run", sparse.string(), dense.string(), "--out", out.string()}, dir.path());
    ASSERT_EQ(started.exit_code, kExitOk) << started.err;
    EXPECT_NE(started.out.find("2 runs stepped together"), std::string::npos) << started.out;
    for (const char* name : {"sparse", "dense"}) {
        const Checkpoint c = read_checkpoint(out / name / kCheckpointFile);
        EXPECT_TRUE(c.complete) << name;
    }
    EXPECT_EQ(read_checkpoint(out / "dense" / kCheckpointFile).step, 3200u);  // 0.004 s / 1.25 µs
    const ChildResult extended =
        run_rodsea({"run", "--resume", (out / "sparse").string(), (out / "dense").string(),
                    "--duration", "0.008", "--quiet"},
                   dir.path());
    ASSERT_EQ(extended.exit_code, kExitOk) << extended.err;
    for (const char* name : {"sparse", "dense"})
        EXPECT_EQ(read_checkpoint(out / name / kCheckpointFile).step, 6400u) << name;
}

}  // namespace
}  // namespace rodsea
