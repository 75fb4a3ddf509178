// pound._core: the C++ side of the Python module. Thin: each function takes plain Python values,
// calls the app/ layer as a `pound` command would, and returns JSON text, NumPy arrays or a
// RunResult; the Python package (python/pound/) gives them their API. Errors are translated into
// the package's exceptions (pound.errors), which carry the file, JSON path and message.
#include <pybind11/pybind11.h>

#include <csignal>
#include <exception>

#include "bindings/bindings.hpp"
#include "core/errors.hpp"
#include "core/interrupt.hpp"
#include "io/output.hpp"

namespace py = pybind11;

namespace {

// Raises pound.errors.<name>(*arguments).
void raise_package_error(const char* name, const py::tuple& arguments) {
  const py::object type = py::module_::import("pound.errors").attr(name);
  const py::object error = type(*arguments);
  PyErr_SetObject(type.ptr(), error.ptr());
}

void translate_errors(std::exception_ptr failure) {
  try {
    if (failure) std::rethrow_exception(failure);
  } catch (const pound::InputError& error) {
    raise_package_error("InputError", py::make_tuple(error.file(), error.where(), error.reason()));
  } catch (const pound::SolveError& error) {
    raise_package_error("AnalysisError", py::make_tuple(error.time(), error.reason()));
  } catch (const pound::io::OutputError& error) {
    raise_package_error("OutputError", py::make_tuple(std::string(error.what())));
  } catch (const pound::Interrupted& stopped) {
    // The signal as Python would have taken it without pound's handlers (restored by now):
    // Python's handler for SIGINT raises KeyboardInterrupt, SIGTERM's default ends the process,
    // and a handler of the script's own runs instead, what it raises being raised. One that
    // returns leaves the call interrupted, as a system call is, with InterruptedError: the run
    // cannot go on from where it stopped.
    if (stopped.signal() == SIGTERM)
      ::raise(SIGTERM);
    else
      PyErr_SetInterrupt();
    if (PyErr_CheckSignals() != 0) return;
    const char* name = stopped.signal() == SIGTERM ? "SIGTERM" : "SIGINT";
    PyErr_Format(PyExc_InterruptedError,
                 "stopped by %s: the script's handler returned, and what was under way cannot go "
                 "on from where it stopped",
                 name);
  }
}

}  // namespace

PYBIND11_MODULE(_core, module) {
  module.doc() = "pound's C++ core; use the package `pound`, not this module";
  py::register_exception_translator(&translate_errors);
  pound::python::bind_models(module);
  pound::python::bind_records(module);
  pound::python::bind_runs(module);
  pound::python::bind_verification(module);
}
