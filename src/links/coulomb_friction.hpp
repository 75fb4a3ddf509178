#pragma once
// Coulomb friction on a link that has tangential directions (one in a 2-D scene, two in 3-D),
// after Suzuki & Toi (1987, eqs. 14-16): while sticking, the tangential force is a penalty of the
// same form as the normal one; while slipping it is mu times the normal force, against the
// relative tangential velocity. With a radius R the link is a friction pendulum bearing (Zayas, Low
// & Mahin 1990, "A simple pendulum technique for achieving seismic isolation", Earthquake Spectra
// 6(2) 317-333): the slider on a concave dish of radius R is pushed back towards the dish's centre
// by the vertical load, a restoring force R_n s / R on top of the friction.
//
//   tangential deformation  s = (u_i - u_j) . t,  t = n rotated by +90 degrees
//   R_t = R_n s / R + F_c                        (R_n s / R only with a radius; flat: F_c alone)
//   stick:  F_c = k_t (s - s_0) + c_t s_dot + m_t s_ddot     (s_0: where sticking began)
//   slip:   F_c = mu R_n sign(s_dot)    when |F_c(stick)| > mu R_n
//
// At rest (s_dot = 0) a slip is along the stick force. One turning back is along the stick
// force's held part h = k_t (s - s_0) + c_t s_dot: a contact that slipped at the last commit the
// way h still points keeps slipping that way, though its velocity turned within the step, until
// the stick branch takes it over (the return mapping of elastic-plastic friction, as in OpenSees'
// flatSliderBearing; h leaves out m_t s_ddot, which an explicit step finds from the link forces
// themselves). The force then passes from +mu R_n to -mu R_n through the stick branch, over
// 2 mu R_n / k_t of slide, instead of jumping by 2 mu R_n with the velocity's sign: at that jump
// Newton's iteration cycles without end when a step ends near a reversal (a friction pendulum
// failed so in 2 of 8 copies of a 1e-4 ensemble). One out of a stick whose velocity points h's way
// (h s_dot > 0) slips along h as well, which with one tangent is the velocity's direction.
// Elsewhere the slip opposes the velocity, as Suzuki & Toi's does: under a belt or a contact that
// lands sliding, the velocity is the only direction there is.
//
// With two tangents (t_1, t_2: links of 3-D scenes) s, F_c and s_0 are vectors of the contact
// plane and the limit is a circle (isotropic friction):
//   stick:  F_c = k_t (s - s_0) + c_t s_dot + m_t s_ddot
//   slip:   F_c = mu R_n e,  e = s_dot / |s_dot|   when |F_c(stick)| > mu R_n
// (at rest e = F_c(stick) / |F_c(stick)|; turning back, h . e_last > 0 for the last commit's slip
// direction e_last, or out of a stick with h . s_dot > 0, e = h / |h|), so a block sliding
// obliquely is held back along its own path, not along each tangent separately. Out of a stick
// s_dot is the stick spring's own rocking, not along h in a plane: e = s_dot / |s_dot| there
// would make F_c jump where the stick force crosses the circle (a diagonal pendulum at rest
// failed so). The direction's derivative de/dw = (I - e e^T) / |w| (w = s_dot, h or the stick
// force) enters the tangent; with one tangent it vanishes and the law is the one above to the bit.
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
// |R_t| <= mu R_n and slipping at R_t = mu R_n against the slide otherwise (in a contact plane,
// R_t = mu R_n e along the step's slide e, the same circle), and imposes both
// (impose_tangential); set_trial then returns the imposed forces with no tangents.
#include <array>
#include <memory>
#include <optional>
#include <span>

#include "links/link_law.hpp"

