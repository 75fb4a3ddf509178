#pragma once
// Published conversions from a coefficient of restitution e (0 < e <= 1) to a law's damping,
// and the closed forms of an elastic Hertz impact. docs/design.md section 2.3.
#include <cmath>
#include <numbers>

namespace pound::links {

// Kelvin-Voigt (Anagnostopoulos 1988): xi = -ln e / sqrt(pi^2 + ln^2 e); c = 2 xi sqrt(k m_eff).
// Exact for a linear spring-dashpot whose contact ends at delta = 0 (tension allowed).
inline double kelvin_voigt_damping_ratio(double restitution) {
  const double log_e = std::log(restitution);
  return -log_e / std::sqrt(std::numbers::pi * std::numbers::pi + log_e * log_e);
}

// Hertz-damp (Ye, Li & Zhu 2009): xi_bar = 8 (1 - e) / (5 e) in F = k_h delta^1.5 (1 + xi_bar
// delta_dot / v0). (Muthukumar & DesRoches' 3 (1 - e^2) / 4 dissipates far too little.)
inline double hertz_damp_ratio_ye(double restitution) {
  return 8.0 * (1.0 - restitution) / (5.0 * restitution);
}

// Jankowski (2005): xi = 9 sqrt(5) / 2 (1 - e^2) / (e (e (9 pi - 16) + 16)),
// c = 2 xi sqrt(beta sqrt(delta) m_eff).
inline double jankowski_damping_ratio(double restitution) {
  const double e = restitution;
  return 9.0 * std::sqrt(5.0) / 2.0 * (1.0 - e * e) /
         (e * (e * (9.0 * std::numbers::pi - 16.0) + 16.0));
}

// Elastic Hertz impact of m_eff at v0 on F = k_h delta^1.5:
// delta_max = (5 m v0^2 / (4 k_h))^0.4, F_max = k_h delta_max^1.5, duration ~ 2.943 delta_max/v0.
struct HertzImpact {
  double max_penetration;
  double max_force;
  double duration;
};
inline HertzImpact hertz_impact(double stiffness, double effective_mass, double velocity) {
  const double penetration =
      std::pow(5.0 * effective_mass * velocity * velocity / (4.0 * stiffness), 0.4);
  return {penetration, stiffness * std::pow(penetration, 1.5), 2.943 * penetration / velocity};
}

}  // namespace pound::links
