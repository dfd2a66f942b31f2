// `rodsea plot` on real (tiny) runs, through the real executable: a run's analysis and a table
// of runs give the expected PNG files, each a valid PNG of the requested size with something
// drawn on it; bad input is refused by name and leaves no PNG or temporary file behind.
#include <gtest/gtest.h>
#include <stdio.h>
#include <stdlib.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "child_process.hpp"
#include "rodsea/view/plot_command.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

constexpr int kDpi = 40;  // small pictures draw fast; the sizes below are inches × kDpi

// Figure sizes in inches, as scripts/rodsea_plots/common.py defines them.
struct Inches {
    double width, height;
};
constexpr Inches kCurve{6.5, 4.5}, kWide{11.0, 4.5}, kMap{6.5, 5.5};

const std::map<std::string, Inches> kRunFigures{{"order_parameters.png", kCurve},
                                                {"autocorrelation.png", kCurve},
                                                {"flocks_time.png", kCurve},
                                                {"flock_sizes.png", kWide},
                                                {"g_r_theta.png", kMap},
                                                {"G_r_theta.png", kMap},
                                                {"pair_correlation.png", kWide},
                                                {"segregation.png", kCurve},
                                                {"bands.png", kCurve},
                                                {"medium_velocity.png", kCurve},
                                                {"fields_mean.png", kWide},
                                                {"fields_last.png", kWide},
                                                {"interface.png", kCurve},
                                                {"defects.png", kWide},
                                                {"flock_defects.png", kWide}};
const std::vector<std::string> kTableFigures{"P_vs_phi_a.png", "Sigma_vs_phi_a.png", "P_vs_D_r.png",
                                             "Sigma_vs_D_r.png", "phase_diagram.png"};

// A run of 6 polar rods (or none) among apolar rods at area fraction phi_a with noise epsilon:
// 11 frames over 0.02 s, a tenth of a second to run.
std::string config(double phi_a, double epsilon, bool polar = true) {
    std::ostringstream s;
    s << "[box]\nside = 20.0\n";
    if (polar) s << "[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 6\n";
    s << "[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
      << "area_fraction = " << phi_a << "\n[noise]\nepsilon = " << epsilon
      << "\n[time]\nduration = 0.02\n[output]\ninterval = 0.002\n[run]\nseed = 5\n";
    return s.str();
}

std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) out.push_back(line);
    return out;
}

std::set<std::string> files_in(const fs::path& dir) {
    std::set<std::string> names;
    if (fs::is_directory(dir))
        for (const auto& e : fs::directory_iterator(dir))
            names.insert(e.path().filename().string());
    return names;
}

struct PngHeader {
    bool valid = false;
    std::uint32_t width = 0, height = 0;
};

// The PNG signature and the size in its IHDR chunk (the first chunk, right after the signature).
PngHeader png_header(const fs::path& path) {
    const std::string bytes = read_text(path);
    PngHeader h;
    static const std::string signature("\x89PNG\r\n\x1a\n", 8);
    if (bytes.size() < 24 || bytes.compare(0, 8, signature) != 0 ||
        bytes.compare(12, 4, "IHDR") != 0)
        return h;
    const auto be32 = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 4; ++k)
            v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
        return v;
    };
    h.valid = true;
    h.width = be32(16);
    h.height = be32(20);
    return h;
}

// Decodes each PNG with Debian's matplotlib and prints "<spread of pixel values> <path>": a
// blank (one-colour) picture has spread 0.
std::string pixel_spread(const std::vector<fs::path>& pngs, const fs::path& scratch) {
    const fs::path script = scratch / "spread.py";
    std::ofstream(script) << "import sys\nimport matplotlib.image as im\n"
                             "for p in sys.argv[1:]:\n"
                             "    a = im.imread(p)[..., :3]\n"
                             "    print(f'{a.std():.4f} {p}')\n";
    std::string command = "/usr/bin/python3 " + script.string();
    for (const fs::path& p : pngs)
        command.append(" ").append(p.string());
    return shell_output(command + " 2>&1");
}

