// What rodsea guarantees against bad files, impossible states and faults (docs/running.md, "What
// rodsea guarantees"), one class of failure at a time: each test feeds the bad file, state or
// fault, and checks the exit code, that the message names what is wrong, and that nothing was
// written or changed.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>

#include "child_process.hpp"
#include "hdf5_poke.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/cli/free_cores.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/simulation.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/progress_file.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_driver.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

// 4 polar rods among apolar rods in a 20 mm box: ~50 bodies, a run of 0.01 s in a fraction of a
// second.
std::string small_config(double duration, double interval, int seed = 11) {
    std::ostringstream s;
    s << "[box]\nside = 20.0\n"
      << "[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 4\n"
      << "[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
      << "area_fraction = 0.15\n"
      << "[time]\nduration = " << duration << "\n[output]\ninterval = " << interval << "\n"
      << "[run]\nseed = " << seed << "\n";
    return s.str();
}

fs::path make_run(const fs::path& dir, double duration = 0.01, double interval = 0.002,
                  int seed = 11) {
    const RunPlan plan = load_config_string(small_config(duration, interval, seed), "test");
    RunOptions options;
    options.out_dir = dir;
    options.quiet = true;
    std::ostringstream out, err;
    if (start_run(plan, options, out, err) != kExitOk)
        throw std::runtime_error("test run failed: " + err.str());
    return dir;
}

// Every file of a directory, by name, with its bytes: "nothing changed" is this map unchanged.
std::map<std::string, std::string> snapshot(const fs::path& dir) {
    std::map<std::string, std::string> files;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_regular_file()) files[e.path().filename().string()] = read_text(e.path());
    return files;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// --- 1. Values read from files -------------------------------------------------------------

struct Corruption {
    const char* dataset;
    std::uint64_t index;
    float value;
    const char* expected;  // a part of the message
};

TEST(FileValues, TrajectoryCorruptionsAreRefusedByEveryReaderNamingDatasetFrameAndValue) {
    const ScratchDir dir("reliability-frames");
    const fs::path good = make_run(dir.path() / "good");
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    // Frame 1 of ~50 bodies: element 3 × N + 3 b + k of position is body b's component k.
    const std::uint64_t n = TrajectoryReader(good / kTrajectoryFile).frame(0).size();
    const std::vector<Corruption> cases = {
        {"/particles/bodies/position/value", 3 * n + 6, nan, "position"},
        {"/particles/bodies/position/value", 3 * n + 7, 1e30f, "position"},
        {"/particles/bodies/velocity/value", 3 * n + 3, inf, "velocity"},
        {"/particles/bodies/angular_velocity/value", 3 * n + 5, -inf, "angular_velocity"},
    };
    for (const Corruption& c : cases) {
        const fs::path bad = dir.path() / "bad";
        fs::remove_all(bad);
        fs::copy(good, bad);
        poke_hdf5((bad / kTrajectoryFile).string(), c.dataset, c.index, c.value);
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"analyze", bad.string(), "--quiet"},
              std::vector<std::string>{"render", bad.string(), "--frame", "1", "-o",
                                       (dir.path() / "f.png").string()},
              std::vector<std::string>{"export", bad.string(), "--format", "xyz", "-o",
                                       (dir.path() / "e.xyz").string(), "--quiet"}}) {
            const ChildResult r = run_rodsea(command, dir.path());
            EXPECT_EQ(r.exit_code, 74) << command[0] << ": " << r.err;
            EXPECT_TRUE(contains(r.err, c.expected)) << r.err;
            EXPECT_TRUE(contains(r.err, "frame 1")) << r.err;
            EXPECT_TRUE(contains(r.err, "trajectory.h5")) << r.err;
        }
        EXPECT_FALSE(fs::exists(bad / "analysis"));
        EXPECT_FALSE(fs::exists(dir.path() / "f.png"));
        EXPECT_FALSE(fs::exists(dir.path() / "e.xyz"));
    }
    // A zero quaternion, a species index out of range either way, a time that is not a number.
    const auto refused = [&](const char* dataset, std::uint64_t index, auto value,
                             const char* expected) {
        const fs::path bad = dir.path() / "bad";
        fs::remove_all(bad);
        fs::copy(good, bad);
        if (std::string(dataset).find("orientation") != std::string::npos) {
            for (std::uint64_t k = 0; k < 4; ++k)
                poke_hdf5((bad / kTrajectoryFile).string(), dataset, index + k, value);
        } else {
            poke_hdf5((bad / kTrajectoryFile).string(), dataset, index, value);
        }
        const ChildResult r = run_rodsea({"analyze", bad.string(), "--quiet"}, dir.path());
        EXPECT_EQ(r.exit_code, 74) << r.err;
        EXPECT_TRUE(contains(r.err, expected)) << r.err;
    };
    refused("/particles/bodies/orientation/value", 4 * n + 8, 0.0f, "orientation");
    refused("/particles/bodies/species", 3, std::int32_t{-1}, "-1");
    refused("/particles/bodies/species", 3, std::int32_t{99}, "99");
    refused("/particles/bodies/position/time", 2, std::numeric_limits<double>::quiet_NaN(),
            "position/time, frame 2");
    refused("/observables/polar_order_polar/value", 2, std::numeric_limits<double>::infinity(),
            "polar_order_polar");
    // A column analyze does not itself use is checked as well: no reader takes a file with an
    // impossible value in it.
    refused("/observables/kinetic_energy_translational_polar/value", 3,
            std::numeric_limits<double>::quiet_NaN(), "kinetic_energy_translational_polar");
    refused("/observables/body_collision_rate/value", 1, -3.0, "body_collision_rate");
    // A species index flipped to another species in range: the counts no longer match the
    // config's.
    refused("/particles/bodies/species", 0, std::int32_t{1}, "species holds 3 bodies of species 0");
}

