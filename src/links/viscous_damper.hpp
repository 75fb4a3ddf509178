#pragma once
// Fluid viscous damper: a damper across an expansion joint, between a deck and an abutment or
// between adjacent buildings, used as a link with gap 0 (Constantinou & Symans 1993; the
// nonlinear damper of Caltrans and of OpenSees' ViscousDamper material without its spring):
//
//   F = c |d'|^alpha sign(d')          for |d'| >= v_l     (d' = d(delta)/dt)
//   F = c v_l^(alpha - 1) d'           for |d'| <  v_l
//
// alpha = 1 is a linear dashpot; alpha < 1 (0.3 to 0.5 for seismic dampers) limits the force at
// high velocity. Below v_l the force is linear, so that the tangent c alpha |d'|^(alpha - 1),
// infinite at rest, stays finite and Newton converges (the force is continuous at v_l, the
// tangent jumps by the factor alpha). v_l near 1 % of the expected peak speed keeps Newton's
// iteration converging (at 0.1 % the steep tangent near rest cost 5 % of the steps a cut on the
// two-girder example). F > 0 in compression (the link closing), < 0 opening.
// A cycle d = X sin(w t) dissipates c w^alpha X^(1 + alpha) 2^(2 + alpha) G(1 + alpha/2)^2 /
// G(2 + alpha) (G: the gamma function; pi c w X^2 when alpha = 1), v_l << w X.
// Units: c [F (T/L)^alpha], alpha [-], v_l [L/T]. No history.
#include "links/link_law.hpp"

namespace pound::links {

class ViscousDamper final : public LinkLaw {
 public:
  ViscousDamper(double coefficient, double exponent, double linear_velocity);

  std::string name() const override { return "viscous_damper"; }
  // Its registry entry: parameters, traits, factory (links/law_registry.hpp).
  static const LawEntry& entry();
  std::unique_ptr<LinkLaw> clone() const override { return std::make_unique<ViscousDamper>(*this); }
  LawResponse set_trial(const LinkKinematics& trial) override;
  void commit() override { committed_loaded_ = trial_loaded_; }
  void revert() override { trial_loaded_ = committed_loaded_; }
  // "In contact" means it carries a force (it moves).
  bool in_contact() const override { return committed_loaded_; }

 private:
  double coefficient_, exponent_, linear_velocity_;
  bool trial_loaded_ = false, committed_loaded_ = false;
};

}  // namespace pound::links
