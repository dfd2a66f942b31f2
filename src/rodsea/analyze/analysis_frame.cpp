#include "rodsea/analyze/analysis_frame.hpp"

#include "rodsea/engine/order_parameters.hpp"

namespace rodsea {

AnalysisFrame make_analysis_frame(const BodyState& bodies, const PeriodicBox2D& box,
                                  std::size_t index, double time, std::int64_t step) {
    AnalysisFrame f;
    f.index = index;
    f.time = time;
    f.step = step;
    f.box = box;
    const std::size_t n = bodies.size();
    f.position.resize(n);
    f.theta.resize(n);
    f.spin_z.resize(n);
    f.species = bodies.species;
    f.velocity = bodies.velocity;
    for (std::size_t i = 0; i < n; ++i) {
        // Stored positions are wrapped already, but float32 rounding can put one at exactly L.
        f.position[i] = {PeriodicBox2D::wrap(bodies.position[i].x, box.lx),
                         PeriodicBox2D::wrap(bodies.position[i].y, box.ly), bodies.position[i].z};
        f.theta[i] = in_plane_angle(bodies.orientation[i]);
        f.spin_z[i] = bodies.spin[i].z;
    }
    return f;
}

}  // namespace rodsea
