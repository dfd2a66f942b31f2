#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "rodsea/engine/state_check.hpp"
#include "rodsea/error.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_rodsea, m) {
    m.doc() = "rodsea's C++ core: configs, the engine, stored runs and observables";
    py::register_exception<rodsea::InvalidParameter>(m, "InvalidParameter", PyExc_ValueError);
    py::register_exception<rodsea::FileError>(m, "FileError", PyExc_OSError);
    py::register_exception<rodsea::BlowUpError>(m, "BlowUpError", PyExc_RuntimeError);
    m.attr("__version__") = RODSEA_VERSION;
    rodsea::python::bind_config(m);
    rodsea::python::bind_simulation(m);
    rodsea::python::bind_run(m);
    rodsea::python::bind_observables(m);
    rodsea::python::bind_fields(m);
}
