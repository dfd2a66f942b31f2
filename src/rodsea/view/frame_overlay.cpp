#include "rodsea/view/frame_overlay.hpp"

#include <algorithm>

#include "rodsea/analyze/analysis_options.hpp"
#include "rodsea/analyze/structure_series.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/error.hpp"

namespace rodsea {

OverlayBuilder::OverlayBuilder(const RunPlan& plan, const OverlayOptions& options)
    : plan_(plan), options_(options), box_{plan.engine.box.lx, plan.engine.box.ly}, tracker_(box_) {
    bool apolar = false;
    for (std::size_t s = 0; s < plan.engine.species.size(); ++s) {
        const Species& sp = plan.engine.species[s];
        if (plan.counts[s] == 0) continue;
        if (sp.kind == BodyKind::polar_rod)
            polar_length_ = std::max(polar_length_, sp.shape.extent);
        apolar = apolar || sp.kind == BodyKind::apolar_rod;
    }
    if ((options.defects || options.director) && !apolar)
        throw InvalidParameter("--overlay", options.defects ? "defects" : "director",
                               "flock-tracks, or a run with apolar rods",
                               "the medium has no apolar rods, so no director field");
    if (options.flock_tracks && polar_length_ == 0.0)
        throw InvalidParameter("--overlay", "flock-tracks", "defects or director",
                               "the run has no polar rods");
    // The analysis' defaults for this run (fields.cell, flocks.eps, flocks.min_samples).
    const AnalysisOptions defaults = automatic_analysis_options({}, analysis_setup(plan));
    cell_ = options.cell.value_or(defaults.field_cell);
    const double half = 0.5 * std::min(box_.lx, box_.ly);
    if (!(cell_ > 0.0 && cell_ <= half))
        throw InvalidParameter("--overlay-cell", format_number(cell_) + " mm",
                               "(0, " + format_number(half) + "] mm (half the box)");
    if (!(options.trail >= 0.0 && std::isfinite(options.trail)))
        throw InvalidParameter("--trail", format_number(options.trail) + " s", "≥ 0 s");
    grid_ = FieldGrid::of(box_, cell_);
    flocks_ = {defaults.flock_eps, defaults.flock_min_samples};
}

OverlayShapes OverlayBuilder::update(const BodyState& bodies, double time) {
    OverlayShapes shapes;
    shapes.cell = grid_.dx;
    shapes.arrow = 1.5 * polar_length_;
    if (options_.defects || options_.director) {
        std::vector<Vec3> centres;
        std::vector<double> angles;
        for (std::size_t b = 0; b < bodies.size(); ++b)
            if (plan_.engine.species[bodies.species[b]].kind == BodyKind::apolar_rod) {
                centres.push_back(bodies.position[b]);
                angles.push_back(in_plane_angle(bodies.orientation[b]));
            }
        const GroupFields f = coarse_grain(grid_, box_, centres, angles, {}, 0.0);
        if (options_.director)
            for (int j = 0; j < grid_.ny; ++j)
                for (int i = 0; i < grid_.nx; ++i) {
                    const std::size_t c = grid_.index(i, j);
                    if (!(f.weight[c] > 0.0)) continue;
                    shapes.director.push_back({(i + 0.5) * grid_.dx, (j + 0.5) * grid_.dy,
                                               f.director(c), 0.9 * grid_.dx * f.S(c)});
                }
        if (options_.defects) shapes.defects = find_nematic_defects(grid_, f.qxx, f.qxy);
    }
    if (options_.flock_tracks && polar_.empty())
        for (std::size_t b = 0; b < bodies.size(); ++b)
            if (plan_.engine.species[bodies.species[b]].kind == BodyKind::polar_rod)
                polar_.push_back(b);
    if (options_.flock_tracks && !polar_.empty()) {
        std::vector<Vec3> centres;
        std::vector<double> angles;
        for (std::size_t b : polar_) {
            const Vec3& p = bodies.position[b];
            centres.push_back(
                {PeriodicBox2D::wrap(p.x, box_.lx), PeriodicBox2D::wrap(p.y, box_.ly), 0.0});
            angles.push_back(in_plane_angle(bodies.orientation[b]));
        }
        const std::vector<int> labels = dbscan(centres, box_, flocks_);
        tracker_.add_frame(time, labels, centres, angles);
        for (const FlockTrack& track : tracker_.tracks()) {
            if (track.ended >= 0.0 || track.states.back().time != time) continue;
            OverlayShapes::Trail trail;
            trail.track = track.id;
            for (const FlockState& s : track.states)
                if (s.time >= time - options_.trail - 1e-9) trail.centres.push_back(s.centre);
            trail.heading = track.states.back().heading;
            trail.leader = centres[track.states.back().leader];
            shapes.trails.push_back(std::move(trail));
        }
    }
    return shapes;
}

std::vector<std::string> OverlayBuilder::caption() const {
    std::vector<std::string> lines;
    std::string medium;
    if (options_.defects) medium = "defects: +1/2 comet, −1/2 trefoil, ±1 ring";
    if (options_.director) medium += std::string(medium.empty() ? "" : "; ") + "director ∝ S";
    if (!medium.empty())
        lines.push_back("overlay: " + medium + " (cells " +
                        format_number(std::round(grid_.dx * 100.0) / 100.0) + " mm)");
    if (options_.flock_tracks)
        lines.push_back("overlay: flock tracks, last " + format_number(options_.trail) +
                        " s; ring: leading rod");
    return lines;
}

}  // namespace rodsea
