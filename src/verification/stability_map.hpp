#pragma once
// The stability map of the rod benchmark: every integrator x contact law over a sweep of link
// stiffness ratio (k / (E A / h)) and time step (dt / T_exact), each cell classified as
//   accurate:   |duration|, |separation velocity| <= 5 % and force_l2_error <= 10 %,
//   inaccurate: a finite answer that misses those,
//   unstable:   NaN/Inf, energy growth over 10 %, or refused before running (explicit above its
//               stable step).
// Implicit methods must never be unstable; explicit ones must refuse rather than blow up.
// (The peak force of a discretised wave front overshoots 25-35 % even when converged, so it is
// not part of "accurate"; the force L2 error carries it.)
#include <string>
#include <vector>

#include "integrators/integrator_catalog.hpp"
#include "io/document.hpp"
#include "io/output.hpp"

namespace pound::verification {

enum class StabilityVerdict { accurate, inaccurate, unstable, refused };
// "accurate", ... as tables write it.
const char* verdict_name(StabilityVerdict verdict);

struct StabilityCell {
  std::string integrator, law;
  double stiffness_ratio = 0.0, step_ratio = 0.0;
  StabilityVerdict verdict = StabilityVerdict::accurate;
  double force_l2_error = 0.0, duration_error = 0.0, separation_velocity_error = 0.0,
         energy_ratio = 0.0;
  std::string note;
};

struct StabilityOptions {
  // Every method of the catalog with its study parameters.
  std::vector<integrators::IntegratorChoice> methods = integrators::IntegratorChoice::studied();
  std::vector<std::string> laws{"gap_spring", "extended_penalty"};
  std::vector<double> stiffness_ratios{1e-2, 1e-1, 1, 10, 1e2, 1e4, 1e6, 1e8};
  std::vector<double> step_ratios{1e-3, 1e-2, 0.05, 0.1, 0.5};
  int elements = 200;
};

std::vector<StabilityCell> stability_map(const StabilityOptions& options);
std::string format_stability_map(const std::vector<StabilityCell>& cells);
io::TextTable stability_table(const std::vector<StabilityCell>& cells);

}  // namespace pound::verification
