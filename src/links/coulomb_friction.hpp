#pragma once
// Coulomb friction on a link that has a tangential direction (2-D links), after Suzuki & Toi
// (1987, eqs. 14-16): while sticking, the tangential force is a penalty of the same form as the
// normal one; while slipping it is mu times the normal force, against the relative tangential
// velocity. With a radius R the link is a friction pendulum bearing (Zayas, Low & Mahin 1990,
// "A simple pendulum technique for achieving seismic isolation", Earthquake Spectra 6(2)
// 317-333): the slider on a concave dish of radius R is pushed back towards the dish's centre by
// the vertical load, a restoring force R_n s / R on top of the friction.
//
//   tangential deformation  s = (u_i - u_j) . t,  t = n rotated by +90 degrees
//   R_t = R_n s / R + F_c                        (R_n s / R only with a radius; flat: F_c alone)
//   stick:  F_c = k_t (s - s_0) + c_t s_dot + m_t s_ddot     (s_0: where sticking began)
//   slip:   F_c = mu R_n sign(s_dot)    when |F_c(stick)| > mu R_n
//
// R_n >= 0 comes from the normal law; without contact R_t = 0. Equal static and kinetic mu.
// Signs as for the normal force: R_t > 0 pushes node i back along -t, so R_n s / R pulls node i
// back to s = 0 (the dish's centre is where the link stands at t = 0). Units: k_t [F/L],
// c_t [F T/L], m_t [M], mu [-], R [L]. After a slip the anchor s_0 moves so that sticking
// resumes without a jump. The consistent tangent couples R_t to the normal quantities,
//   dR_t/d(delta, delta_dot, delta_ddot) = (s / R + mu sign [slipping]) dR_n/d(same),
//   dR_t/ds = R_n / R + k_t [sticking],
// so it is not symmetric. The pendulum is the small-displacement form (Zayas et al.'s
// F = (W / R) D + mu W sgn(D_dot)): the slider's rise s^2 / (2 R) is not modelled, so R should
// be large against the displacement (R >> s, as in every real bearing). The radius is a member
// of this class, not a law of its own, because the restoring part needs R_n and s exactly where
// the Coulomb part has them, and a flat slider is the same law with R -> infinity.
//
// On a hard contact (links/hard_contact.hpp) the friction is a constraint as well, with no stick
// penalty: the integrator finds R_t with R_n, sticking (no slide over the step) while
// |R_t| <= mu R_n and slipping at R_t = mu R_n against the slide otherwise, and imposes both
// (impose_tangential); set_trial then returns the imposed forces with no tangents.
#include <memory>
#include <optional>

#include "links/link_law.hpp"

namespace pound::links {

struct StickPenalty {
  double stiffness = 0.0;  // k_t
  double damping = 0.0;    // c_t
  double mass = 0.0;       // m_t
};

struct FrictionResponse {
  LawResponse normal;                // R_n and its tangents in the normal quantities
  double tangential_force = 0.0;     // R_t
  LawResponse tangential_on_normal;  // dR_t / d(delta, delta_dot, delta_ddot) (force unused)
  LawResponse tangential_on_slip;    // dR_t / d(s, s_dot, s_ddot) (force unused)
  bool slipping = false;
};

class CoulombFriction {
 public:
  // radius: the friction pendulum's effective radius of curvature R > 0; none: a flat slider.
  CoulombFriction(std::unique_ptr<LinkLaw> normal, double coefficient, StickPenalty stick,
                  std::optional<double> radius = std::nullopt);
  CoulombFriction(const CoulombFriction& other);
  CoulombFriction& operator=(const CoulombFriction&) = delete;

  FrictionResponse set_trial(const LinkKinematics& normal, const LinkKinematics& tangential);
  void commit();
  void revert();
  // After a static solve in which the surfaces slid (a belt moving under a held block), moves
  // the committed anchor so that at rest the stick force equals `tangential_force`: the
  // dynamics then starts from that friction force without the jump the stick dashpot would make.
  void anchor_at_rest(double tangential_force);

  const LinkLaw& normal_law() const { return *normal_; }
  // The normal law's hard contact, when it is one: then R_t is imposed, not computed.
  HardContact* hard_contact() { return hard_; }
  // The tangential force the integrator found for the trial state, and whether it slips.
  void impose_tangential(double force, bool slipping) {
    trial_tangential_force_ = force;
    trial_slip_ = slipping;
  }
  double coefficient() const { return coefficient_; }
  bool slipping() const { return committed_slip_; }

 private:
  // F_c and its tangents (the flat slider).
  FrictionResponse coulomb(const LinkKinematics& normal, const LinkKinematics& tangential);
  // R_n and R_t as imposed, for the hard contact.
  FrictionResponse imposed(const LinkKinematics& normal, const LinkKinematics& tangential);
  // The pendulum's R_n s / R, added to a response in contact.
  void add_restoring(const LinkKinematics& tangential, FrictionResponse& response) const;

  std::unique_ptr<LinkLaw> normal_;
  double coefficient_;
  StickPenalty stick_;
  std::optional<double> radius_;
  HardContact* hard_;                                                       // normal_'s, or none
  double committed_tangential_force_ = 0.0, trial_tangential_force_ = 0.0;  // imposed (hard_)
  double committed_anchor_ = 0.0, trial_anchor_ = 0.0;
  bool committed_slip_ = false, trial_slip_ = false;
  double committed_slide_ = 0.0;  // s at the last commit, the anchor when contact begins
  double trial_slide_ = 0.0;
  // R_n at the last commit: anchor_at_rest takes the pendulum's part out of a static force.
  double committed_normal_force_ = 0.0, trial_normal_force_ = 0.0;
};

}  // namespace pound::links
