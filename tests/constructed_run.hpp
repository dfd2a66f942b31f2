#pragma once
// A run directory holding frames placed by hand, as `rodsea run` would have written them: the
// picture and export tests need bodies at positions and angles they choose.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "rodsea/config/config_file.hpp"
#include "rodsea/engine/body_state.hpp"
#include "rodsea/io/trajectory_file.hpp"

namespace rodsea {

// A body lying flat at (x, y) with its axis at angle theta in the plane (thick → thin for polar
// rods), resting on the base (z = its largest sphere radius).
inline void add_flat_body(BodyState& bodies, const RunPlan& plan, std::uint32_t species, double x,
                          double y, double theta) {
    const Quat q = Quat::from_axis_angle({0.0, 0.0, 1.0}, theta);
    bodies.add(species, {x, y, plan.engine.species[species].shape.max_radius}, q);
}

// Writes dir/trajectory.h5 with the config's parameters and one frame per entry of `frames`,
// `interval` seconds apart. Every frame must hold the config's bodies in species order.
inline void write_constructed_run(const std::filesystem::path& dir, const RunPlan& plan,
                                  const std::vector<BodyState>& frames, double interval) {
    std::filesystem::create_directories(dir);
    TrajectoryFile file = TrajectoryFile::create(dir / "trajectory.h5", plan.engine,
                                                 frames.front().species, plan.config_toml, {});
    const double steps_per_frame = std::round(interval / plan.engine.dt);
    for (std::size_t k = 0; k < frames.size(); ++k)
        file.append_frame(static_cast<std::uint64_t>(steps_per_frame) * k,
                          interval * static_cast<double>(k), frames[k], {});
    file.close();
}

}  // namespace rodsea
