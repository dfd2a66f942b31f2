// The file layer: H5MD trajectory layout (read back by Debian's h5py), bit-exact checkpoints,
// atomic replacement, and the truncation that makes a resumed run neither lose nor duplicate
// frames.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

#include "rodsea/error.hpp"
#include "rodsea/io/atomic_file.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/series_csv.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/random.hpp"
#include "rodsea/scenes/scenes.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

BodyState random_bodies(size_t n, std::uint64_t seed) {
    SplitMix64 rng(seed);
    BodyState b;
    for (size_t i = 0; i < n; ++i) {
        const Quat q = normalized(
            Quat{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)});
        b.add(static_cast<std::uint32_t>(i % 2), {rng.uniform(0, 30), rng.uniform(0, 30), 0.5}, q,
              {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)},
              {rng.uniform(-9, 9), rng.uniform(-9, 9), rng.uniform(-9, 9)});
    }
    return b;
}

EngineParameters two_species() {
    EngineParameters p;
    p.box = {30.0, 30.0};
    p.drive.gap = 1.5;  // mm: the box's z edge in the file
    p.species = {polar_rod_species(), apolar_rod_species(2.5)};
    return p;
}

// Runs a script with Debian's Python (h5py, MDAnalysis) on `file`; returns its exit status and
// everything it printed.
std::pair<int, std::string> run_python(const ScratchDir& dir, const std::string& script,
                                       const std::filesystem::path& file) {
    const auto script_path = dir.path() / "check.py";
    std::ofstream(script_path) << script;
    FILE* pipe = popen(
        ("/usr/bin/python3 " + script_path.string() + " " + file.string() + " 2>&1").c_str(), "r");
    if (pipe == nullptr) return {-1, "popen failed"};
    std::string output;
    char buffer[512];
    while (fgets(buffer, sizeof buffer, pipe))
        output += buffer;
    return {pclose(pipe), output};
}

TEST(Checkpoint, RoundTripIsBitExact) {
    const ScratchDir dir("checkpoint");
    Checkpoint c;
    c.config_toml = "[box]\nside = 30.0\n";
    c.step = 123456789012ULL;
    c.frames_written = 17;
    c.bodies = random_bodies(57, 5);
    c.interval_accumulators = {0.125, 3.0, 7.0, 1e300, 1.0 / 3.0};
    c.wall_seconds = 12.5;
    write_checkpoint(dir.path() / "c.h5", c);
    const Checkpoint r = read_checkpoint(dir.path() / "c.h5");
    EXPECT_EQ(r.config_toml, c.config_toml);
    EXPECT_EQ(r.step, c.step);
    EXPECT_EQ(r.frames_written, c.frames_written);
    EXPECT_FALSE(r.complete);
    EXPECT_EQ(r.interval_accumulators, c.interval_accumulators);
    ASSERT_EQ(r.bodies.size(), c.bodies.size());
    // Bit-exact: a resumed run must continue from exactly these doubles.
    for (size_t i = 0; i < c.bodies.size(); ++i) {
        EXPECT_EQ(r.bodies.species[i], c.bodies.species[i]);
        EXPECT_EQ(std::memcmp(&r.bodies.position[i], &c.bodies.position[i], sizeof(Vec3)), 0);
        EXPECT_EQ(std::memcmp(&r.bodies.orientation[i], &c.bodies.orientation[i], sizeof(Quat)), 0);
        EXPECT_EQ(std::memcmp(&r.bodies.velocity[i], &c.bodies.velocity[i], sizeof(Vec3)), 0);
        EXPECT_EQ(std::memcmp(&r.bodies.spin[i], &c.bodies.spin[i], sizeof(Vec3)), 0);
    }
    EXPECT_TRUE(temporaries_of(dir.path() / "c.h5").empty());
}

