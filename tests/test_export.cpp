// `rodsea export` on a real (small) run: the sphere positions that MDAnalysis reads back are the
// ones the stored bodies and their shapes give, the written quaternion carries each body's
// offsets onto its spheres, body ids group the right spheres, and bad input is refused before
// anything is written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "child_process.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/run/run_driver.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

// Three species with 13, 9 and 1 spheres: 4 × 13 + 20 × 9 + 10 × 1 = 242 spheres per frame.
constexpr std::size_t kSpheres = 242;
constexpr std::size_t kBodies = 34;
constexpr std::size_t kFrames = 11;  // 0 to 0.02 s every 2 ms

const char* const kConfig = R"([box]
side = 20.0
[[species]]
name = "polar"
kind = "polar_rod"
count = 4
[[species]]
name = "medium"
kind = "apolar_rod"
length = 2.5
count = 20
[[species]]
name = "beads"
kind = "bead"
count = 10
[time]
duration = 0.02
[output]
interval = 0.002
[run]
seed = 3
)";

// Tolerances, from the digits written and the readers' precision:
// - positions are written with 6 decimals (rounding ≤ 5e-7 mm); read back in double they match
//   the stored bodies to that, plus 1e-12 for the different rotation formulas: 1e-6 mm.
// - differences of two written positions carry two roundings per axis: 2·√3·5e-7 < 2e-6 mm,
//   and the 9-decimal quaternion adds 4.5 mm · 4 · 5e-10 ≈ 1e-8 mm: 3e-6 mm.
// - MDAnalysis keeps coordinates in float32: 2⁻²⁴ ≈ 6e-8 relative, 1.5e-6 mm at the 25 mm a
//   sphere can reach, twice for the box-origin shift it applies, plus the rounding: 1e-5 mm.
constexpr double kWrittenTol = 1e-6;
constexpr double kDifferenceTol = 3e-6;
constexpr double kMDAnalysisTol = 1e-5;
constexpr double kQuaternionTol = 1e-9;  // 9 decimals: rounding ≤ 5e-10

// One sphere as a file gives it.
struct SphereLine {
    long long id = 0, body = 0;
    std::string type;  // the type number (dump) or the species name (XYZ)
    Vec3 p, v;
    double radius = 0.0;
    Quat q;
};
struct FrameText {
    long long step = -1;
    double time = -1.0;
    std::vector<SphereLine> spheres;
};

Vec3 rotated(const Quat& q, const Vec3& v) {
    // The matrix, not rotate(): an independent formula for the same rotation.
    const Mat3 m = to_matrix(q);
    return {m(0, 0) * v.x + m(0, 1) * v.y + m(0, 2) * v.z,
            m(1, 0) * v.x + m(1, 1) * v.y + m(1, 2) * v.z,
            m(2, 0) * v.x + m(2, 1) * v.y + m(2, 2) * v.z};
}

double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                     (a.z - b.z) * (a.z - b.z));
}

std::vector<FrameText> read_dump(const fs::path& path, bool velocities) {
    std::ifstream in(path);
    std::vector<FrameText> frames;
    std::string line;
    while (std::getline(in, line)) {
        EXPECT_EQ(line, "ITEM: TIMESTEP");
        FrameText f;
        std::size_t n = 0;
        in >> f.step;
        in.ignore(1);
        std::getline(in, line);
        EXPECT_EQ(line, "ITEM: NUMBER OF ATOMS");
        in >> n;
        in.ignore(1);
        std::getline(in, line);
        EXPECT_EQ(line, "ITEM: BOX BOUNDS pp pp ff");
        for (int k = 0; k < 3; ++k)
            std::getline(in, line);
        std::getline(in, line);
        EXPECT_EQ(line,
                  std::string("ITEM: ATOMS id mol type x y z radius quatw quati quatj quatk") +
                      (velocities ? " vx vy vz" : ""));
        for (std::size_t i = 0; i < n && std::getline(in, line); ++i) {
            std::istringstream s(line);
            SphereLine l;
            s >> l.id >> l.body >> l.type >> l.p.x >> l.p.y >> l.p.z >> l.radius >> l.q.w >>
                l.q.x >> l.q.y >> l.q.z;
            if (velocities) s >> l.v.x >> l.v.y >> l.v.z;
            EXPECT_TRUE(s && s.eof()) << line;
            f.spheres.push_back(l);
        }
        frames.push_back(f);
    }
    return frames;
}

