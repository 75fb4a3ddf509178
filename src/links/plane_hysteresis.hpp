#pragma once
// The hysteresis of a shear in the plane across a link's axis (links/coupled_shear.hpp): what
// each coupled law gives for a deformation vector s of that plane, in direction 1's units (the
// CoupledShear scales an ellipse to a circle around it). One implementation per law:
// links/plane_bilinear.hpp (the radial return of a bilinear spring) and links/plane_bouc_wen.hpp
// (the Bouc-Wen law); `make_plane_hysteresis` picks it from the numbers.
#include <array>
#include <cmath>
#include <memory>
#include <optional>

#include "links/coulomb_friction.hpp"

namespace pound::links {

// A Bouc-Wen law's shape (links/bouc_wen.hpp): n, beta, gamma, A, with beta and gamma as the law
// uses them (after a `yield_force` has scaled them).
struct SmoothShape {
  double sharpness = 1.0;  // n [-]
  double beta = 0.0;       // [1/L^n]
  double gamma = 0.0;      // [1/L^n]
  double amplitude = 1.0;  // A [-]
  bool operator==(const SmoothShape&) const = default;
};

// One direction's numbers. A bilinear law: k, F_y, b. A Bouc-Wen law: k, a (as b) and its shape,
// with F_y = k z_max / A, the equivalent bilinear yield force (so that F_y / k is its
// yield_deformation).
struct ShearNumbers {
  double stiffness = 0.0;        // k
  double yield_force = 0.0;      // F_y (infinite: elastic)
  double hardening_ratio = 0.0;  // b
  std::optional<SmoothShape> smooth;

  bool yields() const { return std::isfinite(yield_force); }
  double yield_deformation() const { return yield_force / stiffness; }  // delta_y = F_y / k
  // The slope at rest: k, or k (a + (1 - a) A) for a Bouc-Wen law.
  double initial_stiffness() const {
    return smooth ? stiffness * (hardening_ratio + (1.0 - hardening_ratio) * smooth->amplitude)
                  : stiffness;
  }
  // The elastic energy a direction holds at force F and deformation s, as its uniaxial law's
  // (LinkLaw::stored_energy): F^2 / 2k + H p^2 / 2 (H = b k / (1 - b), p = s - F / k) of a
  // bilinear one, a k s^2 / 2 + F_h^2 / (2 (1 - a) k A) (F_h = F - a k s) of a Bouc-Wen one.
  // Summed over the directions, it is the plane law's: both are quadratic forms in them.
  double stored_energy(double force, double deformation) const {
    return smooth ? bouc_wen_stored_energy(stiffness, hardening_ratio, smooth->amplitude, force,
                                           deformation)
                  : bilinear_stored_energy(stiffness,
                                           hardening_ratio / (1.0 - hardening_ratio) * stiffness,
                                           force, deformation);
  }
  bool operator==(const ShearNumbers&) const = default;
};
// Along t_1 and t_2 (equal: a circular surface).
using ShearDirections = std::array<ShearNumbers, kMaxTangents>;

// The force along each tangent and its derivative [a][b] = dF_a / ds_b.
struct PlaneResponse {
  Tangential force{};
  std::array<Tangential, kMaxTangents> tangent{};
};

class PlaneHysteresis {
 public:
  virtual ~PlaneHysteresis() = default;
  virtual std::unique_ptr<PlaneHysteresis> clone() const = 0;
  // The response at the trial deformation (entries past `tangents` are 0).
  virtual PlaneResponse set_trial(const Tangential& deformation) = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;
  // The committed deformation that does not spring back: p of the bilinear law, s - z / A of
  // the Bouc-Wen law (its z being the hysteretic spring's own deformation).
  virtual Tangential plastic_deformation() const = 0;
};

// The hysteresis of direction 1's numbers on `tangents` (1 or 2) axes.
std::unique_ptr<PlaneHysteresis> make_plane_hysteresis(const ShearNumbers& numbers, int tangents);

}  // namespace pound::links
