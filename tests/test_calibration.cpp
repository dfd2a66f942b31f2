// Single-body experiments, the raw material of `rodsea calibrate`: the D_r estimator recovers a
// known rotational diffusion, and a lone polar rod without noise keeps its axis (D_r ≈ 0) while
// it travels along it consistently.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <memory>
#include <numbers>
#include <sstream>

#include "child_process.hpp"
#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/calibration/single_body_experiment.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/random.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

// Angles of a rotational random walk with diffusion coefficient d_r, sampled every `interval`.
SingleBodyTrace random_walk(double d_r, double interval, std::size_t samples, std::uint64_t seed) {
    SplitMix64 rng(seed);
    SingleBodyTrace t;
    double angle = 0.0;
    for (std::size_t k = 0; k < samples; ++k) {
        // Gaussian step of variance 2 D_r Δt by Box–Muller.
        const double u = std::max(rng.uniform(), 1e-300), v = rng.uniform();
        angle += std::sqrt(2.0 * d_r * interval) * std::sqrt(-2.0 * std::log(u)) *
                 std::cos(2.0 * std::numbers::pi * v);
        t.angle.push_back(angle);
        t.axial.push_back(0.01);  // 2 mm/s at a 5 ms interval
        t.transverse.push_back(0.0);
    }
    return t;
}

