#pragma once
// g(r,θ) and G(r,θ) of polar rods in the frame that moves and turns with a reference polar rod
// (x' along its axis, thick → thin), averaged over reference rods and steady frames (MODEL.md
// §4); and from g(r,θ) the flock contour: aspect ratio σ_f and N_avg, the polar rods inside it.
// Error bars of σ_f and N_avg come from the same quantities on time blocks.
#include "rodsea/analysis/analysis_options.hpp"
#include "rodsea/analysis/flock_contour.hpp"
#include "rodsea/analysis/observable.hpp"

namespace rodsea {

class CorotatingMapsObservable final : public Observable {
  public:
    CorotatingMapsObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "corotating"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    // The contour's level is a fraction of the map's maximum, so the maximum is taken over bins
    // with at least this many pairs (Poisson noise ≤ 20 %), not over a nearly empty inner bin.
    static constexpr double kMinPairsForMaximum = 25.0;

    struct Maps {
        std::vector<double> pairs, cos_sum;
        double reference_pairs = 0.0;  // Σ over frames of N (N − 1)
    };
    std::vector<double> pair_density(const Maps& m) const;  // g(r,θ)
    double n_avg(const FlockContour& c) const;

    AnalysisSetup setup_;
    double r_max_, level_;
    std::size_t nr_, nt_;
    std::vector<double> r_edges_, theta_edges_;
    Maps all_;
    std::vector<Maps> blocks_;
    std::size_t steady_index_ = 0;
};

}  // namespace rodsea