TEST(Checkpoint, ForeignOrTruncatedFilesAreRefusedByPath) {
    const ScratchDir dir("checkpoint-bad");
    const auto text = dir.path() / "notes.h5";
    std::ofstream(text) << "not hdf5";
    EXPECT_THROW(read_checkpoint(text), FileError);
    EXPECT_THROW(read_checkpoint(dir.path() / "missing.h5"), FileError);

    Checkpoint c;
    c.bodies = random_bodies(200, 1);
    write_checkpoint(dir.path() / "good.h5", c);
    const std::string bytes = read_text(dir.path() / "good.h5");
    std::ofstream(dir.path() / "cut.h5", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
    try {
        read_checkpoint(dir.path() / "cut.h5");
        FAIL() << "a truncated checkpoint was accepted";
    } catch (const FileError& e) {
        EXPECT_NE(std::string(e.what()).find("cut.h5"), std::string::npos) << e.what();
    }
}

TEST(AtomicFile, AFailedWriteLeavesThePreviousContent) {
    const ScratchDir dir("atomic");
    const auto target = dir.path() / "data.txt";
    write_file_atomically(target, "first\n");
    EXPECT_THROW(replace_file_atomically(target,
                                         [](const std::filesystem::path& tmp) {
                                             std::ofstream(tmp) << "half of the sec";
                                             throw FileError(tmp.string(), "disk full");
                                         }),
                 FileError);
    EXPECT_EQ(read_text(target), "first\n");
    EXPECT_TRUE(temporaries_of(target).empty());
}

TEST(SeriesCsv, ReopenKeepsExactlyTheCheckpointedRows) {
    const ScratchDir dir("csv");
    const auto path = dir.path() / "series.csv";
    const std::vector<SeriesColumn> columns{{"a", "1"}, {"b", "mm"}};
    {
        SeriesCsv csv = SeriesCsv::create(path, columns);
        for (int i = 0; i < 5; ++i)
            csv.append(static_cast<std::uint64_t>(10 * i), 0.5 * i, {1.0 * i, 2.0});
        csv.flush();
    }
    // A crash mid-row leaves a line without its newline: it goes, with every row after row 3.
    std::ofstream(path, std::ios::app) << "50,2.5,5";
    {
        SeriesCsv csv = SeriesCsv::reopen(path, 3);
        csv.append(30, 1.5, {9.0, 9.0});
        csv.flush();
    }
    std::istringstream lines(read_text(path));
    std::vector<std::string> all;
    for (std::string l; std::getline(lines, l);)
        all.push_back(l);
    ASSERT_EQ(all.size(), 2u + 4u);  // comment, header, rows 0..2, the new row
    EXPECT_EQ(all[1], "step,time,a,b");
    EXPECT_EQ(all[4], "20,1,2,2");
    EXPECT_EQ(all[5], "30,1.5,9,9");
    EXPECT_THROW(SeriesCsv::reopen(path, 10), FileError);
}

// Frames 0..4 written, reopened at 3 (the checkpoint's count), two more appended: the file has
// frames 0, 1, 2 and the two new ones, in order, with matching step, time and series rows.
TEST(TrajectoryFile, ReopenDropsFramesAfterTheCheckpoint) {
    const ScratchDir dir("trajectory");
    const auto path = dir.path() / "t.h5";
    const EngineParameters p = two_species();
    const BodyState b = random_bodies(10, 3);
    const std::vector<SeriesColumn> columns{{"polar_order_polar", "1"}};
    {
        TrajectoryFile t = TrajectoryFile::create(path, p, b.species, "[box]\n", columns);
        for (std::uint64_t f = 0; f < 5; ++f)
            t.append_frame(100 * f, 0.1 * static_cast<double>(f), b, {static_cast<double>(f)});
        EXPECT_EQ(t.frames(), 5u);
        t.close();
    }
    {
        TrajectoryFile t = TrajectoryFile::reopen(path, 3, p, columns);
        EXPECT_EQ(t.frames(), 3u);
        t.append_frame(300, 0.3, b, {30.0});
        t.append_frame(400, 0.4, b, {40.0});
        t.close();
    }
    EXPECT_THROW(TrajectoryFile::reopen(path, 9, p, columns), FileError);
    EXPECT_EQ(read_stored_config(path), "[box]\n");

    // Debian's h5py reads the H5MD layout; the script prints what the test compares.
    const std::string script = R"(
import h5py, sys
f = h5py.File(sys.argv[1], "r")
assert list(f["h5md"].attrs["version"]) == [1, 1]
assert f["h5md/creator"].attrs["name"] == "rodsea"  # str: variable-length UTF-8
b = f["particles/bodies"]
for e in ["position", "orientation", "velocity", "angular_velocity"]:
    assert set(b[e].keys()) == {"step", "time", "value"}, e
assert list(b["box"].attrs["boundary"]) == ["periodic", "periodic", "none"]
assert b["box"].attrs["dimension"] == 3
print("steps", *b["position/step"][:])
print("series", *f["observables/polar_order_polar/value"][:])
print("shape", *b["position/value"].shape, *b["orientation/value"].shape)
print("unit", b["position/value"].attrs["unit"], b["velocity/value"].attrs["unit"])
print("edges", *b["box/edges/value"][4], len(b["box/edges/step"]))
print("radii", len(f["parameters/rodsea/species/0/sphere_radii"]), len(f["parameters/rodsea/species/1/sphere_radii"]))
)";
    const auto [status, output] = run_python(dir, script, path);
    ASSERT_EQ(status, 0) << output;
    EXPECT_NE(output.find("steps 0 100 200 300 400\n"), std::string::npos) << output;
    EXPECT_NE(output.find("series 0.0 1.0 2.0 30.0 40.0\n"), std::string::npos) << output;
    EXPECT_NE(output.find("shape 5 10 3 5 10 4\n"), std::string::npos) << output;
    EXPECT_NE(output.find("unit mm mm s-1\n"), std::string::npos) << output;
    EXPECT_NE(output.find("edges 30.0 30.0 1.5 5\n"), std::string::npos) << output;
    EXPECT_NE(output.find("radii 13 9\n"), std::string::npos) << output;
}

