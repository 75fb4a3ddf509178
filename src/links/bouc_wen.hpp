#pragma once
// Smooth Bouc-Wen hysteretic spring (Bouc 1967; Wen 1976, J. Eng. Mech. Div. 102(EM2)), for
// bearings, dampers and hinges whose yielding is gradual. It is OpenSees' uniaxialMaterial BoucWen
// without degradation (deltaA = deltaNu = deltaEta = 0), with the same parameters, so that its
// numbers carry over (OpenSees name in brackets):
//
//   F = a k delta + (1 - a) k z
//   dz/d(delta) = A - |z|^n (beta sgn(d(delta) z) + gamma),   z = 0 at the start
//
//   k      stiffness        [ko]     initial stiffness when A = 1 [F/L]
//   a      hardening_ratio  [alpha]  post-yield / initial stiffness, in [0, 1) [-]
//   n      sharpness        [n]      >= 1: how sharp the knee is (1 smooth; 10 and more nearly
//                                    bilinear) [-]
//   beta   beta             [beta]   > 0: the loop's width; unloading (d(delta) z < 0) is
//                                    stiffer than loading by 2 beta |z|^n [1/L^n]
//   gamma  gamma            [gamma]  with beta, the shape: loading has dz/d(delta) =
//                                    A - (beta + gamma)|z|^n, unloading A + (beta - gamma)|z|^n
//                                    (gamma = beta: unloading at the initial slope A) [1/L^n]
//   A      amplitude        [Ao]     dz/d(delta) at z = 0, default 1 [-]
//
// yield_force F_y (optional) [F]: the equivalent bilinear yield force k z_max / A. With it, beta
// and gamma give only the loop's shape: both are scaled by one factor so that z_max = A F_y / k
// (what a generator sets for a pier hinge, from its yield moment).
//
// z is a deformation [L]; on loading it tends to z_max = (A / (beta + gamma))^(1/n), so the
// force tends to the lines F = a k delta +- (1 - a) k z_max: (1 - a) k z_max is the
// characteristic strength (the force intercept of the post-yield branch), the initial slope is
// k (a + (1 - a) A), and the equivalent bilinear spring yields at delta_y = z_max / A
// (yield_deformation; z_max itself for A = 1), with F_y ~ k z_max for A = 1.
//
// Admissible parameters, refused otherwise (`refusal`): k > 0, 0 <= a < 1 (a = 1 is an elastic
// spring), A > 0 (the spring starts elastic in the direction it is pushed), beta + gamma > 0
// (z is bounded: with beta + gamma <= 0 loading never saturates), beta > 0 (with beta = 0 z is
// a function of delta, an elastic curve that dissipates nothing; with beta < 0 loops run
// anticlockwise and create energy; beta > 0 also keeps the unloading slope >= 2 A beta /
// (beta + gamma) > 0, so |z| <= z_max always), and 1 <= n <= 50 (below 1 the rate of change of
// the tangent is unbounded at every z = 0; above 50 the knee is bilinear's for all purposes while
// the sub-steps, z_max / (64 n A), grow too many). They are derived here from the two branch
// slopes; cf. the bounded-input bounded-output analysis of Ikhouane, Manosa & Rodellar (2007, Syst.
// Control Lett. 56), which also takes n >= 1. Constantinou & Adnane (1987) normalise
// A / (beta + gamma) = 1; Ma, Zhang & Foliente (2004, J. Appl. Mech. 71) show A is redundant
// with k, beta and gamma (it is kept for OpenSees' numbers). The model reader
// also asks gamma >= 0 (its parameter ranges have no signed number); the class accepts
// -beta < gamma < 0.
//
// Rate independent, integrated exactly in delta rather than in time: within a step delta moves
// linearly from the committed delta_n to the trial delta, so sgn(d(delta)) is fixed and z solves
// an autonomous ODE in delta, split where z crosses 0 (where sgn(d(delta) z), and with it the
// branch, changes). For n = 1 each branch is linear in z and solved in closed form; for other n
// by RK4 in sub-steps of at most 1 / (64 lambda), lambda the largest |d(dz/d(delta))/dz| on
// |z| <= z_max, graded down near z = 0 (where |z|^n is not smooth), on a grid that starts at the
// committed state, and the crossing of z = 0 found inside its sub-step by bisection. z agrees
// with the exact ODE solution to ~1e-9 z_max whatever the step of the caller
// (tests/links/bouc_wen_test.cpp). The consistent tangent is
// the ODE's own slope at the trial end: dF/d(delta) = a k + (1 - a) k dz/d(delta); at a trial
// equal to the committed delta, that of the branch of the last committed move.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "links/link_law.hpp"

