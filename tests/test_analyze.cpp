// `rodsea analyze` on real (small) runs: the numbers agree with what the run recorded itself,
// the files are readable from Python, and bad input is refused before anything is written.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "child_process.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/io/run_lock.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_driver.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

std::string config(bool with_polar, int seed = 5) {
    std::ostringstream s;
    s << "[box]\nside = 20.0\n";
    if (with_polar) s << "[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 6\n";
    s << "[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
      << "area_fraction = 0.15\n[time]\nduration = 0.04\n[output]\ninterval = 0.002\n"
      << "[run]\nseed = " << seed << "\n";
    return s.str();
}

// Two small runs shared by every test of the suite: 21 frames each over 0.04 s.
class AnalyzeCli : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("analyze");
        for (const bool polar : {true, false}) {
            RunOptions options;
            options.out_dir = scratch_->path() / (polar ? "mixture" : "medium-only");
            options.quiet = true;
            std::ostringstream out, err;
            ASSERT_EQ(start_run(load_config_string(config(polar), "test"), options, out, err),
                      kExitOk)
                << err.str();
        }
        RunOptions replicate;
        replicate.out_dir = scratch_->path() / "mixture-seed6";
        replicate.quiet = true;
        std::ostringstream out, err;
        ASSERT_EQ(start_run(load_config_string(config(true, 6), "test"), replicate, out, err),
                  kExitOk)
            << err.str();
    }
    static void TearDownTestSuite() { delete scratch_; }
    static fs::path mixture() { return scratch_->path() / "mixture"; }
    static fs::path medium_only() { return scratch_->path() / "medium-only"; }
    static fs::path mixture_seed6() { return scratch_->path() / "mixture-seed6"; }
    static ScratchDir* scratch_;
};
ScratchDir* AnalyzeCli::scratch_ = nullptr;

TEST_F(AnalyzeCli, SteadyPolarOrderIsTheMeanOfTheRunsOwnSeries) {
    AnalyzeRequest request;
    request.from = 0.01;
    request.observables = {"order"};
    const PreparedRun run = prepare_run(mixture(), request);
    EXPECT_EQ(run.window.first_frame, 5u);  // frames every 2 ms
    request.from = 0.0101;                  // the first frame at or after it: 0.012 s
    EXPECT_EQ(prepare_run(mixture(), request).window.first_frame, 6u);
    request.from = 0.01;
    std::ostringstream log;
    const RunAnalysis a = analyze_run(run, log, true);
    const std::vector<double> recorded =
        TrajectoryReader(mixture() / "trajectory.h5").series("polar_order_polar");
    double mean = 0.0;
    for (std::size_t k = 5; k < recorded.size(); ++k)
        mean += recorded[k];
    mean /= static_cast<double>(recorded.size() - 5);
    // The run's series comes from double-precision angles, the analysis from the float32 frames:
    // they agree to float rounding (1e-6 relative in each angle).
    ASSERT_EQ(a.results[0].scalars[0].name, "P_polar");
    EXPECT_NEAR(a.results[0].scalars[0].estimate.mean, mean, 1e-5);
}