// A continuation's file (rodsea run --continue) keeps its run's id and says which of the run's
// frames is its first; reopened, it still says so. A run's first file says 0.
TEST(TrajectoryFile, AContinuationKeepsItsRunIdAndFirstFrame) {
    const ScratchDir dir("trajectory-segment");
    const EngineParameters p = two_species();
    const BodyState b = random_bodies(10, 3);
    const std::vector<SeriesColumn> columns{{"polar_order_polar", "1"}};
    const auto whole = dir.path() / "whole.h5", part = dir.path() / "part.h5";
    std::string id;
    {
        TrajectoryFile t = TrajectoryFile::create(whole, p, b.species, "[box]\n", columns);
        id = t.run_id();
        EXPECT_EQ(t.first_frame(), 0u);
    }
    EXPECT_EQ(read_first_frame(whole), 0u);
    {
        TrajectoryFile t = TrajectoryFile::create(part, p, b.species, "[box]\n", columns,
                                                  TrajectorySegment{id, 7});
        EXPECT_EQ(t.first_frame(), 7u);
        t.close();
    }
    {
        // Reopened with no frame yet: the box edges come from the run's parameters.
        TrajectoryFile t = TrajectoryFile::reopen(part, 0, p, columns);
        EXPECT_EQ(t.first_frame(), 7u);
        EXPECT_EQ(t.run_id(), id);
        t.append_frame(700, 0.7, b, {0.5});
        t.close();
    }
    EXPECT_EQ(read_first_frame(part), 7u);
    EXPECT_EQ(read_run_id(part), id);
    const TrajectoryReader r(part);
    ASSERT_EQ(r.frames(), 1u);
    EXPECT_EQ(r.steps()[0], 700);
}

// MDAnalysis, the readers our users already have, finds the frames (positions, velocities and
// time) where we wrote them.
TEST(TrajectoryFile, MDAnalysisReadsTheFrames) {
    const ScratchDir dir("trajectory-mda");
    const auto path = dir.path() / "t.h5";
    const BodyState b = random_bodies(7, 9);
    {
        TrajectoryFile t = TrajectoryFile::create(path, two_species(), b.species, "", {{"x", "1"}});
        t.append_frame(0, 0.0, b, {0.0});
        t.append_frame(100, 0.25, b, {1.0});
        t.close();
    }
    const auto [status, output] = run_python(dir, R"(
import sys, warnings
warnings.simplefilter("ignore")
from MDAnalysis.coordinates.H5MD import H5MDReader
for kind, unit in (("length", "mm"), ("velocity", "mm s-1")):
    H5MDReader._unit_translation[kind][unit] = unit
r = H5MDReader(sys.argv[1], convert_units=False)
ts = r[1]
print("frames %d atoms %d time %g" % (r.n_frames, r.n_atoms, ts.time))
print("x %.4f %.4f v %.3f" % (ts.positions[3][0], ts.positions[3][1], ts.velocities[3][2]))
)",
                                             path);
    ASSERT_EQ(status, 0) << output;
    EXPECT_NE(output.find("frames 2 atoms 7 time 0.25\n"), std::string::npos) << output;
    char expected[128];
    std::snprintf(expected, sizeof expected, "x %.4f %.4f v %.3f", b.position[3].x, b.position[3].y,
                  b.velocity[3].z);
    EXPECT_NE(output.find(expected), std::string::npos) << output << " vs " << expected;
}

}  // namespace
}  // namespace rodsea
