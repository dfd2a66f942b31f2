#include "rodsea/analyze/corotating_maps_observable.hpp"

#include <cmath>

#include "rodsea/error.hpp"

namespace rodsea {

CorotatingMapsObservable::CorotatingMapsObservable(const AnalysisSetup& setup,
                                                   const AnalysisOptions& options)
    : parameters_{options.corotating_r_max, options.corotating_r_bins,
                  options.corotating_theta_bins},
      level_(options.contour_level),
      blocks_(static_cast<std::size_t>(setup.blocks), CorotatingMaps(parameters_)) {}

void CorotatingMapsObservable::compute(const FrameContext& context) {
    const GroupArrays& polar = context.group(BodyGroup::polar);
    blocks_[static_cast<std::size_t>(context.block())].compute(polar.grid, polar.angle);
}

FlockContour CorotatingMapsObservable::contour_of(const CorotatingMaps& maps) const {
    return flock_contour(maps.pair_density(), maps.r_edges(), maps.theta_edges(), level_,
                         maps.pair_counts(), kMinPairsForMaximum);
}

double CorotatingMapsObservable::n_avg(const CorotatingMaps& maps, const FlockContour& c) const {
    // The reference rod plus the others expected inside: ρ ∫ g dA with ρ = (N − 1) / A, the
    // density g is normalised by.
    return c.level > 0.0 ? 1.0 + maps.partner_density() * c.enclosed_g_area
                         : std::nan("");  // no pairs, no flock
}

ObservableResults CorotatingMapsObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"r_max", parameters_.r_max, "mm"},
                    {"r_bins", static_cast<double>(parameters_.r_bins), ""},
                    {"theta_bins", static_cast<double>(parameters_.theta_bins), ""},
                    {"contour_level", level_, ""}};
    CorotatingMaps all(parameters_);
    std::vector<double> sigma_blocks, navg_blocks;
    for (const CorotatingMaps& m : blocks_) {
        all += m;
        const FlockContour cb = contour_of(m);
        sigma_blocks.push_back(cb.aspect_ratio);
        navg_blocks.push_back(n_avg(m, cb));
    }
    const FlockContour contour = contour_of(all);
    // A contour that does not close round the reference rod in every direction has no aspect
    // ratio and encloses no flock: null, with the reason, rather than a number with an error bar.
    const Estimate none{std::nan(""), std::nan(""), 0.5, 0.0, 0, true};
    const bool flock = contour.encloses_a_flock();
    r.scalars.push_back({"sigma_f", "",
                         "flock aspect ratio: x' (along the rod) over y' extent of the " +
                             format_number(level_ * 100) + " % contour of g(r,θ)",
                         flock ? estimate_from_blocks(contour.aspect_ratio, sigma_blocks) : none});
    r.scalars.push_back({"N_avg", "", "polar rods inside that contour (reference rod included)",
                         flock ? estimate_from_blocks(n_avg(all, contour), navg_blocks) : none});
    const std::size_t nt = all.theta_bins();
    r.parameters.push_back(
        {"contour_closed_directions", static_cast<double>(contour.closed_rays()), ""});
    r.parameters.push_back({"contour_directions", static_cast<double>(nt), ""});
    double pairs = 0.0;
    for (double p : all.pair_counts())
        pairs += p;
    if (pairs == 0.0)
        r.notes.push_back(
            "no two polar rods closer than corotating.r_max = " + format_number(parameters_.r_max) +
            " mm: the maps are empty, σ_f and N_avg null");
    else if (contour.sparse)
        r.notes.push_back("no bin of g(r,θ) holds " + format_number(kMinPairsForMaximum) +
                          " pairs: its maximum, and so the contour, is noisy; use more frames or "
                          "fewer bins");
    if (contour.empty_rays > 0)
        r.notes.push_back(std::to_string(contour.empty_rays) + " of " + std::to_string(nt) +
                          " directions never reach the contour level (the contour passes "
                          "through the reference rod there): no closed contour, σ_f and N_avg "
                          "null; " +
                          std::to_string(contour.closed_rays()) + " directions closed");
    if (!contour.closed)
        r.notes.push_back(std::to_string(contour.rays_at_edge) + " of " + std::to_string(nt) +
                          " directions stay above the contour level to corotating.r_max = " +
                          format_number(parameters_.r_max) +
                          " mm (the flock is larger than the map): σ_f and N_avg null; raise "
                          "corotating.r_max");
    r.maps.push_back({"g_r_theta",
                      "pair density of polar rods around a reference polar rod over the ideal-gas "
                      "density; theta from the reference rod's axis (thick → thin)",
                      "", all.r_edges(), all.theta_edges(), all.pair_density()});
    r.maps.push_back({"G_r_theta", "<cos(θj − θi)> of polar rods around a reference polar rod", "",
                      all.r_edges(), all.theta_edges(), all.polar_correlation()});
    TableResult t{"flock_contour",
                  "the contour of g(r,θ) used for σ_f and N_avg",
                  {"theta", "r", "x_along", "y_across"},
                  {"rad", "mm", "mm", "mm"},
                  {}};
    for (std::size_t k = 0; k < contour.theta.size(); ++k)
        t.rows.push_back({contour.theta[k], contour.radius[k],
                          contour.radius[k] * std::cos(contour.theta[k]),
                          contour.radius[k] * std::sin(contour.theta[k])});
    r.tables.push_back(std::move(t));
    return r;
}

}  // namespace rodsea
