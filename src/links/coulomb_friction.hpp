#pragma once
// Coulomb friction on a link that has a tangential direction (2-D links), after Suzuki & Toi
// (1987, eqs. 14-16): while sticking, the tangential force is a penalty of the same form as the
// normal one; while slipping it is mu times the normal force, against the relative tangential
// velocity.
//
//   tangential deformation  s = (u_i - u_j) . t,  t = n rotated by +90 degrees
//   stick:  R_t = k_t (s - s_0) + c_t s_dot + m_t s_ddot     (s_0: where sticking began)
//   slip:   R_t = mu R_n sign(s_dot)    when |R_t(stick)| > mu R_n
//
// R_n >= 0 comes from the normal law; without contact R_t = 0. Equal static and kinetic mu.
// Signs as for the normal force: R_t > 0 pushes node i back along -t. Units: k_t [F/L],
// c_t [F T/L], m_t [M], mu [-]. After a slip the anchor s_0 moves so that sticking resumes
// without a jump. The consistent tangent couples R_t to the normal quantities while slipping
// (dR_t/d delta = mu sign dR_n/d delta), so it is not symmetric.
#include <memory>

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
  CoulombFriction(std::unique_ptr<LinkLaw> normal, double coefficient, StickPenalty stick);
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
  double coefficient() const { return coefficient_; }
  bool slipping() const { return committed_slip_; }

 private:
  std::unique_ptr<LinkLaw> normal_;
  double coefficient_;
  StickPenalty stick_;
  double committed_anchor_ = 0.0, trial_anchor_ = 0.0;
  bool committed_slip_ = false, trial_slip_ = false;
  double committed_slide_ = 0.0;  // s at the last commit, the anchor when contact begins
  double trial_slide_ = 0.0;
};

}  // namespace pound::links
