// The beyond-paper compute objects on numpy arrays: coarse-grained fields, nematic defects, the
// length of a level line, and the trackers that follow defects and flocks in time. The same
// code as `rodsea analyze` runs (docs/analysis.md, "Beyond the paper"). Maps are [y, x].
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <vector>

#include "array_arguments.hpp"
#include "bindings.hpp"
#include "rodsea/analysis/coarse_grained_fields.hpp"
#include "rodsea/analysis/contour_length.hpp"
#include "rodsea/analysis/defect_tracks.hpp"
#include "rodsea/analysis/flock_tracks.hpp"
#include "rodsea/analysis/histogram_bins.hpp"
#include "rodsea/analysis/nematic_defects.hpp"
#include "rodsea/error.hpp"

namespace py = pybind11;

namespace rodsea::python {

namespace {

FieldGrid grid_of(const PeriodicBox2D& box, double cell) {
    if (!(cell > 0.0) || !std::isfinite(cell) || cell > std::min(box.lx, box.ly))
        throw InvalidParameter("cell", format_number(cell) + " mm",
                               "(0, " + format_number(std::min(box.lx, box.ly)) + "] mm");
    require_bins("cell", format_number(cell) + " mm",
                 std::floor(box.lx / cell) * std::floor(box.ly / cell),
                 "the box sides / cell, squared");
    return FieldGrid::of(box, cell);
}

// A [ny, nx] map as the grid's vector, checked against the grid.
std::vector<double> map_of(const Doubles& a, const FieldGrid& g, const char* name) {
    if (a.ndim() != 2 || a.shape(0) != g.ny || a.shape(1) != g.nx)
        throw InvalidParameter(name, "an array of another shape",
                               "shape (" + std::to_string(g.ny) + ", " + std::to_string(g.nx) +
                                   "), [y, x] on the grid of this box and cell");
    return std::vector<double>(a.data(), a.data() + a.size());
}

py::dict defect_arrays(std::span<const NematicDefect> defects) {
    std::vector<double> x, y, charge, orientation;
    for (const NematicDefect& d : defects) {
        x.push_back(d.x);
        y.push_back(d.y);
        charge.push_back(d.charge);
        orientation.push_back(d.orientation);
    }
    py::dict out;
    out["x"] = array(x);
    out["y"] = array(y);
    out["charge"] = array(charge);
    out["orientation"] = array(orientation);
    return out;
}

std::vector<NematicDefect> defects_of(const Doubles& x, const Doubles& y, const Doubles& charge,
                                      const Doubles& orientation) {
    const auto n = static_cast<std::size_t>(x.size());
    const std::vector<double> xs = values_of(x, n, "x"), ys = values_of(y, n, "y"),
                              qs = values_of(charge, n, "charge"),
                              os = values_of(orientation, n, "orientation", true);
    std::vector<NematicDefect> d(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(xs[i]) || !std::isfinite(ys[i]))
            throw InvalidParameter("x, y [" + std::to_string(i) + "]", "not finite",
                                   "finite positions, mm");
        if (qs[i] != 0.5 && qs[i] != -0.5 && qs[i] != 1.0 && qs[i] != -1.0)
            throw InvalidParameter("charge[" + std::to_string(i) + "]", format_number(qs[i]),
                                   "±0.5 or ±1");
        d[i] = {xs[i], ys[i], qs[i], os[i]};
    }
    return d;
}

}  // namespace

