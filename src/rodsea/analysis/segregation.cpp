#include "rodsea/analysis/segregation.hpp"

#include <algorithm>
#include <cmath>

#include "rodsea/error.hpp"
#include "rodsea/random.hpp"

namespace rodsea {

SegregationGrid segregation_grid(const PeriodicBox2D& box, double cell) {
    require_positive("segregation.cell", cell, "mm");
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

double segregation(const PeriodicBox2D& box, const SegregationGrid& grid,
                   std::span<const Vec3> points, std::span<const std::uint8_t> polar) {
    const auto cells = static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny);
    std::vector<double> p(cells, 0.0), a(cells, 0.0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double x = PeriodicBox2D::wrap(points[i].x, box.lx);
        const double y = PeriodicBox2D::wrap(points[i].y, box.ly);
        const int cx = std::min(grid.nx - 1, static_cast<int>(x / box.lx * grid.nx));
        const int cy = std::min(grid.ny - 1, static_cast<int>(y / box.ly * grid.ny));
        const auto c = static_cast<std::size_t>(cy * grid.nx + cx);
        a[c] += 1.0;
        if (polar[i]) p[c] += 1.0;
    }
    return segregation_index(p, a);
}

}  // namespace rodsea
