// `rodsea calibrate` as users run it: a tiny grid gives a well-formed table, the same on one
// thread and on two, and a bad config is refused by key before any copy runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "child_process.hpp"
#include "rodsea/engine/backend_factory.hpp"
#include "scratch_dir.hpp"
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
    for (const std::string name : {"gap", "dt", "noise_mode", "epsilon", "D_r", "D_r_err", "speed",
                                   "speed_err", "forward_fraction", "copies", "unresolved"})
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
        EXPECT_EQ(row[col("noise_mode")], "add");  // the default rule
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

// The set rule's table says so in its noise_mode column, and a set kick turns the lone rod: at
// ε = 1 /mm its D_r is ~0.3 rad²/s (pilot, 4 copies × 2 s), against ~1e-5 without noise.
TEST_F(CalibrateCli, TheSetRuleIsCalibratedAndLabelled) {
    std::ofstream(path("set.toml"))
        << "[calibrate]\nspecies = \"polar_rod\"\nnoise_mode = \"set\"\nepsilon = [1.0]\n"
           "copies = 2\nduration = 0.3\nwarmup = 0.02\n";
    const ChildResult r = run_rodsea(
        {"calibrate", path("set.toml").string(), "--out", path("set").string(), "--quiet"},
        scratch_->path());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto rows = csv_rows(path("set") / "calibration.csv");
    ASSERT_EQ(rows.size(), 2u);
    const std::vector<std::string>& h = rows[0];
    const auto col = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(h.begin(), h.end(), name) - h.begin());
    };
    ASSERT_LT(col("noise_mode"), h.size());
    EXPECT_EQ(rows[1][col("noise_mode")], "set");
    EXPECT_GT(std::stod(rows[1][col("D_r")]), 0.01);
}

// --backend gpu where no GPU can run is refused before any work, saying why; a bad name too.
TEST_F(CalibrateCli, AnUnusableGpuIsRefusedBeforeAnyRun) {
    const ChildResult bad = run_rodsea({"calibrate", path("grid.toml").string(), "--out",
                                        path("bad").string(), "--backend", "tpu"},
                                       scratch_->path());
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_NE(bad.err.find("--backend = tpu"), std::string::npos) << bad.err;
    EXPECT_FALSE(fs::exists(path("bad")));
    const GpuAvailability gpu = gpu_availability();
    if (gpu.usable) GTEST_SKIP() << "a GPU is usable here: " << gpu.description;
    const ChildResult r = run_rodsea({"calibrate", path("grid.toml").string(), "--out",
                                      path("gpu").string(), "--backend", "gpu"},
                                     scratch_->path());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.err.find("invalid --backend = gpu"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(gpu.description), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(path("gpu")));
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
        // Each noise rule has its own ε range.
        {"[calibrate]\nepsilon = [1.0]\n", "allowed [0 1/mm, 0.5 1/mm]"},
        {"[calibrate]\nnoise_mode = \"set\"\nepsilon = [6.0]\n", "allowed [0 1/mm, 5 1/mm]"},
        {"[calibrate]\nnoise_mode = \"kick\"\n", "\"add\" or \"set\""},
        // Two drive periods fit no lag of C(t): D_r came out as 0 ± 0.
        {"[calibrate]\nduration = 0.01\n", "calibrate.duration = 0.01 s: allowed [0.1 s"},
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
