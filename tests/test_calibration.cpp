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

#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/calibration/single_body_experiment.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/backend_factory.hpp"
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

// The copies of several points stepped together as one ensemble (what `rodsea calibrate
// --backend gpu` does on a device) give each copy the trace it has alone on the same backend, bit
// for bit: here on the CPU and on the GPU's algorithm run by the host.
// Traces too short for one lag of C(t) give no D_r, not a D_r of 0.
TEST(SingleBodyExperiment, TracesTooShortToFitGiveNoRotationalDiffusion) {
    SingleBodyTrace t;
    t.angle = {0.0, 0.1, 0.2};  // three periods: C(t) to lag 3 / 4 = 0
    t.axial = t.transverse = {0.0, 0.0, 0.0};
    const SingleBodyResult r = combine_single_body_traces({t, t}, 0.005);
    EXPECT_TRUE(std::isnan(r.rotational_diffusion.mean)) << r.rotational_diffusion.mean;
}

TEST(SingleBodyExperiment, CopiesSteppedTogetherHaveTheirLoneTraces) {
    std::vector<SingleBodyExperiment> points(2);
    for (SingleBodyExperiment& e : points) {
        e.species = polar_rod_species();
        e.warmup = 0.01;
        e.duration = 0.05;
    }
    points[1].epsilon = 0.02;
    points[1].drive.gap = 1.5;
    const int copies = 2;
    for (const BackendKind kind : {BackendKind::cpu, BackendKind::gpu_on_host}) {
        BackendOptions options;
        options.backend = kind;
        int calls = 0;
        const auto together =
            run_single_body_copies_together(points, copies, options, [&calls](double) { ++calls; });
        ASSERT_TRUE(together.has_value());
        EXPECT_EQ(calls, 12);  // 2 warm-up + 10 measured periods of 5 ms
        for (std::size_t p = 0; p < points.size(); ++p)
            for (int c = 0; c < copies; ++c) {
                const SingleBodyTrace alone = run_single_body_copy(points[p], c, options);
                const SingleBodyTrace& t = (*together)[p][static_cast<std::size_t>(c)];
                SCOPED_TRACE(std::string(to_string(kind)) + " point " + std::to_string(p) +
                             " copy " + std::to_string(c));
                ASSERT_EQ(t.angle.size(), 10u);
                EXPECT_EQ(t.angle, alone.angle);
                EXPECT_EQ(t.axial, alone.axial);
                EXPECT_EQ(t.transverse, alone.transverse);
            }
    }
    // Points with another dt cannot step in lockstep.
    points[1].dt = 2.5e-6;
    EXPECT_THROW(run_single_body_copies_together(points, copies, {}), InvalidParameter);
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
        // The set rule's rows: a kick that replaces ω_z instead of adding to it needs an ε tens
        // of times larger for the same D_r (0.35-2.45 /mm against 0.006-0.031: docs/validation.md).
        const double set = load(table.string(), d_r, "mode = \"set\"\n").engine.noise_epsilon;
        EXPECT_GT(set, 20.0 * eps);
    }
}

// Each noise mode has its own map: a table with a noise_mode column answers a run from its own
// mode's rows, and names the mode when it has none; a table without the column (written before
// there were two modes) holds add rows.
TEST_F(ConfigFromCalibrationTable, EachNoiseModeReadsItsOwnRows) {
    {
        std::ofstream out(path("modes.csv"));
        out << "species,gap,dt,noise_mode,epsilon,D_r\n";
        out << "polar_rod," << exact(kGap) << ',' << exact(kDt) << ",add,0,0\n";
        out << "polar_rod," << exact(kGap) << ',' << exact(kDt) << ",add,0.02,0.4\n";
        out << "polar_rod," << exact(kGap) << ',' << exact(kDt) << ",set,1,0.1\n";
        out << "polar_rod," << exact(kGap) << ',' << exact(kDt) << ",set,3,0.9\n";
    }
    EXPECT_NEAR(load("modes.csv", 0.2).engine.noise_epsilon, 0.01, 1e-12);
    const RunPlan set = load("modes.csv", 0.5, "mode = \"set\"\n");
    EXPECT_EQ(set.engine.noise_mode, physics::NoiseMode::set);
    EXPECT_NEAR(set.engine.noise_epsilon, 2.0, 1e-12);  // halfway from 0.1 to 0.9
    // The stored config keeps the mode beside the ε it resolved to.
    const RunPlan stored = load_config_string(set.config_toml, "stored");
    EXPECT_EQ(stored.engine.noise_mode, physics::NoiseMode::set);
    EXPECT_EQ(stored.engine.noise_epsilon, set.engine.noise_epsilon);
    try {
        load("cal.csv", 0.2, "mode = \"set\"\n");  // no noise_mode column: add rows only
        ADD_FAILURE() << "a table of add rows answered a set run";
    } catch (const InvalidParameter& e) {
        const std::string what = e.what();
        EXPECT_EQ(e.name(), "noise.calibration_table");
        EXPECT_NE(what.find("noise.mode = set"), std::string::npos) << what;
        EXPECT_NE(what.find("its noise modes: add"), std::string::npos) << what;
    }
    {
        std::ofstream out(path("bad-mode.csv"));
        out << "species,gap,dt,noise_mode,epsilon,D_r\n";
        out << "polar_rod," << exact(kGap) << ',' << exact(kDt) << ",kick,0,0\n";
    }
    EXPECT_THROW(load("bad-mode.csv", 0.2), FileError);
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
