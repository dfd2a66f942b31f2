#include "rodsea/builder/overlap_relaxation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

#include "rodsea/neighbors/periodic_grid.hpp"

namespace rodsea {

namespace {

// FIRE's constants, those of Bitzek et al. (2006) and Guénolé et al. (2020). Time is in units of
// the harmonic contact's period / 2π with unit mass per body: a step of 0.1 resolves one contact
// well and stays stable with many; 0.2 and 0.4 took more iterations, or failed, for 2.5 mm rods
// at 0.75 + polar rods at 0.05.
constexpr double kFirstStep = 0.02, kLargestStep = 0.1, kSmallestStep = 0.002;
constexpr double kStepGrowth = 1.1, kStepCut = 0.5;
constexpr double kFirstMixing = 0.1, kMixingDecay = 0.99;
constexpr int kDelay = 5;  // downhill steps before the step may grow

// The pair list holds disc pairs closer than their contact distance plus this skin, and is rebuilt
// once some disc may have moved half of it: one rebuild every few iterations at the start, every
// few tens near the end.
constexpr double kSkin = 0.3;  // mm

// Converged means every gap exceeds the clearance by this much, so that wrapping the positions
// into the box afterwards (round-off of 1e-14 mm) cannot bring a pair below the clearance.
constexpr double kMargin = 1e-9;  // mm

// The largest overlap is looked at every kStallCheck iterations for the stall test.
constexpr int kStallCheck = 250;

using PairList = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// FIRE over the bodies' x, y and angle × arm (arm: the rms distance of the body's discs from its
// centre), so that a unit of every coordinate moves discs by about the same distance. Bodies are
// held in the order of a grid of their centres: neighbours in space are neighbours in memory,
// which halves the time of the pair loop in a large box.
class Relaxation {
  public:
    Relaxation(const PlanarBodies& bodies, const std::vector<Footprint>& feet, const Box& box,
               const OverlapRelaxationOptions& options);
    OverlapRelaxationResult run();
    void write_back(PlanarBodies& bodies) const;

  private:
    void place();
    void maybe_rebuild_pairs(OverlapRelaxationResult& result);
    double forces();
    void fire_step();
    bool stalled(int iteration, double overlap);

