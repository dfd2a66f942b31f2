#pragma once
// Candidate sphere pairs for the engine's contact search, kept over many steps (a Verlet list):
// every pair of discs (spheres seen from above) of different groups whose centres were closer in
// the plane than r_i + r_j + skin when the list was built. It holds every overlapping pair until
// some point has moved skin / 2 in the plane, and is rebuilt only then; bodies move micrometres per
// step, so a list lasts hundreds of steps.
//
// Pairs are kept sorted by (i, j) with i < j, so the order in which contacts are found does not
// depend on when the list was last rebuilt: a run resumed from a checkpoint finds the same
// contacts in the same order as the run that never stopped.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"
#include "rodsea/neighbors/periodic_grid.hpp"
#include "rodsea/neighbors/verlet_skin.hpp"

namespace rodsea {

class VerletPairList {
  public:
    // skin in mm, > 0.
    explicit VerletPairList(double skin = kVerletSkin);

    // Rebuilds when the list is new, the number of points or the box changed, or a point moved
    // more than skin / 2 in the plane (minimum image) since the last build. Radii and groups
    // are taken to be those of the last build unless the number of points changed. Points need
    // not be wrapped, but must lie within half a box of their wrapped image's neighbours (true
    // for the spheres of bodies shorter than half the box). Returns whether it rebuilt.
    //
    // `travel` (mm) bounds how far any point moved in the plane since the last update: the
    // points are only looked at once these bounds add up to skin / 2 (bodies move micrometres
    // per step, so most steps skip the check). Infinity, the default, checks every time.
    // `threads` share the check and the rebuild; the list is the same on any number of them.
    bool update(std::span<const Vec3> points, std::span<const double> radii,
                std::span<const std::uint32_t> groups, const PeriodicBox2D& box,
                double travel = std::numeric_limits<double>::infinity(), int threads = 1);

    // Builds the list now, whatever the points moved (update() calls it when it must).
    void build(std::span<const Vec3> points, std::span<const double> radii,
               std::span<const std::uint32_t> groups, const PeriodicBox2D& box, int threads = 1);

    // visit(i, j, d) for each listed pair, i < j, with d = p_i − p_j (minimum image in x, y),
    // in the list's (i, j) order. `points` are the same points as in the last update().
    template <class Visit>
    void for_each_pair(std::span<const Vec3> points, Visit&& visit) const {
        for_each_pair(points, 0, size(), std::forward<Visit>(visit));
    }

    // Pairs [begin, end) only, for splitting the list between threads.
    template <class Visit>
    void for_each_pair(std::span<const Vec3> points, size_t begin, size_t end,
                       Visit&& visit) const {
        for (size_t k = begin; k < end; ++k) {
            const std::uint32_t i = first_[k], j = second_[k];
            visit(i, j, minimum_image(points[i] - points[j]));
        }
    }

    // visit(i, j, d) as for_each_pair, for the pairs [begin, end) whose spheres (radii r) may
    // touch: all but those with |d| ≥ r_i + r_j (3D) or d = 0, which a contact test rejects; a
    // NaN distance is visited, for the caller to see. Most listed pairs do not touch, and a loop
    // that decides pair by pair mispredicts which and waits for each far sphere in turn, so a
    // block of pairs is sifted first without branches and then only the kept ones are visited,
    // in list order.
    template <class Visit>
    void for_each_touching_pair(std::span<const Vec3> points, std::span<const double> radii,
                                size_t begin, size_t end, Visit&& visit) const {
        constexpr size_t kBlock = 256;
        std::uint16_t kept[kBlock];
        for (size_t block = begin; block < end; block += kBlock) {
            const size_t stop = std::min(end, block + kBlock);
            size_t n = 0;
            for (size_t k = block; k < stop; ++k) {
                const std::uint32_t i = first_[k], j = second_[k];
                const double reach = radii[i] + radii[j];
                const double d2 = norm2(minimum_image(points[i] - points[j]));
                kept[n] = static_cast<std::uint16_t>(k - block);
                n += !((d2 >= reach * reach) | (d2 == 0.0));
            }
            for (size_t h = 0; h < n; ++h) {
                const size_t k = block + kept[h];
                const std::uint32_t i = first_[k], j = second_[k];
                visit(i, j, minimum_image(points[i] - points[j]));
            }
        }
    }

    size_t size() const { return first_.size(); }
    double skin() const { return skin_; }

    // The pairs [begin, end) whose first point is i, i < the points of the last build.
    struct Range {
        size_t begin, end;
    };
    Range row(std::uint32_t i) const { return {i == 0 ? 0 : start_[i - 1], start_[i]}; }

    // A bound on how far any point has moved in the plane since the last build (mm): pairs not
    // listed are at least skin − 2 slack() apart in the plane, beyond their radii.
    double slack() const { return slack_; }
    // Whether update() with this `travel` will look at the points (and so needs them all current).
    bool looks_after(double travel) const { return builds_ == 0 || slack_ + travel > 0.5 * skin_; }
    std::uint64_t builds() const { return builds_; }

  private:
    // One conditional shift per axis: differences of points within half a box of their images
    // are within 1.5 boxes, cheaper than a rounding per pair.
    Vec3 minimum_image(Vec3 d) const {
        if (d.x > half_x_)
            d.x -= box_.lx;
        else if (d.x < -half_x_)
            d.x += box_.lx;
        if (d.y > half_y_)
            d.y -= box_.ly;
        else if (d.y < -half_y_)
            d.y += box_.ly;
        return d;
    }
    double largest_move(std::span<const Vec3> points, int threads) const;  // since the build, mm
    // The pairs of the grid's cell rows [row_begin, row_end) into `out`, unsorted.
    struct Pair {
        std::uint32_t first, second;
    };
    void collect(int row_begin, int row_end, std::vector<Pair>& out) const;

    double skin_;
    PeriodicBox2D box_;
    double half_x_ = 0.0, half_y_ = 0.0;
    std::uint64_t builds_ = 0;
    double slack_ = 0.0;  // bound on the largest move since the last build (mm)
    std::vector<std::uint32_t> first_, second_;  // the pairs, sorted by (first, second)
    std::vector<Vec3> reference_;                // the points at the last build
    // Scratch for rebuilds: the grid, each slot's radius + skin / 2 and group (contiguous for the
    // cell loop), each thread's pairs; and, kept after the build, where each first point's pairs
    // end (start_[i], the start of i + 1's; start_[n] the total).
    PeriodicGrid2D grid_;
    std::vector<double> slot_reach_;
    std::vector<std::uint32_t> slot_group_;
    std::vector<std::vector<Pair>> found_;
    std::vector<std::uint32_t> start_;
};

}  // namespace rodsea
