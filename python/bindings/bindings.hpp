#pragma once
// The parts of pound._core, one function per file that binds them.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

namespace pound::python {

// Model files and dicts: validate, expand, check, modes (models.cpp).
void bind_models(pybind11::module_& module);
// Records: read a file, check given samples, spectra (records.cpp).
void bind_records(pybind11::module_& module);
// pound.run and pound.batch (runs.cpp).
void bind_runs(pybind11::module_& module);
// The verification benchmarks (verification.cpp).
void bind_verification(pybind11::module_& module);

// A NumPy array holding a copy of `values`.
inline pybind11::array_t<double> to_array(const std::vector<double>& values) {
  return pybind11::array_t<double>(static_cast<pybind11::ssize_t>(values.size()), values.data());
}

// While alive: SIGINT and SIGTERM only set pound's flag, polled by the time-step loop, instead of
// going to Python's handlers (which cannot run while a solve holds no GIL); the handlers before
// are put back after the last guard, and a signal that came meanwhile becomes KeyboardInterrupt
// there (core/interrupt.hpp). Guards on several threads share one installation.
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

}  // namespace pound::python
