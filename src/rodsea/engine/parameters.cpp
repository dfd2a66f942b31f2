#include "rodsea/engine/parameters.hpp"

#include "rodsea/error.hpp"
#include "rodsea/shape/sphere_chain.hpp"

namespace rodsea {

const char* to_string(BodyKind kind) {
    switch (kind) {
        case BodyKind::polar_rod:
            return "polar_rod";
        case BodyKind::apolar_rod:
            return "apolar_rod";
        case BodyKind::bead:
            return "bead";
    }
    return "unknown";
}

const char* to_string(physics::NoiseMode mode) {
    return mode == physics::NoiseMode::set ? "set" : "add";
}

double max_noise_epsilon(physics::NoiseMode mode) {
    return mode == physics::NoiseMode::set ? kMaxNoiseEpsilonSet : kMaxNoiseEpsilonAdd;
}

double polar_rod_density() {
    static const double density =
        kPolarRodMass / make_shape(polar_rod_spheres({}), kPolarRodMass, "polar_rod").volume;
    return density;
}

Species polar_rod_species(double mass) {
    // Table S2: polar rod – plate μ = 0.03, e = 0.10.
    return {"polar_rod",
            BodyKind::polar_rod,
            make_shape(polar_rod_spheres({}), mass, "polar_rod"),
            {0.03, 0.10}};
}

Species apolar_rod_species(double length_mm, double mass) {
    // Table S2: apolar rod – plate μ = 0.01, e = 0.30.
    return {"apolar_rod",
            BodyKind::apolar_rod,
            make_shape(apolar_rod_spheres(ApolarRodGeometry::with_length(length_mm)), mass,
                       "apolar_rod"),
            {0.01, 0.30}};
}

Species bead_species(double mass) {
    // docs/model.md CHOICE: beads meet the plates like apolar rods.
    return {"bead", BodyKind::bead, make_shape(bead_spheres({}), mass, "bead"), {0.01, 0.30}};
}

namespace {

void validate_coefficients(const std::string& prefix, const ContactCoefficients& c) {
    require_in_closed_range(prefix + ".friction", c.friction, 0.0, 10.0);
    require_in_closed_range(prefix + ".restitution", c.restitution, 0.0, 1.0);
}

}  // namespace

void validate(const EngineParameters& p) {
    require_positive("box.lx", p.box.lx, "mm");
    require_positive("box.ly", p.box.ly, "mm");
    require_in_closed_range("drive.gamma", p.drive.gamma, 0.0, 1000.0);
    require_positive("drive.angular_frequency", p.drive.angular_frequency, "rad/s");
    require_positive("drive.gap", p.drive.gap, "mm");
    require_non_negative("drive.gravity", p.drive.gravity, "mm/s^2");
    require_positive("dt", p.dt, "s");
    if (p.noise_mode != physics::NoiseMode::add && p.noise_mode != physics::NoiseMode::set)
        throw InvalidParameter("noise_mode", std::to_string(static_cast<int>(p.noise_mode)),
                               "add or set");
    // The per-mode ranges are the config's (where a user sets ε); the engine runs any ε >= 0, so
    // that a blow-up can be provoked on purpose.
    require_non_negative("noise_epsilon", p.noise_epsilon, "1/mm");
    require_positive_count("max_sweeps", p.max_sweeps);
    require_non_negative("approach_tolerance", p.approach_tolerance, "mm/s");
    if (p.species.empty()) throw InvalidParameter("species", "none", "at least one species");

    double longest = 0.0;
    for (const Species& s : p.species) {
        const std::string prefix = "species." + s.name;
        require_positive(prefix + ".mass", s.shape.mass, "mass units");
        for (int k = 0; k < 3; ++k)
            require_positive(prefix + ".principal_inertia", s.shape.principal_inertia[k],
                             "mass units mm^2");
        validate_coefficients(prefix + ".plate", s.plate);
        const double diameter = 2.0 * s.shape.max_radius;
        if (!(diameter < p.drive.gap)) {
            throw InvalidParameter("drive.gap", format_number(p.drive.gap) + " mm",
                                   "> " + format_number(diameter) + " mm",
                                   std::string(to_string(s.kind)) + " '" + s.name +
                                       "' has a sphere of diameter " + format_number(diameter) +
                                       " mm that does not fit between the plates");
        }
        longest = std::max(longest, s.shape.extent);
    }
    // A body must not meet two images of another body through the periodic boundary.
    for (const auto& [name, side] :
         {std::pair{"box.lx", p.box.lx}, std::pair{"box.ly", p.box.ly}}) {
        if (side < 2.0 * longest) {
            throw InvalidParameter(name, format_number(side) + " mm",
                                   ">= " + format_number(2.0 * longest) + " mm",
                                   "twice the longest body");
        }
    }
    validate_coefficients("body_body", p.body_body);
    if (!p.body_body_by_pair.empty()) {
        const size_t n = p.species.size();
        if (p.body_body_by_pair.size() != n * n) {
            throw InvalidParameter("body_body_by_pair",
                                   std::to_string(p.body_body_by_pair.size()) + " entries",
                                   std::to_string(n * n) + " entries (species x species)");
        }
        for (size_t a = 0; a < n; ++a) {
            for (size_t b = 0; b < n; ++b) {
                const std::string key = "body_body." + p.species[a].name + "-" + p.species[b].name;
                validate_coefficients(key, p.body_body_by_pair[a * n + b]);
                const auto& ab = p.body_body_by_pair[a * n + b];
                const auto& ba = p.body_body_by_pair[b * n + a];
                if (ab.friction != ba.friction || ab.restitution != ba.restitution) {
                    throw InvalidParameter(key, "asymmetric", "the same value for both orders");
                }
            }
        }
    }
}

}  // namespace rodsea
