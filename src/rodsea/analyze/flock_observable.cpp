#include "rodsea/analyze/flock_observable.hpp"

#include <algorithm>
#include <limits>

#include "rodsea/analysis/flock_order.hpp"
#include "rodsea/analyze/flock_track_results.hpp"
#include "rodsea/engine/order_parameters.hpp"

namespace rodsea {

FlockObservable::FlockObservable(const AnalysisSetup& setup, const AnalysisOptions& options)
    : setup_(setup),
      parameters_{options.flock_eps, options.flock_min_samples},
      tracker_(setup.box) {}

void FlockObservable::compute(const FrameContext& context) {
    const AnalysisFrame& f = context.frame();
    const GroupArrays& group = context.group(BodyGroup::polar);
    const std::vector<std::uint32_t>& polar = group.members;
    if (bodies_.empty()) bodies_ = polar;
    const std::vector<int>& labels = context.flock_labels(parameters_);
    tracker_.add_frame(f.time, labels, group.position, group.angle);
    if (context.steady() && steady_from_ < 0.0) steady_from_ = f.time;
    const std::vector<double> sizes = cluster_sizes(labels);
    double members = 0.0;
    for (double s : sizes)
        members += s;
    times_.push_back(f.time);
    steady_.push_back(context.steady() ? 1 : 0);
    largest_.push_back(sizes.empty() ? 0.0 : *std::max_element(sizes.begin(), sizes.end()));
    flocks_.push_back(static_cast<double>(sizes.size()));
    in_flocks_.push_back(polar.empty() ? 0.0 : members / static_cast<double>(polar.size()));
    const double p = orientational_order(group.angle, 1);
    const double p_independent = independent_flock_order(group.angle, labels);
    independent_.push_back(p_independent);
    if (context.steady()) {
        const auto b = static_cast<std::size_t>(context.block());
        if (b >= block_p2_.size()) {
            block_p2_.resize(b + 1, 0.0);
            block_independent2_.resize(b + 1, 0.0);
        }
        block_p2_[b] += p * p;
        block_independent2_[b] += p_independent * p_independent;
    }
    labels_.insert(labels_.end(), labels.begin(), labels.end());
    if (context.steady())
        for (double s : sizes) {
            const auto k = static_cast<std::size_t>(s);
            if (k >= size_distribution_.size()) size_distribution_.resize(k + 1, 0.0);
            size_distribution_[k] += 1.0;
        }
}

ObservableResults FlockObservable::finish() {
    ObservableResults r;
    r.observable = name();
    r.parameters = {{"eps", parameters_.eps, "mm"},
                    {"min_samples", static_cast<double>(parameters_.min_samples), ""}};
    r.scalars.push_back(
        {"N_m", "", "largest flock (polar rods), steady mean", steady_estimate(largest_, steady_)});
    r.scalars.push_back(
        {"flock_count", "", "number of flocks, steady mean", steady_estimate(flocks_, steady_)});
    r.scalars.push_back({"flock_fraction", "", "fraction of polar rods in a flock, steady mean",
                         steady_estimate(in_flocks_, steady_)});
    r.scalars.push_back({"P_independent", "",
                         "P if each flock and lone polar rod headed independently (rms over "
                         "random turns of each), steady mean",
                         steady_estimate(independent_, steady_)});
    r.scalars.push_back({"flock_alignment", "",
                         "<P^2> / <P_independent^2> over the steady window: 1 when flocks head "
                         "independently, above 1 when they align with one another",
                         flock_alignment()});
    TableResult series{"flocks",
                       "largest flock N_m, number of flocks, fraction of polar rods in flocks "
                       "and the P of independently heading flocks, every frame",
                       {"time", "steady", "N_m", "flocks", "fraction_in_flocks", "P_independent"},
                       {"s", "", "", "", "", ""},
                       {}};
    std::vector<double> histogram;
    double steady_frames = 0.0;
    for (std::size_t k = 0; k < times_.size(); ++k) {
        series.rows.push_back({times_[k], static_cast<double>(steady_[k]), largest_[k], flocks_[k],
                               in_flocks_[k], independent_[k]});
        if (!steady_[k]) continue;
        const auto n = static_cast<std::size_t>(largest_[k]);
        if (n >= histogram.size()) histogram.resize(n + 1, 0.0);
        histogram[n] += 1.0;
        steady_frames += 1.0;
    }
    r.tables.push_back(std::move(series));
    TableResult hist{"largest_flock_histogram",
                     "histogram of N_m over the steady frames",
                     {"N_m", "frames", "probability"},
                     {"", "", ""},
                     {}};
    for (std::size_t n = 0; n < histogram.size(); ++n)
        if (histogram[n] > 0)
            hist.rows.push_back(
                {static_cast<double>(n), histogram[n], histogram[n] / steady_frames});
    r.tables.push_back(std::move(hist));
    TableResult dist{
        "flock_size_distribution",
        "flocks of each size over the steady frames (every flock, not only the largest)",
        {"size", "flocks", "per_frame"},
        {"", "", ""},
        {}};
    for (std::size_t n = 0; n < size_distribution_.size(); ++n)
        if (size_distribution_[n] > 0)
            dist.rows.push_back({static_cast<double>(n), size_distribution_[n],
                                 size_distribution_[n] / std::max(1.0, steady_frames)});
    r.tables.push_back(std::move(dist));
    r.labels.push_back({"flock_labels",
                        "DBSCAN label of each polar rod per frame (−1: not in a flock)", bodies_,
                        times_, labels_});
    add_flock_track_results(tracker_, bodies_, setup_, steady_from_, r);
    return r;
}

Estimate FlockObservable::flock_alignment() const {
    double p2 = 0.0, independent2 = 0.0;
    std::vector<double> blocks;
    for (std::size_t b = 0; b < block_p2_.size(); ++b) {
        p2 += block_p2_[b];
        independent2 += block_independent2_[b];
        if (block_independent2_[b] > 0.0) blocks.push_back(block_p2_[b] / block_independent2_[b]);
    }
    if (!(independent2 > 0.0)) {  // no steady frame, or no polar rod
        const double nan = std::numeric_limits<double>::quiet_NaN();
        return {.mean = nan, .error = nan};
    }
    return estimate_from_blocks(p2 / independent2, blocks);
}

}  // namespace rodsea