namespace pound::links {

struct StickPenalty {
  double stiffness = 0.0;  // k_t
  double damping = 0.0;    // c_t
  double mass = 0.0;       // m_t
};

// Tangential directions of a link: one in a plane, two in space.
inline constexpr int kMaxTangents = 2;
using Tangential = std::array<double, kMaxTangents>;

struct FrictionResponse {
  LawResponse normal;             // R_n and its tangents in the normal quantities
  Tangential tangential_force{};  // R_t along each tangent
  // dR_t,a / d(delta, delta_dot, delta_ddot) (force unused)
  std::array<LawResponse, kMaxTangents> tangential_on_normal{};
  // [a][b]: dR_t,a / d(s_b, s_b_dot, s_b_ddot) (force unused)
  std::array<std::array<LawResponse, kMaxTangents>, kMaxTangents> tangential_on_slip{};
  bool slipping = false;
};

class CoulombFriction {
 public:
  // radius: the friction pendulum's effective radius of curvature R > 0; none: a flat slider.
  // tangents: 1 (a plane scene) or 2 (a 3-D scene's contact plane).
  CoulombFriction(std::unique_ptr<LinkLaw> normal, double coefficient, StickPenalty stick,
                  std::optional<double> radius = std::nullopt, int tangents = 1);
  CoulombFriction(const CoulombFriction& other);
  CoulombFriction& operator=(const CoulombFriction&) = delete;

  // One kinematics per tangent (tangents() of them).
  FrictionResponse set_trial(const LinkKinematics& normal,
                             std::span<const LinkKinematics> tangential);
  FrictionResponse set_trial(const LinkKinematics& normal, const LinkKinematics& tangential) {
    return set_trial(normal, std::span<const LinkKinematics>(&tangential, 1));
  }
  void commit();
  void revert();
  // After a static solve in which the surfaces slid (a belt moving under a held block), moves
  // the committed anchor so that at rest the stick force equals `tangential_force`: the
  // dynamics then starts from that friction force without the jump the stick dashpot would make.
  void anchor_at_rest(std::span<const double> tangential_force);
  int tangents() const { return tangents_; }

  const LinkLaw& normal_law() const { return *normal_; }
  // The normal law's hard contact, when it is one: then R_t is imposed, not computed.
  HardContact* hard_contact() { return hard_; }
  // The tangential force along tangent `tangent` (0 or 1) the integrator found for the trial
  // state, and whether the contact slips (the same for both tangents of a contact plane).
  void impose_tangential(int tangent, double force, bool slipping) {
    trial_tangential_force_[static_cast<std::size_t>(tangent)] = force;
    trial_slip_ = slipping;
  }
  double coefficient() const { return coefficient_; }
  // The pendulum's radius R; none for a flat slider.
  std::optional<double> radius() const { return radius_; }
  const StickPenalty& stick() const { return stick_; }
  bool slipping() const { return committed_slip_; }
  // Whether the trial state slips (at mu R_n).
  bool trial_slipping() const { return trial_slip_; }

 private:
  // F_c and its tangents (the flat slider), with one tangent.
  FrictionResponse coulomb(const LinkKinematics& normal, const LinkKinematics& tangential);
  // The same in a contact plane (two tangents).
  FrictionResponse coulomb_in_plane(const LinkKinematics& normal,
                                    std::span<const LinkKinematics> tangential);
  // The slip branch in a contact plane: F_c = mu R_n e.
  void slip_in_plane(std::span<const LinkKinematics> tangential, const Tangential& stick_force,
                     FrictionResponse& out);
  // Whether the slip goes along the stick force's spring and dashpot part `held`: a contact that
  // slipped at the last commit the way `held` still points, or stuck with `rate` along it.
  bool slips_along_held(const Tangential& held, const Tangential& rate) const;
  // R_n and R_t as imposed, for the hard contact.
  FrictionResponse imposed(const LinkKinematics& normal,
                           std::span<const LinkKinematics> tangential);
  // The pendulum's R_n s / R, added to a response in contact.
  void add_restoring(std::span<const LinkKinematics> tangential, FrictionResponse& response) const;

  std::unique_ptr<LinkLaw> normal_;
  double coefficient_;
  StickPenalty stick_;
  std::optional<double> radius_;
  int tangents_;
  HardContact* hard_;                                                   // normal_'s, or none
  Tangential committed_tangential_force_{}, trial_tangential_force_{};  // imposed (hard_)
  Tangential committed_anchor_{}, trial_anchor_{};
  bool committed_slip_ = false, trial_slip_ = false;
  Tangential committed_slip_direction_{}, trial_slip_direction_{};  // unit, 0 unless slipping
  Tangential committed_slide_{};  // s at the last commit, the anchor when contact begins
  Tangential trial_slide_{};
  // R_n at the last commit: anchor_at_rest takes the pendulum's part out of a static force.
  double committed_normal_force_ = 0.0, trial_normal_force_ = 0.0;
};

}  // namespace pound::links
