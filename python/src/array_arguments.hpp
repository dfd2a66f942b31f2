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
#include "rodsea/number_text.hpp"

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

// One row of `name` per row of `per`: the arrays describe the same bodies.
inline void require_rows(std::size_t rows, std::size_t expected, const char* name,
                         const char* per) {
    if (rows != expected)
        throw InvalidParameter(name, std::to_string(rows) + " rows",
                               std::to_string(expected) + " rows, one per row of " + per);
}

// One value per point, finite unless `nan_allowed` (a -1/2 defect's orientation is NaN).
inline std::vector<double> values_of(const Doubles& a, std::size_t n, const char* name,
                                     bool nan_allowed = false) {
    if (a.ndim() != 1 || static_cast<std::size_t>(a.shape(0)) != n)
        throw InvalidParameter(name, "an array of another shape",
                               "shape (" + std::to_string(n) + ",)");
    std::vector<double> v(a.data(), a.data() + n);
    for (std::size_t i = 0; i < n; ++i)
        if (!std::isfinite(v[i]) && !(nan_allowed && std::isnan(v[i])))
            throw InvalidParameter(std::string(name) + "[" + std::to_string(i) + "]",
                                   format_number(v[i]), "a finite number");
    return v;
}

// Any number of values, as values_of.
inline std::vector<double> all_values_of(const Doubles& a, const char* name) {
    if (a.ndim() != 1)
        throw InvalidParameter(name, "an array of " + std::to_string(a.ndim()) + " dimensions",
                               "shape (N,)");
    return values_of(a, static_cast<std::size_t>(a.shape(0)), name);
}

// m of an m-fold order (1 polar, 2 nematic, ...).
inline int fold_of(int m) {
    if (m < 1 || m > 12) throw InvalidParameter("m", std::to_string(m), "[1, 12]");
    return m;
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
