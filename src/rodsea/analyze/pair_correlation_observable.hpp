#pragma once
// g(r), G(r), G₂(r) among polar rods and g(r), G₂(r) among apolar medium rods
// (analysis/pair_correlation.hpp), averaged over the steady frames, with error bars from the
// spread of the window's time blocks: the distant pairs' G(r) moves with the global order, whose
// memory is as long as the window.
#include <vector>

#include "rodsea/analysis/pair_correlation.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class PairCorrelationObservable final : public Observable {
  public:
    PairCorrelationObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "pair"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    double bin_;
    // One accumulation per time block of the steady window; empty where the group is absent.
    std::vector<PairCorrelation> polar_, medium_;
};

}  // namespace rodsea
