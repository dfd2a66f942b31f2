// Random corruptions of a small run's trajectory and checkpoint, seeded: one number at a time
// is replaced by NaN, an infinity, an absurd magnitude, an index out of range, or a plausible
// value. Every reader must either refuse the file (FileError or InvalidParameter, never a crash
// or a hang) or, for a plausible value, go on; an invalid value must never be accepted
// silently. A refused resume must leave the run's files as they were.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

#include "hdf5_poke.hpp"
#include "rodsea/analyze/analyze_run.hpp"
#include "rodsea/config/config_file.hpp"
#include "rodsea/error.hpp"
#include "rodsea/io/stored_run.hpp"
#include "rodsea/random.hpp"
#include "rodsea/run/run_driver.hpp"
#include "scratch_dir.hpp"

namespace rodsea {
namespace {

namespace fs = std::filesystem;

constexpr int kTrajectoryCorruptions = 200;
constexpr int kCheckpointCorruptions = 150;

// What is put in, and whether any reader must refuse it.
struct Injected {
    double value;
    bool invalid;
};

std::uint64_t below(SplitMix64& rng, std::uint64_t n) {
    return n == 0 ? 0 : rng.next() % n;
}

Injected draw_value(SplitMix64& rng, bool integer_dataset) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double inf = std::numeric_limits<double>::infinity();
    if (integer_dataset) {
        // Species indices: -1 and 99 are out of range; 0 and 1 are the two species.
        const double choices[] = {-1.0, 99.0, -2147483648.0, 0.0, 1.0};
        const double v = choices[below(rng, 5)];
        return {v, v < 0.0 || v > 1.0};
    }
    switch (below(rng, 6)) {
        case 0:
            return {nan, true};
        case 1:
            return {inf, true};
        case 2:
            return {-inf, true};
        case 3:
            return {1e30, true};
        case 4:
            return {-1e30, true};
        default:
            return {rng.uniform(0.0, 1.0), false};  // plausible or not: either answer is fine
    }
}

class CorruptionFuzz : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        scratch_ = new ScratchDir("fuzz");
        const RunPlan plan = load_config_string(
            "[box]\nside = 20.0\n[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = "
            "3\n[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
            "area_fraction = 0.1\n[time]\nduration = 0.004\n[output]\ninterval = 0.001\n",
            "fuzz");
        RunOptions options;
        options.out_dir = pristine();
        options.quiet = true;
        std::ostringstream out, err;
        ASSERT_EQ(start_run(plan, options, out, err), kExitOk) << err.str();
    }
    static void TearDownTestSuite() { delete scratch_; }
    static fs::path pristine() { return scratch_->path() / "pristine"; }
    static fs::path fresh_copy() {
        const fs::path copy = scratch_->path() / "copy";
        fs::remove_all(copy);
        fs::copy(pristine(), copy);
        return copy;
    }
    static ScratchDir* scratch_;
};
ScratchDir* CorruptionFuzz::scratch_ = nullptr;

// Reads everything a command reads: every frame, then the analysis's preparation.
bool every_reader_accepts(const fs::path& run) {
    try {
        const StoredRun stored = open_stored_run(run);
        for (std::size_t k = 0; k < stored.frames(); ++k)
            stored.frame(k);
        prepare_run(run, {});
        return true;
    } catch (const FileError&) {
        return false;
    } catch (const InvalidParameter&) {
        return false;
    }
}

TEST_F(CorruptionFuzz, TrajectoryCorruptionsAreRefusedOrHarmless) {
    const std::vector<std::pair<std::string, bool>> datasets = {
        {"/particles/bodies/position/value", false},
        {"/particles/bodies/orientation/value", false},
        {"/particles/bodies/velocity/value", false},
        {"/particles/bodies/angular_velocity/value", false},
        {"/particles/bodies/species", true},
        {"/particles/bodies/position/time", false},
        {"/particles/bodies/position/step", false},
        {"/observables/polar_order_polar/value", false},
        {"/observables/nematic_order_medium/value", false},
    };
    SplitMix64 rng(20261124);
    int refused = 0;
    for (int i = 0; i < kTrajectoryCorruptions; ++i) {
        const fs::path run = fresh_copy();
        const auto& [dataset, integer] = datasets[below(rng, datasets.size())];
        const std::string file = (run / kTrajectoryFile).string();
        const std::uint64_t index = below(rng, hdf5_elements(file, dataset));
        const Injected v = draw_value(rng, integer);
        if (integer)
            poke_hdf5(file, dataset, index, static_cast<std::int32_t>(v.value));
        else if (dataset.find("/value") != std::string::npos &&
                 dataset.find("observables") == std::string::npos)
            poke_hdf5(file, dataset, index, static_cast<float>(v.value));
        else
            poke_hdf5(file, dataset, index, v.value);
        const bool accepted = every_reader_accepts(run);
        refused += accepted ? 0 : 1;
        EXPECT_FALSE(v.invalid && accepted) << "corruption " << i << ": " << dataset << "[" << index
                                            << "] = " << v.value << " was accepted";
    }
    std::printf("[ measured ] %d of %d trajectory corruptions refused\n", refused,
                kTrajectoryCorruptions);
}

TEST_F(CorruptionFuzz, CheckpointCorruptionsAreRefusedAndChangeNothing) {
    const std::vector<std::pair<std::string, bool>> datasets = {
        {"/rodsea_checkpoint/position", false},
        {"/rodsea_checkpoint/orientation", false},
        {"/rodsea_checkpoint/velocity", false},
        {"/rodsea_checkpoint/angular_velocity", false},
        {"/rodsea_checkpoint/species", true},
        {"/rodsea_checkpoint/interval_accumulators", false},
        {"/rodsea_checkpoint/wall_seconds", false},
    };
    SplitMix64 rng(112620);
    int refused = 0;
    for (int i = 0; i < kCheckpointCorruptions; ++i) {
        const fs::path run = fresh_copy();
        const auto& [dataset, integer] = datasets[below(rng, datasets.size())];
        const std::string file = (run / kCheckpointFile).string();
        const std::uint64_t index = below(rng, hdf5_elements(file, dataset));
        const Injected v = draw_value(rng, integer);
        if (integer)
            poke_hdf5(file, dataset, index, static_cast<std::int32_t>(v.value));
        else
            poke_hdf5(file, dataset, index, v.value);
        const std::string trajectory = read_text(run / kTrajectoryFile),
                          series = read_text(run / kSeriesFile);
        RunOptions options;
        options.quiet = true;
        std::ostringstream out, err;
        bool accepted = true;
        try {
            accepted = resume_run(run, options, out, err) == kExitOk;
        } catch (const FileError&) {
            accepted = false;
        } catch (const InvalidParameter&) {
            accepted = false;
        }
        refused += accepted ? 0 : 1;
        EXPECT_FALSE(v.invalid && accepted) << "corruption " << i << ": " << dataset << "[" << index
                                            << "] = " << v.value << " was resumed";
        if (!accepted) {
            EXPECT_EQ(read_text(run / kTrajectoryFile), trajectory) << "corruption " << i;
            EXPECT_EQ(read_text(run / kSeriesFile), series) << "corruption " << i;
        }
    }
    std::printf("[ measured ] %d of %d checkpoint corruptions refused\n", refused,
                kCheckpointCorruptions);
}

}  // namespace
}  // namespace rodsea