std::vector<FrameText> read_xyz(const fs::path& path, bool velocities) {
    std::ifstream in(path);
    std::vector<FrameText> frames;
    std::string line;
    while (std::getline(in, line)) {
        const std::size_t n = std::stoul(line);
        std::getline(in, line);
        FrameText f;
        const std::string properties =
            std::string("Properties=species:S:1:pos:R:3:radius:R:1:molecule:I:1:orientation:R:4") +
            (velocities ? ":velo:R:3 " : " ");
        EXPECT_NE(line.find(properties), std::string::npos) << line;
        EXPECT_NE(line.find("pbc=\"T T F\""), std::string::npos) << line;
        f.time = std::stod(line.substr(line.find("Time=") + 5));
        f.step = std::stoll(line.substr(line.find("Step=") + 5));
        for (std::size_t i = 0; i < n && std::getline(in, line); ++i) {
            std::istringstream s(line);
            SphereLine l;
            l.id = static_cast<long long>(i) + 1;
            // OVITO's Orientation order: x y z w.
            s >> l.type >> l.p.x >> l.p.y >> l.p.z >> l.radius >> l.body >> l.q.x >> l.q.y >>
                l.q.z >> l.q.w;
            if (velocities) s >> l.v.x >> l.v.y >> l.v.z;
            EXPECT_TRUE(s && s.eof()) << line;
            f.spheres.push_back(l);
        }
        frames.push_back(f);
    }
    return frames;
}

// What MDAnalysis reads from a file: atom and frame counts, per-atom types (dump) or names
// (XYZ), and per frame its step, box and positions (and velocities when present).
struct MDAnalysisRead {
    std::size_t atoms = 0, frames = 0;
    std::vector<std::string> types;
    std::vector<long long> steps;
    std::vector<std::vector<double>> boxes;
    std::vector<std::vector<Vec3>> positions, velocities;
};

MDAnalysisRead read_with_mdanalysis(const fs::path& file, const std::string& format,
                                    const fs::path& scratch) {
    // Debian's Python (python3-mdanalysis), not whatever python3 comes first on PATH.
    const std::string script =
        "import sys, warnings\n"
        "warnings.simplefilter('ignore')\n"
        "import MDAnalysis as mda\n"
        "path, fmt, out = sys.argv[1:4]\n"
        "u = mda.Universe(path, format=fmt)\n"
        "with open(out, 'w') as f:\n"
        "    f.write('%d %d\\n' % (u.atoms.n_atoms, len(u.trajectory)))\n"
        "    labels = u.atoms.types if fmt == 'LAMMPSDUMP' else u.atoms.names\n"
        "    f.write(' '.join(str(t) for t in labels) + '\\n')\n"
        "    for ts in u.trajectory:\n"
        "        box = ts.dimensions if ts.dimensions is not None else [0] * 6\n"
        "        f.write('%d %d ' % (ts.data.get('step', -1), int(ts.has_velocities)))\n"
        "        f.write(' '.join('%.9g' % b for b in box) + '\\n')\n"
        "        for p in ts.positions:\n"
        "            f.write('%.9g %.9g %.9g\\n' % tuple(p))\n"
        "        if ts.has_velocities:\n"
        "            for v in ts.velocities:\n"
        "                f.write('%.9g %.9g %.9g\\n' % tuple(v))\n";
    const fs::path py = scratch / "read_back.py", out = scratch / (format + ".read");
    std::ofstream(py) << script;
    const std::string command = "/usr/bin/python3 -W ignore " + py.string() + " " + file.string() +
                                " " + format + " " + out.string() + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    MDAnalysisRead r;
    std::ifstream in(out);
    in >> r.atoms >> r.frames;
    for (std::size_t i = 0; i < r.atoms; ++i) {
        std::string t;
        in >> t;
        r.types.push_back(t);
    }
    for (std::size_t f = 0; f < r.frames && in; ++f) {
        long long step = 0;
        int has_velocities = 0;
        std::vector<double> box(6);
        in >> step >> has_velocities;
        for (double& b : box)
            in >> b;
        r.steps.push_back(step);
        r.boxes.push_back(box);
        std::vector<Vec3> p(r.atoms), v;
        for (Vec3& x : p)
            in >> x.x >> x.y >> x.z;
        if (has_velocities) {
            v.resize(r.atoms);
            for (Vec3& x : v)
                in >> x.x >> x.y >> x.z;
        }
        r.positions.push_back(p);
        r.velocities.push_back(v);
    }
    return r;
}

