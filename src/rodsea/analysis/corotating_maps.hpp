#pragma once
// g(r,θ) and G(r,θ) of rods in the frame that moves and turns with a reference rod (x' along
// its axis, thick → thin), every rod of a frame in turn the reference (docs/model.md §4). Maps
// accumulate over frames and add up, so that time blocks can be kept apart and summed.
#include <cstddef>
#include <span>
#include <vector>

#include "rodsea/analysis/neighbor_query.hpp"

namespace rodsea {

struct CorotatingParameters {
    double r_max = 22.5;  // mm, at most half the box
    int r_bins = 60;
    int theta_bins = 72;
};

class CorotatingMaps {
  public:
    explicit CorotatingMaps(const CorotatingParameters& p);

    // One frame: the rods' grid and their angles, rad.
    void compute(const PeriodicGrid2D& rods, std::span<const double> angles);
    void compute(const PeriodicBox2D& box, std::span<const Vec3> rods,
                 std::span<const double> angles) {
        compute(query_grid(box, rods), angles);
    }
    // Adds the frames of `other` (same parameters) to these.
    CorotatingMaps& operator+=(const CorotatingMaps& other);

    std::size_t r_bins() const { return nr_; }
    std::size_t theta_bins() const { return nt_; }
    const std::vector<double>& r_edges() const { return r_edges_; }          // mm
    const std::vector<double>& theta_edges() const { return theta_edges_; }  // rad, −π .. π
    // Maps are [r_bin * theta_bins + theta_bin].
    const std::vector<double>& pair_counts() const { return pairs_; }
    std::vector<double> pair_density() const;       // g(r,θ): over the ideal gas; NaN: no frame
    std::vector<double> polar_correlation() const;  // G(r,θ) = ⟨cos(θ_j − θ_i)⟩; NaN: no pair
    // ρ = (N − 1) / A averaged over frames: the density g(r,θ) is normalised by (mm⁻²).
    double partner_density() const;
    std::size_t frames() const { return frames_; }

  private:
    double r_max_;
    std::size_t nr_, nt_;
    std::vector<double> r_edges_, theta_edges_;
    std::vector<double> pairs_, cos_sum_;
    double reference_pairs_ = 0.0;  // Σ over frames of N (N − 1)
    double partners_ = 0.0;         // Σ over frames of (N − 1) / A
    double area_ = 0.0;             // mm², of the last frame's box
    std::size_t frames_ = 0;
};

}  // namespace rodsea
