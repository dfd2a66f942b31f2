#pragma once
// Segregation Σ = (1 / 2φ(1−φ)) Σ_i (n_i / n_tot) |φ_i − φ| over square cells of side a
// (docs/model.md §4): φ_i the polar number fraction in cell i, φ the global one, n_i all bodies in
// cell i. Σ is 0 when every cell holds the global mixture and 1 when every cell holds one species.
// Finite counts make Σ > 0 even for random mixing: random_mixing_segregation gives that baseline,
// the mean Σ of the same bodies at uniformly random positions (CHOICE: subtracted).
#include <cstdint>
#include <span>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea {

struct SegregationGrid {
    int nx = 1, ny = 1;  // cells per side: floor(L / a), so cells tile the box exactly
};
SegregationGrid segregation_grid(const PeriodicBox2D& box, double cell);

// Σ from per-cell counts of polar and of all bodies; NaN for one species or none.
double segregation_index(std::span<const double> polar_per_cell,
                         std::span<const double> all_per_cell);

// Σ of `polar` polar and `others` other bodies at uniformly random positions, averaged over
// `samples` realisations (deterministic for a seed).
double random_mixing_segregation(long long polar, long long others, const SegregationGrid& grid,
                                 int samples, std::uint64_t seed);

// Σ of one frame: every body's position and whether it is a polar rod (1) or not (0).
double segregation(const PeriodicBox2D& box, const SegregationGrid& grid,
                   std::span<const Vec3> points, std::span<const std::uint8_t> polar);

}  // namespace rodsea