TEST(SingleBodyExperiment, RecoversTheRotationalDiffusionOfARandomWalk) {
    // 16 walks of 2 s at 5 ms, D_r = 0.8 rad²/s: C(t) falls to 0.2 in 2 s, and the
    // jackknife error must cover the truth (3 errors: a miss once in ~370).
    std::vector<SingleBodyTrace> walks;
    for (std::uint64_t s = 0; s < 16; ++s)
        walks.push_back(random_walk(0.8, 0.005, 400, 11 + s));
    const SingleBodyResult r = combine_single_body_traces(walks, 0.005);
    EXPECT_NEAR(r.rotational_diffusion.mean, 0.8, 3.0 * r.rotational_diffusion.error);
    // The error is an honest fraction: 16 walks of 1.6 correlation times each give ~10 %.
    EXPECT_GT(r.rotational_diffusion.error, 0.02);
    EXPECT_LT(r.rotational_diffusion.error, 0.25);
    EXPECT_NEAR(r.axial_speed.mean, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(r.forward_fraction, 1.0);
    EXPECT_EQ(r.period_speeds.size(), 16u * 400u);
    EXPECT_DOUBLE_EQ(r.correlation.front(), 1.0);
}

TEST(SingleBodyExperiment, WithoutNoiseALonePolarRodKeepsItsAxisAndTravelsAlongIt) {
    // ε = 0 and nothing to collide with: nothing turns the rod once its start spin has died
    // down, so its axis does not diffuse. 4 copies × 1 s at the default drive and gap.
    SingleBodyExperiment e;
    e.species = polar_rod_species();
    e.copies = 4;
    e.duration = 1.0;
    std::vector<SingleBodyTrace> traces;
    for (int c = 0; c < e.copies; ++c)
        traces.push_back(run_single_body_copy(e, c));
    const SingleBodyResult r = combine_single_body_traces(traces, 0.005);
    // The paper's smallest non-zero D_r is 0.026 rad²/s: "no noise" must be far below it.
    EXPECT_LT(r.rotational_diffusion.mean, 1e-3);
    // Every copy travels the same way along its axis, many standard errors from zero.
    EXPECT_TRUE(r.forward_fraction == 0.0 || r.forward_fraction == 1.0);
    EXPECT_GT(std::abs(r.axial_speed.mean), 5.0 * r.axial_speed.error);
    EXPECT_GT(std::abs(r.axial_speed.mean), 3.0 * std::abs(r.transverse_speed.mean));
    EXPECT_EQ(r.unresolved, 0u);
}

TEST(SingleBodyExperiment, NoiseMakesTheAxisDiffuse) {
    // ε = 0.01 /mm kicks the rod at every plate hit: D_r well above zero (~0.07 rad²/s).
    SingleBodyExperiment e;
    e.species = polar_rod_species();
    e.epsilon = 0.01;
    e.copies = 4;
    e.duration = 1.0;
    std::vector<SingleBodyTrace> traces;
    for (int c = 0; c < e.copies; ++c)
        traces.push_back(run_single_body_copy(e, c));
    const SingleBodyResult r = combine_single_body_traces(traces, 0.005);
    EXPECT_GT(r.rotational_diffusion.mean, 0.01);
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

namespace fs = std::filesystem;

std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        if (line.rfind('#', 0) == 0) continue;
        std::vector<std::string> cells;
        std::stringstream s(line);
        std::string cell;
        while (std::getline(s, cell, ','))
            cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

class CalibrateCli : public ::testing::Test {
  protected:
    void SetUp() override {
        scratch_ = std::make_unique<ScratchDir>("calibrate");
        std::ofstream(path("grid.toml"))
            << "[calibrate]\nspecies = \"polar_rod\"\nepsilon = [0.0, 0.01]\ngap = [1.4, 1.5]\n"
               "copies = 2\nduration = 0.1\nwarmup = 0.02\n";
    }
    fs::path path(const std::string& name) const { return scratch_->path() / name; }
    std::unique_ptr<ScratchDir> scratch_;
};

TEST_F(CalibrateCli, TinyGridGivesAWellFormedTableWhateverTheThreadCount) {
    for (const std::string threads : {"1", "2"}) {
        const ChildResult r =
            run_rodsea({"calibrate", path("grid.toml").string(), "--out",
                        path("out" + threads).string(), "--threads", threads, "--quiet"},
                       scratch_->path());
        ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const auto rows = csv_rows(path("out1") / "calibration.csv");
    ASSERT_EQ(rows.size(), 5u);  // header + 2 gaps × 2 ε
    const std::vector<std::string>& h = rows[0];
    const auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
    };
    for (const std::string name : {"gap", "dt", "epsilon", "D_r", "D_r_err", "speed", "speed_err",
                                   "forward_fraction", "copies", "unresolved"})
        ASSERT_LT(col(name), h.size()) << name;
    // Points in grid order, ε fastest; D_r is a diffusion coefficient, the forward fraction a
    // fraction of 2 copies.
    const std::vector<std::pair<double, double>> order{
        {1.4, 0.0}, {1.4, 0.01}, {1.5, 0.0}, {1.5, 0.01}};
    for (std::size_t i = 0; i < order.size(); ++i) {
        const auto& row = rows[i + 1];
        ASSERT_EQ(row.size(), h.size());
        EXPECT_DOUBLE_EQ(std::stod(row[col("gap")]), order[i].first);
        EXPECT_DOUBLE_EQ(std::stod(row[col("epsilon")]), order[i].second);
        EXPECT_GE(std::stod(row[col("D_r")]), 0.0);
        const double f = std::stod(row[col("forward_fraction")]);
        EXPECT_TRUE(f == 0.0 || f == 0.5 || f == 1.0) << f;
        EXPECT_EQ(row[col("copies")], "2");
        EXPECT_EQ(row[col("unresolved")], "0");
    }
    // Each point's speed distribution is a probability density: it integrates to 1.
    const auto dist = csv_rows(path("out1") / "speed_distribution.csv");
    std::vector<double> integral(4, 0.0);
    for (std::size_t i = 1; i < dist.size(); ++i)
        integral[std::stoul(dist[i][0])] +=
            std::stod(dist[i][6]) * (std::stod(dist[i][5]) - std::stod(dist[i][4]));
    // Values are written to 8 significant digits: 41 bins of relative rounding 5e-9 each.
    for (double v : integral)
        EXPECT_NEAR(v, 1.0, 1e-6);
    // The same table, bit for bit, on one thread and on two.
    EXPECT_EQ(read_text(path("out1") / "calibration.csv"),
              read_text(path("out2") / "calibration.csv"));
}

TEST_F(CalibrateCli, BadConfigIsRefusedByKeyBeforeAnyRun) {
    struct Case {
        std::string toml, message;
    };
    const std::vector<Case> cases{
        {"[calibrate]\nepsilom = [0.1]\n", "did you mean 'epsilon'"},
        {"[calibrate]\ngap = [1.2]\n", "diameter 1.375 mm"},
        {"[calibrate]\nspecies = \"disc\"\n", "\"polar_rod\", \"apolar_rod\" or \"bead\""},
        {"[calibrate]\ncopies = 1\n", "calibrate.copies"},
        {"[calibrate]\nlength = 3.0\n", "only with species = \"apolar_rod\""},
        {"[calibrat]\n", "[calibrate] only"},
    };
    for (const Case& c : cases) {
        std::ofstream(path("bad.toml")) << c.toml;
        const ChildResult r =
            run_rodsea({"calibrate", path("bad.toml").string(), "--out", path("bad-out").string()},
                       scratch_->path());
        EXPECT_EQ(r.exit_code, 2) << c.toml << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(path("bad-out")));
    }
}

}  // namespace
}  // namespace rodsea

