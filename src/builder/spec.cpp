#include "builder/spec.hpp"

#include <map>
#include <stdexcept>

namespace pound::builder {

double UnitsSpec::gravity() const {
  static const std::map<std::string, double> metres = {
      {"m", 1.0}, {"cm", 0.01}, {"mm", 1e-3}, {"km", 1000.0}, {"in", 0.0254}, {"ft", 0.3048}};
  static const std::map<std::string, double> seconds = {{"s", 1.0}, {"ms", 1e-3}};
  const double metre = metres.at(length), second = seconds.at(time);
  return 9.80665 / metre * second * second;
}

double UnitsSpec::second() const { return time == "ms" ? 1000.0 : 1.0; }

}  // namespace pound::builder
