#pragma once
// numpy arrays in and out of the bindings, checked as the command line checks its input: a
// box is (L_x, L_y) in mm, points (N, 2) or (N, 3) in mm, one value per point; a bad shape or
// a value that is not finite is an InvalidParameter naming the argument.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cmath>
#include <string>
#include <vector>

#include "rodsea/error.hpp"
#include "rodsea/math/periodic_box.hpp"
#include "rodsea/math/vec3.hpp"

namespace rodsea::python {

namespace py = pybind11;

using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;

inline PeriodicBox2D box_of(const py::sequence& box) {
    if (py::len(box) != 2)
        throw InvalidParameter("box", "a sequence of another length", "(L_x, L_y) in mm");
    const PeriodicBox2D b{box[0].cast<double>(), box[1].cast<double>()};
    require_positive("box L_x", b.lx, "mm");
    require_positive("box L_y", b.ly, "mm");
    return b;
}

inline std::vector<Vec3> points_of(const Doubles& a, const char* name) {
    if (a.ndim() != 2 || (a.shape(1) != 2 && a.shape(1) != 3))
        throw InvalidParameter(name, "an array of " + std::to_string(a.ndim()) + " dimensions",
                               "shape (N, 2) or (N, 3), mm");
    const auto r = a.unchecked<2>();
    std::vector<Vec3> v(static_cast<std::size_t>(a.shape(0)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i) {
        v[static_cast<std::size_t>(i)] = {r(i, 0), r(i, 1), a.shape(1) == 3 ? r(i, 2) : 0.0};
        const Vec3& p = v[static_cast<std::size_t>(i)];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw InvalidParameter(std::string(name) + "[" + std::to_string(i) + "]",
                                   "a value that is not finite", "finite coordinates, mm");
    }
    return v;
}

inline std::vector<double> values_of(const Doubles& a, std::size_t n, const char* name) {
    if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
        throw InvalidParameter(name, "an array of another shape",
                               "shape (" + std::to_string(n) + ",)");
    return std::vector<double>(a.data(), a.data() + n);
}

inline py::array_t<double> array(const std::vector<double>& v) {
    return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

inline py::array_t<double> map_array(const std::vector<double>& v, std::size_t rows,
                                     std::size_t cols) {
    py::array_t<double> a({rows, cols});
    std::copy(v.begin(), v.end(), a.mutable_data());
    return a;
}

}  // namespace rodsea::python
