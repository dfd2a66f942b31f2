#include "rodsea/analyze/segregation_observable.hpp"

#include <cmath>

namespace rodsea {

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
    polar_.resize(f.size());
    for (std::uint32_t i = 0; i < f.size(); ++i)
        polar_[i] = context.is_polar(i) ? 1 : 0;
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    raw_.push_back(segregation(f.box, grid_, f.position, polar_));
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
