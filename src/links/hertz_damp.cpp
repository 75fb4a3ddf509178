#include "links/hertz_damp.hpp"

#include <cmath>

namespace pound::links {

HertzDamp::HertzDamp(double stiffness, double damping_ratio)
    : stiffness_(stiffness), damping_ratio_(damping_ratio) {}

LawResponse HertzDamp::set_trial(const LinkKinematics& trial) {
  trial_ = trial;
  if (!(trial.penetration > 0.0)) return {};
  const double root = std::sqrt(trial.penetration);
  const double elastic = stiffness_ * trial.penetration * root;  // k_h delta^1.5
  const double elastic_slope = 1.5 * stiffness_ * root;
  const OnsetVelocity v0 = onset_.at(trial);
  if (!(v0.velocity > 0.0)) return {.force = elastic, .stiffness = elastic_slope};
  const double factor = 1.0 + damping_ratio_ * trial.penetration_rate / v0.velocity;
  if (factor <= 0.0) return {};
  // d(factor)/d(v0) = -xi_bar delta_dot / v0^2, and v0 depends on the trial in the onset step.
  const double d_factor_d_v0 =
      -damping_ratio_ * trial.penetration_rate / (v0.velocity * v0.velocity);
  return {.force = elastic * factor,
          .stiffness = elastic_slope * factor + elastic * d_factor_d_v0 * v0.d_penetration,
          .damping = elastic * (damping_ratio_ / v0.velocity + d_factor_d_v0 * v0.d_rate)};
}

}  // namespace pound::links