    const PeriodicBox2D box_;
    const OverlapRelaxationOptions options_;
    std::vector<std::uint32_t> order_;  // original index of each body held
    // Per body held.
    std::vector<double> x_, y_, angle_, arm_, reach_;
    std::vector<double> fx_, fy_, torque_, vx_, vy_, vturn_, cos_, sin_;
    std::vector<double> x_built_, y_built_, angle_built_;  // when the pair list was built
    // Per disc, in body order.
    std::vector<std::uint32_t> body_;
    std::vector<double> ax_, ay_, radius_;  // offset from the centre at angle 0, radius, mm
    std::vector<Vec3> position_;
    double widest_ = 0.0;
    PeriodicGrid2D grid_;
    PairList pairs_;
    double step_ = kFirstStep, mixing_ = kFirstMixing;
    int downhill_ = 0;
    std::vector<double> history_;  // the largest overlap every kStallCheck iterations
};

Relaxation::Relaxation(const PlanarBodies& bodies, const std::vector<Footprint>& feet,
                       const Box& box, const OverlapRelaxationOptions& options)
    : box_{box.lx, box.ly}, options_(options) {
    std::vector<Vec3> centres;
    for (size_t b = 0; b < bodies.size(); ++b)
        centres.push_back({bodies.x[b], bodies.y[b], 0.0});
    PeriodicGrid2D sorter;
    sorter.build(centres, box_, std::min({2.0, 0.5 * box.lx, 0.5 * box.ly}));
    order_.assign(sorter.order().begin(), sorter.order().end());
    for (const std::uint32_t b : order_) {
        const Footprint& f = feet[bodies.species[b]];
        double arm2 = 0.0, reach = 0.0;
        for (size_t k = 0; k < f.size(); ++k) {
            body_.push_back(static_cast<std::uint32_t>(x_.size()));
            ax_.push_back(f.along[k]);
            ay_.push_back(f.across[k]);
            radius_.push_back(f.radius[k]);
            widest_ = std::max(widest_, f.radius[k]);
            const double r2 = f.along[k] * f.along[k] + f.across[k] * f.across[k];
            arm2 += r2;
            reach = std::max(reach, std::sqrt(r2));
        }
        const bool turns = options.rotate && f.rotatable && f.size() > 0;
        arm_.push_back(turns ? std::sqrt(arm2 / static_cast<double>(f.size())) : 0.0);
        reach_.push_back(reach);
        x_.push_back(bodies.x[b]);
        y_.push_back(bodies.y[b]);
        angle_.push_back(bodies.angle[b]);
    }
    const size_t n = x_.size();
    for (auto* v : {&fx_, &fy_, &torque_, &vx_, &vy_, &vturn_, &cos_, &sin_})
        v->assign(n, 0.0);
    position_.resize(body_.size());
}

void Relaxation::write_back(PlanarBodies& bodies) const {
    for (size_t i = 0; i < order_.size(); ++i) {
        const std::uint32_t b = order_[i];
        bodies.x[b] = PeriodicBox2D::wrap(x_[i], box_.lx);
        bodies.y[b] = PeriodicBox2D::wrap(y_[i], box_.ly);
        bodies.angle[b] = std::remainder(angle_[i], 2.0 * std::numbers::pi);
    }
}

void Relaxation::place() {
    for (size_t b = 0; b < x_.size(); ++b) {
        cos_[b] = std::cos(angle_[b]);
        sin_[b] = std::sin(angle_[b]);
    }
    for (size_t k = 0; k < body_.size(); ++k) {
        const std::uint32_t b = body_[k];
        position_[k] = {x_[b] + cos_[b] * ax_[k] - sin_[b] * ay_[k],
                        y_[b] + sin_[b] * ax_[k] + cos_[b] * ay_[k], 0.0};
    }
}

// Pairs of discs of different bodies within their own contact distance plus the skin: the grid's
// cutoff is set by the widest discs, which would list 2–3 times more pairs of the narrow ones. A
// disc has moved at most its body's shift plus its reach times the body's turn.
void Relaxation::maybe_rebuild_pairs(OverlapRelaxationResult& result) {
    if (!x_built_.empty()) {
        double moved = 0.0;
        for (size_t b = 0; b < x_.size(); ++b) {
            moved = std::max(moved, std::hypot(x_[b] - x_built_[b], y_[b] - y_built_[b]) +
                                        reach_[b] * std::abs(angle_[b] - angle_built_[b]));
        }
        if (2.0 * moved <= kSkin) return;
    }
    pairs_.clear();
    const double c = options_.clearance;
    const double cutoff = 2.0 * widest_ + 2.0 * c + kSkin;
    grid_.build(position_, box_, cutoff);
    grid_.for_each_pair_within(cutoff, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        const double reach = radius_[i] + radius_[j] + 2.0 * c + kSkin;
        if (body_[i] != body_[j] && d.x * d.x + d.y * d.y < reach * reach)
            pairs_.emplace_back(std::min(i, j), std::max(i, j));
    });

