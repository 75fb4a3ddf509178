#include "links/extended_penalty.hpp"

#include <algorithm>
#include <cmath>

namespace pound::links {

ExtendedPenalty::ExtendedPenalty(Numbers numbers) : numbers_(numbers) {}

ExtendedPenalty::Numbers ExtendedPenalty::automatic(const LinkContext& c, double tolerance,
                                                    double eta) {
  const double k1 = c.fixed_i ? 0.0 : c.stiffness_i, k2 = c.fixed_j ? 0.0 : c.stiffness_j;
  const double m1 = c.fixed_i ? 0.0 : c.mass_i, m2 = c.fixed_j ? 0.0 : c.mass_j;
  const double alpha0 = std::max(k1, k2) / tolerance;
  const double alpha2 = alpha0 * (m1 + m2) / (k1 + k2);
  return {alpha0, 2.0 * eta * std::sqrt(alpha0 * alpha2), alpha2};
}

LawResponse ExtendedPenalty::set_trial(const LinkKinematics& trial) {
  const double force = numbers_.alpha0 * trial.penetration +
                       numbers_.alpha1 * trial.penetration_rate +
                       numbers_.alpha2 * trial.penetration_acceleration;
  // In contact the force may hold past delta = 0 while positive (released only when it would
  // pull); out of contact it needs penetration. No condition on the rate: it would leave the
  // condensed Newton equation without a solution near a grazing contact.
  trial_contact_ = force > 0.0 && (committed_contact_ || trial.penetration > 0.0);
  if (!trial_contact_) return {};
  return {.force = force,
          .stiffness = numbers_.alpha0,
          .damping = numbers_.alpha1,
          .mass = numbers_.alpha2};
}

}  // namespace pound::links
