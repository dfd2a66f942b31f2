#include "rodsea/shape/projected_area.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace rodsea {

namespace {

using Interval = std::pair<double, double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Adds [a, b] (angles, a < b, possibly outside [0, 2π)) as pieces inside [0, 2π).
void add_wrapped(std::vector<Interval>& out, double a, double b) {
    if (b - a >= kTwoPi) {
        out.emplace_back(0.0, kTwoPi);
        return;
    }
    const double len = b - a;
    a = std::fmod(a, kTwoPi);
    if (a < 0.0) a += kTwoPi;
    if (a + len <= kTwoPi) {
        out.emplace_back(a, a + len);
    } else {
        out.emplace_back(a, kTwoPi);
        out.emplace_back(0.0, a + len - kTwoPi);
    }
}

// ∮ (x dy − y dx)/2 along the arc of circle (cx, cy, r) from angle a to b.
double arc_contribution(double cx, double cy, double r, double a, double b) {
    return 0.5 * (r * (cx * (std::sin(b) - std::sin(a)) - cy * (std::cos(b) - std::cos(a))) +
                  r * r * (b - a));
}

}  // namespace

double projected_area(const SphereList& spheres) {
    double area = 0.0;
    std::vector<Interval> covered;
    for (size_t i = 0; i < spheres.size(); ++i) {
        const double xi = spheres[i].centre.x, yi = spheres[i].centre.y, ri = spheres[i].radius;
        covered.clear();
        bool hidden = false;
        for (size_t j = 0; j < spheres.size() && !hidden; ++j) {
            if (j == i) continue;
            const double dx = spheres[j].centre.x - xi, dy = spheres[j].centre.y - yi;
            const double rj = spheres[j].radius;
            const double d = std::hypot(dx, dy);
            if (d >= ri + rj) continue;  // disjoint
            // Disc i inside disc j (the earlier of two identical discs is the one kept).
            if (d <= rj - ri && (rj > ri || d > 0.0 || j < i)) {
                hidden = true;
                break;
            }
            if (d <= ri - rj) continue;  // disc j inside disc i: covers none of i's boundary
            const double phi = std::atan2(dy, dx);
            const double half =
                std::acos(std::clamp((d * d + ri * ri - rj * rj) / (2.0 * d * ri), -1.0, 1.0));
            add_wrapped(covered, phi - half, phi + half);
        }
        if (hidden) continue;
        std::sort(covered.begin(), covered.end());
        double cursor = 0.0;  // walk [0, 2π), integrating the gaps between covered intervals
        for (const auto& [a, b] : covered) {
            if (a > cursor) area += arc_contribution(xi, yi, ri, cursor, a);
            cursor = std::max(cursor, b);
        }
        if (cursor < kTwoPi) area += arc_contribution(xi, yi, ri, cursor, kTwoPi);
    }
    return area;
}

}  // namespace rodsea
