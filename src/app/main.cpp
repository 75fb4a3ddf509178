// The `pound` program: command line only; everything else lives in the library.
#include "app/commands.hpp"

int main(int argc, char** argv) { return pound::app::main_entry(argc, argv); }