// A sphere as the stored bodies and the config's shapes place it.
struct Expected {
    long long body;
    std::size_t species;
    Vec3 p, v, offset;
    double radius;
    Quat q;
};

// One small run shared by every test: 34 bodies of three species, 11 frames.
class ExportCli : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("export");
        RunOptions options;
        options.out_dir = run_dir();
        options.quiet = true;
        std::ostringstream out, err;
        ASSERT_EQ(start_run(load_config_string(kConfig, "test"), options, out, err), kExitOk)
            << err.str();
        run_ = new StoredRun(open_stored_run(run_dir()));
    }
    static void TearDownTestSuite() {
        delete run_;
        delete scratch_;
    }
    static fs::path run_dir() { return scratch_->path() / "run"; }
    static const fs::path& scratch() { return scratch_->path(); }

    // Frame k's spheres computed here from the stored bodies and the config's shapes.
    static std::vector<Expected> expected(std::size_t k) {
        const BodyState b = run_->reader.frame(k);
        std::vector<Expected> e;
        for (std::size_t i = 0; i < b.size(); ++i) {
            const Shape& shape = run_->plan.engine.species[b.species[i]].shape;
            const Quat q = normalized(b.orientation[i]);
            for (std::size_t s = 0; s < shape.radii.size(); ++s)
                e.push_back({static_cast<long long>(i) + 1, b.species[i],
                             b.position[i] + rotated(q, shape.offsets[s]), b.velocity[i],
                             shape.offsets[s], shape.radii[s], q});
        }
        return e;
    }
    static ChildResult export_run(std::vector<std::string> args) {
        args.insert(args.begin(), {"export", run_dir().string()});
        return run_rodsea(args, scratch());
    }

    static ScratchDir* scratch_;
    static StoredRun* run_;
};
ScratchDir* ExportCli::scratch_ = nullptr;
StoredRun* ExportCli::run_ = nullptr;

// Every sphere of `file` is where the stored body puts it, with its body id, type, radius and
// the body's quaternion, and the quaternion carries the body's offsets onto its spheres.
void check_frame(const FrameText& f, const std::vector<Expected>& e, const RunPlan& plan,
                 bool velocities, bool names) {
    ASSERT_EQ(f.spheres.size(), e.size());
    const Box& box = plan.engine.box;
    std::size_t first_of_body = 0;
    for (std::size_t i = 0; i < e.size(); ++i) {
        const SphereLine& s = f.spheres[i];
        ASSERT_EQ(s.id, static_cast<long long>(i) + 1);
        ASSERT_EQ(s.body, e[i].body) << "sphere " << s.id;
        const Species& species = plan.engine.species[e[i].species];
        EXPECT_EQ(s.type, names ? species.name : std::to_string(e[i].species + 1));
        EXPECT_NEAR(distance(s.p, e[i].p), 0.0, kWrittenTol) << "sphere " << s.id;
        EXPECT_NEAR(s.radius, e[i].radius, kWrittenTol);
        EXPECT_NEAR(s.q.w, e[i].q.w, kQuaternionTol) << "sphere " << s.id;
        EXPECT_NEAR(s.q.x, e[i].q.x, kQuaternionTol);
        EXPECT_NEAR(s.q.y, e[i].q.y, kQuaternionTol);
        EXPECT_NEAR(s.q.z, e[i].q.z, kQuaternionTol);
        if (velocities) {
            EXPECT_NEAR(distance(s.v, e[i].v), 0.0, kWrittenTol);
        }
        // From the file alone: the written quaternion rotates the body's offsets onto its
        // spheres, and the centre it implies is inside the box (bodies are kept whole).
        if (i == 0 || e[i].body != e[i - 1].body) first_of_body = i;
        const SphereLine& s0 = f.spheres[first_of_body];
        EXPECT_EQ(s.q.w, s0.q.w);  // one quaternion per body
        const Vec3 predicted = s0.p + rotated(s.q, e[i].offset - e[first_of_body].offset);
        EXPECT_NEAR(distance(s.p, predicted), 0.0, kDifferenceTol) << "sphere " << s.id;
        const Vec3 centre = s.p - rotated(s.q, e[i].offset);
        EXPECT_GE(centre.x, -kDifferenceTol);
        EXPECT_LE(centre.x, box.lx + kDifferenceTol);
        EXPECT_GE(centre.y, -kDifferenceTol);
        EXPECT_LE(centre.y, box.ly + kDifferenceTol);
    }
    // The body ids group exactly each species' number of spheres.
    std::size_t start = 0;
    for (std::size_t body = 1; body <= kBodies; ++body) {
        std::size_t n = 0;
        while (start + n < f.spheres.size() &&
               f.spheres[start + n].body == static_cast<long long>(body))
            ++n;
        const std::size_t species = e[start].species;
        EXPECT_EQ(n, plan.engine.species[species].shape.sphere_count()) << "body " << body;
        start += n;
    }
    EXPECT_EQ(start, kSpheres);
}

