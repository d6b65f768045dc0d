// SPDX-License-Identifier: Apache-2.0
// gazelod._gazelod._cli: the gazelod program's commands called in-process (the same parser and
// code as the command line), their output captured. The error stream's lines go to a Python
// callback as they are written (progress), and Ctrl-C raised while a command runs stops it
// at the next line: the command unwinds (its files are atomic: no partial output), then
// KeyboardInterrupt is raised in Python.
#include "bindings/python/py_common.hpp"

#include "apps/gazelod/commands/command.hpp"

#include <pybind11/stl.h>

#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

namespace gazelod::python {
namespace {

struct Interrupted : std::exception {
  const char* what() const noexcept override { return "interrupted (Ctrl-C)"; }
};
struct CallbackFailed : std::exception {
  const char* what() const noexcept override { return "the progress callback raised an exception"; }
};

// Collects the text, hands each finished line to `on_line` (with the GIL), checks for signals.
class LineBuf final : public std::streambuf {
 public:
  explicit LineBuf(py::object on_line) : on_line_(std::move(on_line)) {}
  std::string text;
  bool interrupted = false;
  // The progress callback's own exception, re-raised in Python once the command has unwound.
  PyObject* error_type = nullptr;
  PyObject* error_value = nullptr;
  PyObject* error_traceback = nullptr;

 protected:
  int overflow(int c) override {
    if (c == traits_type::eof()) return 0;
    text.push_back(static_cast<char>(c));
    if (c == '\n') line_done();
    return c;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) overflow(static_cast<unsigned char>(s[i]));
    return n;
  }

 private:
  void line_done() {
    const std::size_t start = text.rfind('\n', text.size() - 2);
    const std::string line = text.substr(start == std::string::npos ? 0 : start + 1);
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) {
      interrupted = true;
      throw Interrupted();
    }
    if (on_line_.is_none()) return;
    try {
      on_line_(text_of(line.substr(0, line.size() - 1)));
    } catch (py::error_already_set& e) {
      e.restore();
      PyErr_Fetch(&error_type, &error_value, &error_traceback);
      throw CallbackFailed();
    }
  }
  py::object on_line_;
};

py::tuple cli(const std::vector<std::string>& args, py::object on_line) {
  LineBuf errbuf(std::move(on_line));
  std::ostringstream out;
  std::ostream err(&errbuf);
  err.exceptions(std::ios::badbit);  // Interrupted leaves the stream, not swallowed by it
  int rc = 0;
  {
    py::gil_scoped_release release;
    try {
      rc = cli::run(args, out, err);
    } catch (const Interrupted&) {
      rc = 130;
    } catch (const std::exception&) {
      rc = errbuf.interrupted ? 130 : 1;
    }
  }
  if (errbuf.error_type != nullptr) {  // the callback's exception, as it was raised
    PyErr_Restore(errbuf.error_type, errbuf.error_value, errbuf.error_traceback);
    throw py::error_already_set();
  }
  // 130: the run stopped for Ctrl-C (its report written, marked interrupted).
  if (errbuf.interrupted || rc == 130) {
    if (!PyErr_Occurred()) PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw py::error_already_set();
  }
  return py::make_tuple(rc, text_of(out.str()), text_of(errbuf.text));
}

}  // namespace

void register_cli(py::module_& m) {
  m.def("_cli", &cli, py::arg("args"), py::arg("on_line") = py::none());
}

}  // namespace gazelod::python
