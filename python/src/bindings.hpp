#pragma once
// The parts of the _rodsea extension, one file each (docs/python.md). Every C++ error reaches
// Python with its message unchanged: InvalidParameter as rodsea.InvalidParameter (a ValueError),
// FileError as rodsea.FileError (an OSError), BlowUpError as rodsea.BlowUpError.
#include <pybind11/pybind11.h>

namespace rodsea::python {

void bind_config(pybind11::module_& m);       // Config: a validated, resolved config
void bind_simulation(pybind11::module_& m);   // Simulation: build, run, state as arrays
void bind_run(pybind11::module_& m);          // StoredRun: a run directory's frames and series
void bind_observables(pybind11::module_& m);  // compute objects on arrays, freud's style
void bind_fields(pybind11::module_& m);       // fields, defects, trackers

}  // namespace rodsea::python