    x_built_ = x_, y_built_ = y_, angle_built_ = angle_;
    ++result.list_builds;
}

// Forces and torques from the listed pairs with the harmonic overlap energy ½ (σ − r)², σ = r_i +
// r_j + 2 × clearance; returns the largest σ − clearance − r (≤ 0: every gap at least the
// clearance).
double Relaxation::forces() {
    std::fill(fx_.begin(), fx_.end(), 0.0);
    std::fill(fy_.begin(), fy_.end(), 0.0);
    std::fill(torque_.begin(), torque_.end(), 0.0);
    const double c = options_.clearance;
    double largest = -c;
    for (const auto& [i, j] : pairs_) {
        const Vec3 d = box_.minimum_image(position_[i] - position_[j]);
        const double sigma = radius_[i] + radius_[j] + 2.0 * c;
        const double r2 = d.x * d.x + d.y * d.y;
        if (r2 >= sigma * sigma) continue;
        const double r = std::sqrt(r2);
        largest = std::max(largest, sigma - c - r);
        // Along the line of centres; discs on top of each other part along x.
        const double fx = r > 0.0 ? (sigma - r) * d.x / r : sigma;
        const double fy = r > 0.0 ? (sigma - r) * d.y / r : 0.0;
        const std::uint32_t a = body_[i], b = body_[j];
        fx_[a] += fx, fy_[a] += fy;
        fx_[b] -= fx, fy_[b] -= fy;
        // Torque about each body's centre: (disc − centre) × f.
        torque_[a] += (position_[i].x - x_[a]) * fy - (position_[i].y - y_[a]) * fx;
        torque_[b] -= (position_[j].x - x_[b]) * fy - (position_[j].y - y_[b]) * fx;
    }
    return largest;
}

void Relaxation::fire_step() {
    const size_t n = x_.size();
    const auto turn_force = [&](size_t b) { return arm_[b] > 0.0 ? torque_[b] / arm_[b] : 0.0; };
    double power = 0.0;
    for (size_t b = 0; b < n; ++b)
        power += fx_[b] * vx_[b] + fy_[b] * vy_[b] + turn_force(b) * vturn_[b];
    if (power > 0.0) {
        if (++downhill_ > kDelay) {
            step_ = std::min(step_ * kStepGrowth, kLargestStep);
            mixing_ *= kMixingDecay;
        }
    } else {
        // Uphill: back off half a step, stop, and go on more carefully.
        downhill_ = 0;
        step_ = std::max(step_ * kStepCut, kSmallestStep);
        mixing_ = kFirstMixing;
        for (size_t b = 0; b < n; ++b) {
            x_[b] -= 0.5 * step_ * vx_[b];
            y_[b] -= 0.5 * step_ * vy_[b];
            if (arm_[b] > 0.0) angle_[b] -= 0.5 * step_ * vturn_[b] / arm_[b];
            vx_[b] = vy_[b] = vturn_[b] = 0.0;
        }
    }
    double v2 = 0.0, f2 = 0.0;
    for (size_t b = 0; b < n; ++b) {
        const double turn = turn_force(b);
        vx_[b] += step_ * fx_[b];
        vy_[b] += step_ * fy_[b];
        vturn_[b] += step_ * turn;
        v2 += vx_[b] * vx_[b] + vy_[b] * vy_[b] + vturn_[b] * vturn_[b];
        f2 += fx_[b] * fx_[b] + fy_[b] * fy_[b] + turn * turn;
    }
    // Mix the velocity toward the force, keeping its size.
    const double toward = f2 > 0.0 ? mixing_ * std::sqrt(v2 / f2) : 0.0;
    for (size_t b = 0; b < n; ++b) {
        vx_[b] = (1.0 - mixing_) * vx_[b] + toward * fx_[b];
        vy_[b] = (1.0 - mixing_) * vy_[b] + toward * fy_[b];
        vturn_[b] = (1.0 - mixing_) * vturn_[b] + toward * turn_force(b);
        x_[b] += step_ * vx_[b];
        y_[b] += step_ * vy_[b];
        if (arm_[b] > 0.0) angle_[b] += step_ * vturn_[b] / arm_[b];
    }
}

// Whether the largest overlap is now more than half what it was stall_iterations ago.
bool Relaxation::stalled(int iteration, double overlap) {
    const int window = options_.stall_iterations;
    if (window <= 0 || iteration % kStallCheck != 0) return false;
    history_.push_back(overlap);
    const auto back = static_cast<size_t>((window + kStallCheck - 1) / kStallCheck);
    return history_.size() > back && overlap > 0.5 * history_[history_.size() - 1 - back];
}

OverlapRelaxationResult Relaxation::run() {
    OverlapRelaxationResult result;
    place();
    for (;;) {
        maybe_rebuild_pairs(result);
        result.largest_overlap = forces();
        if (result.largest_overlap <= -kMargin) {
            result.converged = true;
            break;
        }
        if (result.iterations == options_.max_iterations) break;
        if (stalled(result.iterations, result.largest_overlap)) {
            result.stalled = true;
            break;
        }
        ++result.iterations;
        fire_step();
        place();
    }
    return result;
}

}  // namespace

OverlapRelaxationResult relax_overlaps(PlanarBodies& bodies, const std::vector<Footprint>& feet,
                                       const Box& box, const OverlapRelaxationOptions& options) {
    if (bodies.size() == 0) return {.converged = true};
    Relaxation relaxation(bodies, feet, box, options);
    const OverlapRelaxationResult result = relaxation.run();
    relaxation.write_back(bodies);
    return result;
}

}  // namespace rodsea