namespace pound::links {

// The RK4 sub-steps both Bouc-Wen laws integrate z with (this one and links/plane_bouc_wen.hpp),
// as travel [L]: at most 1 / (64 lambda), lambda = n A max(1, |beta - gamma| / (beta + gamma)) /
// z_max the largest |d(dz/d(delta))/dz| on |z| <= z_max (n A / z_max loading, n A |beta - gamma|
// / ((beta + gamma) z_max) unloading, both at z_max); near z = 0, where |z|^n is not smooth, at
// most 1/8 of the travel from z = 0 (~ |z| / A) and at least 1e-3 of the largest. z is then
// within ~1e-10 z_max of the ODE's solution and the tangent (the ODE's slope) within ~1e-8 of
// the derivative of the computed force (tests/links/bouc_wen_test.cpp measures both).
class BoucWenSubsteps {
 public:
  BoucWenSubsteps(double saturation, double sharpness, double amplitude, double beta, double gamma)
      : largest_(saturation / (kPerRate * sharpness * amplitude *
                               std::max(1.0, std::abs(beta - gamma) / (beta + gamma)))),
        amplitude_(amplitude) {}
  double largest() const { return largest_; }
  // The sub-step at |z| = magnitude.
  double at(double magnitude) const {
    return std::min(largest_, std::max(kGrading * magnitude / amplitude_, kSmallest * largest_));
  }

 private:
  static constexpr double kPerRate = 64.0, kGrading = 0.125, kSmallest = 1e-3;
  double largest_, amplitude_;
};

class BoucWen final : public LinkLaw {
 public:
  struct Parameters {
    double stiffness = 0.0;        // k [F/L]
    double hardening_ratio = 0.0;  // a [-]
    double sharpness = 1.0;        // n [-]
    double beta = 0.0;             // [1/L^n]
    double gamma = 0.0;            // [1/L^n]
    double amplitude = 1.0;        // A [-]
  };
  // A parameter outside the admissible set: its name and why.
  struct Refusal {
    std::string parameter;
    std::string reason;
  };
  static std::optional<Refusal> refusal(const Parameters& parameters);
  // The parameters with beta and gamma scaled so that k z_max / A = yield_force.
  static Parameters with_yield_force(Parameters parameters, double yield_force);

  // Throws std::invalid_argument when `refusal` refuses the parameters.
  explicit BoucWen(const Parameters& parameters);

  std::string name() const override { return "bouc_wen"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<BoucWen>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  // A spring is always attached; "in contact" means it carries a force.
  bool in_contact() const override { return committed_force_ != 0.0; }
  std::optional<double> yield_deformation() const override { return saturation_ / amplitude_; }
  // bouc_wen_stored_energy (F_h = (1 - a) k z).
  std::optional<double> stored_energy(double force, double deformation) const override {
    return bouc_wen_stored_energy(stiffness_, hardening_ratio_, amplitude_, force, deformation);
  }

  const Parameters& parameters() const { return parameters_; }
  double hysteretic_deformation() const { return committed_z_; }  // z [L]
  double saturation() const { return saturation_; }               // z_max [L]

 private:
  // A move of |z| = w along the travel t = |delta - delta_n| >= 0: loading when z has the sign
  // of the move (w grows toward z_max), unloading when it has the other (w falls to 0).
  enum class Branch { loading, unloading };
  // dw/dt on a branch.
  double rate(double w, Branch branch) const;
  // w after a travel on a branch; an unloading stops at w = 0 and `travel` is cut to what it
  // took to get there.
  double advance(double w, double& travel, Branch branch) const;
  double advance_exact(double w, double& travel, Branch branch) const;  // n = 1
  double advance_rk4(double w, double& travel, Branch branch) const;
  double rk4_step(double w, double h, Branch branch) const;
  // z at `penetration`, from the committed state.
  double z_at(double penetration) const;
  // dz/d(delta) at z moving in `direction`.
  double slope(double z, double direction) const;

  Parameters parameters_;
  double stiffness_, hardening_ratio_, sharpness_, beta_, gamma_, amplitude_;
  double saturation_;         // z_max
  BoucWenSubsteps substeps_;  // of RK4 (n != 1)
  double committed_delta_ = 0.0, committed_z_ = 0.0, committed_force_ = 0.0;
  double committed_direction_ = 0.0;  // sign of the last committed move (0: none yet)
  double trial_delta_ = 0.0, trial_z_ = 0.0, trial_force_ = 0.0;
};

}  // namespace pound::links
