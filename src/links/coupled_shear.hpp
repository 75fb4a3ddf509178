#pragma once
// A bearing's shear in the plane across its axis, its two directions coupled: a circular yield
// surface (an isotropic elastomeric or lead-rubber bearing, or a bilinear bearing, in space). It
// acts on a link's tangential rows (links/coulomb_friction.hpp's tangents t_1, t_2 of its axis),
// beside the link's own law on its normal row (the bearing's axial stiffness):
//
//   s = (u_i - u_j) . t_a                   (a vector of the plane; a = 1, 2)
//   F = k (s - p)                           p: plastic deformation (a vector, history)
//   yield surface |F - alpha| <= F_y        alpha = H p: the back-force, H = b k / (1 - b)
//   flow along F - alpha                    (associated: the radial return)
//
// which is BilinearSpring's law (links/bilinear_spring.hpp) with vectors for scalars. Return
// mapping from the committed (p, alpha) (Simo & Hughes 1998, Computational Inelasticity, §2.3.2,
// in two dimensions): the elastic trial xi = k (s - p_n) - alpha_n exceeding F_y moves p by
// dgamma = (|xi| - F_y) / (k + H) along e = xi / |xi|; consistent tangent
//
//   dF/ds = k I - k^2 / (k + H) e e^T - k^2 dgamma / |xi| (I - e e^T)
//
// (k I while elastic). With one tangent (a plane scene) it is BilinearSpring's law to the bit.
// Uncoupled springs along x and y yield a diagonal motion at sqrt(2) F_y; this one yields at F_y
// whatever the direction. Driven steadily around a circle of radius r > delta_y = F_y / k
// (b = 0) its plastic deformation trails the motion by asin(delta_y / r), the force |F| = F_y
// points along that slip, and each turn dissipates 2 pi F_y sqrt(r^2 - delta_y^2) (what the
// tests check).
//
// Made from a uniaxial law's numbers: bilinear_spring, lead_rubber and elastic_perfectly_plastic
// (BilinearSpring objects), or elastic_spring (F_y infinite: k I). Shear and axial are not
// coupled (no axial-load-dependent strength, no P-Delta of the bearing). Units: k [F/L], F_y [F],
// b [-] in [0, 1), s and p [L].
#include <cmath>
#include <memory>
#include <optional>
#include <span>

#include "links/coulomb_friction.hpp"
#include "links/link_law.hpp"

namespace pound::links {

struct ShearNumbers {
  double stiffness = 0.0;        // k
  double yield_force = 0.0;      // F_y (infinite: elastic)
  double hardening_ratio = 0.0;  // b

  bool yields() const { return std::isfinite(yield_force); }
  double yield_deformation() const { return yield_force / stiffness; }  // delta_y = F_y / k
};

struct LawSpec;
struct LawSource;

class CoupledShear {
 public:
  // The laws that have the coupled form, for messages and docs.
  static constexpr const char* kLaws =
      "bilinear_spring, lead_rubber, elastic_perfectly_plastic or elastic_spring";
  // The numbers of a uniaxial law that has a coupled form (see above); none for the others.
  static std::optional<ShearNumbers> numbers_of(const LinkLaw& law);
  static std::optional<ShearNumbers> numbers_of(const LawSpec& law, const LawSource& where);

  // normal: the link's law on its normal row; tangents: 1 (a plane) or 2 (space).
  CoupledShear(std::unique_ptr<LinkLaw> normal, ShearNumbers numbers, int tangents);
  CoupledShear(const CoupledShear& other);
  CoupledShear& operator=(const CoupledShear&) = delete;

  // The normal law's response, and the shear's along each tangent (s_a alone: no rate terms).
  FrictionResponse set_trial(const LinkKinematics& normal,
                             std::span<const LinkKinematics> tangential);
  void commit();
  void revert();
  int tangents() const { return tangents_; }
  const LinkLaw& normal_law() const { return *normal_; }
  const ShearNumbers& numbers() const { return numbers_; }
  const Tangential& plastic_deformation() const { return committed_plastic_; }

 private:
  // The elastic trial force k (s - p_n) and xi = that - H p_n along each tangent; returns |xi|.
  double elastic_trial(std::span<const LinkKinematics> tangential, Tangential& relative,
                       FrictionResponse& out) const;
  // The radial return of a trial past the yield circle, with its consistent tangent.
  void return_to_circle(const Tangential& relative, double length, FrictionResponse& out);

  std::unique_ptr<LinkLaw> normal_;
  ShearNumbers numbers_;
  double hardening_modulus_;  // H
  int tangents_;
  Tangential committed_plastic_{}, trial_plastic_{};
};

}  // namespace pound::links