TEST_F(ExportCli, LammpsDumpGivesEverySphereWhereItsBodyPutsIt) {
    ASSERT_EQ(run_->frames(), kFrames);
    const fs::path file = scratch() / "every3.lammpstrj";
    const ChildResult r = export_run(
        {"--format", "lammps-dump", "-o", file.string(), "--every", "3", "--velocities"});
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("spheres per frame: 242 in 34 bodies"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("frames: 4 of 11"), std::string::npos) << r.out;
    const std::vector<FrameText> frames = read_dump(file, true);
    const std::vector<std::size_t> chosen{0, 3, 6, 9};  // every 3rd of 11
    ASSERT_EQ(frames.size(), chosen.size());
    for (std::size_t f = 0; f < chosen.size(); ++f) {
        EXPECT_EQ(frames[f].step, run_->reader.steps()[chosen[f]]);
        check_frame(frames[f], expected(chosen[f]), run_->plan, true, false);
    }
}

TEST_F(ExportCli, XyzGivesEverySphereWithItsSpeciesNameAndTime) {
    // --from/--to select the frames at 0.006, 0.008, 0.010, 0.012 s; --every 2 keeps two.
    const fs::path file = scratch() / "window.xyz";
    const ChildResult r = export_run({"--format", "xyz", "-o", file.string(), "--from", "0.005",
                                      "--to", "0.013", "--every", "2", "--quiet"});
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    EXPECT_EQ(r.out, "");  // --quiet
    const std::vector<FrameText> frames = read_xyz(file, false);
    const std::vector<std::size_t> chosen{3, 5};
    ASSERT_EQ(frames.size(), chosen.size());
    for (std::size_t f = 0; f < chosen.size(); ++f) {
        EXPECT_EQ(frames[f].step, run_->reader.steps()[chosen[f]]);
        EXPECT_EQ(frames[f].time, run_->times()[chosen[f]]);  // written to round-trip
        check_frame(frames[f], expected(chosen[f]), run_->plan, false, true);
    }
    // The box: [0, L]² in x, y; the plates' whole travel [−A, w + A] in z.
    const std::string text = read_text(file);
    const double a = run_->plan.engine.drive.amplitude(), w = run_->plan.engine.drive.gap;
    std::ostringstream lattice;
    lattice << "Lattice=\"20 0 0 0 20 0 0 0 ";
    EXPECT_NE(text.find(lattice.str()), std::string::npos);
    const std::size_t h = text.find(lattice.str()) + lattice.str().size();
    EXPECT_NEAR(std::stod(text.substr(h)), w + 2 * a, 1e-12);
    EXPECT_NEAR(std::stod(text.substr(text.find("Origin=\"0 0 ") + 12)), -a, 1e-15);
}

