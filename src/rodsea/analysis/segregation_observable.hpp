#pragma once
// Segregation Σ = (1 / 2φ(1−φ)) Σ_i (n_i / n_tot) |φ_i − φ| over square cells of side a (MODEL.md
// §4): φ_i the polar number fraction in cell i, φ the global one, n_i all bodies in cell i. Σ is
// 0 when every cell holds the global mixture and 1 when every cell holds one species. Finite
// counts make Σ > 0 even for random mixing, so the mean Σ of the same bodies at uniformly random
// positions (CHOICE: the baseline) is subtracted. It depends only on the counts, so it is
// computed once per run.
#include "rodsea/analysis/analysis_options.hpp"
#include "rodsea/analysis/observable.hpp"

namespace rodsea {

struct SegregationGrid {
    int nx = 1, ny = 1;  // cells per side: floor(L / a), so cells tile the box exactly
};
SegregationGrid segregation_grid(const PeriodicBox2D& box, double cell);

// Σ from per-cell counts of polar and of all bodies.
double segregation_index(std::span<const double> polar_per_cell,
                         std::span<const double> all_per_cell);

// Σ of `polar` polar and `others` other bodies at uniformly random positions, averaged over
// `samples` realisations (deterministic for a seed).
double random_mixing_segregation(long long polar, long long others, const SegregationGrid& grid,
                                 int samples, std::uint64_t seed);

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
    std::vector<double> times_, raw_;
    std::vector<char> steady_;
};

}  // namespace rodsea
