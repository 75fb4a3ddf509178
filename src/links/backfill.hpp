#pragma once
// Abutment backfill: the passive resistance of the soil behind an abutment backwall, pushed once
// the expansion joint (the link's gap, already in delta) has closed. Compression only, with the
// hyperbolic force-displacement (HFD) backbone of Shamsabadi et al. (2007, 2010):
//
//   F_env(delta) = K delta / (1 + D delta)   for 0 <= delta <= delta_ult
//   F_env(delta) = F_ult                     beyond (perfectly plastic)
//   D = K / F_ult - 1 / delta_ult            so that F_env(delta_ult) = F_ult; D > 0 needs
//                                            F_ult / K < delta_ult (else no softening hyperbola)
//
// slope K at delta = 0 and K / (1 + D delta)^2 on the hyperbola. This is Duncan & Mokwa's
// F = delta / (1/K + R_f delta / F_ult) with the failure ratio R_f = 1 - F_ult / (K delta_ult).
//
// Unloading and reloading follow the initial stiffness K from the largest force reached, and
// the soil does not pull:
//
//   F = max(0, min(K (delta - p), F_env(delta)))
//   p = delta_max - F_env(delta_max) / K      the permanent soil deformation (history)
//
// so unloading opens a gap of p: on reloading the wall meets the soil again at delta = p and
// rejoins the backbone at delta_max. Consistent tangent K, F_env' or 0 (plateau, open).
//
// With a stem stiffness k_s the wall is held toward the span too, where the girder last pushed
// it: F = k_s (delta - p) (negative) for delta < p, p = 0 until the soil yields. A backwall is
// cast on the abutment's stem and moves with it until the girder pushes it into the soil, and a
// wall pushed in stays there (wedged in the yielded soil, on its seat); without the stem it hangs
// free on the span's side, and under shaking alone a backwall's mass drifts across the joint's
// gap before any girder reaches it (relative coordinates: nothing carries it with the ground),
// or rattles in the gap p the soil left. A backwall's own flexural stiffness, 3 E I / h^3 of a 1.7
// m high, 0.3 m thick wall per metre of width, is 4e7 N/m/m, of the order of K (Caltrans: 28.7
// MN/m/m).
//
// Units: K [F/L], F_ult [F], delta_ult and delta [L]. Typical numbers (per metre of backwall
// width): Caltrans SDC v1.7 (2013, sec. 7.8.1) K_i = 28.7 kN/mm/m (50 kip/in/ft) and an
// ultimate passive pressure of 239 kPa (5.0 ksf), both for a 1.7 m (5.5 ft) backwall and scaled
// by h / 1.7 m; Shamsabadi et al. (2007): F_ult mobilised at about 0.05 h for granular and
// 0.1 h for cohesive backfill; OpenSees HyperbolicGapMaterial (Wilson & Elgamal, 1.68 m
// backwall): K_max = 20,300 kN/m and F_ult = 326 kN per metre of width.
#include "links/link_law.hpp"

namespace pound::links {

class Backfill final : public LinkLaw {
 public:
  // Throws std::invalid_argument unless all are positive (the stem's >= 0, 0: no stem) and
  // hyperbola_curvature(...) > 0.
  Backfill(double initial_stiffness, double ultimate_force, double ultimate_deformation,
           double stem_stiffness = 0.0);

  // D = K / F_ult - 1 / delta_ult; the backbone exists only for D > 0.
  static double hyperbola_curvature(double initial_stiffness, double ultimate_force,
                                    double ultimate_deformation) {
    return initial_stiffness / ultimate_force - 1.0 / ultimate_deformation;
  }

  std::string name() const override { return "backfill"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<Backfill>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  bool in_contact() const override { return committed_contact_; }  // pushing the soil

  // The backbone F_env and its slope at delta (0 for delta <= 0).
  LawResponse envelope(double penetration) const;
  double permanent_deformation() const override { return committed_permanent_; }

 private:
  double stiffness_, ultimate_force_, ultimate_deformation_, curvature_, stem_stiffness_;
  double committed_permanent_ = 0.0, trial_permanent_ = 0.0;
  bool committed_contact_ = false, trial_contact_ = false;
};

}  // namespace pound::links
