#include "rodsea/run/series_recorder.hpp"

#include <cmath>

#include <algorithm>
#include <stdexcept>

#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

SeriesRecorder::SeriesRecorder(const RunPlan& plan)
    : species_count_(plan.engine.species.size()),
      steps_per_output_(static_cast<double>(plan.steps_per_output())),
      sweep_cap_(plan.engine.max_sweeps),
      structure_(analysis_setup(plan)) {
    const EngineParameters& params = plan.engine;
    for (const Species& sp : params.species) {
        columns_.push_back({"polar_order_" + sp.name, "1"});
        columns_.push_back({"nematic_order_" + sp.name, "1"});
    }
    if (structure_.has_segregation()) columns_.push_back({kSegregationColumn, "1"});
    if (structure_.has_flocks()) columns_.push_back({kLargestFlockColumn, "polar rods"});
    for (const Species& sp : params.species) {
        columns_.push_back({"kinetic_energy_translational_" + sp.name, "mass-unit mm2 s-2/body"});
        columns_.push_back({"kinetic_energy_rotational_" + sp.name, "mass-unit mm2 s-2/body"});
    }
    // The mean in-plane velocity of each species: the medium's drift along the polar rods'
    // heading is the paper's mechanism, and a medium alone must show none.
    for (const Species& sp : params.species) {
        columns_.push_back({"mean_velocity_x_" + sp.name, "mm s-1"});
        columns_.push_back({"mean_velocity_y_" + sp.name, "mm s-1"});
    }
    columns_.push_back({"max_overlap_fraction", "1"});
    columns_.push_back({"unresolved_contacts", "1"});
    columns_.push_back({"max_sweeps", "1"});
    columns_.push_back({"impulses_per_step", "1"});
    // Collisions (impulses at approach speeds above kCollisionSpeed) per body per simulated
    // second; a collision between two bodies counts for both.
    columns_.push_back({"body_collision_rate", "s-1"});
    columns_.push_back({"plate_collision_rate", "s-1"});
    columns_.push_back({"steps_per_second", "s-1"});
}

void SeriesRecorder::accumulate(const StepTally& s) {
    max_overlap_ = std::max(max_overlap_, s.max_overlap_fraction);
    unresolved_ += static_cast<double>(s.unresolved);
    max_sweeps_ = std::max(max_sweeps_, static_cast<double>(s.max_sweeps));
    impulses_ += static_cast<double>(s.impulses);
    body_collisions_ += static_cast<double>(s.body_collisions);
    plate_collisions_ += static_cast<double>(s.plate_collisions);
    steps_ += static_cast<double>(s.steps);
}

std::vector<double> SeriesRecorder::row(const EngineParameters& p, const BodyState& b,
                                        double steps_per_second) const {
    std::vector<double> values;
    values.reserve(columns_.size());
    for (size_t s = 0; s < species_count_; ++s) {
        values.push_back(orientational_order(b, static_cast<std::uint32_t>(s), 1));
        values.push_back(orientational_order(b, static_cast<std::uint32_t>(s), 2));
    }
    if (structure_.has_segregation()) values.push_back(structure_.segregation(b));
    if (structure_.has_flocks()) values.push_back(structure_.largest_flock(b));
    std::vector<double> translational(species_count_), rotational(species_count_),
        count(species_count_), vx(species_count_), vy(species_count_);
    for (size_t i = 0; i < b.size(); ++i) {
        const Shape& shape = p.species[b.species[i]].shape;
        const Vec3& v = b.velocity[i];
        const Vec3 w = rotate(conjugate(b.orientation[i]), b.spin[i]);  // body frame
        const Vec3& I = shape.principal_inertia;
        translational[b.species[i]] += 0.5 * shape.mass * (v.x * v.x + v.y * v.y + v.z * v.z);
        rotational[b.species[i]] += 0.5 * (I.x * w.x * w.x + I.y * w.y * w.y + I.z * w.z * w.z);
        count[b.species[i]] += 1.0;
        vx[b.species[i]] += v.x;
        vy[b.species[i]] += v.y;
    }
    for (size_t s = 0; s < species_count_; ++s) {
        const double n = std::max(count[s], 1.0);
        values.push_back(translational[s] / n);
        values.push_back(rotational[s] / n);
    }
    for (size_t s = 0; s < species_count_; ++s) {
        const double n = std::max(count[s], 1.0);
        values.push_back(vx[s] / n);
        values.push_back(vy[s] / n);
    }
    values.push_back(max_overlap_);
    values.push_back(unresolved_);
    values.push_back(max_sweeps_);
    values.push_back(steps_ > 0.0 ? impulses_ / steps_ : 0.0);
    const double body_seconds = steps_ * p.dt * static_cast<double>(b.size());
    values.push_back(body_seconds > 0.0 ? 2.0 * body_collisions_ / body_seconds : 0.0);
    values.push_back(body_seconds > 0.0 ? plate_collisions_ / body_seconds : 0.0);
    values.push_back(steps_per_second);
    return values;
}

std::vector<double> SeriesRecorder::interval_state() const {
    return {max_overlap_,     unresolved_,       max_sweeps_, impulses_,
            body_collisions_, plate_collisions_, steps_};
}

std::string SeriesRecorder::interval_problem(const std::vector<double>& state) const {
    if (state.size() != 7) return std::to_string(state.size()) + " numbers, not 7";
    const char* names[] = {"max_overlap",     "unresolved",       "max_sweeps", "impulses",
                           "body_collisions", "plate_collisions", "steps"};
    const double steps = state[6];
    const double per_output = steps_per_output_;
    // No step has more than 10^12 impulses, collisions or unresolved contacts.
    const double hi[] = {kGrossOverlapFraction, steps * 1e12, sweep_cap_, steps * 1e12,
                         steps * 1e12,          steps * 1e12, per_output};
    for (std::size_t k = 0; k < 7; ++k) {
        const double v = state[k];
        const bool whole = k == 0 || v == std::floor(v);
        if (!std::isfinite(v) || v < 0.0 || v > hi[k] || !whole)
            return std::string(names[k]) + " = " + format_number(v) + ", allowed " +
                   (k == 0 ? "" : "a whole number ") + "in [0, " + format_number(hi[k]) + "]";
    }
    return "";
}

void SeriesRecorder::restore_interval(const std::vector<double>& state) {
    if (state.size() != 7)
        throw std::invalid_argument("time-series interval state needs 7 numbers");
    max_overlap_ = state[0];
    unresolved_ = state[1];
    max_sweeps_ = state[2];
    impulses_ = state[3];
    body_collisions_ = state[4];
    plate_collisions_ = state[5];
    steps_ = state[6];
}

}  // namespace rodsea
