// SPDX-License-Identifier: Apache-2.0
// Shared by the Python binding's files (bindings/python/): pybind11 and the registration
// functions each file defines.
#pragma once

#include <pybind11/pybind11.h>

namespace gazelod::python {

namespace py = pybind11;

void register_trace(py::module_& m);   // py_trace.cpp
void register_select(py::module_& m);  // py_select.cpp
void register_plugin(py::module_& m);  // py_plugin.cpp
void register_cli(py::module_& m);     // py_cli.cpp

}  // namespace gazelod::python