// Every PNG named in `printed` (rodsea plot's stdout) exists in `dir`, is a valid PNG of the size
// its figure has at kDpi, and is not blank; nothing else (no temporary file) is in `dir`.
void expect_pictures(const std::vector<std::string>& printed, const fs::path& dir,
                     const std::map<std::string, Inches>& sizes, const fs::path& scratch) {
    std::vector<fs::path> pngs;
    std::set<std::string> names;
    for (const std::string& line : printed) {
        const fs::path p(line);
        EXPECT_EQ(p.parent_path(), dir) << line;
        names.insert(p.filename().string());
        pngs.push_back(p);
        const PngHeader h = png_header(p);
        ASSERT_TRUE(h.valid) << line << " is not a PNG";
        const auto size = sizes.find(p.filename().string());
        const Inches in = size != sizes.end() ? size->second : kCurve;
        EXPECT_EQ(h.width, static_cast<std::uint32_t>(in.width * kDpi)) << line;
        EXPECT_EQ(h.height, static_cast<std::uint32_t>(in.height * kDpi)) << line;
        EXPECT_GT(fs::file_size(p), 3000u) << line;
    }
    EXPECT_EQ(files_in(dir), names) << "the output directory holds exactly the PNGs printed";
    const std::vector<std::string> spread = lines(pixel_spread(pngs, scratch));
    ASSERT_EQ(spread.size(), pngs.size()) << testing::PrintToString(spread);
    for (const std::string& line : spread)
        EXPECT_GT(std::stod(line), 0.02) << "blank picture: " << line;
}

// Four tiny runs shared by the suite, analysed into one table: three with polar rods (two area
// fractions of the medium, two noises) and one of the medium alone (a row without P).
class PlotCli : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("plot");
        const std::vector<std::pair<std::string, std::string>> runs{
            {"sparse", config(0.10, 0.0)},
            {"dense", config(0.30, 0.0)},
            {"noisy", config(0.10, 0.3)},
            {"medium-only", config(0.30, 0.0, false)}};
        std::vector<std::string> analyze{"analyze"};
        for (const auto& [name, text] : runs) {
            std::ofstream(dir() / (name + ".toml")) << text;
            const ChildResult r = run_rodsea({"run", (dir() / (name + ".toml")).string(), "--out",
                                              (dir() / name).string(), "--quiet"},
                                             dir());
            ASSERT_EQ(r.exit_code, 0) << name << ": " << r.err;
            analyze.push_back((dir() / name).string());
        }
        analyze.insert(analyze.end(), {"--table", table().string(), "--quiet"});
        const ChildResult r = run_rodsea(analyze, dir());
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    static void TearDownTestSuite() { delete scratch_; }
    static fs::path dir() { return scratch_->path(); }
    static fs::path table() { return dir() / "table.csv"; }
    static ChildResult plot(std::vector<std::string> args) {
        args.insert(args.begin(), "plot");
        return run_rodsea(args, dir());
    }
    static ScratchDir* scratch_;
};
ScratchDir* PlotCli::scratch_ = nullptr;

TEST_F(PlotCli, RunAnalysisGivesEveryFigureOfItsObservables) {
    const fs::path out = dir() / "run-figures";
    const ChildResult r =
        plot({(dir() / "sparse").string(), "-o", out.string(), "--dpi", std::to_string(kDpi)});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<std::string> printed = lines(r.out);
    std::set<std::string> names;
    for (const std::string& line : printed)
        names.insert(fs::path(line).filename().string());
    for (const auto& [name, size] : kRunFigures)
        EXPECT_TRUE(names.count(name)) << name << " missing from:\n" << r.out;
    expect_pictures(printed, out, kRunFigures, dir());
}

// A run extended after its analysis: plot draws what analysis/ holds, and says that it is older
// than the run; an analysis of the run as it is draws without a note.
TEST_F(PlotCli, AnAnalysisOlderThanItsRunIsNamedAsSuch) {
    const fs::path run = dir() / "extended";
    fs::copy(dir() / "sparse", run, fs::copy_options::recursive);
    const ChildResult fresh = plot({run.string(), "-o", (dir() / "fresh").string(), "--quiet"});
    ASSERT_EQ(fresh.exit_code, 0) << fresh.err;
    EXPECT_EQ(fresh.err.find("note:"), std::string::npos) << fresh.err;
    ASSERT_EQ(run_rodsea({"run", "--resume", run.string(), "--duration", "0.03", "--quiet"}, dir())
                  .exit_code,
              0);
    const ChildResult stale = plot({run.string(), "-o", (dir() / "stale").string(), "--quiet"});
    ASSERT_EQ(stale.exit_code, 0) << stale.err;
    EXPECT_NE(stale.err.find("was made from this run up to step 16000; it now reaches step 24000"),
              std::string::npos)
        << stale.err;
    EXPECT_NE(stale.err.find("rodsea analyze " + run.string() + " again"), std::string::npos)
        << stale.err;
    // An analysis cut short with --to ends before its run by design: no note.
    ASSERT_EQ(run_rodsea({"analyze", run.string(), "--to", "0.02", "--quiet"}, dir()).exit_code, 0);
    const ChildResult cut = plot({run.string(), "-o", (dir() / "cut").string(), "--quiet"});
    ASSERT_EQ(cut.exit_code, 0) << cut.err;
    EXPECT_EQ(cut.err.find("note:"), std::string::npos) << cut.err;
}

