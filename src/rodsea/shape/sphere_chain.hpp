#pragma once
// Builds the sphere chains of docs/model.md §2 from a diameter profile. Every chain lies along the
// x axis of its definition frame and is centred on its geometric centre.
//
// Construction (docs/model.md CHOICE, reproduces the paper's Table S1): N equally spaced centres;
// the end centres sit one end-radius inside the rod's ends, so the chain spans exactly its length;
// each sphere's diameter is the profile's value at its centre, the profile running linearly
// between the end centres (polar) or from the centre to the end centres (apolar).
#include "rodsea/shape/sphere.hpp"

namespace rodsea {

struct PolarRodGeometry {
    double length = 4.5;            // mm, ℓ_p
    double thick_diameter = 1.375;  // mm, at the thick end (body -x)
    double thin_diameter = 0.4;     // mm, at the thin end (body +x)
    int sphere_count = 13;
};

struct ApolarRodGeometry {
    double length = 2.5;           // mm, ℓ_a
    double centre_diameter = 0.8;  // mm
    double end_diameter = 0.4;     // mm
    int sphere_count = 9;          // docs/model.md CHOICE: 4 ℓ_a/mm − 1

    static int default_sphere_count(double length_mm);
    static ApolarRodGeometry with_length(double length_mm);
};

struct BeadGeometry {
    double diameter = 0.8;  // mm
};

// Each throws InvalidParameter for a non-positive length, diameter or count, or for end
// spheres that do not fit in the rod's length.
SphereList polar_rod_spheres(const PolarRodGeometry& g);
SphereList apolar_rod_spheres(const ApolarRodGeometry& g);
SphereList bead_spheres(const BeadGeometry& g);

}  // namespace rodsea
