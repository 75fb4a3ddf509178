#include "core/interrupt.hpp"

#include <fmt/format.h>

#include <atomic>
#include <csignal>

namespace pound {
namespace {

// Lock-free, so the handler may set it, and atomic, so every worker thread sees it.
std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void on_signal(int signal) {
  if (g_signal != 0) {
    // Asked twice: the user wants out now. signal() and raise() are async-signal-safe.
    std::signal(signal, SIG_DFL);
    std::raise(signal);
    return;
  }
  g_signal = signal;
}

}  // namespace

Interrupted::Interrupted(int signal)
    : std::runtime_error(fmt::format("interrupted by {}", signal == SIGINT    ? "SIGINT"
                                                          : signal == SIGTERM ? "SIGTERM"
                                                                              : "a signal")),
      signal_(signal) {}

void install_interrupt_handlers() { (void)replace_interrupt_handlers(); }

PreviousHandlers replace_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // reads and writes in progress go on; the flag is polled
  PreviousHandlers previous;
  sigaction(SIGINT, &action, &previous.interrupt);
  sigaction(SIGTERM, &action, &previous.terminate);
  return previous;
}

void restore_interrupt_handlers(const PreviousHandlers& previous) {
  sigaction(SIGINT, &previous.interrupt, nullptr);
  sigaction(SIGTERM, &previous.terminate, nullptr);
}

void clear_interrupt() { g_signal = 0; }

int interrupt_signal() { return g_signal; }

void throw_if_interrupted() {
  if (const int signal = g_signal; signal != 0) throw Interrupted(signal);
}

}  // namespace pound
