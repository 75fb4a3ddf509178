#pragma once
// Restitution achieved by each impact law (docs/design.md §3.2): two free masses collide once
// through a link with a small initial gap (so contact begins inside a step), integrated with
// Newmark (average acceleration, Newton) at 2,000 steps per contact. Achieved e is the relative
// separation velocity over the relative approach velocity.
#include <string>
#include <vector>

#include "builder/spec.hpp"

namespace pound::verification {

struct RestitutionRow {
  std::string law;      // as named in model files, with the variant ("kelvin_voigt (clip)")
  double target = 0.0;  // e asked for; 1 for elastic laws
  double achieved = 0.0;
  double peak_force = 0.0;
  double contact_time = 0.0;
  double max_penetration = 0.0;
  bool calibrated = false;  // the law is calibrated for e (so achieved must be close to target)
};

struct ImpactSetup {
  double mass_1 = 1.0e5, mass_2 = 2.0e5;       // [kg]
  double velocity_1 = 0.6, velocity_2 = -0.4;  // [m/s], closing at 1 m/s
  double gap = 1.0e-3;                         // [m]
  double linear_stiffness = 1.0e9;             // k of linear laws [N/m]
  double hertz_stiffness = 4.0e10;             // k_h of Hertz-type laws [N/m^1.5]
  int steps_per_contact = 2000;
};

// One impact with the given law; `contact_estimate` sets the time step.
RestitutionRow simulate_impact(const ImpactSetup& setup, const builder::LawSpec& law,
                               double contact_estimate);
// Every impact law and e in {0.3, 0.5, 0.7, 0.9}, and the elastic ones once.
std::vector<RestitutionRow> restitution_study(const ImpactSetup& setup = {});

}  // namespace pound::verification
