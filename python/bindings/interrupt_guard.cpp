#include <Python.h>

#include <csignal>
#include <exception>
#include <mutex>

#include "bindings/bindings.hpp"
#include "core/interrupt.hpp"

namespace pound::python {
namespace {

std::mutex g_guards_mutex;
int g_guards = 0;
PreviousHandlers g_previous;

}  // namespace

InterruptGuard::InterruptGuard() {
  const std::lock_guard lock(g_guards_mutex);
  if (g_guards++ == 0) {
    clear_interrupt();
    g_previous = replace_interrupt_handlers();
  }
}

InterruptGuard::~InterruptGuard() {
  const std::lock_guard lock(g_guards_mutex);
  if (--g_guards > 0) return;
  restore_interrupt_handlers(g_previous);
  // A signal that no poll saw (the run ended first) still reaches Python: as if it came now.
  // One that stopped a run is on its way as an exception (module.cpp raises it again there).
  if (const int signal = interrupt_signal(); signal != 0 && std::uncaught_exceptions() == 0) {
    if (signal == SIGTERM)
      ::raise(SIGTERM);  // Python's own disposition: by default the process ends
    else
      PyErr_SetInterrupt();
  }
  clear_interrupt();
}

}  // namespace pound::python
