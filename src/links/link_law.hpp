#pragma once
// The force-deformation law of a link, in OpenSees' trial -> commit / revert protocol: a law is
// given a trial deformation (any number of times within a step), answers with its force and
// tangents, and is told at the end of the step whether the trial became the committed state.
//
// Sign convention, shared by every law: the deformation is the penetration
//   delta = (u_i - u_j) . n - gap
// along the unit axis n from node i to node j (contact while delta > 0), and the force F is
// positive in compression (it pushes node i back along -n and node j along +n).
#include <memory>
#include <optional>
#include <string>

namespace pound::links {

struct LawEntry;    // links/law_registry.hpp: what each law is, for readers, writers and docs
class HardContact;  // links/hard_contact.hpp

// Penetration and its rates at the trial state.
struct LinkKinematics {
  double penetration = 0.0;               // delta [L]
  double penetration_rate = 0.0;          // d(delta)/dt [L/T]
  double penetration_acceleration = 0.0;  // d2(delta)/dt2 [L/T^2]
};

// Force and its partial derivatives at the trial state (consistent tangent for Newton).
struct LawResponse {
  double force = 0.0;      // F [F], > 0 compression
  double stiffness = 0.0;  // dF/d(delta) [F/L]
  double damping = 0.0;    // dF/d(delta_dot) [F T/L]
  double mass = 0.0;       // dF/d(delta_ddot) [F T^2/L]
};

// The viscous part of a law's force that stiffness-proportional damping adds to a spring's
// (links/stiffness_damping.hpp), so that its work is not taken for hysteresis.
struct ViscousPart {
  double work = 0.0;   // integral of F_viscous d(delta) up to the committed state [F L]
  double force = 0.0;  // committed F_viscous [F]
};

class LinkLaw {
 public:
  virtual ~LinkLaw() = default;

  virtual std::string name() const = 0;
  // A fresh copy in the committed state of this one (each analysis owns its laws).
  virtual std::unique_ptr<LinkLaw> clone() const = 0;

  virtual LawResponse set_trial(const LinkKinematics& trial) = 0;
  virtual void commit() = 0;
  virtual void revert() = 0;

  // True while the committed state is in contact (for impact counting and recorders).
  virtual bool in_contact() const = 0;

  // The deformation at first yield of a law that yields (a hysteretic spring or hinge), the
  // reference of its ductility demand peak |delta| / delta_y; none for a law that does not yield.
  virtual std::optional<double> yield_deformation() const { return std::nullopt; }
  // The deformation the law keeps at zero force in its committed state: a yielded restrainer's
  // plastic elongation, the backfill soil's permanent deformation; 0 for the others.
  virtual double permanent_deformation() const { return 0.0; }
  // The elastic energy a yielding law holds at force F and deformation delta of its committed
  // history, which its work less the change of it has dissipated [F L]: a bilinear spring's
  // F^2 / 2k plus its hardening's H p^2 / 2 (a lead-rubber bearing's rubber), a degrading law's
  // F^2 / 2k_u on its unloading slope. None: F^2 / 2k0 of its initial stiffness.
  virtual std::optional<double> stored_energy(double /*force*/, double /*deformation*/) const {
    return std::nullopt;
  }
  // How far a tension law opens before it engages (a restrainer's slack): its yield_deformation
  // and ductility are its elongation beyond that. 0 for the others.
  virtual double slack() const { return 0.0; }
  // Zero for every law but one with added stiffness-proportional damping.
  virtual ViscousPart viscous_part() const { return {}; }
  // A hard contact is a constraint whose force the integrator finds; none for a force law.
  virtual HardContact* hard_contact() { return nullptr; }
  virtual bool is_hard_contact() const { return false; }
};

// The elastic energy a bilinear spring with kinematic hardening holds at force F and deformation
// delta: k (delta - p)^2 / 2 + H p^2 / 2 = F^2 / 2k + H p^2 / 2, p = delta - F / k; the parallel
// springs b k and an elastic-perfectly-plastic (1 - b) k hold as much (H = b k / (1 - b)) [F L].
inline double bilinear_stored_energy(double stiffness, double hardening_modulus, double force,
                                     double deformation) {
  const double plastic = deformation - force / stiffness;
  return 0.5 * (force * force / stiffness + hardening_modulus * plastic * plastic);
}

// A Bouc-Wen law's, F = a k delta + F_h: a k delta^2 / 2 and the hysteretic part's
// F_h^2 / (2 (1 - a) k A), on its initial slope (1 - a) k A [F L].
inline double bouc_wen_stored_energy(double stiffness, double hardening_ratio, double amplitude,
                                     double force, double deformation) {
  const double elastic = hardening_ratio * stiffness, hysteretic = force - elastic * deformation;
  return 0.5 * (elastic * deformation * deformation +
                hysteretic * hysteretic / ((1.0 - hardening_ratio) * stiffness * amplitude));
}

}  // namespace pound::links
