#pragma once
// Clough & Johnston (1966) peak-oriented degrading-stiffness model for reinforced-concrete
// members (a pier or beam plastic hinge as a zero-length link, delta a displacement or a
// rotation), symmetric, F > 0 with delta > 0: Clough & Johnston (1966), "Effect of stiffness
// degradation on earthquake ductility requirements", Proc. 2nd Japan Earthquake Engineering
// Symposium, Tokyo. Their paper gives the outer loops; the inner-loop rule 3 is the one this
// program's Takeda law uses (a small cycle stays on the unloading line).
//
// Skeleton (bilinear):  F = k d for |d| <= d_y = F_y / k,  F = sign(d) (F_y + b k (|d| - d_y))
// beyond. Memory: the peak d_p of each side (largest |delta| reached there, d_y at the start).
//
// Rules (s the side of the force, s' = -s):
//  1. Skeleton: loading away from zero on the skeleton follows it and raises the peak.
//  2. Unloading: a reversal at a point T on the skeleton or on a reloading line unloads on a
//     straight line from T of slope k_u = k (d_y / d_p)^alpha, d_p the peak of side s (alpha = 0,
//     the default, is Clough's elastic unloading with k; alpha > 0 degrades it as Takeda's),
//     never softer than the secant F_T / d_T (T on the skeleton) nor than the reloading line T
//     is on; it reaches
//     zero force at d_0 = d_T - F_T / k_u.
//  3. Inner loops: an unloading line reversed before zero force retraces itself to T and then
//     continues on the branch T was on (skeleton, or the reloading line toward its target).
//  4. Crossing zero force: from (d_0, 0) reloading runs straight to the largest previous
//     excursion on the skeleton of side s', (s' d_p', S(s' d_p')) — the yield point if s' has
//     not yielded — and then follows the skeleton.
// The law is the modified Takeda law (links/takeda.hpp) with a bilinear skeleton and beta = 0,
// whose rules reduce to these: one implementation of the branch walk for both. A trial walks
// from the committed state through every branch point; its tangent is the slope of the branch
// it ends on. With alpha = 0 a symmetric cycle between the peaks +-d_m dissipates the
// parallelogram 2 F_m d_0, F_m = S(d_m), d_0 = d_m - F_m / k.
//
// Units: k [F/L] (or [F L/rad]), F_y [F], delta [L] (or rad), b and alpha [-]; 0 <= b < 1,
// 0 <= alpha < 1.
#include "links/takeda.hpp"

namespace pound::links {

class Clough final : public LinkLaw {
 public:
  Clough(double stiffness, double yield_force, double hardening_ratio,
         double unloading_exponent = 0.0);

  std::string name() const override { return "clough"; }
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Clough>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override { return law_.set_trial(trial); }
  void commit() override { law_.commit(); }
  void revert() override { law_.revert(); }
  bool in_contact() const override { return law_.in_contact(); }
  std::optional<double> yield_deformation() const override { return law_.yield_deformation(); }
  std::optional<double> stored_energy(double force, double deformation) const override {
    return law_.stored_energy(force, deformation);
  }

  double peak(int side) const { return law_.peak(side); }

 private:
  Takeda law_;
};

}  // namespace pound::links