// --to analyses the run as if it had ended there: the mean is the recorded series' over the
// window and nothing after it, the frames left out are named, and a run still being written
// needs no note when the window ends before its last frame.
TEST_F(AnalyzeCli, ToEndsTheWindowAsIfTheRunHadEndedThere) {
    AnalyzeRequest request;
    request.from = 0.01;
    request.to = 0.0301;  // the last frame at or before it: 0.030 s
    request.observables = {"order"};
    const RunDirectoryLock writer(mixture());
    const PreparedRun run = prepare_run(mixture(), request);
    EXPECT_EQ(run.times.size(), 16u);  // 0 to 30 ms every 2 ms
    EXPECT_EQ(run.window.first_frame, 5u);
    EXPECT_EQ(run.setup.steady_frames, 11u);
    EXPECT_TRUE(run.window.to_given);
    EXPECT_NEAR(run.times.back(), 0.03, 1e-12);
    EXPECT_EQ(run.stored_frames, 21u);
    EXPECT_EQ(run.still_running, "");
    ASSERT_FALSE(run.skipped.empty());
    EXPECT_NE(run.skipped.back().find("5 frames after --to"), std::string::npos)
        << run.skipped.back();
    std::ostringstream log;
    const RunAnalysis a = analyze_run(run, log, true);
    const std::vector<double> recorded =
        TrajectoryReader(mixture() / "trajectory.h5").series("polar_order_polar");
    double mean = 0.0;
    for (std::size_t k = 5; k <= 15; ++k)
        mean += recorded[k];
    mean /= 11.0;
    // Float32 frames against the run's double-precision series, as above.
    ASSERT_EQ(a.results[0].scalars[0].name, "P_polar");
    EXPECT_NEAR(a.results[0].scalars[0].estimate.mean, mean, 1e-5);
}

// A run that a process still writes (its lock held, as `rodsea run` holds it) is analysed as
// far as it has gone, and the analysis says so, with where progress.txt puts the run; once no
// process holds it, nothing is said.
TEST_F(AnalyzeCli, ARunStillGoingIsAnalysedWithANoteThatSaysSo) {
    AnalyzeRequest request;
    request.observables = {"order"};
    {
        const RunDirectoryLock writer(mixture());
        const PreparedRun run = prepare_run(mixture(), request);
        EXPECT_NE(run.still_running.find("still going (t = 0.04 of 0.04 s)"), std::string::npos)
            << run.still_running;
        std::ostringstream log;
        analyze_run(run, log, false);
        EXPECT_NE(log.str().find("NOTE: the run is still going"), std::string::npos) << log.str();
    }
    EXPECT_EQ(prepare_run(mixture(), request).still_running, "");
}

// The column `name` of the table `table` of the observable `observable`, one value per row.
std::vector<double> table_column(const RunAnalysis& a, const std::string& observable,
                                 const std::string& table, const std::string& name) {
    for (const ObservableResults& r : a.results) {
        if (r.observable != observable) continue;
        for (const TableResult& t : r.tables) {
            if (t.name != table) continue;
            const auto c = std::find(t.columns.begin(), t.columns.end(), name) - t.columns.begin();
            std::vector<double> v;
            for (const std::vector<double>& row : t.rows)
                v.push_back(row[static_cast<std::size_t>(c)]);
            return v;
        }
    }
    return {};
}

TEST_F(AnalyzeCli, TheRunRecordsSegregationAndTheLargestFlockAsAnalyzeMeasuresThem) {
    // The steady window looks at Σ and N_m from the run's own series: they must be the analysis'
    // numbers, frame by frame. The run measures double-precision positions, the analysis float32
    // frames; a body within 1e-6 mm of a cell edge or of eps could tip one count, which these
    // 21 frames (a fixed seed) do not have.
    AnalyzeRequest request;
    request.from = 0.0;
    request.observables = {"segregation", "flocks"};
    std::ostringstream log;
    const RunAnalysis a = analyze_run(prepare_run(mixture(), request), log, true);
    const TrajectoryReader reader(mixture() / "trajectory.h5");
    const std::vector<double> sigma = reader.series("segregation");
    const std::vector<double> largest = reader.series("largest_flock");
    EXPECT_EQ(sigma, table_column(a, "segregation", "segregation", "Sigma_raw"));
    EXPECT_EQ(largest, table_column(a, "flocks", "flocks", "N_m"));
    // Without polar rods neither exists.
    EXPECT_FALSE(TrajectoryReader(medium_only() / "trajectory.h5").has_series("segregation"));
}

