#pragma once
// Flocks: DBSCAN on polar-rod centres with periodic distances (analysis/dbscan.hpp; docs/model.md
// §4, CHOICE eps = ℓ_p/2, min_samples = 3), every frame: the largest flock N_m(t), the number of
// flocks, the fraction of polar rods in a flock, the labels per frame, and over the steady window
// ⟨N_m⟩, the histogram of N_m and the distribution of flock sizes; how much of P the flocks
// explain (analysis/flock_order.hpp); and the flocks followed in time (analysis/flock_tracks.hpp,
// flock_track_results.hpp).
#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/flock_tracks.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class FlockObservable final : public Observable {
  public:
    FlockObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "flocks"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    Estimate flock_alignment() const;

    AnalysisSetup setup_;
    DbscanParameters parameters_;
    FlockTracker tracker_;
    double steady_from_ = -1.0;          // s, the first steady frame's time
    std::vector<std::uint32_t> bodies_;  // polar rods, in trajectory order
    std::vector<double> times_, largest_, flocks_, in_flocks_, independent_;
    std::vector<double> block_p2_, block_independent2_;  // steady Σ P², Σ P_independent² per block
    std::vector<char> steady_;
    std::vector<std::int32_t> labels_;       // [frame][polar rod]
    std::vector<double> size_distribution_;  // steady frames: flocks of each size
};

}  // namespace rodsea
