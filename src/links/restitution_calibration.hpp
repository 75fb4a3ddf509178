#pragma once
// Damping that makes a law reach a target coefficient of restitution e exactly. For the damped
// impact laws the restitution of a two-mass impact depends on their damping knob alone: scaling
// delta by (m_eff v0^2 / k)^(1/(p+1)) and time accordingly turns every impact into the law's own
// at unit stiffness, effective mass and approach velocity,
//   x'' = -F_unit(x, x'),  x(0) = 0,  x'(0) = 1,  e = -x' when contact ends,
// (Kelvin-Voigt: F = x + 2 xi x'; Hertz-damp: x^1.5 (1 + xi_bar x'); Jankowski:
// x^1.5 + 2 xi x^0.25 x' while approaching). The law object itself is run on it (RK4 at 1e-3,
// trial -> commit at every step; steps from 1e-12 growing by 10 % at first touch, where
// Jankowski's damping grows as x^(1/4), and halved down to 1e-12 onto the turn, the release and
// a clipped law's let-go, so that forces with kinks or jumps there cost no accuracy: e to 1e-10
// against an adaptive Dormand-Prince), and the knob is found by TOMS 748 (Boost.Math) to 1e-12,
// about ten impacts where bisection took over thirty. The published
// conversions (links/restitution.hpp) approximate this inverse: Ye's xi_bar gives e = 0.256 for a
// target 0.3, Jankowski's 0.292; clipping Kelvin-Voigt's tension gives 0.397.
#include "links/law_registry.hpp"

namespace pound::links {

// Restitution of the unit impact of `law` (a law at unit stiffness, mass and approach velocity,
// in its committed state before contact).
double impact_restitution(LinkLaw& law);

// The damping knob of `entry`'s unit law (for the choices of `law`) that gives e; cached. Throws
// std::domain_error when e cannot be reached.
double damping_for_restitution(const LawEntry& entry, const LawSpec& law, double restitution);

// The knob for `law`'s own "restitution", as its "calibration" choice says: "exact" (by the law's
// impact) or "published" (the source's formula). Errors name `where`'s restitution.
double calibrated_damping(const LawEntry& entry, const LawSpec& law, const LawSource& where);

}  // namespace pound::links
