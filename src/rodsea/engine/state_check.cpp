#include "rodsea/engine/state_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/error.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"

namespace rodsea {

namespace {

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Appended piece by piece: GCC 12 warns (-Wrestrict) about a chain of + on a literal.
std::string vec_text(const Vec3& v, const char* unit) {
    std::string text(1, '(');
    text.append(format_number(v.x)).append(", ").append(format_number(v.y)).append(", ");
    text.append(format_number(v.z)).append(") ").append(unit);
    return text;
}

StateProblem problem(std::size_t body, std::string field, std::string value, std::string allowed,
                     std::string detail = "") {
    return {body, std::move(field), std::move(value), std::move(allowed), std::move(detail)};
}

// How far a unit quaternion may be from norm 1: doubles renormalised every step drift by
// rounding only; float32 frames carry 24-bit mantissas.
double quaternion_tolerance(StateOrigin origin) {
    return origin == StateOrigin::stored_frame ? 1e-3 : 1e-6;
}

// x and y are wrapped into [0, L) by the engine; a float32 copy may round up to L itself.
bool inside_box_side(double x, double side, StateOrigin origin) {
    const double slack = origin == StateOrigin::stored_frame ? 1e-5 * side : 0.0;
    return x >= -slack && x <= side + slack;
}

std::optional<StateProblem> sphere_outside_plates(const Species& sp, const Vec3& x, const Quat& q,
                                                  const physics::PlateState& plates, double time,
                                                  StateOrigin origin, std::size_t body) {
    const double tolerance = origin == StateOrigin::fresh ? 0.0 : kGrossOverlapFraction;
    for (std::size_t s = 0; s < sp.shape.sphere_count(); ++s) {
        const double z = x.z + rotate(q, sp.shape.offsets[s]).z;
        const double r = sp.shape.radii[s];
        if (z - r >= plates.base_z - tolerance * r && z + r <= plates.lid_z + tolerance * r)
            continue;
        std::string allowed = "every sphere between the base (z = " + format_number(plates.base_z) +
                              " mm at t = " + format_number(time) +
                              " s) and the lid (z = " + format_number(plates.lid_z) + " mm)";
        if (origin != StateOrigin::fresh)
            allowed += ", within " + format_number(tolerance) + " of its radius";
        return problem(body, "position.z", format_number(x.z) + " mm", allowed,
                       std::string(to_string(sp.kind)) + " sphere " + std::to_string(s) +
                           " spans z = " + format_number(z - r) + " .. " + format_number(z + r) +
                           " mm");
    }
    return std::nullopt;
}

}  // namespace

std::optional<StateProblem> find_state_problem(const EngineParameters& params,
                                               const BodyState& bodies, double time,
                                               StateOrigin origin) {
    const std::size_t n = bodies.size();
    const physics::PlateState plates = physics::plate_state(params.drive.motion(), time);
    const double speed_bound = planar_speed_bound(params);
    const double q_tolerance = quaternion_tolerance(origin);
    for (std::size_t b = 0; b < n; ++b) {
        if (bodies.species[b] >= params.species.size())
            return problem(b, "species", std::to_string(bodies.species[b]),
                           "[0, " + std::to_string(params.species.size() - 1) + "]");
        const Species& sp = params.species[bodies.species[b]];
        const Vec3& x = bodies.position[b];
        if (!finite(x)) return problem(b, "position", vec_text(x, "mm"), "finite values");
        if (!finite(bodies.velocity[b]))
            return problem(b, "velocity", vec_text(bodies.velocity[b], "mm/s"), "finite values");
        if (!finite(bodies.spin[b]))
            return problem(b, "angular_velocity", vec_text(bodies.spin[b], "rad/s"),
                           "finite values");
        const Quat& q = bodies.orientation[b];
        const double norm = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
        std::string q_text(1, '(');
        q_text.append(format_number(q.w)).append(", ").append(format_number(q.x)).append(", ");
        q_text.append(format_number(q.y)).append(", ").append(format_number(q.z)).append(")");
        // A fresh start is normalised by the Simulation; anything the engine wrote is a unit
        // quaternion already.
        if (!std::isfinite(norm) || norm == 0.0)
            return problem(b, "orientation", q_text, "a non-zero quaternion");
        if (origin != StateOrigin::fresh && std::abs(norm - 1.0) > q_tolerance)
            return problem(
                b, "orientation", q_text + " (norm " + format_number(norm) + ")",
                "a unit quaternion (norm within " + format_number(q_tolerance) + " of 1)");
        if (origin != StateOrigin::fresh && (!inside_box_side(x.x, params.box.lx, origin) ||
                                             !inside_box_side(x.y, params.box.ly, origin)))
            return problem(b, "position", vec_text(x, "mm"),
                           "x in [0, " + format_number(params.box.lx) + "] mm and y in [0, " +
                               format_number(params.box.ly) +
                               "] mm (the engine wraps them into the periodic box)");
        if (auto p = sphere_outside_plates(sp, x, origin == StateOrigin::fresh ? normalized(q) : q,
                                           plates, time, origin, b))
            return p;
        if (origin == StateOrigin::fresh) continue;
        // The speed of the body's fastest point, in any direction: a stored state has no reason
        // to move faster across the gap than in the plane.
        const Vec3& v = bodies.velocity[b];
        const Vec3& w = bodies.spin[b];
        const double fastest = std::sqrt(norm2(v)) + std::sqrt(norm2(w)) * sp.shape.extent;
        if (!(fastest <= speed_bound))
            return problem(b, "velocity",
                           vec_text(v, "mm/s") + " with angular velocity " + vec_text(w, "rad/s"),
                           "speeds up to " + format_number(speed_bound) +
                               " mm/s (a quarter of the smallest sphere radius per time step)");
    }
    return std::nullopt;
}

std::optional<std::string> find_species_count_problem(const std::vector<std::uint32_t>& species,
                                                      const std::vector<long long>& counts) {
    std::vector<long long> held(counts.size(), 0);
    for (const std::uint32_t s : species) {
        if (s >= counts.size())
            return "a body of species " + std::to_string(s) + ", but the config has " +
                   std::to_string(counts.size()) + " species";
        ++held[s];
    }
    for (std::size_t s = 0; s < counts.size(); ++s)
        if (held[s] != counts[s])
            return std::to_string(held[s]) + " bodies of species " + std::to_string(s) +
                   ", but the config asks for " + std::to_string(counts[s]);
    return std::nullopt;
}

std::optional<StateProblem> find_gross_overlap(const EngineParameters& params,
                                               const BodyState& bodies) {
    std::vector<Vec3> centres;
    std::vector<double> radii;
    std::vector<std::uint32_t> owner;
    double largest = 0.0;
    for (std::size_t b = 0; b < bodies.size(); ++b) {
        const Shape& shape = params.species.at(bodies.species[b]).shape;
        for (std::size_t s = 0; s < shape.sphere_count(); ++s) {
            centres.push_back(bodies.position[b] + rotate(bodies.orientation[b], shape.offsets[s]));
            radii.push_back(shape.radii[s]);
            owner.push_back(static_cast<std::uint32_t>(b));
            largest = std::max(largest, shape.radii[s]);
        }
    }
    PeriodicGrid2D grid;
    const PeriodicBox2D box{params.box.lx, params.box.ly};
    grid.build(centres, box, 2.0 * largest);
    std::optional<StateProblem> found;
    grid.for_each_pair_within(2.0 * largest, [&](std::uint32_t i, std::uint32_t j, const Vec3& d) {
        if (found || owner[i] == owner[j]) return;
        const double overlap = radii[i] + radii[j] - std::sqrt(norm2(d));
        const double smaller = std::min(radii[i], radii[j]);
        if (overlap <= kGrossOverlapFraction * smaller) return;
        const std::uint32_t a = std::min(owner[i], owner[j]), b = std::max(owner[i], owner[j]);
        found = problem(
            a, "position",
            "overlapping body " + std::to_string(b) + " by " + format_number(overlap / smaller) +
                " of a sphere radius",
            "overlaps up to " + format_number(kGrossOverlapFraction) + " of the smaller radius",
            "bodies " + std::to_string(a) + " at " + vec_text(bodies.position[a], "mm") + " and " +
                std::to_string(b) + " at " + vec_text(bodies.position[b], "mm"));
    });
    return found;
}

double planar_speed_bound(const EngineParameters& params) {
    double smallest = std::numeric_limits<double>::infinity();
    for (const Species& sp : params.species)
        for (double r : sp.shape.radii)
            smallest = std::min(smallest, r);
    return 0.25 * smallest / params.dt;
}

BlowUpBounds BlowUpBounds::of(const EngineParameters& params, std::size_t bodies) {
    BlowUpBounds b;
    b.planar_speed = planar_speed_bound(params);
    b.overlap_fraction = kGrossOverlapFraction;
    b.unresolved = std::max<std::size_t>(10, bodies / 100);
    return b;
}

std::optional<BlowUp> detect_blow_up(const BlowUpBounds& bounds, const StepStatistics& step) {
    if (!(step.max_planar_speed <= bounds.planar_speed))
        return BlowUp{"the largest in-plane speed", format_number(step.max_planar_speed) + " mm/s",
                      format_number(bounds.planar_speed) +
                          " mm/s (a quarter of the smallest sphere radius per step)",
                      "a smaller time.dt resolves faster bodies; a noise.epsilon (or "
                      "noise.rotational_diffusion) far above the calibrated range spins polar "
                      "rods up without bound"};
    if (!(step.max_overlap_fraction <= bounds.overlap_fraction))
        return BlowUp{"the largest overlap",
                      format_number(step.max_overlap_fraction) + " of a sphere radius",
                      format_number(bounds.overlap_fraction) + " of the smaller radius",
                      "bodies pushed into each other: a smaller time.dt, a less dense packing "
                      "(area fractions) or a smaller noise.epsilon"};
    if (step.unresolved > bounds.unresolved)
        return BlowUp{"unresolved contacts in one step", std::to_string(step.unresolved),
                      std::to_string(bounds.unresolved) + " (1 % of the bodies, at least 10)",
                      "contacts still approaching after engine.max_sweeps sweeps, or overlapping "
                      "by more than half a radius: a smaller time.dt, a larger engine.max_sweeps "
                      "or a less dense packing"};
    return std::nullopt;
}

BlowUpError::BlowUpError(BlowUp what, std::uint64_t step, double time)
    : std::runtime_error("the simulation blew up at step " + std::to_string(step) + " (t = " +
                         format_number(time) + " s): " + what.what + " is " + what.value +
                         ", beyond " + what.bound + ". What to change: " + what.advice),
      blow_up_(std::move(what)),
      step_(step) {}

}  // namespace rodsea
