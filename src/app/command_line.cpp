#include "app/command_line.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>

namespace pound::app {
namespace po = boost::program_options;

std::optional<po::variables_map> parse_command_line(const Arguments& arguments,
                                                    const po::options_description& options,
                                                    const char* positional_name,
                                                    std::string& positional_value) {
  po::options_description hidden;
  hidden.add_options()(positional_name, po::value(&positional_value));
  po::options_description all;
  all.add(options).add(hidden);
  po::positional_options_description positional;
  positional.add(positional_name, 1);
  po::variables_map vm;
  po::store(po::command_line_parser(arguments).options(all).positional(positional).run(), vm);
  po::notify(vm);
  // No number an option takes may be NaN or infinite ("--eta nan" would run with it): the ranges
  // each command checks then need not think of them.
  for (const auto& [name, value] : vm)
    if (const double* number = boost::any_cast<double>(&value.value()))
      if (!std::isfinite(*number))
        throw po::error(fmt::format("--{} must be a finite number, got {}", name, *number));
  if (vm.count("help")) {
    std::cout << options << "\n";
    return std::nullopt;
  }
  return vm;
}

}  // namespace pound::app
