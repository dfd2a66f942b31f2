#pragma once
// The structure of one state as `rodsea analyze` measures it with its default options: the
// segregation Σ (raw, cells of 2 ℓ_p) and the largest flock N_m (DBSCAN, eps ℓ_p/2, 3 samples).
// `rodsea run` records both every frame beside P and S, so that the steady window is chosen from
// every order series of a run (steady_state.hpp), structure included.
#include <optional>
#include <string>
#include <vector>

#include "rodsea/analysis/dbscan.hpp"
#include "rodsea/analysis/segregation.hpp"
#include "rodsea/analyze/observable.hpp"
#include "rodsea/config/run_plan.hpp"
#include "rodsea/engine/body_state.hpp"

namespace rodsea {

// The bodies of a run as the analysis sees them: box, species, counts, area fractions.
AnalysisSetup analysis_setup(const RunPlan& plan);

// The time-series columns Σ and N_m are written under.
inline const char* const kSegregationColumn = "segregation";
inline const char* const kLargestFlockColumn = "largest_flock";

class StructureSeries {
  public:
    explicit StructureSeries(const AnalysisSetup& setup);

    // Σ needs polar rods, another species and a box of at least one cell; N_m polar rods.
    bool has_segregation() const { return segregation_grid_.has_value(); }
    bool has_flocks() const { return flocks_.has_value(); }
    double segregation(const BodyState& bodies) const;    // NaN when it does not apply
    double largest_flock(const BodyState& bodies) const;  // NaN when it does not apply

  private:
    PeriodicBox2D box_;
    std::vector<std::uint8_t> polar_species_;  // 1 for each polar species
    std::optional<SegregationGrid> segregation_grid_;
    std::optional<DbscanParameters> flocks_;
};

// The columns of the time series that decide the steady window, in this order: P and S of each
// polar species, S of each apolar rod species, then Σ and N_m where they apply.
std::vector<std::string> steady_series_columns(const AnalysisSetup& setup);

}  // namespace rodsea