// --resume --duration would extend a file with an impossible series value; a checkpoint whose
// species were edited would simulate a polar rod as an apolar one. Both are refused, nothing
// changes.
TEST(ResumeChecks, StoredSeriesAndSpeciesAreCheckedBeforeARunGoesOn) {
    const ScratchDir dir("reliability-series");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002);
    const auto refused = [&](const std::function<void()>& damage, const std::string& expected) {
        const fs::path b = dir.path() / "b";
        fs::remove_all(b);
        fs::copy(a, b);
        damage();
        const auto before = snapshot(b);
        const ChildResult r =
            run_rodsea({"run", "--resume", b.string(), "--duration", "0.02"}, dir.path());
        EXPECT_EQ(r.exit_code, 74) << expected << ": " << r.err;
        EXPECT_TRUE(contains(r.err, expected)) << r.err;
        EXPECT_EQ(snapshot(b), before);
    };
    const std::string b = (dir.path() / "b").string();
    refused(
        [&] {
            poke_hdf5(b + "/trajectory.h5",
                      "/observables/kinetic_energy_translational_medium/value", 2,
                      std::numeric_limits<double>::quiet_NaN());
        },
        "kinetic_energy_translational_medium/value, frame 2");
    refused(
        [&] { poke_hdf5(b + "/checkpoint.h5", "/rodsea_checkpoint/species", 1, std::int32_t{1}); },
        "damaged: dataset species holds 3 bodies of species 0");
    // Two bodies' species swapped: the counts hold, the trajectory's species do not.
    refused(
        [&] {
            const Checkpoint c = read_checkpoint(a / kCheckpointFile);
            const std::size_t medium = c.bodies.size() - 1;
            poke_hdf5(b + "/checkpoint.h5", "/rodsea_checkpoint/species", 0, std::int32_t{1});
            poke_hdf5(b + "/checkpoint.h5", "/rodsea_checkpoint/species", medium, std::int32_t{0});
        },
        "holds other bodies (/particles/bodies/species) than the checkpoint");
}

