#pragma once
// Radial pair correlations with minimum-image distances (docs/model.md §4), accumulated over
// frames: g(r), the pair density over the ideal-gas density (1 for an uncorrelated fluid); G(r) =
// ⟨cos(θ_i − θ_j)⟩_r and G₂(r) = ⟨cos 2(θ_i − θ_j)⟩_r over ordered pairs.
#include <cstddef>
#include <span>
#include <vector>

#include "rodsea/analysis/neighbor_query.hpp"

namespace rodsea {

struct PairCorrelationParameters {
    double r_max = 45.0;  // mm, at most half the box
    double bin = 0.25;    // mm; the bins are whole, the last may end past r_max by < one bin
};

class PairCorrelation {
  public:
    explicit PairCorrelation(const PairCorrelationParameters& p);

    // One frame: the points of one group (their grid) and their angles, rad.
    void compute(const PeriodicGrid2D& points, std::span<const double> angles);
    void compute(const PeriodicBox2D& box, std::span<const Vec3> points,
                 std::span<const double> angles) {
        compute(query_grid(box, points), angles);
    }

    double r_max() const { return static_cast<double>(bins_) * bin_; }  // mm, whole bins
    std::vector<double> bin_centres() const;                            // mm
    const std::vector<double>& pair_counts() const { return pairs_; }   // ordered pairs
    std::vector<double> pair_density() const;                           // g(r); NaN: no frame
    std::vector<double> polar_correlation() const;                      // G(r); NaN: no pair
    std::vector<double> nematic_correlation() const;                    // G₂(r)
    std::size_t frames() const { return frames_; }

    // Pools another accumulation of the same parameters (e.g. one time block of the window); an
    // empty one changes nothing, and the pooled range is the shorter of the two.
    PairCorrelation& operator+=(const PairCorrelation& other);

  private:
    double bin_;
    std::size_t bins_;
    std::vector<double> pairs_, cos1_, cos2_;
    double reference_pairs_ = 0.0;  // Σ over frames of N (N − 1)
    double area_ = 0.0;             // mm², of the last frame's box
    std::size_t frames_ = 0;
};

}  // namespace rodsea
