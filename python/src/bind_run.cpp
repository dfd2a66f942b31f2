#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "rodsea/engine/order_parameters.hpp"
#include "rodsea/io/stored_run.hpp"

namespace py = pybind11;

namespace rodsea::python {

namespace {

py::array_t<double> rows(const std::vector<Vec3>& v) {
    py::array_t<double> a({v.size(), std::size_t{3}});
    auto w = a.mutable_unchecked<2>();
    for (std::size_t i = 0; i < v.size(); ++i) {
        w(i, 0) = v[i].x;
        w(i, 1) = v[i].y;
        w(i, 2) = v[i].z;
    }
    return a;
}

}  // namespace

void bind_run(py::module_& m) {
    py::class_<StoredRun>(m, "_StoredRun")
        .def(py::init([](const std::string& path) { return open_stored_run(path); }),
             py::arg("path"))
        .def_property_readonly("run_dir", [](const StoredRun& r) { return r.run_dir.string(); })
        .def_property_readonly("frames", &StoredRun::frames)
        .def_property_readonly(
            "times", [](const StoredRun& r) { return py::array_t<double>(py::cast(r.times())); })
        .def_property_readonly("steps",
                               [](const StoredRun& r) {
                                   return py::array_t<std::int64_t>(py::cast(r.reader.steps()));
                               })
        .def_property_readonly("config", [](const StoredRun& r) { return r.plan.config_toml; })
        .def_property_readonly("species_names",
                               [](const StoredRun& r) {
                                   std::vector<std::string> names;
                                   for (const Species& s : r.plan.engine.species)
                                       names.push_back(s.name);
                                   return names;
                               })
        .def_property_readonly("box",
                               [](const StoredRun& r) {
                                   return py::make_tuple(r.plan.engine.box.lx,
                                                         r.plan.engine.box.ly);
                               })
        .def_property_readonly("series_names",
                               [](const StoredRun& r) { return r.reader.series_names(); })
        .def("series",
             [](const StoredRun& r, const std::string& column) {
                 return py::array_t<double>(py::cast(r.reader.series(column)));
             })
        .def("frame", [](const StoredRun& r, std::size_t k) {
            if (k >= r.frames())
                throw py::index_error("frame " + std::to_string(k) + " of " +
                                      std::to_string(r.frames()));
            const BodyState b = r.frame(k);
            py::dict d;
            d["positions"] = rows(b.position);
            py::array_t<double> q({b.size(), std::size_t{4}});
            auto w = q.mutable_unchecked<2>();
            py::array_t<double> angle(b.size());
            auto a = angle.mutable_unchecked<1>();
            for (std::size_t i = 0; i < b.size(); ++i) {
                const Quat& o = b.orientation[i];
                w(i, 0) = o.w;
                w(i, 1) = o.x;
                w(i, 2) = o.y;
                w(i, 3) = o.z;
                a(i) = in_plane_angle(o);
            }
            d["quaternions"] = q;
            d["angles"] = angle;
            d["velocities"] = rows(b.velocity);
            d["spins"] = rows(b.spin);
            d["species"] = py::array_t<std::uint32_t>(py::cast(b.species));
            return d;
        });
}

}  // namespace rodsea::python
