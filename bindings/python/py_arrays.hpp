// SPDX-License-Identifier: Apache-2.0
// Strict conversions of the Python binding's arguments, each naming the argument it refuses.
// numpy's forcecast alone truncated 1000.9 ns to 1000, wrapped -1 triangles to 4294967295 and
// NaN times to INT64_MIN; an array_t without c_style read a strided view (a table's column,
// ts[::2]) as if it were contiguous, past its end.
#pragma once

#include "bindings/python/py_common.hpp"

#include <pybind11/numpy.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace gazelod::python {

// Every element of an integer array (Python ints, or a numpy integer dtype), contiguous, in
// C order, as int64; `what` names the argument. Refuses a float, bool or object dtype, and an
// unsigned value past int64.
inline std::vector<std::int64_t> int64s(const py::object& o, const std::string& what, py::array* shape = nullptr) {
  py::array a = py::array::ensure(o);
  if (!a) throw py::value_error(what + " must be an integer or an array of integers");
  const char kind = a.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::value_error(what + " must hold integers, got dtype " + std::string(py::str(a.dtype())));
  std::vector<std::int64_t> out(static_cast<std::size_t>(a.size()));
  if (kind == 'u') {
    const auto u = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (u.data()[i] > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()))
        throw py::value_error(what + ": " + std::to_string(u.data()[i]) + " is past int64");
      out[i] = static_cast<std::int64_t>(u.data()[i]);
    }
  } else {
    const auto s = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = s.data()[i];
  }
  if (shape != nullptr) *shape = a;
  return out;
}

// Numbers as a C-ordered float64 array (lists, tuples, any numeric dtype); anything else is
// refused naming `what`, not with pybind11's "Unable to cast Python instance".
using Doubles = py::array_t<double, py::array::c_style | py::array::forcecast>;
inline Doubles doubles(const py::handle& o, const std::string& what) {
  try {
    return py::cast<Doubles>(o);
  } catch (const py::cast_error&) {
    throw py::value_error(what + " must be numbers, got " + std::string(py::repr(o)));
  } catch (const py::error_already_set& e) {  // numpy's own "could not convert string to float"
    if (!e.matches(PyExc_ValueError) && !e.matches(PyExc_TypeError)) throw;
    throw py::value_error(what + " must be numbers, got " + std::string(py::repr(o)));
  }
}

// An (N, L) table of triangle counts like a levels table: integers in 0 to 2^32 - 1, row-major,
// each refusal naming the element.
inline std::vector<std::uint32_t> triangle_table(const py::object& o, py::ssize_t n, py::ssize_t width) {
  py::array shape;
  const std::vector<std::int64_t> v = int64s(o, "triangles", &shape);
  if (shape.ndim() != 2 || shape.shape(0) != n || shape.shape(1) != width)
    throw py::value_error("triangles must be an (N, L) array like levels");
  std::vector<std::uint32_t> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (v[k] < 0 || v[k] > std::numeric_limits<std::uint32_t>::max())
      throw py::value_error("triangles[" + std::to_string(k / width) + ", " + std::to_string(k % width) +
                            "] = " + std::to_string(v[k]) + " is not a triangle count (0 to 4294967295)");
    out[k] = static_cast<std::uint32_t>(v[k]);
  }
  return out;
}

// Row i of an (N, L) levels table: how many levels its chain has. NaN pads a shorter chain at
// the row's end; a level after a NaN is refused (it was dropped unseen).
inline py::ssize_t chain_length(const Doubles& levels, py::ssize_t i) {
  const py::ssize_t width = levels.shape(1);
  const double* row = levels.data() + i * width;
  py::ssize_t length = width;
  for (py::ssize_t j = 1; j < width; ++j) {
    if (length == width && std::isnan(row[j])) length = j;
    if (length < j && !std::isnan(row[j]))
      throw py::value_error("levels[" + std::to_string(i) + ", " + std::to_string(j) +
                            "] follows a NaN (NaN only pads a shorter chain at its end)");
  }
  return length;
}

// A positive pixel count (a Python or numpy integer, not a bool or a float) that fits 32 bits.
inline std::uint32_t pixel_count(const py::handle& v, const std::string& what) {
  long long x = 0;
  int overflow = 0;
  if (PyIndex_Check(v.ptr()) && !PyBool_Check(v.ptr())) {
    const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(v.ptr()));
    if (!i) throw py::error_already_set();
    x = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  }
  if (overflow != 0 || x < 1 || x > static_cast<long long>(std::numeric_limits<std::uint32_t>::max()))
    throw py::value_error(what + " must be a positive integer (pixels), got " + std::string(py::repr(v)));
  return static_cast<std::uint32_t>(x);
}

}  // namespace gazelod::python