namespace rodsea {
namespace {

// A config giving D_r gets the ε that the table interpolates, measured at its own gap and dt;
// the resolved config holds that ε, so a stored run never needs the table again.
class ConfigFromCalibrationTable : public ::testing::Test {
  protected:
    inline static const double kGap = DriveParameters{}.gap;  // mm
    inline static const double kDt = EngineParameters{}.dt;   // s
    static std::string exact(double x) {
        std::ostringstream s;
        s << std::setprecision(17) << x;
        return s.str();
    }
    void SetUp() override {
        scratch_ = std::make_unique<ScratchDir>("calibration-table");
        // The map at the default gap and dt, and one row each at another gap and another dt.
        write_table("cal.csv", {{kGap, kDt, 0.0, 0.0},
                                {kGap, kDt, 0.01, 0.1},
                                {kGap, kDt, 0.02, 0.5},
                                {kGap + 0.1, kDt, 0.01, 0.7},
                                {kGap, 2 * kDt, 0.01, 0.9}});
    }
    // Rows of (gap mm, dt s, ε 1/mm, D_r rad²/s) with the columns rodsea calibrate writes.
    void write_table(const std::string& name, const std::vector<std::array<double, 4>>& rows) {
        std::ofstream out(path(name));
        out << "# rodsea calibration\nspecies,gap,dt,epsilon,D_r,D_r_err,speed\n";
        for (const auto& [gap, dt, eps, d_r] : rows)
            out << "polar_rod," << gap << ',' << dt << ',' << eps << ',' << d_r << ",0.01,3\n";
        out << "bead,1.5,5e-06,0.05,7,0,0\n";  // other species are not the polar rod's map
    }
    RunPlan load(const std::string& table, double d_r, const std::string& extra = "") {
        return load_config_string("[noise]\nrotational_diffusion = " + std::to_string(d_r) +
                                      "\ncalibration_table = \"" + path(table).string() + "\"\n" +
                                      extra,
                                  "test", calibration_table_lookup());
    }
    fs::path path(const std::string& name) const { return scratch_->path() / name; }
    std::unique_ptr<ScratchDir> scratch_;
};

TEST_F(ConfigFromCalibrationTable, InterpolatesEpsilonAtTheRunsGapAndStep) {
    // At the default gap and dt, D_r = 0.3 lies halfway between 0.1 (ε 0.01) and 0.5 (0.02).
    EXPECT_NEAR(load("cal.csv", 0.3).engine.noise_epsilon, 0.015, 1e-12);
    EXPECT_NEAR(load("cal.csv", 0.05).engine.noise_epsilon, 0.005, 1e-12);
    EXPECT_NEAR(load("cal.csv", 0.5).engine.noise_epsilon, 0.02, 1e-12);  // the table's end
    // The rows at another gap or step are another map.
    EXPECT_THROW(load("cal.csv", 0.3, "[drive]\ngap = " + exact(kGap + 0.1) + "\n"),
                 InvalidParameter);
    EXPECT_THROW(load("cal.csv", 0.3, "[time]\ndt = " + exact(2 * kDt) + "\n"), InvalidParameter);
    // Stored runs carry ε itself: their config loads without the table.
    const RunPlan plan = load("cal.csv", 0.3);
    fs::remove(path("cal.csv"));
    EXPECT_NEAR(load_config_string(plan.config_toml, "stored").engine.noise_epsilon, 0.015, 1e-12);
}

TEST_F(ConfigFromCalibrationTable, TheCommittedTableGivesThePapersNoiseAtTheDefaults) {
    // data/calibration.csv is measured at the default gap and dt (validate/epsilon.toml), so the
    // paper's D_r values resolve without naming either, to ε growing with D_r. A changed default
    // gap or dt without a re-measured table fails here.
    const fs::path table = fs::path(RODSEA_SOURCE_DIR) / "data" / "calibration.csv";
    EXPECT_EQ(load(table.string(), 0.0).engine.noise_epsilon, 0.0);  // its ε = 0 row
    double previous = 0.0;
    for (double d_r : {0.026, 0.23, 1.21, 1.87}) {
        SCOPED_TRACE(d_r);
        const double eps = load(table.string(), d_r).engine.noise_epsilon;
        EXPECT_GT(eps, previous);
        previous = eps;
    }
}

TEST_F(ConfigFromCalibrationTable, RefusesWhatTheTableCannotAnswer) {
    const auto message = [&](const std::string& table, double d_r) {
        try {
            load(table, d_r);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    // Outside the measured range: the message gives the range and the way to extend it.
    const std::string above = message("cal.csv", 0.6);
    EXPECT_NE(above.find("noise.rotational_diffusion"), std::string::npos) << above;
    EXPECT_NE(above.find("[0, 0.5] rad²/s"), std::string::npos) << above;
    EXPECT_NE(above.find("rodsea calibrate"), std::string::npos) << above;
    // Below a table that does not start at ε = 0 is outside it too; one that does start there
    // maps any D_r up to its noiseless rod's to ε = 0.
    write_table("noisy.csv", {{kGap, kDt, 0.01, 0.1}, {kGap, kDt, 0.02, 0.5}});
    EXPECT_NE(message("noisy.csv", 0.05).find("[0.1, 0.5] rad²/s"), std::string::npos);
    write_table("offset.csv", {{kGap, kDt, 0.0, 0.001}, {kGap, kDt, 0.02, 0.5}});
    EXPECT_EQ(load("offset.csv", 0.0005).engine.noise_epsilon, 0.0);
    // D_r that does not grow with ε cannot be inverted.
    write_table("flat.csv",
                {{kGap, kDt, 0.0, 0.0}, {kGap, kDt, 0.01, 0.2}, {kGap, kDt, 0.02, 0.2}});
    EXPECT_NE(message("flat.csv", 0.1).find("D_r increasing with ε"), std::string::npos);
    // One point is not a map; the message lists the gaps and steps the table does have.
    write_table("one.csv", {{1.5, 5e-6, 0.0, 0.0}, {1.6, 5e-6, 0.01, 0.2}});
    const std::string one = message("one.csv", 0.0);
    EXPECT_NE(one.find("its gaps: 1.5, 1.6 mm"), std::string::npos) << one;
    // A missing file is a file error naming it.
    EXPECT_THROW(load("missing.csv", 0.1), FileError);
}

}  // namespace
}  // namespace rodsea
