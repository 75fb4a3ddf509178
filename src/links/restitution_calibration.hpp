#pragma once
// Damping that makes a law reach a target coefficient of restitution exactly. For these laws
// the restitution of a two-mass impact depends on the damping parameter alone: scaling delta by
// delta* = (m_eff v0^2 / k)^(1/(p+1)) and time by delta*/v0 turns every impact into
//   kelvin_voigt:  x'' = -(x + 2 xi x')              (optionally clipped at 0)
//   hertz_damp:    x'' = -x^1.5 (1 + xi_bar x')        (clipped at 0)
//   jankowski:     x'' = -(x^1.5 + 2 xi x^0.25 x')     (damping only while x' > 0)
// with x(0) = 0, x'(0) = 1 and e = -x' when contact ends. The published conversions
// (links/restitution.hpp) are approximations of this inverse: Ye's xi_bar gives e = 0.256
// for a target 0.3, Jankowski's 0.292; clipping Kelvin-Voigt's tension gives 0.397. Here the
// impact is integrated (RK4, 10^4 steps per unit time) and the damping found by bisection.
namespace pound::links {

enum class DampedImpact { kelvin_voigt, kelvin_voigt_clipped, hertz_damp, jankowski };

// Restitution of the nondimensional impact with damping parameter `damping`.
double impact_restitution(DampedImpact law, double damping);
// The damping parameter (xi for Kelvin-Voigt and Jankowski, xi_bar for Hertz-damp) giving e;
// throws std::domain_error when e cannot be reached.
double damping_for_restitution(DampedImpact law, double restitution);

}  // namespace pound::links
