#pragma once
// BilinearSpring's law (links/bilinear_spring.hpp) with vectors for scalars, on a circle in the
// units of direction 1 (links/coupled_shear.hpp scales an ellipse to it):
//
//   F = k (s - p)                           p: plastic deformation (a vector, history)
//   yield surface |F - alpha| <= F_y        alpha = H p: the back-force, H = b k / (1 - b)
//   flow along F - alpha                    (associated: the radial return)
//
// Return mapping from the committed (p, alpha) (Simo & Hughes 1998, Computational Inelasticity,
// §2.3.2, in two dimensions): the elastic trial xi = k (s - p_n) - alpha_n exceeding F_y moves p
// by dgamma = (|xi| - F_y) / (k + H) along e = xi / |xi|; consistent tangent
//
//   dF/ds = k I - k^2 / (k + H) e e^T - k^2 dgamma / |xi| (I - e e^T)
//
// (k I while elastic). With one tangent (a plane scene) it is BilinearSpring's law to the bit.
// Uncoupled springs along x and y yield a diagonal motion at sqrt(2) F_y; this one yields at F_y
// whatever the direction. Driven steadily around a circle of radius r > delta_y = F_y / k
// (b = 0) its plastic deformation trails the motion by asin(delta_y / r), the force |F| = F_y
// points along that slip, and each turn dissipates 2 pi F_y sqrt(r^2 - delta_y^2). Units: k
// [F/L], F_y [F], b [-] in [0, 1), s and p [L] (a hinge's: k [F L/rad], F_y [F L], rad).
#include "links/plane_hysteresis.hpp"

namespace pound::links {

class PlaneBilinear final : public PlaneHysteresis {
 public:
  PlaneBilinear(const ShearNumbers& numbers, int tangents);
  std::unique_ptr<PlaneHysteresis> clone() const override;
  PlaneResponse set_trial(const Tangential& deformation) override;
  void commit() override { committed_plastic_ = trial_plastic_; }
  void revert() override { trial_plastic_ = committed_plastic_; }
  Tangential plastic_deformation() const override { return committed_plastic_; }

 private:
  // The elastic trial force k (s - p_n) and xi = that - H p_n along each tangent; returns |xi|.
  double elastic_trial(const Tangential& deformation, Tangential& relative,
                       PlaneResponse& out) const;
  // The radial return of a trial past the yield circle, with its consistent tangent.
  void return_to_circle(const Tangential& relative, double length, PlaneResponse& out);

  ShearNumbers numbers_;
  double hardening_modulus_;  // H
  int tangents_;
  Tangential committed_plastic_{}, trial_plastic_{};
};

}  // namespace pound::links