TEST_F(AnalyzeCli, TheAutomaticWindowNamesEveryOrderSeriesAndTheOneThatDecided) {
    const PreparedRun run = prepare_run(mixture(), {});
    ASSERT_TRUE(run.window.automatic);
    std::vector<std::string> names;
    for (const SeriesStart& s : run.window.series)
        names.push_back(s.name);
    EXPECT_EQ(names,
              (std::vector<std::string>{"polar_order_polar", "nematic_order_polar",
                                        "nematic_order_medium", "segregation", "largest_flock"}));
    // The window starts at the latest series' start, and that series is the one named.
    std::size_t latest = 0;
    for (const SeriesStart& s : run.window.series)
        latest = std::max(latest, s.start);
    EXPECT_EQ(run.window.first_frame, latest);
    const auto decided = std::find(names.begin(), names.end(), run.window.basis);
    ASSERT_NE(decided, names.end());
    EXPECT_EQ(run.window.series[static_cast<std::size_t>(decided - names.begin())].start, latest);
}

TEST_F(AnalyzeCli, OneFrameWindowGivesValuesWithoutErrorBars) {
    // One steady frame: means exist, error bars cannot (NaN, JSON null), time blocks shrink to
    // the frames there are, and C(t) needs two frames so it is skipped with its reason.
    AnalyzeRequest request;
    request.from = 0.04;
    const PreparedRun run = prepare_run(mixture(), request);
    EXPECT_EQ(run.setup.steady_frames, 1u);
    EXPECT_EQ(run.setup.blocks, 1);
    ASSERT_FALSE(run.skipped.empty());
    EXPECT_NE(run.skipped[0].find("autocorrelation"), std::string::npos);
    std::ostringstream log;
    const RunAnalysis a = analyze_run(run, log, true);
    for (const ObservableResults& r : a.results)
        for (const ScalarResult& s : r.scalars) {
            // Not time averages: the random-mixing Σ and the random |ρ_k|, √(π/4N).
            if (s.name == "Sigma_baseline" || s.name == "band_random") continue;
            EXPECT_TRUE(std::isnan(s.estimate.error)) << s.name;
        }
}

TEST_F(AnalyzeCli, WritesJsonCsvAndHdf5ThatPythonReads) {
    const ChildResult r =
        run_rodsea({"analyze", mixture().string(), "--from", "0.01"}, scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
    EXPECT_NE(r.out.find("steady window from 0.01 s"), std::string::npos) << r.out;
    const fs::path dir = mixture() / "analysis";
    for (const char* f : {"analysis.json", "analysis.h5", "summary.csv", "order_parameters.csv",
                          "pair_correlation_polar.csv", "orientation_autocorrelation.csv",
                          "flocks.csv", "segregation.csv", "bands.csv", "medium_velocity.csv"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    // Debian's Python reads what the docs promise: the JSON's P with an error bar, the maps'
    // shapes matching their bin edges, one flock label per polar rod per frame.
    const std::string script =
        "import json, h5py, numpy as np, sys\n"
        "d = sys.argv[1]\n"
        "j = json.load(open(d + '/analysis.json'))\n"
        "p = j['observables']['order']['scalars']['P_polar']\n"
        "assert 0 <= p['value'] <= 1 and p['error'] >= 0, p\n"
        "assert j['steady_state']['first_frame'] == 5\n"
        "with h5py.File(d + '/analysis.h5') as f:\n"
        "    g = f['maps/g_r_theta']\n"
        "    assert g['value'].shape == (len(g['r_edges']) - 1, len(g['theta_edges']) - 1)\n"
        "    assert f['labels/flock_labels/value'].shape == (21, 6)\n"
        "t = np.loadtxt(d + '/order_parameters.csv', delimiter=',', skiprows=2)\n"
        "steady = t[t[:, 1] == 1, 2]\n"
        "assert abs(steady.mean() - p['value']) < 1e-12\n";
    std::ofstream(scratch_->path() / "check.py") << script;
    const std::string command = "/usr/bin/python3 " + (scratch_->path() / "check.py").string() +
                                " " + dir.string() + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0);
}

TEST_F(AnalyzeCli, SeveralRunsGiveOneRowEach) {
    const fs::path table = scratch_->path() / "table.csv";
    const ChildResult r = run_rodsea({"analyze", mixture().string(), medium_only().string(),
                                      "--table", table.string(), "--quiet"},
                                     scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    std::ifstream in(table);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(in, line))
        lines.push_back(line);
    ASSERT_EQ(lines.size(), 4u);  // comment, header, two runs
    EXPECT_NE(lines[1].find("phi_medium"), std::string::npos);
    EXPECT_NE(lines[1].find("P_polar_err"), std::string::npos);
    EXPECT_NE(lines[2].find("mixture"), std::string::npos);
    EXPECT_NE(lines[3].find("medium-only"), std::string::npos);
}

// The CSV's rows as maps from column name to cell (no cell of these runs holds a comma).
std::vector<std::map<std::string, std::string>> read_table(const fs::path& path) {
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);  // the comment
    const auto cells = [](const std::string& text) {
        std::vector<std::string> out;
        std::stringstream s(text);
        for (std::string cell; std::getline(s, cell, ',');)
            out.push_back(cell);
        if (!text.empty() && text.back() == ',') out.emplace_back();
        return out;
    };
    std::getline(in, line);
    const std::vector<std::string> header = cells(line);
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        const std::vector<std::string> c = cells(line);
        std::map<std::string, std::string> row;
        for (std::size_t i = 0; i < header.size() && i < c.size(); ++i)
            row[header[i]] = c[i];
        rows.push_back(std::move(row));
    }
    return rows;
}

