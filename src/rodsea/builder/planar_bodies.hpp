#pragma once
// The builder's working state: bodies lying flat, each a geometric centre in the plane and the
// angle of its body x axis. Heights, quaternions and velocities are added only at the end.
#include <cstdint>
#include <vector>

namespace rodsea {

struct PlanarBodies {
    std::vector<std::uint32_t> species;
    std::vector<double> x, y;   // geometric centre, mm, wrapped into [0, L)
    std::vector<double> angle;  // of the body x axis from world x, rad (thick → thin for polar)

    size_t size() const { return species.size(); }
    void add(std::uint32_t s, double x_, double y_, double a) {
        species.push_back(s);
        x.push_back(x_);
        y.push_back(y_);
        angle.push_back(a);
    }
};

}  // namespace rodsea