// A byte flipped on disk in a frame (the value is still a plausible float) fails the chunk's
// Fletcher-32 checksum instead of being read as data.
TEST(FileValues, AFlippedByteInAFrameFailsItsChecksum) {
    const ScratchDir dir("reliability-flip");
    const fs::path run = make_run(dir.path() / "r");
    const std::string file = (run / kTrajectoryFile).string();
    const std::uint64_t at = hdf5_chunk_offset(file, "/particles/bodies/position/value", 2) + 17;
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(static_cast<std::streamoff>(at));
        char byte = 0;
        f.get(byte);
        f.seekp(static_cast<std::streamoff>(at));
        f.put(static_cast<char>(byte ^ 0x04));
    }
    const ChildResult r = run_rodsea({"analyze", run.string(), "--quiet"}, dir.path());
    EXPECT_EQ(r.exit_code, 74) << r.err;
    EXPECT_TRUE(contains(r.err, "checksum")) << r.err;
    EXPECT_FALSE(fs::exists(run / "analysis"));
}

TEST(FileValues, CalibrationTablesAreReadStrictly) {
    const ScratchDir dir("reliability-calibration");
    const std::string header = "species,gap,dt,epsilon,D_r\npolar_rod,1.4,1.25e-06,0,0.001\n";
    const auto refused = [&](const std::string& table_text, const std::string& expected) {
        const fs::path table = dir.path() / "table.csv";
        std::ofstream(table) << table_text;
        std::ofstream(dir.path() / "run.toml")
            << small_config(0.01, 0.002)
            << "[noise]\nrotational_diffusion = 0.01\ncalibration_table = \"table.csv\"\n";
        const ChildResult r = run_rodsea({"info", (dir.path() / "run.toml").string()}, dir.path());
        EXPECT_NE(r.exit_code, 0);
        EXPECT_TRUE(contains(r.err, expected)) << r.err;
    };
    refused(header + "polar_rod,1.4,1.25e-06,0.01,nan\n", "column D_r: 'nan'");
    refused(header + "polar_rod,1.4,1.25e-06,7,0.5\n", "column epsilon: '7'");
    refused(header + "polar_rod,1.4,1.25e-06,0.01,0.5x\n", "'0.5x'");
    fs::remove(dir.path() / "table.csv");
    fs::create_directory(dir.path() / "table.csv");
    std::ofstream(dir.path() / "run.toml")
        << small_config(0.01, 0.002)
        << "[noise]\nrotational_diffusion = 0.01\ncalibration_table = \"table.csv\"\n";
    const ChildResult r = run_rodsea({"info", (dir.path() / "run.toml").string()}, dir.path());
    EXPECT_EQ(r.exit_code, 74) << r.err;
    EXPECT_TRUE(contains(r.err, "is a directory")) << r.err;
}

// campaign status reads each run's progress.txt: a damaged one says nothing, not NaN percent.
TEST(FileValues, ADamagedProgressFileIsIgnored) {
    const ScratchDir dir("reliability-progress");
    const fs::path run = make_run(dir.path() / "r");
    const std::string good = read_text(run / "progress.txt");
    ASSERT_TRUE(read_progress_file(run));
    for (const auto& [from, to] : {std::pair<std::string, std::string>{"time = ", "time = nan"},
                                   {"wall_seconds = ", "wall_seconds = -5"},
                                   {"step = ", "step = 99999999999"}}) {
        std::string bad = good;
        const std::size_t at = bad.find(from);
        ASSERT_NE(at, std::string::npos);
        bad.replace(at, bad.find('\n', at) - at, to);
        std::ofstream(run / "progress.txt") << bad;
        EXPECT_FALSE(read_progress_file(run)) << to;
    }
}

// --- 2. Resume checks what it resumes ------------------------------------------------------

int resume(const fs::path& dir, std::string& err) {
    RunOptions options;
    options.quiet = true;
    std::ostringstream out, errors;
    try {
        const int code = resume_run(dir, options, out, errors);
        err = errors.str();
        return code;
    } catch (const FileError& e) {
        err = e.what();
        return kExitIoError;
    } catch (const InvalidParameter& e) {
        err = e.what();
        return kExitBadInput;
    }
}

TEST(ResumeChecks, AnotherRunsCheckpointIsRefusedAndNothingChanges) {
    const ScratchDir dir("reliability-foreign");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002, 11);
    const fs::path b = make_run(dir.path() / "b", 0.01, 0.002, 12);
    // b's checkpoint, made resumable, copied into a.
    Checkpoint c = read_checkpoint(b / kCheckpointFile);
    c.complete = false;
    write_checkpoint(a / kCheckpointFile, c);
    const auto before = snapshot(a);
    std::string err;
    EXPECT_EQ(resume(a, err), kExitIoError);
    EXPECT_TRUE(contains(err, "belongs to another run")) << err;
    EXPECT_EQ(snapshot(a), before);
}

