#pragma once
// The small run the tests of `rodsea run` step, and comparing run directories and states bit for
// bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/body_state.hpp"
#include "rodsea/io/checkpoint.hpp"
#include "rodsea/io/trajectory_file.hpp"
#include "rodsea/io/trajectory_reader.hpp"
#include "rodsea/run/run_driver.hpp"
#include "rodsea/run/run_files.hpp"
#include "scratch_dir.hpp"

namespace rodsea {

// 4 polar rods among apolar rods in a 20 mm box: ~50 bodies, thousands of steps per second.
inline std::string small_config(double duration, double interval,
                                const std::string& output_extra = "") {
    std::ostringstream s;
    s << "[box]\nside = 20.0\n"
      << "[[species]]\nname = \"polar\"\nkind = \"polar_rod\"\ncount = 4\n"
      << "[[species]]\nname = \"medium\"\nkind = \"apolar_rod\"\nlength = 2.5\n"
      << "area_fraction = 0.15\n"
      << "[time]\nduration = " << duration << "\n"
      << "[output]\ninterval = " << interval << "\n"
      << output_extra << "[run]\nseed = 11\n";
    return s.str();
}

inline std::filesystem::path write_config(const ScratchDir& dir, const std::string& text) {
    const auto path = dir.path() / "run.toml";
    std::ofstream(path) << text;
    return path;
}

// Runs `config` into `out` in this process (quiet); its exit code.
inline int run_quietly(const std::string& config, const std::filesystem::path& out) {
    RunOptions options;
    options.out_dir = out;
    options.quiet = true;
    std::ostringstream log, err;
    return start_run(load_config_string(config, "test"), options, log, err);
}

inline std::size_t line_count(const std::filesystem::path& path) {
    const std::string text = read_text(path);
    return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

inline bool same_bits(const BodyState& a, const BodyState& b) {
    const auto same = [](const auto& x, const auto& y) {
        return x.size() == y.size() &&
               std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
    };
    return same(a.species, b.species) && same(a.position, b.position) &&
           same(a.orientation, b.orientation) && same(a.velocity, b.velocity) &&
           same(a.spin, b.spin);
}

// Two run directories hold the same run: the same end state bit for bit, the same frames, the
// same time series (all but the wall-clock steps_per_second).
inline void expect_same_run(const std::filesystem::path& a, const std::filesystem::path& b) {
    const Checkpoint end_a = read_checkpoint(a / kCheckpointFile);
    const Checkpoint end_b = read_checkpoint(b / kCheckpointFile);
    EXPECT_TRUE(end_a.complete);
    EXPECT_EQ(end_a.step, end_b.step);
    EXPECT_TRUE(same_bits(end_a.bodies, end_b.bodies));
    EXPECT_EQ(end_a.interval_accumulators, end_b.interval_accumulators);
    EXPECT_EQ(end_a.config_toml, end_b.config_toml);
    const TrajectoryReader ta(a / kTrajectoryFile), tb(b / kTrajectoryFile);
    ASSERT_EQ(ta.frames(), tb.frames());
    EXPECT_EQ(ta.steps(), tb.steps());
    EXPECT_EQ(ta.times(), tb.times());
    for (std::uint64_t f = 0; f < ta.frames(); ++f)
        EXPECT_TRUE(same_bits(ta.frame(f), tb.frame(f))) << "frame " << f;
    for (const char* column :
         {"polar_order_polar", "nematic_order_medium", "segregation", "largest_flock",
          "max_overlap_fraction", "impulses_per_step", "body_collision_rate"})
        EXPECT_EQ(ta.series(column), tb.series(column)) << column;
    EXPECT_EQ(line_count(a / kSeriesFile), line_count(b / kSeriesFile));
    EXPECT_EQ(read_stored_config(a / kTrajectoryFile), read_stored_config(b / kTrajectoryFile));
    EXPECT_EQ(read_text(a / kConfigFile), read_text(b / kConfigFile));
}

}  // namespace rodsea
