#include "rodsea/analysis/segregation_observable.hpp"

#include <algorithm>

#include <cmath>
#include "rodsea/error.hpp"

#include "rodsea/random.hpp"

namespace rodsea {

SegregationGrid segregation_grid(const PeriodicBox2D& box, double cell) {
    return {std::max(1, static_cast<int>(box.lx / cell)),
            std::max(1, static_cast<int>(box.ly / cell))};
}

double segregation_index(std::span<const double> polar, std::span<const double> all) {
    double total = 0.0, polar_total = 0.0;
    for (std::size_t c = 0; c < all.size(); ++c)
        total += all[c], polar_total += polar[c];
    if (total <= 0.0) return std::nan("");
    const double phi = polar_total / total;
    if (phi <= 0.0 || phi >= 1.0) return std::nan("");  // one species: nothing to segregate
    double sum = 0.0;
    for (std::size_t c = 0; c < all.size(); ++c)
        if (all[c] > 0.0) sum += all[c] / total * std::abs(polar[c] / all[c] - phi);
    return sum / (2.0 * phi * (1.0 - phi));
}

double random_mixing_segregation(long long polar, long long others, const SegregationGrid& grid,
                                 int samples, std::uint64_t seed) {
    const auto cells = static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny);
    SplitMix64 rng(seed);
    double sum = 0.0;
    std::vector<double> p(cells), a(cells);
    for (int s = 0; s < samples; ++s) {
        std::fill(p.begin(), p.end(), 0.0);
        std::fill(a.begin(), a.end(), 0.0);
        for (long long b = 0; b < polar + others; ++b) {
            // Uniform positions in a box tiled by equal cells: a uniform cell index.
            const auto c = std::min(
                cells - 1, static_cast<std::size_t>(rng.uniform() * static_cast<double>(cells)));
            a[c] += 1.0;
            if (b < polar) p[c] += 1.0;
        }
        sum += segregation_index(p, a);
    }
    return sum / samples;
}

SegregationObservable::SegregationObservable(const AnalysisSetup& setup,
                                             const AnalysisOptions& options)
    : setup_(setup),
      cell_(options.segregation_cell),
      grid_(segregation_grid(setup.box, options.segregation_cell)),
      samples_(options.segregation_baseline_samples),
      baseline_(random_mixing_segregation(setup.polar_count(),
                                          setup.total_count() - setup.polar_count(), grid_,
                                          samples_, 0x5E6E6A7E)) {}

void SegregationObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    const auto cells = static_cast<std::size_t>(grid_.nx) * static_cast<std::size_t>(grid_.ny);
    std::vector<double> p(cells, 0.0), a(cells, 0.0);
    for (std::size_t i = 0; i < f.size(); ++i) {
        const int cx = std::min(grid_.nx - 1, static_cast<int>(f.x[i] / f.box.lx * grid_.nx));
        const int cy = std::min(grid_.ny - 1, static_cast<int>(f.y[i] / f.box.ly * grid_.ny));
        const auto c = static_cast<std::size_t>(cy * grid_.nx + cx);
        a[c] += 1.0;
        if (context.is_polar(static_cast<std::uint32_t>(i))) p[c] += 1.0;
    }
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    raw_.push_back(segregation_index(p, a));
}

ObservableResults SegregationObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"cell", cell_, "mm"},
                    {"cell_used_x", setup_.box.lx / grid_.nx, "mm"},
                    {"cell_used_y", setup_.box.ly / grid_.ny, "mm"},
                    {"cells", static_cast<double>(grid_.nx * grid_.ny), ""},
                    {"baseline_samples", static_cast<double>(samples_), ""}};
    std::vector<double> corrected;
    TableResult t{"segregation",
                  "Σ every frame, raw and with the random-mixing baseline removed",
                  {"time", "steady", "Sigma_raw", "Sigma"},
                  {"s", "", "", ""},
                  {}};
    for (std::size_t k = 0; k < raw_.size(); ++k) {
        corrected.push_back(raw_[k] - baseline_);
        t.rows.push_back({times_[k], static_cast<double>(steady_[k]), raw_[k], corrected.back()});
    }
    r.scalars.push_back({"Sigma", "", "segregation Σ minus its random-mixing baseline, steady mean",
                         steady_estimate(corrected, steady_)});
    r.scalars.push_back({"Sigma_raw", "", "segregation Σ as measured, steady mean",
                         steady_estimate(raw_, steady_)});
    r.scalars.push_back(
        {"Sigma_baseline", "",
         "Σ of the same bodies at uniformly random positions (mean of " + std::to_string(samples_) +
             " realisations)",
         Estimate{baseline_, std::nan(""), 0.5, 0.0, static_cast<std::size_t>(samples_)}});
    r.tables.push_back(std::move(t));
    return r;
}

}  // namespace rodsea
