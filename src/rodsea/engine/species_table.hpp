#pragma once
// The species as the step reads them: plain numbers in flat arrays, worked out once when the
// simulation starts instead of in every step, and what a device copies once. Names and the
// Shape (with its construction data) stay cold in EngineParameters.
#include <cstdint>
#include <vector>

#include "rodsea/engine/parameters.hpp"
#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/rigid_rotation.hpp"

namespace rodsea {

struct SpeciesTable {
    std::vector<double> inverse_mass;   // 1 / mass units
    std::vector<Vec3> inverse_inertia;  // inverse principal moments, 1 / (mass units mm²)
    std::vector<physics::Rotor> rotor;  // torque-free rotation constants
    std::vector<double> reach2;         // farthest sphere centre from the centre, mm²
    std::vector<int> sphere_axis;       // the body axis every sphere centre is on, or -1
    // The outline of each species in height: sphere k of a body on axis sphere_axis, at offset
    // a_k along it with radius r_k, reaches z + a_k u ± r_k, u the axis's vertical component; its
    // lowest bottom is z − max_k (r_k − a_k u) and its highest top z + max_k (r_k + a_k u). The
    // outline keeps the spheres that attain those maxima at some tilt u in [−1, 1] (the two ends
    // and the thick middle of a tapered rod), their radii grown by 2 n 10⁻⁹ max|a_k| (n spheres;
    // 7×10⁻⁸ mm for a 4.5 mm rod) for the slivers of tilt it leaves out (species_table.cpp).
    // Any other shape: one entry, a = 0 and r its
    // farthest sphere surface from the centre. Outline k of species s: first_outline[s] ≤ k <
    // first_outline[s + 1].
    std::vector<std::uint32_t> first_outline;
    std::vector<double> outline_along, outline_radius;  // mm
    std::vector<std::uint32_t> first_sphere;  // into sphere_offset/radius, plus one past the end
    std::vector<Vec3> sphere_offset;          // principal body frame, mm
    std::vector<double> sphere_radius;        // mm
    std::vector<ContactCoefficients> plate;   // with the base and the lid
    std::vector<ContactCoefficients> pair;    // body–body, species × species, row-major
    std::vector<std::uint8_t> polar;          // 1: the plates kick it (docs/model.md §3 noise)

    static SpeciesTable from(const EngineParameters& params);

    std::size_t size() const { return inverse_mass.size(); }
    std::uint32_t sphere_count(std::uint32_t species) const {
        return first_sphere[species + 1] - first_sphere[species];
    }
    const ContactCoefficients& pair_coefficients(std::uint32_t a, std::uint32_t b) const {
        return pair[a * size() + b];
    }
};

}  // namespace rodsea