TEST(ResumeChecks, ACheckpointWhoseConfigWasEditedIsRefusedNamingTheLine) {
    const ScratchDir dir("reliability-edited");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002);
    Checkpoint c = read_checkpoint(a / kCheckpointFile);
    c.complete = false;
    const std::size_t at = c.config_toml.find("duration = 0.01");
    ASSERT_NE(at, std::string::npos) << c.config_toml;
    c.config_toml.replace(at, 15, "duration = 0.05");
    write_checkpoint(a / kCheckpointFile, c);
    const auto before = snapshot(a);
    std::string err;
    EXPECT_EQ(resume(a, err), kExitIoError);
    EXPECT_TRUE(contains(err, "duration = 0.01")) << err;
    EXPECT_TRUE(contains(err, "duration = 0.05")) << err;
    EXPECT_EQ(snapshot(a), before);
}

TEST(ResumeChecks, ImpossibleStatesAreRefused) {
    const ScratchDir dir("reliability-impossible");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002);
    const Checkpoint original = read_checkpoint(a / kCheckpointFile);
    const auto refused = [&](const std::function<void(Checkpoint&)>& edit,
                             const std::string& expected) {
        Checkpoint c = original;
        c.complete = false;
        edit(c);
        write_checkpoint(a / kCheckpointFile, c);
        const auto before = snapshot(a);
        std::string err;
        EXPECT_EQ(resume(a, err), kExitIoError) << expected;
        EXPECT_TRUE(contains(err, expected)) << err;
        EXPECT_EQ(snapshot(a), before);
    };
    refused([](Checkpoint& c) { c.bodies.position[3].z += 5.0; }, "position.z");  // above the lid
    refused([](Checkpoint& c) { c.bodies.position[4] = c.bodies.position[5]; },
            "impossible state");  // two bodies on top of each other
    refused([](Checkpoint& c) { c.bodies.velocity[2].x = 1e9; }, "velocity");
    refused([](Checkpoint& c) { c.bodies.orientation[1] = {0.5, 0.0, 0.0, 0.0}; }, "orientation");
    refused([](Checkpoint& c) { c.frames_written += 3; }, "frames");
}

TEST(ResumeChecks, AnExtensionInterruptedBeforeItsFilesSaidSoIsFinished) {
    const ScratchDir dir("reliability-extension");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002);
    // The state an extension to 0.02 s leaves after its checkpoint and before config.toml and
    // the trajectory's stored config are rewritten.
    Checkpoint c = read_checkpoint(a / kCheckpointFile);
    const std::string old_config = c.config_toml;
    c.extending_from = config_fingerprint(old_config);
    c.config_toml.replace(c.config_toml.find("duration = 0.01"), 15, "duration = 0.02");
    c.complete = false;
    write_checkpoint(a / kCheckpointFile, c);
    std::string err;
    ASSERT_EQ(resume(a, err), kExitOk) << err;
    EXPECT_TRUE(contains(read_text(a / kConfigFile), "duration = 0.02"));
    EXPECT_TRUE(read_checkpoint(a / kCheckpointFile).complete);
    EXPECT_NEAR(TrajectoryReader(a / kTrajectoryFile).times().back(), 0.02, 1e-12);
}

// --- 3. A simulation that blows up ---------------------------------------------------------

