#pragma once
// Ctrl-C and `kill`: SIGINT and SIGTERM only set a flag (all a signal handler may safely do).
// The time-step loop and the writers of results poll it and throw Interrupted, so the stack
// unwinds, temporary files are removed and `main` exits with 128 + the signal's number. A second
// signal while the first is being honoured ends the process at once, as the signal would have.
#include <signal.h>

#include <stdexcept>
#include <string>

namespace pound {

class Interrupted : public std::runtime_error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }
  int exit_code() const { return 128 + signal_; }

 private:
  int signal_;
};

// Installs the handlers for SIGINT and SIGTERM (once, from main).
void install_interrupt_handlers();

// For a program that embeds pound (the Python module) and has handlers of its own: installs
// pound's, returning the ones they replace, and puts those back.
struct PreviousHandlers {
  struct sigaction interrupt {};
  struct sigaction terminate {};
};
PreviousHandlers replace_interrupt_handlers();
void restore_interrupt_handlers(const PreviousHandlers& previous);

// Forgets a signal received, once it has been honoured (the next run starts afresh).
void clear_interrupt();

// The signal received, or 0.
int interrupt_signal();

// Throws Interrupted once a signal has been received.
void throw_if_interrupted();

}  // namespace pound