void bind_fields(py::module_& m) {
    m.def(
        "coarse_grain",
        [](const py::sequence& box, double cell, const Doubles& positions, const Doubles& angles,
           const py::object& velocities, double body_area) {
            const PeriodicBox2D b = box_of(box);
            const FieldGrid g = grid_of(b, cell);
            const std::vector<Vec3> p = points_of(positions, "positions");
            const std::vector<double> a = values_of(angles, p.size(), "angles");
            std::vector<Vec3> v;
            if (!velocities.is_none()) {
                v = points_of(velocities.cast<Doubles>(), "velocities");
                require_rows(v.size(), p.size(), "velocities", "positions");
            }
            if (!std::isfinite(body_area) || body_area < 0.0)
                throw InvalidParameter("body_area", format_number(body_area) + " mm²",
                                       "a finite area >= 0 mm²");
            const GroupFields f = coarse_grain(g, b, p, a, v, body_area);
            const auto ny = static_cast<std::size_t>(g.ny), nx = static_cast<std::size_t>(g.nx);
            py::dict out;
            std::vector<double> x, y;
            for (int i = 0; i < g.nx; ++i)
                x.push_back((i + 0.5) * g.dx);
            for (int j = 0; j < g.ny; ++j)
                y.push_back((j + 0.5) * g.dy);
            out["x"] = array(x);
            out["y"] = array(y);
            for (const auto& [name, values] : {std::pair{"weight", &f.weight},
                                               {"area_fraction", &f.area_fraction},
                                               {"px", &f.px},
                                               {"py", &f.py},
                                               {"qxx", &f.qxx},
                                               {"qxy", &f.qxy},
                                               {"vx", &f.vx},
                                               {"vy", &f.vy}})
                out[name] = map_array(*values, ny, nx);
            return out;
        },
        py::arg("box"), py::arg("cell"), py::arg("positions"), py::arg("angles"),
        py::arg("velocities") = py::none(), py::arg("body_area") = 0.0,
        "Cloud-in-cell fields of one group on cells of side ~cell (mm, tiling the box): a dict "
        "of [y, x] maps weight, area_fraction (with body_area in mm²), px, py, qxx, qxy, vx, vy "
        "(NaN where no body reaches) and the cell centres x, y (mm)");

    m.def(
        "nematic_defects",
        [](const py::sequence& box, double cell, const Doubles& qxx, const Doubles& qxy) {
            const PeriodicBox2D b = box_of(box);
            const FieldGrid g = grid_of(b, cell);
            const std::vector<double> xx = map_of(qxx, g, "qxx"), xy = map_of(qxy, g, "qxy");
            return defect_arrays(find_nematic_defects(g, xx, xy));
        },
        py::arg("box"), py::arg("cell"), py::arg("qxx"), py::arg("qxy"),
        "The defects of a Q field on the grid coarse_grain(box, cell) makes: a dict of arrays "
        "x, y (mm), charge (±0.5, ±1) and orientation (rad, +1/2 only; NaN otherwise)");

    m.def(
        "level_set",
        [](const py::sequence& box, double cell, const Doubles& values, double level) {
            const PeriodicBox2D b = box_of(box);
            const FieldGrid g = grid_of(b, cell);
            const LevelSet s = level_set(g, map_of(values, g, "values"), level);
            return py::make_tuple(s.length, s.above_fraction);
        },
        py::arg("box"), py::arg("cell"), py::arg("values"), py::arg("level"),
        "(length in mm of the line values = level, fraction of cells above it) of a [y, x] map "
        "on the grid coarse_grain(box, cell) makes, periodic (marching squares)");

    py::class_<DefectTracker>(m, "DefectTracker",
                              "nematic defects followed frame to frame, with ± pair events")
        .def(py::init([](const py::sequence& box, double link, double pair) {
                 require_positive("link", link, "mm");
                 require_positive("pair", pair, "mm");
                 return DefectTracker(box_of(box), link, pair);
             }),
             py::arg("box"), py::arg("link"), py::arg("pair"))
        .def(
            "add_frame",
            [](DefectTracker& self, double time, const Doubles& x, const Doubles& y,
               const Doubles& charge, const Doubles& orientation) -> DefectTracker& {
                self.add_frame(time, defects_of(x, y, charge, orientation));
                return self;
            },
            py::arg("time"), py::arg("x"), py::arg("y"), py::arg("charge"), py::arg("orientation"),
            py::return_value_policy::reference_internal,
            "one frame's defects (as nematic_defects gives them), later than the last")
        .def_property_readonly(
            "tracks",
            [](const DefectTracker& self) {
                py::list out;
                for (const DefectTrack& t : self.tracks()) {
                    py::dict d = defect_arrays(t.states);
                    d["id"] = t.id;
                    d["charge"] = t.charge;
                    d["time"] = array(t.times);
                    out.append(d);
                }
                return out;
            },
            "a dict per track: id, charge, and arrays time, x, y, orientation")
        .def_property_readonly(
            "events",
            [](const DefectTracker& self) {
                py::list out;
                for (const DefectEvent& e : self.events())
                    out.append(py::make_tuple(to_string(e.kind), e.time, e.tracks));
                return out;
            },
            "(kind: birth, death, creation or annihilation; time; [track ids])");

    py::class_<FlockTracker>(m, "FlockTracker",
                             "DBSCAN flocks followed frame to frame by the rods they share")
        .def(py::init([](const py::sequence& box) { return FlockTracker(box_of(box)); }),
             py::arg("box"))
        .def(
            "add_frame",
            [](FlockTracker& self, double time,
               const py::array_t<int, py::array::c_style | py::array::forcecast>& labels,
               const Doubles& positions, const Doubles& angles) -> FlockTracker& {
                const std::vector<Vec3> p = points_of(positions, "positions");
                const std::vector<double> a = values_of(angles, p.size(), "angles");
                if (static_cast<std::size_t>(labels.size()) != p.size())
                    throw InvalidParameter("labels", "another length",
                                           std::to_string(p.size()) + ", one per rod");
                self.add_frame(time, std::span<const int>(labels.data(), p.size()), p, a);
                return self;
            },
            py::arg("time"), py::arg("labels"), py::arg("positions"), py::arg("angles"),
            py::return_value_policy::reference_internal,
            "one frame: each rod's DBSCAN label (dbscan), position (mm) and angle (rad); the "
            "same rods every frame, later than the last")
        .def_property_readonly(
            "tracks",
            [](const FlockTracker& self) {
                py::list out;
                for (const FlockTrack& t : self.tracks()) {
                    FlockStateColumns c;
                    c.append(t);
                    std::vector<double> leader(c.leader.begin(), c.leader.end());
                    py::dict d;
                    d["id"] = t.id;
                    d["born"] = t.born;
                    d["ended"] =
                        t.ended >= 0.0 ? t.ended : std::numeric_limits<double>::quiet_NaN();
                    d["lifetime"] = t.lifetime();
                    for (const auto& [name, v] : {std::pair{"time", &c.time},
                                                  {"size", &c.size},
                                                  {"x", &c.x},
                                                  {"y", &c.y},
                                                  {"vx", &c.vx},
                                                  {"vy", &c.vy},
                                                  {"polar_order", &c.polar_order},
                                                  {"heading", &c.heading},
                                                  {"leader", &leader}})
                        d[name] = array(*v);
                    d["leaders"] = t.leaders;
                    out.append(d);
                }
                return out;
            },
            "a dict per track: id, born, ended (NaN while alive), lifetime (s), arrays time, "
            "size, x, y, vx, vy (mm/s), polar_order, heading, leader (rod index), and leaders: "
            "[(rod, frames led)] in order")
        .def_property_readonly(
            "events",
            [](const FlockTracker& self) {
                py::list out;
                for (const FlockEvent& e : self.events())
                    out.append(py::make_tuple(to_string(e.kind), e.time, e.from, e.to));
                return out;
            },
            "(kind: birth, death, merge or split; time; [tracks before]; [tracks after])");
}

}  // namespace rodsea::python