TEST_F(ExportCli, MDAnalysisReadsTheSpherePositionsWritten) {
    const fs::path dump = scratch() / "mda.lammpstrj", xyz = scratch() / "mda.xyz";
    ASSERT_EQ(export_run({"--format", "lammps-dump", "-o", dump.string(), "--every", "5",
                          "--velocities", "--quiet"})
                  .exit_code,
              0);
    ASSERT_EQ(
        export_run({"--format", "xyz", "-o", xyz.string(), "--frame", "-1", "--quiet"}).exit_code,
        0);
    const double a = run_->plan.engine.drive.amplitude(), w = run_->plan.engine.drive.gap;

    // LAMMPS dump: frames 0, 5, 10. MDAnalysis ≥ 2.4 moves the box's low corner to the origin
    // (positions − (xlo, ylo, zlo)): z comes back shifted by +A, added back here. It applies no
    // unit conversion (lengths stay mm, read as "Å").
    const MDAnalysisRead d = read_with_mdanalysis(dump, "LAMMPSDUMP", scratch());
    EXPECT_EQ(d.atoms, kSpheres);
    ASSERT_EQ(d.frames, 3u);
    const std::vector<std::size_t> chosen{0, 5, 10};
    for (std::size_t f = 0; f < chosen.size(); ++f) {
        EXPECT_EQ(d.steps[f], run_->reader.steps()[chosen[f]]);
        EXPECT_NEAR(d.boxes[f][0], 20.0, 1e-5);
        EXPECT_NEAR(d.boxes[f][1], 20.0, 1e-5);
        EXPECT_NEAR(d.boxes[f][2], w + 2 * a, 1e-5);
        const std::vector<Expected> e = expected(chosen[f]);
        ASSERT_EQ(d.positions[f].size(), e.size());
        ASSERT_EQ(d.velocities[f].size(), e.size());
        for (std::size_t i = 0; i < e.size(); ++i) {
            const Vec3 p = d.positions[f][i] + Vec3{0.0, 0.0, -a};
            EXPECT_NEAR(distance(p, e[i].p), 0.0, kMDAnalysisTol) << "frame " << f << " " << i;
            // Velocities are float32 too: 6e-8 of ~100 mm/s, plus the 5e-7 rounding.
            EXPECT_NEAR(distance(d.velocities[f][i], e[i].v), 0.0, 2e-5);
            EXPECT_EQ(d.types[i], std::to_string(e[i].species + 1));
        }
    }
    // XYZ: the last frame, positions unshifted, names are the species' names.
    const MDAnalysisRead x = read_with_mdanalysis(xyz, "XYZ", scratch());
    EXPECT_EQ(x.atoms, kSpheres);
    ASSERT_EQ(x.frames, 1u);
    const std::vector<Expected> e = expected(kFrames - 1);
    ASSERT_EQ(x.positions[0].size(), e.size());
    for (std::size_t i = 0; i < e.size(); ++i) {
        EXPECT_NEAR(distance(x.positions[0][i], e[i].p), 0.0, kMDAnalysisTol) << i;
        EXPECT_EQ(x.types[i], run_->plan.engine.species[e[i].species].name);
    }
}

struct BadCase {
    std::vector<std::string> args;  // after `rodsea export RUN_DIR`
    int exit_code;
    std::string message;
};