TEST(BlowUp, ARunWhoseNoiseSpinsTheRodsUpStopsWithTheLastGoodFrame) {
    const ScratchDir dir("reliability-blowup");
    RunPlan plan = load_config_string(small_config(0.05, 0.002), "test");
    plan.engine.noise_epsilon = 10.0;  // beyond the config's range: the engine's guard decides
    RunOptions options;
    options.out_dir = dir.path() / "r";
    options.quiet = true;  // the message comes all the same
    std::ostringstream out, err;
    ASSERT_EQ(start_run(plan, options, out, err), kExitBlownUp) << err.str();
    EXPECT_TRUE(contains(err.str(), "blew up")) << err.str();
    EXPECT_TRUE(contains(err.str(), "time.dt")) << err.str();
    const Checkpoint c = read_checkpoint(options.out_dir / kCheckpointFile);
    const TrajectoryReader frames(options.out_dir / kTrajectoryFile);
    // The checkpoint is the last frame's state, which passed every check.
    EXPECT_EQ(c.frames_written, frames.frames());
    EXPECT_EQ(static_cast<std::int64_t>(c.step), frames.steps().back());
    EXPECT_FALSE(find_state_problem(
        plan.engine, c.bodies, static_cast<double>(c.step) * plan.engine.dt, StateOrigin::resumed));
    EXPECT_TRUE(contains(read_text(options.out_dir / "progress.txt"), "state = blown_up"));
}

TEST(BlowUp, EpsilonBeyondItsRangeIsRefusedBeforeAnyWork) {
    EXPECT_THROW(load_config_string(small_config(0.01, 0.002) + "[noise]\nepsilon = 10\n", "t"),
                 InvalidParameter);
}

// Two beads put 150 % of a radius into each other: the step counts them unresolved (it used to
// report 0) and the guard names the overlap.
TEST(BlowUp, GrossOverlapsCountAsUnresolvedAndStopTheStep) {
    EngineParameters p;
    p.box = {10.0, 10.0};
    p.species = {bead_species()};
    const double r = p.species[0].shape.radii[0], z = p.drive.amplitude() + r + 0.1;
    BodyState bodies;
    bodies.add(0, {5.0, 5.0, z}, {1, 0, 0, 0});
    bodies.add(0, {5.0 + 0.5 * r, 5.0, z}, {1, 0, 0, 0});
    Simulation quiet_sim(p, bodies, {.threads = 1, .stop_on_blow_up = false});
    quiet_sim.step();
    EXPECT_GE(quiet_sim.last_step().unresolved, 1u);
    EXPECT_NEAR(quiet_sim.last_step().max_overlap_fraction, 1.5, 0.01);
    Simulation guarded(p, bodies);
    try {
        guarded.step();
        ADD_FAILURE() << "a 150 % overlap passed the guard";
    } catch (const BlowUpError& e) {
        EXPECT_EQ(e.blow_up().what, "the largest overlap");
        EXPECT_EQ(e.step(), 1u);
    }
}

// --- 4. Whatever run accepts, the other commands accept ------------------------------------

TEST(OffGridEnd, EveryCommandAcceptsADurationOffTheOutputGrid) {
    const ScratchDir dir("reliability-offgrid");
    for (const auto& [duration, interval] : {std::pair{0.021, 0.002}, std::pair{0.02, 0.003}}) {
        const fs::path run = dir.path() / ("r" + std::to_string(interval));
        make_run(run, duration, interval);
        const PreparedRun p = prepare_run(run, {});
        // The frames on the grid: floor(duration / interval) + 1; the last one is left out.
        EXPECT_EQ(p.times.size(), static_cast<std::size_t>(duration / interval) + 1);
        EXPECT_TRUE(contains(p.skipped.back(), "off the")) << p.skipped.back();
        for (const std::vector<std::string>& command :
             {std::vector<std::string>{"analyze", run.string(), "--quiet"},
              std::vector<std::string>{"render", run.string(), "-o", (run / "last.png").string()},
              std::vector<std::string>{"export", run.string(), "--format", "xyz", "-o",
                                       (run / "all.xyz").string(), "--quiet"},
              std::vector<std::string>{"movie", run.string(), "-o", (run / "m.mp4").string(),
                                       "--quiet"},
              std::vector<std::string>{"plot", run.string(), "-o", (run / "plots").string(),
                                       "--quiet"}}) {
            const ChildResult r = run_rodsea(command, dir.path());
            EXPECT_EQ(r.exit_code, 0) << command[0] << ": " << r.err;
        }
    }
}

// --- 5. Sizes ------------------------------------------------------------------------------

