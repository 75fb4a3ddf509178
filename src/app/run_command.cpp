#include "app/commands.hpp"
#include <iostream>
namespace pound::app {
int run_command(const Arguments&) { std::cerr << "run: not yet\n"; return 1; }
}
