#pragma once
// The Bouc-Wen law (links/bouc_wen.hpp) with vectors for scalars: the smooth hysteresis of an
// isolator's shear, or a column's bending about two axes, its two directions coupled:
//
//   F = a k s + (1 - a) k z
//   dz = A ds - |z|^(n-2) z (beta |z . ds| + gamma z . ds),     z = 0 at the start
//
// with s, z and F vectors of the plane, in direction 1's units (links/coupled_shear.hpp scales
// an ellipse to this circle). For n = 2 it is Park, Wen & Ang's biaxial model (1986, J. Struct.
// Eng. 112(11); 3D-BASIS's and SAP2000's isolators) with |z . ds| where they have
// sum_a |z_a ds_a|: the same when the motion is along z or along an axis, and, unlike theirs,
// unchanged by a rotation of the plane (cf. Harvey & Gavin 2014, Earthq. Eng. Struct. Dyn. 43,
// who make the same point for any n). Along one line it is the uniaxial law. Each step,
// d|z|^2 / 2 = (z . ds)(A - (beta sgn(z . ds) + gamma) |z|^n), so |z| never passes
// z_max = (A / (beta + gamma))^(1/n) (with beta > 0 and beta + gamma > 0, the uniaxial law's
// admissible numbers). Driven steadily around a circle of radius r > z_max / A, z settles at
// |z| = z_max, lagging the motion's direction by asin(z_max / (A r)), and each turn dissipates
// 2 pi (1 - a) k z_max sqrt(r^2 - (z_max / A)^2) (what the tests check; the bilinear circle's
// formula with delta_y = z_max / A).
//
// Integrated in s, not in time (rate independent): within a step s moves on the straight line
// from the committed s_n to the trial s, D = s - s_n, so with t in [0, 1]
//
//   dz/dt = A D - |z|^(n-2) z (beta sigma + gamma) (z . D),    sigma = sgn(z . D)
//
// z . D can only grow through 0 (its rate there is A |D|^2), so a move unloads (sigma = -1)
// until z . D = 0 and loads after: RK4 on each branch, in sub-steps of at most 1 / (64 lambda)
// of travel as the uniaxial law takes, graded down near z = 0, the change of branch found inside
// its sub-step by bisection; a move whose loading travel passes 64 z_max / A takes its
// limit instead (z = z_max d, d = D / |D|, to rounding), so any move costs a bounded number of
// sub-steps (plane_bouc_wen.cpp). The consistent tangent dF/ds = a k I + (1 - a) k dz/dD integrates
// the sensitivity S = dz/dD along with z (dS/dt = df/dz S + df/dD; the branch change adds no
// jump, f being continuous there). A trial equal to the committed s takes the slope of the last
// committed move's branch. Units: k [F/L], beta and gamma [1/L^n], s and z [L] (a hinge's rad).
#include "links/bouc_wen.hpp"
#include "links/plane_hysteresis.hpp"

namespace pound::links {

class PlaneBoucWen final : public PlaneHysteresis {
 public:
  PlaneBoucWen(const ShearNumbers& numbers, int tangents);
  std::unique_ptr<PlaneHysteresis> clone() const override;
  PlaneResponse set_trial(const Tangential& deformation) override;
  void commit() override;
  void revert() override;
  Tangential plastic_deformation() const override;
  Tangential hysteretic_deformation() const { return committed_z_; }  // z [L]
  double saturation() const { return saturation_; }                   // z_max [L]

  using Matrix = std::array<Tangential, kMaxTangents>;
  // z and dz/dD along a move.
  struct State {
    Tangential z{};
    Matrix sensitivity{};
  };

 private:
  // dz/dt and dS/dt on a branch (sign sigma) for the move D.
  State rate(const State& state, const Tangential& move, double sign) const;
  State rk4_step(const State& state, double h, const Tangential& move, double sign) const;
  // z and S after the move D from the committed state.
  State advance(const Tangential& move) const;
  // One branch from `from` over t in [start, 1]; returns where it stopped (an unloading stops
  // where z . D reaches 0).
  double advance_branch(State& state, double start, const Tangential& move, double sign) const;
  // The slope dz/dD at z moving along `direction` (the ODE's own, for a trial at the committed s).
  Matrix slope(const Tangential& z, const Tangential& direction) const;

  double stiffness_, hardening_ratio_, amplitude_;
  double sharpness_;
  double loading_, unloading_;  // A (beta sigma + gamma) / ((beta + gamma) z_max^2), sigma = +-1
  double saturation_;           // z_max
  BoucWenSubsteps substeps_;    // as the uniaxial law's
  int tangents_;
  Tangential committed_s_{}, committed_z_{}, committed_direction_{};
  Tangential trial_s_{}, trial_z_{};
};

}  // namespace pound::links
