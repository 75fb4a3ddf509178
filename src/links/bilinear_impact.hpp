#pragma once
// Bilinear impact law (Muthukumar 2003; OpenSees ImpactMaterial): a compression-only hysteretic
// loop between two parallel lines of slope K2,
//   upper F_u(delta) = K1 delta_y + K2 (delta - delta_y),   lower F_l(delta) = K2 delta,
// moving with slope K1 in between (compression positive, F = 0 while delta <= 0). One cycle to
// delta_m dissipates (K1 - K2) delta_y (delta_m - delta_y).
//
// Calibration from a target restitution e (at every impact, from the approach velocity v0 at
// first contact and the effective mass): with K_eff = k_h sqrt(delta_m), delta_y = a delta_m
// (a = 0.1), K1 = K_eff + dE / (a delta_m^2), K2 = K_eff - dE / ((1 - a) delta_m^2), the loading
// work is 1/2 K_eff delta_m^2 + 1/2 dE and the peak force k_h delta_m^1.5 (Hertz). Asking the loop
// to dissipate dE = (1 - e^2) 1/2 m_eff v0^2 and the loading work to absorb 1/2 m_eff v0^2 gives
//   delta_m = (m_eff v0^2 (1 + e^2) / (2 k_h))^0.4,
// so the actual penetration is delta_m and the restitution of a two-mass impact is e exactly.
// (Muthukumar's dE = k_h delta_m^2.5 (1 - e^2)/2.5 with the elastic-Hertz delta_m under-dissipates,
// e ~ 0.76 for a target 0.65.) Alternatively K1, K2, delta_y are given and used as they are.
// Units: K1, K2 [F/L], k_h [F/L^1.5], delta [L].
#include <optional>

#include "links/impact_onset.hpp"
#include "links/link_law.hpp"

namespace pound::links {

class BilinearImpact final : public LinkLaw {
 public:
  struct Calibration {            // from e at each impact
    double hertz_stiffness;       // k_h
    double restitution;           // e
    double effective_mass;        // m_eff
    double yield_fraction = 0.1;  // a = delta_y / delta_m
  };
  struct Loop {
    double k1, k2, yield_penetration;
  };
  explicit BilinearImpact(Calibration calibration);
  explicit BilinearImpact(Loop loop);

  std::string name() const override { return "bilinear_impact"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override {
    return std::make_unique<BilinearImpact>(*this);
  }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override;
  void revert() override;
  bool in_contact() const override { return onset_.in_contact(); }

  // The loop calibrated for an impact at v0 (with dK/dv0), and whether e is reachable with a:
  // K2 > 0 needs (1 - e^2) / (1 + e^2) < 1 - a.
  struct Calibrated {
    Loop loop;
    Loop d_velocity;  // derivatives of k1, k2, delta_y with respect to v0
  };
  static Calibrated calibrate(const Calibration& c, double velocity);
  const Loop& loop() const { return committed_loop_; }

 private:
  std::optional<Calibration> calibration_;
  Loop committed_loop_{}, trial_loop_{};
  ImpactOnset onset_;
  LinkKinematics trial_;
  double committed_force_ = 0.0, trial_force_ = 0.0;
};

}  // namespace pound::links
