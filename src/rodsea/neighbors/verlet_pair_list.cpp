#include "rodsea/neighbors/verlet_pair_list.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rodsea {

VerletPairList::VerletPairList(double skin) : skin_(skin) {
    if (!(skin > 0.0) || !std::isfinite(skin))
        throw std::invalid_argument("VerletPairList: the skin must be positive and finite");
}

bool VerletPairList::update(std::span<const Vec3> points, std::span<const double> radii,
                            std::span<const std::uint32_t> groups, const PeriodicBox2D& box,
                            double travel, int threads) {
    const bool changed = builds_ == 0 || points.size() != reference_.size() || box.lx != box_.lx ||
                         box.ly != box_.ly;
    if (!changed) {
        slack_ += travel;
        if (slack_ <= 0.5 * skin_) return false;
        slack_ = largest_move(points, threads);  // the bound ran out: measure
        if (slack_ <= 0.5 * skin_) return false;
    }
    build(points, radii, groups, box, threads);
    return true;
}

double VerletPairList::largest_move(std::span<const Vec3> points, int threads) const {
    double largest2 = 0.0;  // a maximum: the same on any number of threads
    const auto n = static_cast<std::ptrdiff_t>(points.size());
    [[maybe_unused]] constexpr std::ptrdiff_t kWorthThreads = 4096;
#pragma omp parallel for schedule(static) reduction(max         \
                                                    : largest2) \
    num_threads(threads) if (threads > 1 && n >= kWorthThreads)
    for (std::ptrdiff_t i = 0; i < n; ++i) {
        const auto k = static_cast<size_t>(i);
        const Vec3 d = minimum_image(points[k] - reference_[k]);
        largest2 = std::max(largest2, d.x * d.x + d.y * d.y);
    }
    return std::sqrt(largest2);
}

void VerletPairList::collect(int row_begin, int row_end, std::vector<Pair>& out) const {
    out.clear();
    const std::span<const std::uint32_t> order = grid_.order();
    const std::span<const Vec3> p = grid_.slot_points();
    const bool single_x = grid_.single_cell_x(), single_y = grid_.single_cell_y();
    // The grid's own pair loop less its cutoff test: no two grown discs reach farther than the
    // widest, the cutoff, and (r_i + s/2) + (r_j + s/2) <= 2 (r_max + s/2) holds in rounding too,
    // so the same pairs are kept. Most candidates are out of reach or spheres of one body: one
    // test that seldom passes instead of a chain of branches.
    const auto cells = [&](std::uint32_t a_begin, std::uint32_t a_end, std::uint32_t b_begin,
                           std::uint32_t b_end, double sx, double sy, bool same) {
        for (std::uint32_t a = a_begin; a < a_end; ++a) {
            const Vec3 pa = p[a];
            const double reach_a = slot_reach_[a];
            const std::uint32_t group_a = slot_group_[a];
            for (std::uint32_t b = same ? a + 1 : b_begin; b < b_end; ++b) {
                double dx = (pa.x - p[b].x) + sx, dy = (pa.y - p[b].y) + sy;
                if (single_x) dx -= box_.lx * std::nearbyint(dx / box_.lx);
                if (single_y) dy -= box_.ly * std::nearbyint(dy / box_.ly);
                const double reach = reach_a + slot_reach_[b];
                if ((group_a != slot_group_[b]) & (dx * dx + dy * dy < reach * reach)) {
                    const std::uint32_t i = order[a], j = order[b];
                    out.push_back({std::min(i, j), std::max(i, j)});
                }
            }
        }
    };
    grid_.for_each_cell_pair(row_begin, row_end, cells);
}

void VerletPairList::build(std::span<const Vec3> points, std::span<const double> radii,
                           std::span<const std::uint32_t> groups, const PeriodicBox2D& box,
                           int threads) {
    if (radii.size() != points.size() || groups.size() != points.size())
        throw std::invalid_argument("VerletPairList: radii and groups need one per point");
    box_ = box;
    half_x_ = 0.5 * box.lx;
    half_y_ = 0.5 * box.ly;
    // Discs grown by skin / 2 each overlap when their centres are closer than r_i + r_j + skin;
    // no pair is farther apart than the widest such disc.
    const double half_skin = 0.5 * skin_;
    double widest = 0.0;
    for (const double r : radii)
        widest = std::max(widest, 2.0 * (r + half_skin));
    const size_t n = points.size();
    for (std::vector<Pair>& f : found_)
        f.clear();
    if (n > 0) {
        grid_.build(points, box, widest);
        const std::span<const std::uint32_t> order = grid_.order();
        slot_reach_.resize(n);
        slot_group_.resize(n);
        for (size_t s = 0; s < n; ++s) {
            slot_reach_[s] = radii[order[s]] + half_skin;
            slot_group_[s] = groups[order[s]];
        }
        // Threads split the cell rows, one share each (a smaller team takes several); each row's
        // pairs are found in one share only.
        const int rows = grid_.rows();
        const int shares = std::max(1, std::min(threads, rows));
        if (found_.size() < static_cast<size_t>(shares)) found_.resize(static_cast<size_t>(shares));
#pragma omp parallel for schedule(static, 1) num_threads(shares) if (shares > 1)
        for (int t = 0; t < shares; ++t)
            collect(rows * t / shares, rows * (t + 1) / shares, found_[static_cast<size_t>(t)]);
    }
    // Sorted by (first, second): counted by first point, placed, and each first point's few
    // partners sorted. The pairs are distinct, so this order does not depend on the threads.
    start_.assign(n + 1, 0);
    for (const std::vector<Pair>& f : found_)
        for (const Pair& p : f)
            ++start_[p.first + 1];
    for (size_t i = 0; i < n; ++i)
        start_[i + 1] += start_[i];
    first_.resize(start_[n]);
    second_.resize(start_[n]);
    for (const std::vector<Pair>& f : found_)
        for (const Pair& p : f)
            second_[start_[p.first]++] = p.second;  // start_[i] ends at the start of i + 1
    std::uint32_t begin = 0;
    for (size_t i = 0; i < n; ++i) {
        const std::uint32_t end = start_[i];
        std::fill(first_.begin() + begin, first_.begin() + end, static_cast<std::uint32_t>(i));
        std::sort(second_.begin() + begin, second_.begin() + end);
        begin = end;
    }
    reference_.assign(points.begin(), points.end());
    slack_ = 0.0;
    ++builds_;
}

}  // namespace rodsea
