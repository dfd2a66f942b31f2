#pragma once
// The mean in-plane velocity of each species, every frame, and its steady mean: how the medium
// drifts. With polar rods, the medium's velocity is also projected on the polar rods' mean
// heading p̂ = ⟨(cos θ, sin θ)⟩/P of the same frame: the drift along the flocks' motion that the
// paper's mechanism predicts. Without polar rods nothing sets a direction, and the medium's
// mean velocity must average to zero within its error (the validate tier's control).
// Beside the drift, each species' agitation: the rms of its in-plane velocities about their mean
// and the rms of its spins about z. The plates give every body these; they are what a medium's
// collisions carry into the polar rods (docs/reproduction.md, the dilute end).
#include "rodsea/analyze/observable.hpp"

namespace rodsea {

class DriftObservable final : public Observable {
  public:
    explicit DriftObservable(const AnalysisSetup& setup);
    std::string name() const override { return "drift"; }
    bool wants_transient() const override { return true; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    AnalysisSetup setup_;
    std::vector<double> times_;
    std::vector<char> steady_;
    std::vector<std::vector<double>> vx_, vy_;   // [species][frame], mm/s
    std::vector<std::vector<double>> v_rms_;     // [species][frame], mm/s, about the mean
    std::vector<std::vector<double>> spin_rms_;  // [species][frame], rad/s
    std::vector<double> along_;                  // medium along p̂, mm/s (with polar rods)
};

}  // namespace rodsea
