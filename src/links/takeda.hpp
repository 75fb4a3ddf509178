#pragma once
// Modified Takeda hysteresis for reinforced-concrete members (a pier or column plastic hinge as a
// zero-length link, delta a displacement or a rotation): Takeda, Sozen & Nielsen (1970), J.
// Struct. Div. ASCE 96(ST12), with the unloading stiffness of Otani (1974, 1981) and the
// reloading factor beta of Ruaumoko's "modified Takeda" (Carr). Symmetric: the same skeleton in
// both directions, F > 0 with delta > 0.
//
// Skeleton S (trilinear; bilinear when no cracking point is given: F_c = F_y, d_c = d_y = F_y/k0):
//   |d| <= d_c:         F = k0 d                                 d_c = F_c / k0
//   d_c < |d| <= d_y:   F = sign(d) (F_c + k1 (|d| - d_c))        k1 = (F_y - F_c) / (d_y - d_c)
//   |d| > d_y:          F = sign(d) (F_y + r k_y (|d| - d_y))     k_y = F_y / d_y (secant)
// with F_c < F_y, d_y > F_y / k0 (so k1 < k0) and r k_y <= k1 (the skeleton is concave: every
// reloading line below stays inside it).
//
// Memory: the peak d_p of each side (largest |delta| reached there, d_c at the start: an
// uncracked side's "peak" is its cracking point); a side has cracked once d_p > d_c and yielded
// once d_p > d_y. The branch the state is on: the skeleton, a reloading line, or an unloading
// line with its departure point and the outer branch (skeleton or reloading line) it left.
//
// Rules (s = +1 or -1 the side, all |.| on that side):
//  1. Skeleton: loading away from zero on the skeleton follows S and raises the peak. Before any
//     cracking this is the elastic line k0 both ways.
//  2. Unloading: a reversal at a point T = (d_T, F_T) on the skeleton or on a reloading line
//     (F_T of sign s) unloads on a straight line of slope k_u from T, as long as F keeps the
//     sign of F_T:
//       side s uncracked:              k_u = k0;
//       cracked, not yielded:          k_u = (S(d_p) + F_c) / (d_p + d_c), the line from the
//                                      peak aims at the cracking point of the other side
//                                      (Takeda's rule before yield);
//       yielded:                       k_u = k_y (d_y / d_p)^alpha (Otani; alpha = 0.4 in
//                                      Takeda et al. 1970);
//     and never softer than the secant F_T / d_T to the origin when T is on the skeleton, nor
//     than the reloading line T is on: so unloading reaches zero force at d_0 = d_T - F_T / k_u
//     between the origin (or the start of that reloading line) and T. With the usual numbers
//     (r small) the secant never governs. (A secant to the origin from a reloading line would
//     be unbounded near d = 0; OpenSees' Hysteretic unloads there at the elastic slope too.)
//  3. Inner loops: an unloading line reversed before zero force retraces itself back to its
//     departure point T (the point where it left the outer curve) and then continues on the
//     outer branch T was on (skeleton, or the reloading line toward its target). Small cycles
//     inside it dissipate nothing.
//  4. Crossing zero force: at d_0 the path turns into a reloading line from (d_0, 0) straight
//     to a target on the skeleton of the other side s' = -s, then follows the skeleton (rule 1):
//       s' yielded:                    the skeleton point at |d| = d_p' - beta (d_p' - d_y),
//                                      beta times the peak's plastic part back toward the yield
//                                      point (beta = 0: the previous peak); if d_0 is not short
//                                      of that point (an inner excursion that crossed zero
//                                      inside it), the previous peak itself;
//       s' not yielded, s yielded:     the yield point (s' d_y, s' F_y);
//       neither yielded:               the peak of s' (its cracking point if uncracked, so an
//                                      unloading from a cracked peak runs straight through zero
//                                      force to the opposite cracking point).
//     A reloading line reversed unloads by rule 2; reversed exactly at its start (zero force),
//     it reloads toward the other side by rule 4.
// Every branch is a straight line or the skeleton, so the force is piecewise linear in delta;
// a trial walks from the committed state to the trial delta through every branch point on the
// way, and its tangent is the slope of the branch it ends on.
//
// Units: k0 [F/L] (or [F L/rad] for a rotation), F_c and F_y [F], d_y and delta [L] (or rad),
// r, alpha, beta [-]; 0 <= r < 1, 0 <= alpha < 1, 0 <= beta <= 1.
#include "links/link_law.hpp"

namespace pound::links {

class Takeda final : public LinkLaw {
 public:
  struct Parameters {
    double stiffness = 0.0;           // k0
    double cracking_force = 0.0;      // F_c; 0: bilinear skeleton (no cracking point)
    double yield_force = 0.0;         // F_y
    double yield_deformation = 0.0;   // d_y; ignored (F_y / k0) for a bilinear skeleton
    double hardening_ratio = 0.0;     // r
    double unloading_exponent = 0.4;  // alpha
    double reloading_factor = 0.0;    // beta
  };

  // Throws std::invalid_argument for numbers outside the rules above (the factory reports them
  // as input errors first).
  explicit Takeda(const Parameters& parameters);

  std::string name() const override { return "takeda"; }
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Takeda>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_ = trial_; }
  void revert() override { trial_ = committed_; }
  bool in_contact() const override { return committed_.force != 0.0; }
  std::optional<double> yield_deformation() const override { return yield_deformation_; }
  // F^2 / 2k_u, k_u the slope it would unload on from its committed state (degraded past yield).
  std::optional<double> stored_energy(double force, double deformation) const override;

  // The skeleton S(d) and its slope on the segment of d (an end point belongs to the inner one).
  double skeleton_force(double deformation) const;
  double skeleton_slope(double deformation) const;
  // Largest |delta| reached on the positive and negative sides (committed).
  double peak(int side) const { return committed_.peak[index(side)]; }

 private:
  enum class Branch { skeleton, reloading, unloading };
  // A reloading line from (start, 0) to the skeleton point (target, target_force).
  struct Line {
    double start = 0.0, target = 0.0, target_force = 0.0;
    double slope() const { return target_force / (target - start); }
  };
  struct State {
    double deformation = 0.0, force = 0.0, slope = 0.0;
    double peak[2] = {0.0, 0.0};  // + side, - side
    Branch branch = Branch::reloading;
    Line line;                       // the reloading line (also while unloading from it)
    bool departed_skeleton = false;  // while unloading: the outer branch was the skeleton
    double departure = 0.0, departure_force = 0.0, unloading_slope = 0.0;
  };

  static int index(int side) { return side > 0 ? 0 : 1; }
  // One move of `state` toward `goal`: along its branch to `goal` or to the branch's end.
  void advance(State& state, double goal) const;
  void along_skeleton(State& state, double goal, int direction) const;
  void along_line(State& state, double goal, int direction) const;
  void along_unloading(State& state, double goal, int direction) const;
  void start_unloading(State& state) const;
  Line reloading_line(const State& state, double start, int side) const;
  double unloading_stiffness(const State& state, int side) const;

  double k0_, cracking_force_, cracking_deformation_, yield_force_, yield_deformation_;
  double cracked_slope_, post_yield_slope_, alpha_, beta_;
  State committed_, trial_;
};

}  // namespace pound::links
