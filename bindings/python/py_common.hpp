// SPDX-License-Identifier: Apache-2.0
// Shared by the Python binding's files (bindings/python/): pybind11 and the registration
// functions each file defines.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace gazelod::python {

namespace py = pybind11;

// Text from C++ as a Python str: a file name that is not UTF-8 (os.listdir's surrogate-escaped
// names) reaches messages and reports byte for byte, and a strict decode raised
// UnicodeDecodeError in place of the message. Invalid bytes become U+FFFD.
inline py::str text_of(const std::string& s) {
  PyObject* u = PyUnicode_DecodeUTF8(s.data(), static_cast<Py_ssize_t>(s.size()), "replace");
  if (u == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::str>(u);
}
inline std::string utf8_of(const std::string& s) {
  return text_of(s).cast<std::string>();
}

void register_trace(py::module_& m);   // py_trace.cpp
void register_select(py::module_& m);  // py_select.cpp
void register_plugin(py::module_& m);  // py_plugin.cpp
void register_cli(py::module_& m);     // py_cli.cpp

}  // namespace gazelod::python