TEST_F(ExportCli, BadInputIsRefusedByNameAndWritesNothing) {
    const fs::path dir = scratch() / "bad";
    fs::create_directories(dir);
    const std::string out = (dir / "out.lammpstrj").string();
    const std::string trajectory = (run_dir() / "trajectory.h5").string();
    const auto before = fs::file_size(trajectory);
    const std::vector<BadCase> cases{
        {{"--format", "lammps", "-o", out}, 2, "did you mean 'lammps-dump'"},
        {{"--format", "xzy", "-o", out}, 2, "invalid --format = 'xzy': allowed lammps-dump or xyz"},
        {{"-o", out}, 2, "--format"},
        {{"--format", "xyz"}, 2, "invalid -o"},
        {{"--format", "xyz", "-o", out, "--frame", "999"}, 2, "invalid --frame = 999"},
        {{"--format", "xyz", "-o", out, "--time", "3"}, 2, "invalid --time"},
        {{"--format", "xyz", "-o", out, "--frame", "1", "--every", "2"}, 2, "--every"},
        {{"--format", "xyz", "-o", out, "--every", "0"}, 2, "--every"},
        {{"--format", "xyz", "-o", out, "--from", "1"}, 2, "[0, 0.02] s"},
        {{"--format", "xyz", "-o", out, "--from", "0.011", "--to", "0.005"}, 2, "--to"},
        {{"--format", "xyz", "-o", out, "--from", "0.0101", "--to", "0.0109"}, 2, "one frame"},
        {{"--format", "xyz", "-o", out, "--colour", "red"}, 2, "--colour"},
        {{"--format", "xyz", "-o", (dir / "missing" / "out.xyz").string()}, 74, "does not exist"},
        {{"--format", "xyz", "-o", dir.string()}, 2, "it is a directory"},
        {{"--format", "lammps-dump", "-o", trajectory}, 2, "other than the run's own"},
    };
    for (const BadCase& c : cases) {
        const ChildResult r = export_run(c.args);
        EXPECT_EQ(r.exit_code, c.exit_code) << c.message << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    const ChildResult missing = run_rodsea(
        {"export", (scratch() / "no-run").string(), "--format", "xyz", "-o", out}, scratch());
    EXPECT_EQ(missing.exit_code, 74);
    EXPECT_NE(missing.err.find("no-run"), std::string::npos) << missing.err;
    // Nothing written: no output, no temporary file, the trajectory untouched.
    EXPECT_TRUE(fs::is_empty(dir));
    EXPECT_EQ(fs::file_size(trajectory), before);
    EXPECT_EQ(open_stored_run(run_dir()).frames(), kFrames);
}

TEST_F(ExportCli, AFullDiskLeavesNoFileBehind) {
    // A 64 kB file-size limit stands in for a full disk: the third frame (27 kB each) cannot
    // be written. The old file is kept and no temporary file is left.
    const fs::path dir = scratch() / "full";
    fs::create_directories(dir);
    const fs::path file = dir / "big.lammpstrj";
    std::ofstream(file) << "previous content\n";
    ChildOptions limit;
    limit.file_size_limit = 64 * 1024;
    const ChildResult r = run_rodsea(
        {"export", run_dir().string(), "--format", "lammps-dump", "-o", file.string(), "--quiet"},
        scratch(), limit);
    EXPECT_EQ(r.exit_code, 74) << r.err;
    EXPECT_NE(r.err.find("write failed"), std::string::npos) << r.err;
    EXPECT_EQ(read_text(file), "previous content\n");
    EXPECT_TRUE(temporaries_of(file).empty());
    // The same export without the limit replaces the old content.
    const ChildResult ok = run_rodsea(
        {"export", run_dir().string(), "--format", "lammps-dump", "-o", file.string(), "--quiet"},
        scratch());
    ASSERT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_EQ(read_dump(file, false).size(), kFrames);
}

TEST_F(ExportCli, CtrlCLeavesNoFileBehind) {
    // A run with a frame every step (1001 frames of 27 kB: a quarter of a second to export), so
    // that SIGINT arrives mid-export, once the temporary file exists.
    std::string config = kConfig;
    config.replace(config.find("interval = 0.002"), 16, "interval = 0.000005");
    config.replace(config.find("duration = 0.02"), 15, "duration = 0.005");
    RunOptions options;
    options.out_dir = scratch() / "dense";
    options.quiet = true;
    std::ostringstream log;
    ASSERT_EQ(start_run(load_config_string(config, "test"), options, log, log), kExitOk)
        << log.str();
    const fs::path file = scratch() / "dense.lammpstrj";
    ChildOptions interrupt;
    interrupt.interrupt_when = [&] {
        const std::vector<fs::path> tmp = temporaries_of(file);
        std::error_code ec;
        return !tmp.empty() && fs::file_size(tmp.front(), ec) > 0 && !ec;
    };
    const ChildResult r = run_rodsea({"export", options.out_dir.string(), "--format", "lammps-dump",
                                      "-o", file.string(), "--quiet"},
                                     scratch(), interrupt);
    ASSERT_TRUE(r.interrupted);
    EXPECT_EQ(r.exit_code, 130) << r.err;  // 128 + SIGINT, as `rodsea run`
    EXPECT_NE(r.err.find("nothing written"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(file));
    EXPECT_TRUE(temporaries_of(file).empty());
}

TEST_F(ExportCli, HelpStatesTheUnits) {
    const ChildResult r = run_rodsea({"export", "--help"}, scratch());
    EXPECT_EQ(r.exit_code, 0);
    EXPECT_NE(r.out.find("Units: mm and s"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace rodsea
