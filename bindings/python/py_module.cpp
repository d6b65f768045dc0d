// SPDX-License-Identifier: Apache-2.0
// gazelod._gazelod: the compiled half of the Python package (bindings/python/gazelod/).
#include "bindings/python/py_common.hpp"

PYBIND11_MODULE(_gazelod, m) {
  m.doc() = "gazelod's C++ core for Python (use the gazelod package, not this module)";
  m.attr("__version__") = GAZELOD_VERSION;
  gazelod::python::register_trace(m);
  gazelod::python::register_select(m);
  gazelod::python::register_plugin(m);
  gazelod::python::register_cli(m);
}
