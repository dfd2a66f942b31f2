#pragma once
// C(t) = ⟨cos(θ_i(t+τ) − θ_i(τ))⟩ of polar rods and C₂(t) (2θ) of every rod species, over rods
// and time origins in the steady window (docs/model.md §4), and the rotational diffusion
// coefficient from C = exp(−D_r t) (polar) or C₂ = exp(−4 D_r t) (apolar): a least-squares fit of
// −ln C through the origin over the lags before C first falls below `fit_floor`, where the estimate
// is still far above its statistical noise. Error bars: the same fit on each time block.
#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class AutocorrelationObservable final : public Observable {
  public:
    AutocorrelationObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "autocorrelation"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    struct Series {
        std::uint32_t species;
        int m;                      // 1: C, 2: C₂
        std::vector<float> angles;  // [frame][body of this species]
        std::size_t bodies = 0;
    };

    AnalysisSetup setup_;
    double max_lag_, fit_floor_;
    std::vector<Series> series_;
    std::size_t frames_ = 0;
};

}  // namespace rodsea