TEST(Sizes, CountsMemoryBinsAndNamesBeyondTheirLimitsAreRefusedByName) {
    const auto refused = [](const std::string& config, const std::string& key) {
        try {
            load_config_string(config, "test");
            ADD_FAILURE() << "accepted " << key;
        } catch (const InvalidParameter& e) {
            EXPECT_TRUE(contains(e.what(), key)) << e.what();
        }
    };
    std::string huge = small_config(0.01, 0.002);
    huge.replace(huge.find("side = 20.0"), 11, "side = 1e5");
    refused(huge, "species[1].area_fraction");
    std::string tiny = small_config(0.01, 0.002);
    tiny.replace(tiny.find("side = 20.0"), 11, "side = 1e-300");
    refused(tiny, "box.side");
    std::string named = small_config(0.01, 0.002);
    named.replace(named.find("\"polar\""), 7, "\"" + std::string(65, 'p') + "\"");
    refused(named, "species[0].name");

    const ScratchDir dir("reliability-sizes");
    const fs::path run = make_run(dir.path() / "r");
    AnalyzeRequest request;
    request.options.corotating_r_bins = 10000;
    request.options.corotating_theta_bins = 10000;
    try {
        prepare_run(run, request);
        ADD_FAILURE() << "10^8 bins accepted";
    } catch (const InvalidParameter& e) {
        EXPECT_TRUE(contains(e.what(), "corotating.theta_bins")) << e.what();
    }
}

// A kill -9 between writing checkpoint.h5.tmp.<pid> and renaming it leaves the temporary: the
// resume that follows removes it (its writer is gone), and leaves a live process's alone.
TEST(ResumeChecks, AResumeRemovesTheTemporaryAKilledWriterLeft) {
    const ScratchDir dir("reliability-temporary");
    const fs::path a = make_run(dir.path() / "a", 0.01, 0.002);
    const pid_t gone = fork();  // a process that has exited and been reaped: its pid is free
    if (gone == 0) _exit(0);
    ASSERT_GT(gone, 0);
    waitpid(gone, nullptr, 0);
    const fs::path stale = a / ("checkpoint.h5.tmp." + std::to_string(gone));
    const fs::path live = a / ("checkpoint.h5.tmp." + std::to_string(getpid()));
    std::ofstream(stale) << "half a checkpoint";
    std::ofstream(live) << "another process's";
    std::string err;
    ASSERT_EQ(resume(a, err), kExitOk) << err;
    EXPECT_FALSE(fs::exists(stale));
    EXPECT_TRUE(fs::exists(live));
}

