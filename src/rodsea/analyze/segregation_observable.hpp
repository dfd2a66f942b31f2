#pragma once
// Segregation Σ every frame (analysis/segregation.hpp), raw and with its random-mixing baseline
// removed (CHOICE: the baseline, computed once per run since it depends only on the counts).
#include "rodsea/analysis/segregation.hpp"
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class SegregationObservable final : public Observable {
  public:
    SegregationObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "segregation"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    AnalysisSetup setup_;
    double cell_;
    SegregationGrid grid_;
    int samples_;
    double baseline_;
    std::vector<std::uint8_t> polar_;  // per body of the frame, 1 for a polar rod
    std::vector<double> times_, raw_;
    std::vector<char> steady_;
};

}  // namespace rodsea
