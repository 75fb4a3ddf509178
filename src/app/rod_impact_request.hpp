#pragma once
// The numbers of `pound verify rod-impact` (and of the Python module's verify.rod_impact), checked
// and turned into the run they describe.
#include <optional>
#include <string>

#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::app {

struct RodImpactRequest {
  std::string case_name = "kawashima";  // kawashima, fixed-end, area-ratio-3, unequal-lengths, ...
  int elements = 10;                    // per rod
  double stiffness_ratio = 1.0;         // link / axial stiffness of the softer adjacent element
  double dt_ratio = 0.01;               // time step / exact contact duration
  bool dt_ratio_given = false;          // else an explicit method takes its stable step
  std::optional<double> courant;        // dt C0 / h of the striking rod, instead of dt_ratio
  double duration_ratio = 3.0;          // run length after first contact / contact duration
  std::string law = "gap_spring";
  double eta = 1.0;  // extended_penalty: damping factor of alpha1
  std::string integrator = "newmark_average_acceleration";
  double hht_alpha = -0.1, rho_infinity = 0.8;  // where the integrator has them
  // Given rather than defaulted: refused where the law or integrator has no such number (a user
  // who sets --alpha without --integrator hht would otherwise get Newmark's results unawares).
  bool eta_given = false, hht_alpha_given = false, rho_infinity_given = false;
  double tolerance = 1e-10;  // relative, of the Newton iteration
  bool profiles = false;     // keep the rods' profiles at 0, T/4, T/2, 3T/4
};

// What is wrong with the numbers, named by their `pound verify` options ("--n must be >= 1").
std::optional<std::string> rod_impact_request_error(const RodImpactRequest& request);

// The run the request describes; throws std::invalid_argument with what is wrong.
verification::RodImpactOptions rod_impact_options(const RodImpactRequest& request);

}  // namespace pound::app
