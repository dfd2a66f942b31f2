#include "rodsea/analyze/flock_defect_observable.hpp"

#include <cmath>
#include <limits>

#include "rodsea/analysis/flock_tracks.hpp"

namespace rodsea {

namespace {

// The nearest of `defects` to (x, y): its distance (mm) and index.
std::pair<double, std::size_t> nearest(const PeriodicBox2D& box,
                                       const std::vector<const NematicDefect*>& defects, double x,
                                       double y) {
    double best = std::numeric_limits<double>::infinity();
    std::size_t at = 0;
    for (std::size_t k = 0; k < defects.size(); ++k) {
        const Vec3 d = box.minimum_image(Vec3{defects[k]->x - x, defects[k]->y - y, 0.0});
        const double r = std::hypot(d.x, d.y);
        if (r < best) best = r, at = k;
    }
    return {best, at};
}

void add_to(std::vector<double>& histogram, double bin, double r, double weight) {
    const auto k = static_cast<std::size_t>(r / bin);
    if (k >= histogram.size()) histogram.resize(k + 1, 0.0);
    histogram[k] += weight;
}

}  // namespace

FlockDefectObservable::FlockDefectObservable(const AnalysisSetup& setup,
                                             const AnalysisOptions& options)
    : setup_(setup),
      flocks_{options.flock_eps, options.flock_min_samples},
      cell_(options.field_cell),
      bin_(0.5 * options.field_cell) {}

void FlockDefectObservable::compute(const FrameContext& context) {
    std::vector<const NematicDefect*> plus;
    for (const NematicDefect& d : context.defects(cell_))
        if (d.charge == 0.5) plus.push_back(&d);
    const GroupArrays& polar = context.group(BodyGroup::polar);
    const std::vector<FlockSummary> flocks =
        summarise_flocks(context.flock_labels(flocks_), polar.position, polar.angle, setup_.box);
    if (plus.empty() || flocks.empty()) {
        ++frames_without_;
        return;
    }
    const PeriodicBox2D& box = setup_.box;
    double distance = 0.0, alignment = 0.0;
    for (const FlockSummary& f : flocks) {
        const auto [r, k] = nearest(box, plus, f.centre.x, f.centre.y);
        const double c = std::cos(f.heading - plus[k]->orientation);
        distance += r;
        alignment += c;
        add_to(flock_histogram_, bin_, r, 1.0);
        rows_.push_back({context.frame().time, static_cast<double>(f.size), f.centre.x, f.centre.y,
                         f.heading, r, plus[k]->orientation, c});
    }
    const auto n = static_cast<double>(flocks.size());
    flock_distance_.push_back(distance / n);
    alignment_.push_back(alignment / n);
    // A random point's nearest +1/2, averaged over the cell centres of the field grid.
    const FieldGrid& grid = context.fields(cell_).grid;
    double random = 0.0;
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const double r = nearest(box, plus, (i + 0.5) * grid.dx, (j + 0.5) * grid.dy).first;
            random += r;
            add_to(random_histogram_, bin_, r, n / static_cast<double>(grid.cells()));
        }
    random_distance_.push_back(random / static_cast<double>(grid.cells()));
}

ObservableResults FlockDefectObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"cell", cell_, "mm"}, {"bin", bin_, "mm"}};
    const Estimate flock = estimate_mean(flock_distance_);
    const Estimate random = estimate_mean(random_distance_);
    r.scalars.push_back({"flock_defect_distance", "mm",
                         "distance from a flock's centre to the nearest +1/2 defect, mean over "
                         "the steady frames' flocks",
                         flock});
    r.scalars.push_back(
        {"random_defect_distance", "mm", "the same from a point at random: the baseline", random});
    // The ratio's error from the per-frame ratios, which share each frame's defects.
    std::vector<double> ratio;
    for (std::size_t k = 0; k < flock_distance_.size(); ++k)
        ratio.push_back(flock_distance_[k] / random_distance_[k]);
    r.scalars.push_back({"defect_distance_ratio", "",
                         "flock distance over random distance, per frame, mean (< 1: flocks sit "
                         "near +1/2 defects)",
                         estimate_mean(ratio)});
    r.scalars.push_back({"flock_defect_alignment", "",
                         "cos(flock heading − orientation of its nearest +1/2 defect), mean (0: "
                         "unrelated)",
                         estimate_mean(alignment_)});
    r.tables.push_back(
        {"flock_defect_pairs",
         "each flock of each steady frame with its nearest +1/2 defect: the "
         "distance, the defect's orientation and the alignment cos(heading − "
         "orientation)",
         {"time", "size", "x", "y", "heading", "distance", "defect_orientation", "alignment"},
         {"s", "", "mm", "mm", "rad", "mm", "rad", ""},
         std::move(rows_)});
    TableResult histogram{"flock_defect_distance_histogram",
                          "distance to the nearest +1/2 defect: flocks' centres against random "
                          "points (scaled to the same count), per bin",
                          {"r_low", "r_high", "flocks", "random"},
                          {"mm", "mm", "", ""},
                          {}};
    const std::size_t bins = std::max(flock_histogram_.size(), random_histogram_.size());
    flock_histogram_.resize(bins, 0.0);
    random_histogram_.resize(bins, 0.0);
    for (std::size_t k = 0; k < bins; ++k)
        histogram.rows.push_back({static_cast<double>(k) * bin_, static_cast<double>(k + 1) * bin_,
                                  flock_histogram_[k], random_histogram_[k]});
    r.tables.push_back(std::move(histogram));
    if (frames_without_ > 0)
        r.notes.push_back(std::to_string(frames_without_) +
                          " steady frames had no flock or no +1/2 defect and were left out");
    return r;
}

}  // namespace rodsea
