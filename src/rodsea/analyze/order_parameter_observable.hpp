#pragma once
// P and S per species, every frame (docs/model.md §4): the time series over the whole run and the
// steady-state means. Beads are spheres, so their axis means nothing and they are skipped.
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class OrderParameterObservable final : public Observable {
  public:
    explicit OrderParameterObservable(const AnalysisSetup& setup);
    std::string name() const override { return "order"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    AnalysisSetup setup_;
    std::vector<std::uint32_t> oriented_;  // species with an axis (rods)
    std::vector<double> times_;
    std::vector<char> steady_;
    std::vector<std::vector<double>> polar_, nematic_;  // [species][frame]
};

}  // namespace rodsea
