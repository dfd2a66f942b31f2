#include <pybind11/stl.h>

#include "bindings.hpp"
#include "config.hpp"
#include "rodsea/calibration/calibration_table.hpp"
#include "rodsea/config/config_file.hpp"

namespace py = pybind11;

namespace rodsea::python {

void bind_config(py::module_& m) {
    py::class_<Config>(m, "Config",
                       "A validated, resolved config: every key with its value, defaults "
                       "included (the config.toml a run writes). Lengths in mm, times in s.")
        .def_property_readonly(
            "toml", [](const Config& c) { return c.plan.config_toml; },
            "the resolved config as TOML text")
        .def_property_readonly("source", [](const Config& c) { return c.source; })
        .def_property_readonly(
            "species",
            [](const Config& c) {
                py::list out;
                for (std::size_t s = 0; s < c.plan.engine.species.size(); ++s) {
                    const Species& sp = c.plan.engine.species[s];
                    py::dict d;
                    d["name"] = sp.name;
                    d["kind"] = std::string(to_string(sp.kind));
                    d["count"] = c.plan.counts[s];
                    d["spheres"] = sp.shape.sphere_count();
                    d["length_mm"] = sp.shape.extent;
                    d["mass"] = sp.shape.mass;
                    d["density"] = sp.shape.mass / sp.shape.volume / polar_rod_density();
                    out.append(d);
                }
                return out;
            },
            "one dict per species: name, kind, count, spheres, length_mm, mass (the polar rod's "
            "= 1) and density (relative to the paper's polar rod's)")
        .def_property_readonly(
            "box",
            [](const Config& c) {
                return py::make_tuple(c.plan.engine.box.lx, c.plan.engine.box.ly);
            },
            "(L_x, L_y), mm")
        .def_property_readonly(
            "gap", [](const Config& c) { return c.plan.engine.drive.gap; }, "w, mm")
        .def_property_readonly(
            "dt", [](const Config& c) { return c.plan.engine.dt; }, "s")
        .def_property_readonly(
            "duration", [](const Config& c) { return c.plan.control.duration; }, "s")
        .def_property_readonly(
            "output_interval", [](const Config& c) { return c.plan.control.output_interval; }, "s")
        .def_property_readonly("total_steps", [](const Config& c) { return c.plan.total_steps(); })
        .def_property_readonly("seed", [](const Config& c) { return c.plan.engine.seed; })
        .def_property_readonly(
            "noise_epsilon", [](const Config& c) { return c.plan.engine.noise_epsilon; }, "1/mm")
        .def_property_readonly(
            "noise_mode",
            [](const Config& c) { return std::string(to_string(c.plan.engine.noise_mode)); },
            "\"add\" or \"set\": how a plate collision's kick meets ω_z (docs/model.md §3.2)")
        .def_property_readonly("threads", [](const Config& c) { return c.plan.control.threads; })
        .def("__repr__", [](const Config& c) {
            // Appended piece by piece: GCC 12 warns (-Wrestrict) about a chain of + on a literal.
            std::string s("<rodsea.Config ");
            s.append(c.source).append(":");
            for (std::size_t k = 0; k < c.plan.counts.size(); ++k)
                s.append(" ")
                    .append(std::to_string(c.plan.counts[k]))
                    .append(" ")
                    .append(c.plan.engine.species[k].name);
            return s.append(">");
        });
    m.def(
        "_load_config_file",
        [](const std::string& path) {
            return Config{load_config_file(path, calibration_table_lookup()), path};
        },
        py::arg("path"));
    m.def(
        "_load_config_text",
        [](const std::string& text, const std::string& name) {
            return Config{load_config_string(text, name, calibration_table_lookup()), name};
        },
        py::arg("text"), py::arg("name"));
}

}  // namespace rodsea::python
