#pragma once
// Constructed frames for the analysis tests: known structures whose observables have known
// answers, handed to observables exactly as `rodsea analyze` does.
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/frame_context.hpp"
#include "rodsea/analyze/observable.hpp"
#include "rodsea/random.hpp"

namespace rodsea::testing {

struct Body {
    double x, y, theta;
    std::uint32_t species = 0;
    double vx = 0.0, vy = 0.0;
    double spin_z = 0.0;
};

inline AnalysisFrame make_frame(double side, const std::vector<Body>& bodies, std::size_t index = 0,
                                double interval = 0.01) {
    AnalysisFrame f;
    f.index = index;
    f.time = static_cast<double>(index) * interval;
    f.step = static_cast<std::int64_t>(index);
    f.box = {side, side};
    for (const Body& b : bodies) {
        f.position.push_back({PeriodicBox2D::wrap(b.x, side), PeriodicBox2D::wrap(b.y, side), 0.0});
        f.theta.push_back(std::remainder(b.theta, 2.0 * std::numbers::pi));
        f.velocity.push_back({b.vx, b.vy, 0.0});
        f.spin_z.push_back(b.spin_z);
        f.species.push_back(b.species);
    }
    return f;
}

// Species 0: polar rods (ℓ_p = 4.5 mm); species 1: apolar medium rods of 2.5 mm.
inline AnalysisSetup make_setup(double side, const std::vector<Body>& bodies, std::size_t frames,
                                double interval = 0.01) {
    AnalysisSetup s;
    s.box = {side, side};
    s.species = {{"polar", BodyKind::polar_rod, 4.5, 0, 0.0},
                 {"medium", BodyKind::apolar_rod, 2.5, 0, 0.0}};
    for (const Body& b : bodies)
        ++s.species[b.species].count;
    s.frame_interval = interval;
    s.steady_frames = frames;
    return s;
}

inline AnalysisOptions resolved(const AnalysisSetup& setup, AnalysisOptions o = {}) {
    return resolve_analysis_options(o, setup);
}

// Feeds every frame (all steady, in time blocks as `rodsea analyze` has them) to the observable
// and returns its results.
inline ObservableResults run_on(Observable& observable, const std::vector<AnalysisFrame>& frames,
                                const AnalysisSetup& setup) {
    for (std::size_t k = 0; k < frames.size(); ++k) {
        const FrameContext context(frames[k], setup.species, true, setup.block_of(k));
        observable.compute(context);
    }
    return observable.finish();
}

inline const ScalarResult& scalar(const ObservableResults& r, const std::string& name) {
    for (const ScalarResult& s : r.scalars)
        if (s.name == name) return s;
    throw std::runtime_error("no scalar " + name);
}

inline const TableResult& table(const ObservableResults& r, const std::string& name) {
    for (const TableResult& t : r.tables)
        if (t.name == name) return t;
    throw std::runtime_error("no table " + name);
}

inline std::size_t column(const TableResult& t, const std::string& name) {
    for (std::size_t c = 0; c < t.columns.size(); ++c)
        if (t.columns[c] == name) return c;
    throw std::runtime_error("no column " + name);
}

inline std::vector<Body> uniform_bodies(std::size_t n, double side, SplitMix64& rng,
                                        std::uint32_t species = 0) {
    std::vector<Body> b;
    for (std::size_t i = 0; i < n; ++i)
        b.push_back({rng.uniform(0, side), rng.uniform(0, side),
                     rng.uniform(-std::numbers::pi, std::numbers::pi), species});
    return b;
}

}  // namespace rodsea::testing
