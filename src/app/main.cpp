// The `pound` program: command line only; everything else lives in the library.
#include "app/commands.hpp"
#include "core/interrupt.hpp"

int main(int argc, char** argv) {
  pound::install_interrupt_handlers();
  return pound::app::main_entry(argc, argv);
}
