#pragma once
// The medium's flow around polar rods (analysis/medium_velocity.hpp; paper Fig. 5b) over the
// steady frames: the profile against distance, and the value at the paper's d as a per-frame
// series, which gives its error bar.
#include "rodsea/analysis/medium_velocity.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class MediumVelocityObservable final : public Observable {
  public:
    MediumVelocityObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "medium_velocity"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    MediumVelocityParameters parameters_;
    MediumVelocity profile_;
    std::vector<double> along_at_d_, speed_at_d_, relative_speed_at_d_;
};

}  // namespace rodsea
