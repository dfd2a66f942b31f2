#pragma once
// g(r,θ) and G(r,θ) around polar rods (analysis/corotating_maps.hpp), averaged over the steady
// frames, and from g(r,θ) the flock contour (analysis/flock_contour.hpp): aspect ratio σ_f and
// N_avg, the polar rods inside it. Error bars of σ_f and N_avg come from the same quantities on
// time blocks.
#include <vector>

#include "rodsea/analysis/corotating_maps.hpp"
#include "rodsea/analysis/flock_contour.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

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

    FlockContour contour_of(const CorotatingMaps& maps) const;
    double n_avg(const CorotatingMaps& maps, const FlockContour& c) const;

    CorotatingParameters parameters_;
    double level_;
    std::vector<CorotatingMaps> blocks_;  // one per time block of the steady window
};

}  // namespace rodsea
