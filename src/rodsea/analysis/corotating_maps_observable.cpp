#include "rodsea/analysis/corotating_maps_observable.hpp"

#include <cmath>

#include <numbers>
#include "rodsea/error.hpp"

namespace rodsea {

CorotatingMapsObservable::CorotatingMapsObservable(const AnalysisSetup& setup,
                                                   const AnalysisOptions& options)
    : setup_(setup),
      r_max_(options.corotating_r_max),
      level_(options.contour_level),
      nr_(static_cast<std::size_t>(options.corotating_r_bins)),
      nt_(static_cast<std::size_t>(options.corotating_theta_bins)) {
    for (std::size_t k = 0; k <= nr_; ++k)
        r_edges_.push_back(r_max_ * static_cast<double>(k) / static_cast<double>(nr_));
    for (std::size_t t = 0; t <= nt_; ++t)
        theta_edges_.push_back(-std::numbers::pi + 2.0 * std::numbers::pi * static_cast<double>(t) /
                                                       static_cast<double>(nt_));
    all_.pairs.assign(nr_ * nt_, 0.0);
    all_.cos_sum.assign(nr_ * nt_, 0.0);
    blocks_.assign(static_cast<std::size_t>(setup.blocks), all_);
}

void CorotatingMapsObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    const BodyGrid& grid = context.grid(BodyGroup::polar);
    Maps& block = blocks_[static_cast<std::size_t>(setup_.block_of(steady_index_++))];
    const double dr = r_max_ / static_cast<double>(nr_);
    const double dtheta = 2.0 * std::numbers::pi / static_cast<double>(nt_);
    for (std::uint32_t i : grid.members()) {
        const double c = std::cos(f.theta[i]), s = std::sin(f.theta[i]);
        grid.for_each_within(f.x[i], f.y[i], r_max_, [&](std::uint32_t j, double dx, double dy) {
            if (j == i) return;
            // The neighbour in the reference rod's frame: x' along its axis.
            const double xp = dx * c + dy * s, yp = -dx * s + dy * c;
            const auto k = std::min(nr_ - 1, static_cast<std::size_t>(std::hypot(xp, yp) / dr));
            const auto t = std::min(nt_ - 1, static_cast<std::size_t>(
                                                 (std::atan2(yp, xp) + std::numbers::pi) / dtheta));
            const double alignment = std::cos(f.theta[j] - f.theta[i]);
            for (Maps* m : {&all_, &block}) {
                m->pairs[k * nt_ + t] += 1.0;
                m->cos_sum[k * nt_ + t] += alignment;
            }
        });
    }
    const auto n = static_cast<double>(grid.members().size());
    all_.reference_pairs += n * (n - 1.0);
    block.reference_pairs += n * (n - 1.0);
}

std::vector<double> CorotatingMapsObservable::pair_density(const Maps& m) const {
    const double area = setup_.box.lx * setup_.box.ly;
    std::vector<double> g(nr_ * nt_, std::nan(""));
    for (std::size_t k = 0; k < nr_; ++k) {
        const double bin_area = 0.5 *
                                (r_edges_[k + 1] * r_edges_[k + 1] - r_edges_[k] * r_edges_[k]) *
                                (theta_edges_[1] - theta_edges_[0]);
        const double ideal = m.reference_pairs * bin_area / area;
        for (std::size_t t = 0; t < nt_; ++t)
            if (ideal > 0.0) g[k * nt_ + t] = m.pairs[k * nt_ + t] / ideal;
    }
    return g;
}

double CorotatingMapsObservable::n_avg(const FlockContour& c) const {
    // The reference rod plus the others expected inside: ρ ∫ g dA with ρ = (N − 1) / A, the
    // density g is normalised by.
    const double rho =
        static_cast<double>(setup_.polar_count() - 1) / (setup_.box.lx * setup_.box.ly);
    return c.level > 0.0 ? 1.0 + rho * c.enclosed_g_area : std::nan("");  // no pairs, no flock
}

ObservableResults CorotatingMapsObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"r_max", r_max_, "mm"},
                    {"r_bins", static_cast<double>(nr_), ""},
                    {"theta_bins", static_cast<double>(nt_), ""},
                    {"contour_level", level_, ""}};
    const std::vector<double> g = pair_density(all_);
    std::vector<double> G(nr_ * nt_, std::nan(""));
    for (std::size_t b = 0; b < G.size(); ++b)
        if (all_.pairs[b] > 0.0) G[b] = all_.cos_sum[b] / all_.pairs[b];
    const FlockContour contour =
        flock_contour(g, r_edges_, theta_edges_, level_, all_.pairs, kMinPairsForMaximum);
    std::vector<double> sigma_blocks, navg_blocks;
    for (const Maps& m : blocks_) {
        const FlockContour cb = flock_contour(pair_density(m), r_edges_, theta_edges_, level_,
                                              m.pairs, kMinPairsForMaximum);
        sigma_blocks.push_back(cb.aspect_ratio);
        navg_blocks.push_back(n_avg(cb));
    }
    r.scalars.push_back({"sigma_f", "",
                         "flock aspect ratio: x' (along the rod) over y' extent of the " +
                             format_number(level_ * 100) + " % contour of g(r,θ)",
                         estimate_from_blocks(contour.aspect_ratio, sigma_blocks)});
    r.scalars.push_back({"N_avg", "", "polar rods inside that contour (reference rod included)",
                         estimate_from_blocks(n_avg(contour), navg_blocks)});
    double pairs = 0.0;
    for (double p : all_.pairs)
        pairs += p;
    if (pairs == 0.0)
        r.notes.push_back("no two polar rods closer than corotating.r_max = " +
                          format_number(r_max_) + " mm: the maps are empty, σ_f and N_avg null");
    else if (contour.sparse)
        r.notes.push_back("no bin of g(r,θ) holds " + format_number(kMinPairsForMaximum) +
                          " pairs: its maximum, and so the contour, is noisy; use more frames or "
                          "fewer bins");
    if (contour.empty_rays > 0)
        r.notes.push_back(std::to_string(contour.empty_rays) + " of " + std::to_string(nt_) +
                          " directions never reach the contour level: the contour passes "
                          "through the reference rod there");
    if (!contour.closed)
        r.notes.push_back(
            "the g(r,θ) contour reaches corotating.r_max: the flock is larger than "
            "the map, so σ_f and N_avg are lower bounds; raise corotating.r_max");
    r.maps.push_back({"g_r_theta",
                      "pair density of polar rods around a reference polar rod over the ideal-gas "
                      "density; theta from the reference rod's axis (thick → thin)",
                      "", r_edges_, theta_edges_, g});
    r.maps.push_back({"G_r_theta", "<cos(θj − θi)> of polar rods around a reference polar rod", "",
                      r_edges_, theta_edges_, G});
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
