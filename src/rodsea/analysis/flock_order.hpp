#pragma once
// How much of the polar rods' order P their flocks explain. A flock carries its rods' headings
// together, so a few flocks make P large in a small box even when the flocks head independently:
// P then falls as 1/√(number of flocks) when the box grows. Rotating each flock (and each lone rod)
// by its own uniformly random angle keeps every flock's internal order and destroys only the
// order between them; the mean of P² over such rotations is
//     P_ind² = (Σ_k |m_k|² + n_lone) / N²,    m_k = Σ_{i in flock k} (cos θ_i, sin θ_i),
// exactly (the cross terms average to zero). ⟨P²⟩ / ⟨P_ind²⟩ over a run is then 1 when flocks and
// lone rods head independently, above 1 when they align with one another, below 1 when they head
// against one another. Alignment that spans the box makes the ratio grow with the number of rods;
// alignment of a finite reach leaves it the same in a larger box.
#include <span>

namespace rodsea {

// √⟨P²⟩ over independent random rotations of each flock and lone rod; `labels` as dbscan's
// (−1: a lone rod), one per angle (rad). 0 for no rods.
double independent_flock_order(std::span<const double> angles, std::span<const int> labels);

}  // namespace rodsea