TEST(Sizes, ASystemBeyondTheMachinesMemoryIsRefusedBeforeAnyFileIsWritten) {
    const ScratchDir dir("reliability-memory");
    // 8.8×10^7 medium rods (under the 10^8 cap) need ~355 GB: more than any machine this runs
    // on has free.
    std::ostringstream config;
    config << "[box]\nside = 20000.0\n[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\n"
           << "length = 2.5\narea_fraction = 0.3\n[time]\nduration = 0.01\n"
           << "[output]\ninterval = 0.01\n";
    std::ofstream(dir.path() / "big.toml") << config.str();
    const ChildResult r = run_rodsea(
        {"run", (dir.path() / "big.toml").string(), "--out", (dir.path() / "out").string()},
        dir.path());
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.err;
    EXPECT_TRUE(contains(r.err, "available")) << r.err;
    EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

// --- 6. A full disk ------------------------------------------------------------------------

// A real full file system: a 900 kB tmpfs in a private mount namespace (unshare, no root
// needed where user namespaces are allowed). The run must stop with a checkpoint at the step
// where it stopped, not an older one, and resume to the uninterrupted run's end.
TEST(FullDisk, TheRunCheckpointsTheStepWhereTheDiskFilled) {
    const ScratchDir dir("reliability-disk");
    if (std::system("unshare -r -m true > /dev/null 2>&1") != 0)
        GTEST_SKIP() << "no user namespaces here (unshare -r -m): cannot mount a small tmpfs";
    std::ofstream(dir.path() / "run.toml") << small_config(0.5, 0.002);
    const fs::path mount = dir.path() / "disk", log = dir.path() / "log";
    fs::create_directory(mount);
    const std::string script = "mount -t tmpfs -o size=900k tmpfs " + mount.string() + " && " +
                               RODSEA_EXECUTABLE + " run " + (dir.path() / "run.toml").string() +
                               " --out " + (mount / "r").string() + " --quiet 2> " + log.string() +
                               "; echo $? > " + (dir.path() / "code").string() + "; cp " +
                               (mount / "r" / kCheckpointFile).string() + " " + dir.path().string();
    ASSERT_EQ(std::system(("unshare -r -m sh -c '" + script + "'").c_str()), 0);
    const std::string err = read_text(log);
    EXPECT_EQ(read_text(dir.path() / "code"), "74\n") << err;
    EXPECT_TRUE(contains(err, "checkpoint written")) << err;
    EXPECT_FALSE(contains(err, "18446744073709551615")) << err;
    const std::size_t at = err.find("at step ");
    ASSERT_NE(at, std::string::npos) << err;
    const std::uint64_t stopped = std::stoull(err.substr(at + 8));
    EXPECT_EQ(read_checkpoint(dir.path() / kCheckpointFile).step, stopped);
}

// --- 7. Messages ---------------------------------------------------------------------------

TEST(Messages, ADirectoryWithoutACheckpointIsNotOfferedResume) {
    const ScratchDir dir("reliability-nocheckpoint");
    const fs::path run = make_run(dir.path() / "r");
    fs::remove(run / kCheckpointFile);  // killed before its first checkpoint
    std::ofstream(dir.path() / "run.toml") << small_config(0.01, 0.002);
    const ChildResult again =
        run_rodsea({"run", (dir.path() / "run.toml").string(), "--out", run.string()}, dir.path());
    EXPECT_EQ(again.exit_code, kExitBadInput);
    EXPECT_TRUE(contains(again.err, "--overwrite")) << again.err;
    EXPECT_FALSE(contains(again.err, "--resume")) << again.err;
    const ChildResult resumed = run_rodsea({"run", "--resume", run.string()}, dir.path());
    EXPECT_EQ(resumed.exit_code, 74);
    EXPECT_TRUE(contains(resumed.err, "--overwrite")) << resumed.err;
}

TEST(Messages, OverwriteRemovesTheOldAnalysis) {
    const ScratchDir dir("reliability-overwrite");
    const fs::path run = make_run(dir.path() / "r");
    ASSERT_EQ(run_rodsea({"analyze", run.string(), "--quiet"}, dir.path()).exit_code, 0);
    ASSERT_TRUE(fs::exists(run / "analysis"));
    std::ofstream(dir.path() / "run.toml") << small_config(0.01, 0.002, 99);
    ASSERT_EQ(run_rodsea({"run", (dir.path() / "run.toml").string(), "--out", run.string(),
                          "--overwrite", "--quiet"},
                         dir.path())
                  .exit_code,
              0);
    EXPECT_FALSE(fs::exists(run / "analysis"));
}

TEST(Messages, SighupStopsARunWithACheckpointLikeSigterm) {
    const ScratchDir dir("reliability-sighup");
    std::ofstream(dir.path() / "run.toml") << small_config(5.0, 0.01);
    const fs::path run = dir.path() / "r";
    ChildOptions options;
    options.interrupt_signal = SIGHUP;
    options.interrupt_when = [&] { return fs::exists(run / "progress.txt"); };
    const ChildResult r =
        run_rodsea({"run", (dir.path() / "run.toml").string(), "--out", run.string(), "--quiet"},
                   dir.path(), options);
    ASSERT_TRUE(r.interrupted);
    EXPECT_EQ(r.exit_code, 143) << r.err;
    EXPECT_TRUE(contains(r.err, "SIGHUP")) << r.err;
    EXPECT_FALSE(read_checkpoint(run / kCheckpointFile).complete);
}

TEST(Messages, PlotSaysWhenItsPythonFails) {
    const ScratchDir dir("reliability-plot");
    const fs::path run = make_run(dir.path() / "r");
    ASSERT_EQ(run_rodsea({"analyze", run.string(), "--quiet"}, dir.path()).exit_code, 0);
    const ScopedEnv python("RODSEA_PYTHON", "/bin/false");
    const ChildResult r =
        run_rodsea({"plot", run.string(), "-o", (dir.path() / "plots").string()}, dir.path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_TRUE(contains(r.err, "failed (exit code 1)")) << r.err;
}

TEST(Messages, RefusalsNameTheRightThing) {
    const ScratchDir dir("reliability-refusals");
    // An unknown key without a guess: no empty "did you mean".
    std::ofstream(dir.path() / "u.toml") << "[box]\nzzzzqqq = 3\n";
    const ChildResult unknown = run_rodsea({"info", (dir.path() / "u.toml").string()}, dir.path());
    EXPECT_EQ(unknown.exit_code, kExitBadInput);
    EXPECT_FALSE(contains(unknown.err, "; ;")) << unknown.err;
    EXPECT_FALSE(contains(unknown.err, "( ;")) << unknown.err;
    // A huge mean-field parameter is named, not reported as an unstable --dt.
    const ChildResult huge = run_rodsea({"meanfield", "--a", "1e300"}, dir.path());
    EXPECT_EQ(huge.exit_code, kExitBadInput);
    EXPECT_TRUE(contains(huge.err, "--a")) << huge.err;
    EXPECT_FALSE(contains(huge.err, "--dt")) << huge.err;
    // 3000 species of one bead each in a 200 mm box: sparse, so feasible.
    std::ostringstream many;
    many << "[box]\nside = 200.0\n";
    for (int i = 0; i < 3000; ++i)
        many << "[[species]]\nname = \"b" << i << "\"\nkind = \"bead\"\ncount = 1\n";
    many << "[time]\nduration = 0.001\n[output]\ninterval = 0.001\n";
    std::ofstream(dir.path() / "many.toml") << many.str();
    const ChildResult info = run_rodsea({"info", (dir.path() / "many.toml").string()}, dir.path());
    EXPECT_EQ(info.exit_code, 0) << info.err;
    EXPECT_TRUE(contains(info.out, "packing  feasible")) << info.out.substr(0, 2000);
}

// The first Ctrl-C stops calibrate within a drive period of every running copy, not after it.
TEST(Messages, CalibrateStopsWithinSecondsOfCtrlC) {
    const ScratchDir dir("reliability-calibrate-stop");
    std::ofstream(dir.path() / "grid.toml")
        << "[calibrate]\nspecies = \"polar_rod\"\nepsilon = [0.0]\ncopies = 2\n"
           "duration = 1000.0\nwarmup = 0.0\n";  // an hour per copy
    ChildOptions options;
    const auto start = std::chrono::steady_clock::now();
    options.interrupt_when = [&] {
        return std::chrono::steady_clock::now() - start > std::chrono::milliseconds(500);
    };
    options.timeout_seconds = 30.0;
    const ChildResult r = run_rodsea({"calibrate", (dir.path() / "grid.toml").string(), "--out",
                                      (dir.path() / "out").string(), "--quiet"},
                                     dir.path(), options);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    ASSERT_TRUE(r.interrupted);
    EXPECT_EQ(r.exit_code, 130) << r.err;
    EXPECT_LT(seconds, 10.0);  // a drive period is 5 ms of simulated time, ~0.1 s of wall time
}

// --- 8. Threads beyond free cores ----------------------------------------------------------

TEST(FreeCores, ThreadsFollowTheFreeCoresAndNeverDropBelowOne) {
    EXPECT_EQ(threads_for_free_cores(2, 2.0), 2);
    EXPECT_EQ(threads_for_free_cores(2, 1.6), 1);  // a core shared with another process is taken
    EXPECT_EQ(threads_for_free_cores(4, 2.9), 3);
    EXPECT_EQ(threads_for_free_cores(2, 0.0), 1);
    EXPECT_EQ(threads_for_free_cores(1, 8.0), 1);
    FreeCoreMonitor monitor;
    std::this_thread::sleep_for(std::chrono::milliseconds(120));
    const double free = monitor.sample();
    EXPECT_GE(free, 0.0);
    EXPECT_LE(free, monitor.usable());
}

}  // namespace
}  // namespace rodsea
