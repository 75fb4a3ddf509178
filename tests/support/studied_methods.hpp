#pragma once
// The studied methods whose behaviour the study tests spell out (refused above the explicit
// limit, accurate with the extended penalty at small steps): the catalog's first four. A method
// added to the catalog later is run on an oscillator by integrator_catalog_test, so the study
// tests need no edit when one is added.
#include <set>
#include <string>
#include <vector>

#include "integrators/integrator_catalog.hpp"

namespace pound::testing {

inline std::vector<integrators::IntegratorChoice> studied_methods() {
  const std::set<std::string> known{"newmark_average_acceleration", "hht", "generalized_alpha",
                                    "central_difference"};
  std::vector<integrators::IntegratorChoice> methods;
  for (const integrators::IntegratorChoice& choice : integrators::IntegratorChoice::studied())
    if (known.contains(choice.label())) methods.push_back(choice);
  return methods;
}

}  // namespace pound::testing
