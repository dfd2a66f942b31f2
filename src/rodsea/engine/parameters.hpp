#pragma once
// Everything the engine needs besides the bodies, with docs/model.md's defaults. Units: mm, s, and
// an arbitrary mass unit (the polar rod's mass is 1 by default; only ratios matter).
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "rodsea/engine/physics/contact.hpp"
#include "rodsea/engine/physics/plate_noise.hpp"
#include "rodsea/engine/physics/plates.hpp"
#include "rodsea/shape/shape.hpp"

namespace rodsea {

// The two plates: base at A cos Ωt, lid at A cos Ωt + w, A = Γ g / Ω².
struct DriveParameters {
    double gamma = 7.0;                                   // Γ = AΩ²/g, dimensionless, [0, 1000]
    double angular_frequency = 400.0 * std::numbers::pi;  // Ω, rad/s, > 0
    double gap = 1.40;        // w, mm (CHOICE by calibration, docs/model.md), > 0
    double gravity = 9810.0;  // g, mm/s² (docs/model.md CHOICE 9.81 m/s²), >= 0

    double amplitude() const {  // A, mm
        return gamma * gravity / (angular_frequency * angular_frequency);
    }
    physics::PlateMotion motion() const { return {amplitude(), angular_frequency, gap}; }
};

enum class BodyKind { polar_rod, apolar_rod, bead };
const char* to_string(BodyKind kind);

// One kind of body: its shape (with mass) and how it meets the plates.
struct Species {
    std::string name;
    BodyKind kind = BodyKind::polar_rod;
    Shape shape;
    ContactCoefficients plate;  // body–base and body–lid
};

// Masses in an arbitrary unit: only ratios matter, and the paper's m_apolar / m_polar = 0.20
// (docs/model.md CHOICE: kept for every ℓ_a and for beads).
// The largest noise.epsilon (1/mm) per noise mode. add: 10× the calibrated range (0.05 /mm gives
// D_r ≈ 5 rad²/s); at 1 /mm polar rods spin up without bound, at 3 /mm a run blows up within
// 20 ms. set: a set spin does not accumulate from kick to kick, but it feeds the next approach
// speed through the impulses: a lone rod has D_r = 1.1 rad²/s at 2 /mm, spins (22 rad²/s) at
// 4 /mm and blows up at 16 /mm (data/model-readings/calibration-set-a.toml); the paper's largest
// D_r, 1.87, lies near 2.5 /mm.
inline constexpr double kMaxNoiseEpsilonAdd = 0.5;
inline constexpr double kMaxNoiseEpsilonSet = 5.0;
inline constexpr double kMaxNoiseEpsilon = kMaxNoiseEpsilonSet;  // of either mode
double max_noise_epsilon(physics::NoiseMode mode);
const char* to_string(physics::NoiseMode mode);

// The most bodies one run may hold, in all species together: 250× the paper's largest system,
// ~100 GB of memory.
inline constexpr long long kMaxBodies = 100'000'000;

inline constexpr double kPolarRodMass = 1.0;
inline constexpr double kMediumMass = 0.2;

// The paper's polar rod's density (mass units per mm³): kPolarRodMass in the volume of its
// default 13-sphere shape (3.119 mm³). A species given by its density relative to the polar rod
// (the other reading of the paper's "mass ratio 0.20", docs/model.md §2) weighs that many times
// this density times its own volume.
double polar_rod_density();

// The paper's species with docs/model.md's defaults (Table S2 coefficients, mass ratio 0.20).
Species polar_rod_species(double mass = kPolarRodMass);
Species apolar_rod_species(double length_mm, double mass = kMediumMass);
Species bead_species(double mass = kMediumMass);

struct Box {
    double lx = 252.0;  // mm, periodic: the paper's 56 ℓ_p
    double ly = 252.0;  // mm, periodic
};

struct EngineParameters {
    Box box;
    DriveParameters drive;
    std::vector<Species> species;
    // Body–body coefficients per species pair, row-major species × species; empty means
    // `body_body` for every pair (the paper uses one value for all pairs).
    ContactCoefficients body_body;
    std::vector<ContactCoefficients> body_body_by_pair;
    double dt = 1.25e-6;         // s (CHOICE by convergence, docs/model.md: 4000 per period), > 0
    double noise_epsilon = 0.0;  // ε, 1/mm: ω_z += (or =) ε |u_n| η at polar rods' plate hits
    physics::NoiseMode noise_mode = physics::NoiseMode::add;  // docs/model.md §3, docs/model.md
    std::uint64_t seed = 1;
    int max_sweeps = 2000;  // impulse sweeps per step before contacts count as unresolved
    // Relative normal speeds above −tolerance count as not approaching (mm/s). 1 nm/s moves a
    // body 5e-15 mm per step: far below any length in the model.
    double approach_tolerance = 1e-6;

    const ContactCoefficients& pair_coefficients(size_t a, size_t b) const {
        return body_body_by_pair.empty() ? body_body : body_body_by_pair[a * species.size() + b];
    }
};

// Every parameter at its default: the paper's values and docs/model.md's CHOICEs, the ones the
// config schema documents and fills in (one source of defaults: the initialisers above).
inline EngineParameters default_engine_parameters() {
    return {};
}

// Throws InvalidParameter naming the first bad parameter, its value and the allowed range.
void validate(const EngineParameters& p);

}  // namespace rodsea
