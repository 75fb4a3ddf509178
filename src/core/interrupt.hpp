#pragma once
// Ctrl-C and `kill`: SIGINT and SIGTERM only set a flag (all a signal handler may safely do).
// The time-step loop and the writers of results poll it and throw Interrupted, so the stack
// unwinds, temporary files are removed and `main` exits with 128 + the signal's number. A second
// signal while the first is being honoured ends the process at once, as the signal would have.
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

// The signal received, or 0.
int interrupt_signal();

// Throws Interrupted once a signal has been received.
void throw_if_interrupted();

}  // namespace pound
