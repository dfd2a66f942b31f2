#pragma once
// Radial pair correlations with minimum-image distances (MODEL.md §4): among polar rods g(r),
// G(r) = ⟨cos(θ_i − θ_j)⟩_r and G₂(r) = ⟨cos 2(θ_i − θ_j)⟩_r; among apolar medium rods g(r) and
// G₂(r). g(r) is the pair density over the ideal-gas density of the same group: 1 for an
// uncorrelated fluid. Averaged over the steady frames.
#include "rodsea/analysis/analysis_options.hpp"
#include "rodsea/analysis/observable.hpp"

namespace rodsea {

class PairCorrelationObservable final : public Observable {
  public:
    PairCorrelationObservable(const AnalysisSetup& setup, const AnalysisOptions& options);
    std::string name() const override { return "pair"; }
    void compute(const FrameContext& frame) override;
    ObservableResults finish() override;

  private:
    struct Accumulator {
        double r_max = 0.0;
        std::size_t bins = 0;
        std::vector<double> pairs, cos1, cos2;  // per bin, ordered pairs
        double reference_pairs = 0.0;           // Σ over frames of N (N − 1)
    };
    void accumulate(const FrameContext& context, BodyGroup group, BodyKind kind,
                    Accumulator& acc) const;
    TableResult table(const Accumulator& acc, const std::string& name,
                      const std::string& description, bool polar) const;

    AnalysisSetup setup_;
    double bin_;
    Accumulator polar_, medium_;
    bool has_medium_rods_;
    std::size_t frames_ = 0;
};

}  // namespace rodsea