TEST_F(AnalyzeCli, ReplicatesGetOneRowWithTheErrorFromTheirSpread) {
    const fs::path table = scratch_->path() / "replicates.csv";
    const ChildResult r =
        run_rodsea({"analyze", mixture().string(), medium_only().string(), mixture_seed6().string(),
                    "--observables", "order", "--table", table.string()},
                   scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("replicates: 2 runs of one state point (seeds 5 6)"), std::string::npos)
        << r.out;
    const auto rows = read_table(table);
    ASSERT_EQ(rows.size(), 4u);  // three runs, one group: the medium alone has no replicate
    const auto& group = rows[3];
    EXPECT_NE(group.at("run").find("replicates of"), std::string::npos);
    EXPECT_EQ(group.at("replicates"), "2");
    EXPECT_EQ(group.at("seed"), "5 6");
    // Two values: the mean is their midpoint, sd/√2 is half their difference, and χ²/1 is the
    // squared difference from the mean over each run's own error, summed.
    const double a = std::stod(rows[0].at("P_polar")), b = std::stod(rows[2].at("P_polar"));
    const double ea = std::stod(rows[0].at("P_polar_err")),
                 eb = std::stod(rows[2].at("P_polar_err"));
    EXPECT_NEAR(std::stod(group.at("P_polar")), 0.5 * (a + b), 1e-12);
    EXPECT_NEAR(std::stod(group.at("P_polar_err")), 0.5 * std::abs(a - b), 1e-12);
    const double d2 = 0.25 * (a - b) * (a - b);
    EXPECT_NEAR(std::stod(group.at("P_polar_chi2")), d2 / (ea * ea) + d2 / (eb * eb),
                1e-9 * (d2 / (ea * ea) + d2 / (eb * eb)));
    for (const auto& row : {rows[0], rows[2]}) {
        EXPECT_TRUE(row.at("P_polar_short") == "0" || row.at("P_polar_short") == "1");
        EXPECT_EQ(row.at("replicates"), "");
    }
}

