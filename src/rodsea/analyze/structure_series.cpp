#include "rodsea/analyze/structure_series.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

AnalysisSetup analysis_setup(const RunPlan& plan) {
    AnalysisSetup setup;
    setup.box = {plan.engine.box.lx, plan.engine.box.ly};
    const double area = setup.box.lx * setup.box.ly;
    for (std::size_t s = 0; s < plan.engine.species.size(); ++s) {
        const Species& sp = plan.engine.species[s];
        setup.species.push_back(
            {sp.name, sp.kind, sp.shape.extent, plan.counts[s],
             static_cast<double>(plan.counts[s]) * sp.shape.projected_area / area});
    }
    return setup;
}

StructureSeries::StructureSeries(const AnalysisSetup& setup) : box_(setup.box) {
    for (const SpeciesInfo& s : setup.species)
        polar_species_.push_back(s.kind == BodyKind::polar_rod ? 1 : 0);
    const long long polar = setup.polar_count();
    if (polar == 0) return;
    // The analysis defaults, resolved as `rodsea analyze` resolves them; a box too small for
    // them has no Σ (its cell would not fit), which is not an error of the run.
    AnalysisOptions options;
    try {
        options = resolve_analysis_options(AnalysisOptions{}, setup);
    } catch (const InvalidParameter&) {
        return;
    }
    flocks_ = DbscanParameters{options.flock_eps, options.flock_min_samples};
    if (setup.total_count() > polar)
        segregation_grid_ = rodsea::segregation_grid(box_, options.segregation_cell);
}

double StructureSeries::segregation(const BodyState& bodies) const {
    if (!segregation_grid_) return std::numeric_limits<double>::quiet_NaN();
    std::vector<std::uint8_t> polar(bodies.size());
    for (std::size_t i = 0; i < bodies.size(); ++i)
        polar[i] = polar_species_[bodies.species[i]];
    return rodsea::segregation(box_, *segregation_grid_, bodies.position, polar);
}

double StructureSeries::largest_flock(const BodyState& bodies) const {
    if (!flocks_) return std::numeric_limits<double>::quiet_NaN();
    std::vector<Vec3> points;
    for (std::size_t i = 0; i < bodies.size(); ++i)
        if (polar_species_[bodies.species[i]]) points.push_back(bodies.position[i]);
    const std::vector<double> sizes = cluster_sizes(dbscan(points, box_, *flocks_));
    return sizes.empty() ? 0.0 : *std::max_element(sizes.begin(), sizes.end());
}

std::vector<std::string> steady_series_columns(const AnalysisSetup& setup) {
    std::vector<std::string> columns;
    for (const SpeciesInfo& s : setup.species) {
        if (s.count == 0) continue;
        if (s.kind == BodyKind::polar_rod) columns.push_back("polar_order_" + s.name);
        if (s.kind != BodyKind::bead) columns.push_back("nematic_order_" + s.name);
    }
    const StructureSeries structure(setup);
    if (structure.has_segregation()) columns.push_back(kSegregationColumn);
    if (structure.has_flocks()) columns.push_back(kLargestFlockColumn);
    return columns;
}

}  // namespace rodsea
