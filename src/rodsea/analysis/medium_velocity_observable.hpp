#pragma once
// The flow of the medium around polar rods (MODEL.md §4; paper Fig. 5b): for every polar rod i
// and medium body j at distance r, the medium's in-plane velocity in the rod's corotating axes
// (along its axis, thick → thin, and across it), its speed, and the same relative to the rod
// (the comoving frame), averaged per distance bin over rods and steady frames. The value at the
// paper's d is also a per-frame series, which gives its error bar.
#include "rodsea/analysis/analysis_options.hpp"
#include "rodsea/analysis/observable.hpp"

namespace rodsea {

class MediumVelocityObservable final : public Observable {
  public:
    MediumVelocityObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "medium_velocity"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    enum Column { kPairs, kAlong, kAcross, kSpeed, kRelativeAlong, kRelativeSpeed, kColumns };

    AnalysisSetup setup_;
    double d_, r_max_, bin_;
    std::size_t bins_;
    std::vector<double> sums_;  // [bin][column]
    std::vector<double> along_at_d_, speed_at_d_, relative_speed_at_d_;
};

}  // namespace rodsea
