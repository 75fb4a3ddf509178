#pragma once
// A bearing's shear in the plane across its axis, or a column hinge's bending about the two axes
// across the column, its two directions coupled: a circular yield surface (an isotropic
// elastomeric or lead-rubber bearing, a bilinear bearing, a circular column) or an elliptic one
// (a rectangular column: each direction its own k_a and F_y,a). It acts on a link's tangential
// rows (links/coulomb_friction.hpp's tangents t_1, t_2 of its axis; a rotational link's rows turn
// about them), beside the link's own law on its normal row (the bearing's axial stiffness, the
// hinge's torsion), s = (u_i - u_j) . t_a along each. Its hysteresis is one of the plane laws of
// links/plane_hysteresis.hpp: the bilinear spring's radial return (links/plane_bilinear.hpp) or
// the Bouc-Wen law (links/plane_bouc_wen.hpp), each along one line its uniaxial law.
//
// Elliptic: with k_a, F_y,a and one b, the bilinear law's surface is
// sum_a ((F_a - alpha_a) / F_y,a)^2 <= 1. In units of direction 1
// (s~_a = s_a (k_a / k_1) / (F_y,a / F_y,1), F~_a = F_a F_y,1 / F_y,a) the law is the circular
// one with k_1, F_y,1 and b: the same return, F_a = F~_a F_y,a / F_y,1 and the tangent scaled
// row by row and column by column. Equal directions scale by exactly 1: the circular law to the
// bit. Each direction alone is its own bilinear law. The flow is normal to the ellipse in those
// units: in forces it is associated only when F_y,1^2 / k_1 = F_y,2^2 / k_2 (the tangent is then
// symmetric; otherwise not), and it always dissipates,
// F . dp = dgamma / |F~| sum_a (F_y,a / F_y,1)^2 / (k_a / k_1) F~_a^2 >= 0 (b = 0).
//
// With stiffness-proportional damping (set_damping, a link's `rayleigh`): F_t += C ds/dt, C the
// initial a1 diag(k_a) (the slopes at rest) or a1 times the 2 x 2 tangent of the last converged
// step, its work kept apart (viscous_part), as links/stiffness_damping.hpp does for one direction.
//
// Made from a uniaxial law's numbers: bilinear_spring, lead_rubber and elastic_perfectly_plastic
// (BilinearSpring objects), elastic_spring (F_y infinite: k I) or bouc_wen (two Bouc-Wen
// directions make an ellipse when n, A and a are equal and beta / (beta + gamma) is: then
// z~ = z_a z_max,1 / z_max,a follows direction 1's law, and F_y,a = k_a z_max,a / A). Shear
// and axial are not coupled (no axial-load-dependent strength, no P-Delta of the bearing).
// Units: k [F/L], F_y [F], b [-] in [0, 1), s and p [L] (a hinge's: k [F L/rad], F_y [F L], rad).
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <string>

#include "links/coulomb_friction.hpp"
#include "links/link_law.hpp"
#include "links/plane_hysteresis.hpp"
#include "links/stiffness_damping.hpp"

namespace pound::links {

// Stiffness-proportional damping of the shear (links/stiffness_damping.hpp in two directions):
// F_t += C ds/dt with C = a1 diag(k_a) (initial) or a1 times the law's 2 x 2 tangent at the last
// converged step (committed), held through the step.
struct ShearDamping {
  double stiffness_coefficient = 0.0;  // a1 [T]
  DampingStiffness stiffness = DampingStiffness::initial;
};
// What that damping did: its work up to the committed state and its committed force.
struct ShearViscousPart {
  double work = 0.0;   // [F L]
  Tangential force{};  // [F]
};

struct LawSpec;
struct LawSource;

class CoupledShear {
 public:
  // The laws that have the coupled form, for messages and docs.
  static constexpr const char* kLaws =
      "bilinear_spring, lead_rubber, elastic_perfectly_plastic, bouc_wen or elastic_spring";
  // The numbers of a uniaxial law that has a coupled form (see above); none for the others.
  static std::optional<ShearNumbers> numbers_of(const LinkLaw& law);
  static std::optional<ShearNumbers> numbers_of(const LawSpec& law, const LawSource& where);

  // Why two directions' numbers cannot make one law (a hardening ratio, a yielding or a
  // Bouc-Wen shape that differs); none when they can.
  static std::optional<std::string> mismatch(const ShearNumbers& first, const ShearNumbers& second);

  // normal: the link's law on its normal row; tangents: 1 (a plane) or 2 (space).
  CoupledShear(std::unique_ptr<LinkLaw> normal, ShearDirections numbers, int tangents);
  CoupledShear(const CoupledShear& other);
  CoupledShear& operator=(const CoupledShear&) = delete;

  // The normal law's response, and the shear's along each tangent (s_a alone: no rate terms).
  FrictionResponse set_trial(const LinkKinematics& normal,
                             std::span<const LinkKinematics> tangential);
  void commit();
  void revert();
  int tangents() const { return tangents_; }
  const LinkLaw& normal_law() const { return *normal_; }
  const ShearDirections& numbers() const { return numbers_; }
  // The committed deformation that does not spring back, along each tangent [L]
  // (links/plane_hysteresis.hpp).
  Tangential plastic_deformation() const;
  void set_damping(const ShearDamping& damping);
  ShearViscousPart viscous_part() const { return {committed_viscous_work_, committed_viscous_}; }

 private:
  // Forces and tangent from direction 1's units to each direction's own.
  void to_own_units(FrictionResponse& out) const;
  // The damping's force C ds/dt, its work and its tangent, added to the law's response.
  void add_damping(std::span<const LinkKinematics> tangential, FrictionResponse& out);

  std::unique_ptr<LinkLaw> normal_;
  ShearDirections numbers_;
  std::unique_ptr<PlaneHysteresis> hysteresis_;  // direction 1's law, in its units
  int tangents_;
  // Direction a's units to direction 1's: s~ = s * deformation_scale, F = F~ * force_scale.
  Tangential deformation_scale_{1.0, 1.0}, force_scale_{1.0, 1.0};
  // Damping: a1 (none: 0), C of the step, the law's last trial tangent; the viscous force, the
  // slide it works through and its work, trial and committed.
  std::optional<ShearDamping> damping_;
  std::array<Tangential, kMaxTangents> dashpot_{}, trial_tangent_{};
  Tangential trial_viscous_{}, committed_viscous_{}, trial_slide_{}, committed_slide_{};
  double trial_viscous_work_ = 0.0, committed_viscous_work_ = 0.0;
  bool started_ = false;
};

}  // namespace pound::links