TEST_F(PlotCli, MediumOnlyRunSkipsThePolarFiguresWithANote) {
    const fs::path out = dir() / "medium-figures";
    // Its analysis.json, given directly, is the same input as the directory.
    const ChildResult r = plot({(dir() / "medium-only" / "analysis" / "analysis.json").string(),
                                "-o", out.string(), "--dpi", std::to_string(kDpi)});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::set<std::string> written = files_in(out);
    EXPECT_TRUE(written.count("order_parameters.png"));
    EXPECT_FALSE(written.count("g_r_theta.png"));
    EXPECT_FALSE(written.count("flocks_time.png"));
    EXPECT_NE(r.err.find("g_r_theta.png"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("rodsea analyze skipped 'corotating'"), std::string::npos) << r.err;
    expect_pictures(lines(r.out), out, kRunFigures, dir());
}

TEST_F(PlotCli, TableOfRunsGivesOrderSegregationAndPhaseDiagram) {
    const fs::path out = dir() / "table-figures";
    const ChildResult r =
        plot({table().string(), "-o", out.string(), "--dpi", std::to_string(kDpi)});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::set<std::string> written = files_in(out);
    for (const std::string& name : kTableFigures)
        EXPECT_TRUE(written.count(name)) << name << " missing; stderr:\n" << r.err;
    expect_pictures(lines(r.out), out, {}, dir());
}

// A constructed table (the columns `rodsea analyze --table` writes) with known P: the phase
// diagram draws the P = 0.5 boundary when the runs lie on both sides of it, and says why not
// when they do not.
TEST_F(PlotCli, PhaseDiagramDrawsTheBoundaryWhereThereIsOne) {
    const auto table_with = [&](const std::string& name, double p_offset) {
        const fs::path path = dir() / name;
        std::ofstream t(path);
        t << "# rodsea 0.1.0 analysis summary: constructed\n"
          << "run,epsilon_per_mm,phi_polar,phi_medium,length_mm_medium,P_polar,P_polar_err,"
             "D_r_polar,D_r_polar_err,Sigma,Sigma_err\n";
        int k = 0;
        for (const double phi_a : {0.2, 0.5, 0.8})
            for (const double d_r : {0.0, 0.5, 1.0})
                t << "run" << k++ << ",0,0.05," << phi_a << ",2.5,"
                  << p_offset + 1.0 - 0.5 * phi_a - 0.4 * d_r << ",0.01," << d_r << ",0.02,"
                  << 0.1 * phi_a << ",0.01\n";
        return path;
    };
    const fs::path out = dir() / "phase";
    ChildResult r = plot({table_with("both-sides.csv", 0.0).string(), "-o", out.string(), "--dpi",
                          std::to_string(kDpi), "--only", "phase_diagram"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(files_in(out), std::set<std::string>{"phase_diagram.png"});
    EXPECT_EQ(r.err.find("boundary not drawn"), std::string::npos) << r.err;
    expect_pictures(lines(r.out), out, {}, dir());

    r = plot({table_with("all-ordered.csv", 1.0).string(), "-o", out.string(), "--dpi",
              std::to_string(kDpi), "--only", "phase_diagram.png"});
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.err.find("every run is on one side of P = 0.5"), std::string::npos) << r.err;
}

struct BadCase {
    std::vector<std::string> args;
    int exit_code;
    std::string message;
};

TEST_F(PlotCli, BadInputIsRefusedByNameAndLeavesNoFile) {
    const fs::path out = dir() / "bad-output";
    const std::string o = out.string();
    const fs::path regular_file = dir() / "a-file";
    std::ofstream(regular_file) << "not a directory\n";
    const fs::path not_a_table = dir() / "sparse" / "analysis" / "order_parameters.csv";
    const std::string sparse = (dir() / "sparse").string();
    const std::vector<BadCase> cases{
        {{(dir() / "missing").string(), "-o", o}, 74, "no such file or directory"},
        {{not_a_table.string(), "-o", o}, 2, "is not a table of runs"},
        {{(dir() / "sparse.toml").string(), "-o", o}, 2, "unknown kind of input"},
        {{dir().string(), "-o", o}, 2, "without analysis.json"},
        {{sparse, "-o", (regular_file / "figures").string()}, 74, "cannot be created"},
        {{sparse}, 2, "-o"},
        {{sparse, "-o", o, "--dpi", "5"}, 2, "--dpi"},
        {{sparse, "-o", o, "--colour", "red"}, 2, "--colour"},
        {{sparse, "-o", o, "--only", "phase_diagram"}, 2, "allowed figures of a run's analysis"},
    };
    for (const BadCase& c : cases) {
        const ChildResult r = plot(c.args);
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args[0] << ": " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_EQ(r.out, "") << "no PNG is reported";
        EXPECT_FALSE(fs::exists(out)) << "the output directory is not even created";
    }
    EXPECT_EQ(read_text(regular_file), "not a directory\n");

    // A run without its analysis is named, with the command that makes one.
    const fs::path bare = dir() / "bare";
    fs::create_directories(bare);
    fs::copy_file(dir() / "sparse" / "trajectory.h5", bare / "trajectory.h5");
    const ChildResult r = plot({bare.string(), "-o", o});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("rodsea analyze " + bare.string()), std::string::npos) << r.err;
}

TEST_F(PlotCli, AFileThatCannotBeWrittenLeavesNoTemporaryOrHalfPng) {
    // A 4 kB file-size limit (a disk that fills up): the first PNG cannot be written whole.
    const fs::path out = dir() / "full-disk";
    ChildOptions options;
    options.file_size_limit = 4096;
    const ChildResult r =
        run_rodsea({"plot", table().string(), "-o", out.string(), "--dpi", std::to_string(kDpi)},
                   dir(), options);
    EXPECT_EQ(r.exit_code, 74) << r.err;
    EXPECT_NE(r.err.find("could not be written"), std::string::npos) << r.err;
    for (const std::string& name : files_in(out)) {
        EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
        EXPECT_TRUE(png_header(out / name).valid) << name;
    }
}

// In-process: the environment picks the interpreter and the script folder; when either, or
// matplotlib, is missing the message names it and the install command.
class PlotEnvironment : public ::testing::Test {
  protected:
    // Sets an environment variable for this test only; TearDown restores what was there.
    void set(const char* name, const std::string& value) {
        if (!saved_.count(name)) {
            const char* old = std::getenv(name);
            saved_[name] = old ? std::optional<std::string>(old) : std::nullopt;
        }
        ::setenv(name, value.c_str(), 1);
    }
    void restore() {
        for (const auto& [name, value] : saved_)
            value ? ::setenv(name.c_str(), value->c_str(), 1) : ::unsetenv(name.c_str());
        saved_.clear();
    }
    void TearDown() override { restore(); }

  private:
    std::map<std::string, std::optional<std::string>> saved_;
};

TEST_F(PlotEnvironment, MissingPythonScriptOrMatplotlibIsNamedWithTheInstallCommand) {
    ScratchDir scratch("plot-environment");
    // A table that exists (its content never gets read when Python cannot start).
    const fs::path input = scratch.path() / "t.csv";
    std::ofstream(input) << "run,phi_medium\n";
    const auto run = [&](std::string& out, std::string& err) {
        std::ostringstream o, e;
        const int code =
            plot_command({input.string(), "-o", (scratch.path() / "figures").string()}, o, e);
        out = o.str(), err = e.str();
        return code;
    };
    std::string out, err;

    set("RODSEA_PYTHON", "/nonexistent/python3");
    EXPECT_EQ(run(out, err), 1);
    EXPECT_NE(err.find("/nonexistent/python3"), std::string::npos) << err;
    EXPECT_NE(err.find("./scripts/install-deps.sh"), std::string::npos) << err;
    restore();

    set("RODSEA_SCRIPTS_DIR", (scratch.path() / "no-scripts").string());
    EXPECT_EQ(run(out, err), 1);
    EXPECT_NE(err.find("rodsea_plot.py"), std::string::npos) << err;
    restore();

    // A matplotlib that fails to import, first on Python's path.
    fs::create_directories(scratch.path() / "fake");
    std::ofstream(scratch.path() / "fake" / "matplotlib.py")
        << "raise ImportError(\"No module named 'matplotlib'\")\n";
    set("PYTHONPATH", (scratch.path() / "fake").string());
    EXPECT_EQ(run(out, err), 1);
    EXPECT_NE(err.find("'matplotlib' is missing"), std::string::npos) << err;
    EXPECT_NE(err.find("./scripts/install-deps.sh"), std::string::npos) << err;
    restore();

    // The script's own output comes back through the streams: an empty table is refused.
    EXPECT_EQ(run(out, err), 2);
    EXPECT_NE(err.find("without any row"), std::string::npos) << err;
    EXPECT_FALSE(fs::exists(scratch.path() / "figures"));
}

}  // namespace
}  // namespace rodsea