// The same run given twice would be two replicates with no spread: refused. A copy of a run
// (its config and seed) is its trajectory again: counted once, and said so. The sentence about
// short windows comes once, the lines it concerns marked.
TEST_F(AnalyzeCli, TheSameRunTwiceIsNotAReplicate) {
    const ChildResult twice = run_rodsea(
        {"analyze", mixture().string(), (mixture() / "").string(), "--observables", "order"},
        scratch_->path());
    EXPECT_EQ(twice.exit_code, 2);
    EXPECT_NE(twice.err.find("the same run"), std::string::npos) << twice.err;

    const fs::path copy = scratch_->path() / "mixture-copy";
    fs::copy(mixture(), copy, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    const fs::path table = scratch_->path() / "copies.csv";
    const ChildResult r = run_rodsea({"analyze", mixture().string(), copy.string(), "--observables",
                                      "order", "--table", table.string()},
                                     scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find("the same trajectory, counted once"), std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("runs of one state point"), std::string::npos) << r.out;
    EXPECT_EQ(read_table(table).size(), 2u);  // the two runs' rows, no group
    const std::string sentence = "the error bar is an underestimate";
    const std::size_t first = r.out.find(sentence);
    if (first != std::string::npos) {
        EXPECT_EQ(r.out.find(sentence, first + 1), std::string::npos) << r.out;
    }
}

struct BadCase {
    std::vector<std::string> args;
    int exit_code;
    std::string message;
};

TEST_F(AnalyzeCli, BadInputIsRefusedByNameAndWritesNothing) {
    const fs::path junk = scratch_->path() / "junk";
    fs::create_directories(junk);
    std::ofstream(junk / "trajectory.h5") << "this is not HDF5\n";
    const fs::path truncated = scratch_->path() / "truncated";
    fs::create_directories(truncated);
    fs::copy_file(mixture() / "trajectory.h5", truncated / "trajectory.h5");
    fs::resize_file(truncated / "trajectory.h5", fs::file_size(truncated / "trajectory.h5") / 2);
    const std::string mix = mixture().string(), medium = medium_only().string();
    const std::vector<BadCase> cases{
        {{"analyze", junk.string()}, 74, "trajectory.h5"},
        {{"analyze", truncated.string()}, 74, "trajectory.h5"},
        {{"analyze", (scratch_->path() / "missing").string()}, 74, "no such file"},
        {{"analyze", mix, "--from", "5"}, 2, "[0, 0.04] s"},
        {{"analyze", mix, "--from", "-1"}, 2, "--from"},
        {{"analyze", mix, "--to", "5"}, 2, "invalid --to = 5 s: allowed [0, 0.04] s"},
        // --from past --to: the message names both ends.
        {{"analyze", mix, "--from", "0.03", "--to", "0.02"},
         2,
         "invalid --to = 0.02 s: allowed at least --from (0.03 s)"},
        // A window between two frames holds none: refused, not analysed empty.
        {{"analyze", mix, "--from", "0.0201", "--to", "0.0219"}, 2, "at least one frame"},
        {{"analyze", medium, "--observables", "flocks"}, 2, "needs polar rods"},
        {{"analyze", mix, "--observables", "flock"}, 2, "did you mean 'flocks'"},
        {{"analyze", mix, "--param", "flocks.epss=1"}, 2, "did you mean 'flocks.eps'"},
        {{"analyze", mix, "--param", "flocks.eps=-1"},
         2,
         "invalid --param flocks.eps = -1: allowed"},
        {{"analyze", mix, "--param", "pair.r_max=50"}, 2, "L/2 = 10"},
        {{"analyze", mix, medium, "--out", "x"}, 2, "--out"},
    };
    fs::remove_all(mixture() / "analysis");
    fs::remove_all(medium_only() / "analysis");
    for (const BadCase& c : cases) {
        const ChildResult r = run_rodsea(c.args, scratch_->path());
        EXPECT_EQ(r.exit_code, c.exit_code) << c.args[1] << " " << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    }
    // Everything is checked before anything is computed or written.
    EXPECT_FALSE(fs::exists(mixture() / "analysis"));
    EXPECT_FALSE(fs::exists(medium_only() / "analysis"));
    EXPECT_FALSE(fs::exists(junk / "analysis"));
}

}  // namespace
}  // namespace rodsea
