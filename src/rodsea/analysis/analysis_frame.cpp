#include "rodsea/analysis/analysis_frame.hpp"

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
    f.x.resize(n);
    f.y.resize(n);
    f.theta.resize(n);
    f.vx.resize(n);
    f.vy.resize(n);
    f.species = bodies.species;
    for (std::size_t i = 0; i < n; ++i) {
        // Stored positions are wrapped already, but float32 rounding can put one at exactly L.
        f.x[i] = PeriodicBox2D::wrap(bodies.position[i].x, box.lx);
        f.y[i] = PeriodicBox2D::wrap(bodies.position[i].y, box.ly);
        f.theta[i] = in_plane_angle(bodies.orientation[i]);
        f.vx[i] = bodies.velocity[i].x;
        f.vy[i] = bodies.velocity[i].y;
    }
    return f;
}

}  // namespace rodsea
