#include "links/coulomb_friction.hpp"

#include <cmath>

namespace pound::links {
namespace {

// The stick penalty's force along one tangent: k_t (s - s_0) + c_t s_dot + m_t s_ddot.
double stick_force(const StickPenalty& stick, const LinkKinematics& slide, double anchor) {
  return stick.stiffness * (slide.penetration - anchor) + stick.damping * slide.penetration_rate +
         stick.mass * slide.penetration_acceleration;
}

// The anchor at which the stick force equals a slip force: sticking resumes without a jump.
double slip_anchor(const StickPenalty& stick, const LinkKinematics& slide, double force) {
  return slide.penetration - (force - stick.damping * slide.penetration_rate -
                              stick.mass * slide.penetration_acceleration) /
                                 stick.stiffness;
}

}  // namespace

CoulombFriction::CoulombFriction(std::unique_ptr<LinkLaw> normal, double coefficient,
                                 StickPenalty stick, std::optional<double> radius, int tangents)
    : normal_(std::move(normal)),
      coefficient_(coefficient),
      stick_(stick),
      radius_(radius),
      tangents_(tangents),
      hard_(normal_->hard_contact()) {}

CoulombFriction::CoulombFriction(const CoulombFriction& other)
    : normal_(other.normal_->clone()),
      coefficient_(other.coefficient_),
      stick_(other.stick_),
      radius_(other.radius_),
      tangents_(other.tangents_),
      hard_(normal_->hard_contact()),
      committed_tangential_force_(other.committed_tangential_force_),
      trial_tangential_force_(other.committed_tangential_force_),
      committed_anchor_(other.committed_anchor_),
      trial_anchor_(other.committed_anchor_),
      committed_slip_(other.committed_slip_),
      trial_slip_(other.committed_slip_),
      committed_slip_direction_(other.committed_slip_direction_),
      trial_slip_direction_(other.committed_slip_direction_),
      committed_slide_(other.committed_slide_),
      trial_slide_(other.committed_slide_),
      committed_normal_force_(other.committed_normal_force_),
      trial_normal_force_(other.committed_normal_force_) {}

FrictionResponse CoulombFriction::set_trial(const LinkKinematics& normal,
                                            std::span<const LinkKinematics> tangential) {
  if (hard_) return imposed(normal, tangential);
  FrictionResponse out =
      tangents_ == 1 ? coulomb(normal, tangential[0]) : coulomb_in_plane(normal, tangential);
  trial_normal_force_ = out.normal.force;
  // A flat slider's arithmetic stays exactly the Coulomb law's (no "+ 0" anywhere).
  if (radius_ && out.normal.force > 0.0) add_restoring(tangential, out);
  return out;
}

FrictionResponse CoulombFriction::imposed(const LinkKinematics& normal,
                                          std::span<const LinkKinematics> tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  out.tangential_force = trial_tangential_force_;
  out.slipping = trial_slip_;
  for (std::size_t a = 0; a < tangential.size(); ++a) trial_slide_[a] = tangential[a].penetration;
  trial_normal_force_ = out.normal.force;
  return out;
}

// R_t += R_n s / R along each tangent: its derivatives are R_n / R along s and (s / R) dR_n
// along the normal quantities, the vertical load's share of the restoring force.
void CoulombFriction::add_restoring(std::span<const LinkKinematics> tangential,
                                    FrictionResponse& response) const {
  for (int a = 0; a < tangents_; ++a) {
    const auto i = static_cast<std::size_t>(a);
    const double lever = tangential[i].penetration / *radius_;
    response.tangential_force[i] += response.normal.force * lever;
    response.tangential_on_slip[i][i].stiffness += response.normal.force / *radius_;
    LawResponse& on_normal = response.tangential_on_normal[i];
    on_normal.stiffness += lever * response.normal.stiffness;
    on_normal.damping += lever * response.normal.damping;
    on_normal.mass += lever * response.normal.mass;
  }
}

FrictionResponse CoulombFriction::coulomb(const LinkKinematics& normal,
                                          const LinkKinematics& tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  trial_slide_[0] = tangential.penetration;
  trial_slip_ = false;
  trial_slip_direction_ = {};
  if (!(out.normal.force > 0.0)) {
    trial_anchor_[0] = tangential.penetration;  // a new contact sticks where it lands
    return out;
  }
  // A contact that begins in this step sticks from where the step began.
  const double anchor = normal_->in_contact() ? committed_anchor_[0] : committed_slide_[0];
  trial_anchor_[0] = anchor;
  const double stick = stick_force(stick_, tangential, anchor);
  const double limit = coefficient_ * out.normal.force;
  if (std::abs(stick) <= limit) {
    out.tangential_force[0] = stick;
    out.tangential_on_slip[0][0] = {0.0, stick_.stiffness, stick_.damping, stick_.mass};
    return out;
  }
  // Slip against the relative tangential velocity; at rest along the stick force, and turning
  // back along its held part (see slips_along_held).
  const double held = stick - stick_.mass * tangential.penetration_acceleration;
  const double direction =
      slips_along_held(Tangential{held, 0.0}, Tangential{tangential.penetration_rate, 0.0})
          ? std::copysign(1.0, held)
      : tangential.penetration_rate != 0.0 ? std::copysign(1.0, tangential.penetration_rate)
                                           : std::copysign(1.0, stick);
  trial_slip_direction_[0] = direction;
  trial_slip_ = true;
  out.slipping = true;
  out.tangential_force[0] = direction * limit;
  const double scale = direction * coefficient_;
  out.tangential_on_normal[0] = {0.0, scale * out.normal.stiffness, scale * out.normal.damping,
                                 scale * out.normal.mass};
  // Move the anchor so that the stick force would equal the slip force: no jump on sticking.
  if (stick_.stiffness > 0.0)
    trial_anchor_[0] = slip_anchor(stick_, tangential, out.tangential_force[0]);
  return out;
}

FrictionResponse CoulombFriction::coulomb_in_plane(const LinkKinematics& normal,
                                                   std::span<const LinkKinematics> tangential) {
  FrictionResponse out;
  out.normal = normal_->set_trial(normal);
  for (std::size_t a = 0; a < kMaxTangents; ++a) trial_slide_[a] = tangential[a].penetration;
  trial_slip_ = false;
  trial_slip_direction_ = {};
  if (!(out.normal.force > 0.0)) {
    trial_anchor_ = trial_slide_;  // a new contact sticks where it lands
    return out;
  }
  // A contact that begins in this step sticks from where the step began.
  trial_anchor_ = normal_->in_contact() ? committed_anchor_ : committed_slide_;
  Tangential stick;
  for (std::size_t a = 0; a < kMaxTangents; ++a)
    stick[a] = stick_force(stick_, tangential[a], trial_anchor_[a]);
  if (std::hypot(stick[0], stick[1]) <= coefficient_ * out.normal.force) {
    out.tangential_force = stick;
    for (std::size_t a = 0; a < kMaxTangents; ++a)
      out.tangential_on_slip[a][a] = {0.0, stick_.stiffness, stick_.damping, stick_.mass};
    return out;
  }
  slip_in_plane(tangential, stick, out);
  return out;
}

// F_c = mu R_n e along w / |w|: w the stick force's held part where it points along the last
// slip or, out of a stick, along the slide rate (see slips_along_held); else the slide rate, or
// at rest the stick force. Its tangent: e mu dR_n along the normal quantities, and
// mu R_n (I - e e^T) / |w| dw along the slide's: dw = d s_dot, k_t ds + c_t ds_dot, or
// k_t ds + c_t ds_dot + m_t ds_ddot.
void CoulombFriction::slip_in_plane(std::span<const LinkKinematics> tangential,
                                    const Tangential& stick_force, FrictionResponse& out) {
  const Tangential rate{tangential[0].penetration_rate, tangential[1].penetration_rate};
  Tangential held;
  for (std::size_t a = 0; a < kMaxTangents; ++a)
    held[a] = stick_force[a] - stick_.mass * tangential[a].penetration_acceleration;
  const bool returning = slips_along_held(held, rate);
  const bool moving = !returning && (rate[0] != 0.0 || rate[1] != 0.0);
  const Tangential& along = returning ? held : moving ? rate : stick_force;
  const double length = std::hypot(along[0], along[1]);
  const Tangential direction{along[0] / length, along[1] / length};
  // dw per unit turn: (k_t, c_t, m_t) of the stick force, its held part's, or the rate's.
  const LawResponse dw = moving ? LawResponse{0.0, 0.0, 1.0, 0.0}
                         : returning
                             ? LawResponse{0.0, stick_.stiffness, stick_.damping, 0.0}
                             : LawResponse{0.0, stick_.stiffness, stick_.damping, stick_.mass};
  const double limit = coefficient_ * out.normal.force;
  trial_slip_ = true;
  out.slipping = true;
  const LawResponse& n = out.normal;
  for (std::size_t a = 0; a < kMaxTangents; ++a) {
    out.tangential_force[a] = direction[a] * limit;
    trial_slip_direction_[a] = direction[a];
    const double scale = direction[a] * coefficient_;
    out.tangential_on_normal[a] = {0.0, scale * n.stiffness, scale * n.damping, scale * n.mass};
    for (std::size_t b = 0; b < kMaxTangents; ++b) {
      const double turn = limit * ((a == b ? 1.0 : 0.0) - direction[a] * direction[b]) / length;
      out.tangential_on_slip[a][b] = {0.0, turn * dw.stiffness, turn * dw.damping, turn * dw.mass};
    }
    // Move the anchor so that the stick force would equal the slip force: no jump on sticking.
    if (stick_.stiffness > 0.0)
      trial_anchor_[a] = slip_anchor(stick_, tangential[a], out.tangential_force[a]);
  }
}

// Whether the slip goes along the stick force's held part h (the spring and dashpot,
// k_t (s - s_0) + c_t s_dot) of a contact in contact at the last commit: one that slipped then the
// way h still points, or stuck then with h . s_dot > 0. Where its velocity has turned within the
// step a slip then goes on along h until the stick branch takes over, so the force passes from
// +mu R_n to -mu R_n continuously instead of jumping with the velocity's sign (a jump at which
// Newton's iteration cycles without end). Out of a stick, sign(s_dot) = sign(h) with one tangent;
// in a plane h / |h| keeps F_c continuous where the stick force crosses the circle, and
// s_dot / |s_dot| does not: a pendulum at rest rocking on its stick spring (|s_dot| ~ 1e-7 m/s,
// 0.7 degrees off h) met a jump of 700 N there and a turn of mu R_n / |s_dot| ~ 1e15 N/m, between
// which Newton's iteration cycled. The held part leaves out m_t s_ddot: an explicit step finds
// s_ddot from the link forces themselves, and a direction that turned with them would flip at
// every iteration where m_t outweighs the contact's mass.
bool CoulombFriction::slips_along_held(const Tangential& held, const Tangential& rate) const {
  const Tangential& along = committed_slip_ ? committed_slip_direction_ : rate;
  return normal_->in_contact() && held[0] * along[0] + held[1] * along[1] > 0.0;
}

void CoulombFriction::commit() {
  normal_->commit();
  committed_anchor_ = trial_anchor_;
  committed_slip_ = trial_slip_;
  committed_slip_direction_ = trial_slip_direction_;
  committed_slide_ = trial_slide_;
  committed_normal_force_ = trial_normal_force_;
  committed_tangential_force_ = trial_tangential_force_;
}

void CoulombFriction::anchor_at_rest(std::span<const double> tangential_force) {
  for (int a = 0; a < tangents_; ++a) {
    const auto i = static_cast<std::size_t>(a);
    double force = tangential_force[i];
    // Only F_c sticks: the pendulum's R_n s / R is not part of the stick penalty.
    if (radius_ && committed_normal_force_ > 0.0)
      force -= committed_normal_force_ * committed_slide_[i] / *radius_;
    if (stick_.stiffness > 0.0)
      committed_anchor_[i] = committed_slide_[i] - force / stick_.stiffness;
  }
  trial_anchor_ = committed_anchor_;
}

void CoulombFriction::revert() {
  normal_->revert();
  trial_anchor_ = committed_anchor_;
  trial_slip_ = committed_slip_;
  trial_slip_direction_ = committed_slip_direction_;
  trial_slide_ = committed_slide_;
  trial_normal_force_ = committed_normal_force_;
  trial_tangential_force_ = committed_tangential_force_;
}

}  // namespace pound::links
