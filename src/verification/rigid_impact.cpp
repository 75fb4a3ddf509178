#include "verification/rigid_impact.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace pound::verification {
namespace {

double dot(const PlaneVector& a, const PlaneVector& b) { return a.x * b.x + a.y * b.y; }
PlaneVector turned(const PlaneVector& a) { return {-a.y, a.x}; }  // z x a

// The contact's normal and tangent, and z x r.
struct Frame {
  PlaneVector normal, tangent, arm;
};
Frame frame(const PlanContact& contact) {
  return {contact.normal, turned(contact.normal), turned(contact.point)};
}

// The velocity of the contact point along `direction`.
double contact_velocity(const PlanVelocity& v, const Frame& f, const PlaneVector& direction) {
  return v.x * direction.x + v.y * direction.y + v.spin * dot(f.arm, direction);
}

// What a unit impulse along `b` at contact j does to the velocity along `a` at contact i.
double mobility(const RigidBodyInPlan& body, const Frame& i, const PlaneVector& a, const Frame& j,
                const PlaneVector& b) {
  return dot(a, b) / body.mass + dot(i.arm, a) * dot(j.arm, b) / body.inertia;
}

void apply(const RigidBodyInPlan& body, const Frame& f, double normal, double tangential,
           PlanVelocity& v) {
  const PlaneVector impulse{normal * f.normal.x + tangential * f.tangent.x,
                            normal * f.normal.y + tangential * f.tangent.y};
  v.x += impulse.x / body.mass;
  v.y += impulse.y / body.mass;
  v.spin += dot(f.arm, impulse) / body.inertia;
}

double kinetic_energy(const RigidBodyInPlan& body, const PlanVelocity& v) {
  return 0.5 * body.mass * (v.x * v.x + v.y * v.y) + 0.5 * body.inertia * v.spin * v.spin;
}

void check_inputs(const RigidBodyInPlan& body, double restitution, double friction) {
  if (!(body.mass > 0.0) || !(body.inertia > 0.0))
    throw std::invalid_argument("a rigid body needs a positive mass and inertia");
  if (!(restitution >= 0.0 && restitution <= 1.0))
    throw std::invalid_argument("the restitution must be in [0, 1]");
  if (!(friction >= 0.0) || !std::isfinite(friction))
    throw std::invalid_argument("the friction coefficient must be >= 0");
}

int sign(double x) { return (x > 0.0) - (x < 0.0); }

}  // namespace

PlanImpact routh_impact(const RigidBodyInPlan& body, const PlanVelocity& before,
                        const PlanContact& contact, double restitution, double friction) {
  check_inputs(body, restitution, friction);
  const Frame f = frame(contact);
  PlanImpact result{before, {0.0}, {0.0}, {ContactEnd::lifted}, false, 0.0};
  double normal_velocity = contact_velocity(before, f, f.normal);
  double slide_velocity = contact_velocity(before, f, f.tangent);
  if (!(normal_velocity < 0.0)) return result;
  const double w_nn = mobility(body, f, f.normal, f, f.normal);
  const double w_nt = mobility(body, f, f.normal, f, f.tangent);
  const double w_tt = mobility(body, f, f.tangent, f, f.tangent);
  const double target = -restitution * normal_velocity;
  double normal = 0.0, tangential = 0.0;
  int slide = sign(slide_velocity), first_slide = slide;
  // Each pass follows one straight line of impulse space: a slide, or sticking.
  for (int pass = 0; pass < 8; ++pass) {
    if (slide == 0 && std::abs(w_nt) > friction * w_tt) {
      slide = sign(w_nt);  // cannot stick: it slides again, the way the coupling drives it
      result.slide_reversed = result.slide_reversed || (first_slide != 0 && slide != first_slide);
      first_slide = first_slide == 0 ? slide : first_slide;
    }
    const double tangential_rate = slide != 0 ? -friction * slide : -w_nt / w_tt;
    const double normal_rate = w_nn + w_nt * tangential_rate;  // dg_N / dLambda_N
    const double slide_rate = slide != 0 ? w_nt + w_tt * tangential_rate : 0.0;
    double step = std::numeric_limits<double>::infinity();
    bool stops = false;
    if (normal_rate > 0.0) step = (target - normal_velocity) / normal_rate;
    if (slide != 0 && slide * slide_rate < 0.0 && -slide_velocity / slide_rate < step) {
      step = -slide_velocity / slide_rate;
      stops = true;
    }
    if (!std::isfinite(step))
      throw std::runtime_error("Routh's method found no end of the impact (a jam)");
    normal += step;
    tangential += tangential_rate * step;
    normal_velocity += normal_rate * step;
    slide_velocity += slide_rate * step;
    if (!stops) break;
    slide_velocity = 0.0;
    slide = 0;
  }
  apply(body, f, normal, tangential, result.after);
  result.normal_impulse = {normal};
  result.tangential_impulse = {tangential};
  result.ends = {slide != 0 ? ContactEnd::slipping : ContactEnd::sticking};
  result.energy_lost = kinetic_energy(body, before) - kinetic_energy(body, result.after);
  return result;
}

PlanImpact simultaneous_impact(const RigidBodyInPlan& body, const PlanVelocity& before,
                               const std::vector<PlanContact>& contacts, double restitution,
                               double friction) {
  check_inputs(body, restitution, friction);
  std::vector<Frame> frames;
  std::vector<std::size_t> approaching;  // indices into contacts
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    frames.push_back(frame(contacts[k]));
    if (contact_velocity(before, frames.back(), frames.back().normal) < 0.0)
      approaching.push_back(k);
  }
  if (approaching.size() > 4) throw std::invalid_argument("at most 4 contacts at once");
  const int count = static_cast<int>(approaching.size()), size = 2 * count;
  // Velocities before and the mobility between every pair of (normal, tangent) directions.
  Eigen::VectorXd velocity(size);
  Eigen::MatrixXd mobility_matrix(size, size);
  for (int i = 0; i < count; ++i) {
    const Frame& fi = frames[approaching[i]];
    const PlaneVector directions_i[2] = {fi.normal, fi.tangent};
    for (int a = 0; a < 2; ++a) {
      velocity[2 * i + a] = contact_velocity(before, fi, directions_i[a]);
      for (int j = 0; j < count; ++j) {
        const Frame& fj = frames[approaching[j]];
        const PlaneVector directions_j[2] = {fj.normal, fj.tangent};
        for (int b = 0; b < 2; ++b)
          mobility_matrix(2 * i + a, 2 * j + b) =
              mobility(body, fi, directions_i[a], fj, directions_j[b]);
      }
    }
  }
  const double scale = velocity.cwiseAbs().maxCoeff(), tolerance = 1e-10;
  // States: 0 lifted, 1 sticking, 2 slipping +t, 3 slipping -t.
  std::vector<PlanImpact> found;
  int combinations = 1;
  for (int i = 0; i < count; ++i) combinations *= 4;
  for (int code = 0; code < combinations; ++code) {
    std::vector<int> states(count);
    for (int i = 0, c = code; i < count; ++i, c /= 4) states[i] = c % 4;
    Eigen::MatrixXd equations = Eigen::MatrixXd::Zero(size, size);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
    for (int i = 0; i < count; ++i) {
      const int n = 2 * i, t = n + 1;
      if (states[i] == 0) {
        equations(n, n) = equations(t, t) = 1.0;
        continue;
      }
      equations.row(n) = mobility_matrix.row(n);  // g_N+ = -e g_N-
      rhs[n] = -(1.0 + restitution) * velocity[n];
      if (states[i] == 1) {
        equations.row(t) = mobility_matrix.row(t);  // g_T+ = 0
        rhs[t] = -velocity[t];
      } else {
        equations(t, t) = 1.0;  // Lambda_T = -mu s Lambda_N
        equations(t, n) = friction * (states[i] == 2 ? 1.0 : -1.0);
      }
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(equations);
    if (lu.rank() < size) continue;
    const Eigen::VectorXd impulse = lu.solve(rhs);
    const Eigen::VectorXd after = velocity + mobility_matrix * impulse;
    const double impulse_scale = std::max(impulse.cwiseAbs().maxCoeff(), 1e-300);
    bool consistent = true;
    for (int i = 0; i < count && consistent; ++i) {
      const int n = 2 * i, t = n + 1;
      if (states[i] == 0) {
        consistent = after[n] + restitution * velocity[n] >= -tolerance * scale;
      } else {
        consistent = impulse[n] >= -tolerance * impulse_scale;
        if (states[i] == 1)
          consistent = consistent &&
                       std::abs(impulse[t]) <= friction * impulse[n] + tolerance * impulse_scale;
        else
          consistent = consistent && (states[i] == 2 ? 1.0 : -1.0) * after[t] >= -tolerance * scale;
      }
    }
    if (!consistent) continue;
    PlanImpact result{before,
                      std::vector<double>(contacts.size(), 0.0),
                      std::vector<double>(contacts.size(), 0.0),
                      std::vector<ContactEnd>(contacts.size(), ContactEnd::lifted),
                      false,
                      0.0};
    for (int i = 0; i < count; ++i) {
      const std::size_t k = approaching[i];
      result.normal_impulse[k] = impulse[2 * i];
      result.tangential_impulse[k] = impulse[2 * i + 1];
      result.ends[k] = states[i] == 0   ? ContactEnd::lifted
                       : states[i] == 1 ? ContactEnd::sticking
                                        : ContactEnd::slipping;
      apply(body, frames[k], impulse[2 * i], impulse[2 * i + 1], result.after);
    }
    result.energy_lost = kinetic_energy(body, before) - kinetic_energy(body, result.after);
    found.push_back(result);
  }
  if (found.empty())
    throw std::runtime_error("no combination of contact states satisfies the impact laws");
  // The outcomes must move the body alike: velocities, and the spin times the farthest contact.
  const PlanVelocity& first = found.front().after;
  double speed = std::max(std::abs(before.x), std::abs(before.y)), reach = 0.0;
  for (const PlanContact& contact : contacts)
    reach = std::max(reach, std::hypot(contact.point.x, contact.point.y));
  speed = std::max(speed, std::abs(before.spin) * reach);
  for (const PlanImpact& other : found)
    if (std::max({std::abs(other.after.x - first.x), std::abs(other.after.y - first.y),
                  std::abs(other.after.spin - first.spin) * reach}) > 1e-8 * speed)
      throw std::runtime_error(
          fmt::format("the impact laws allow {} outcomes with different velocities", found.size()));
  return found.front();
}

RigidBodyInPlan SkewedDeck::body() const {
  const double cosine = std::cos(skew);
  return {mass, mass * (length * length + width * width / (cosine * cosine)) / 12.0};
}

std::vector<PlanContact> SkewedDeck::corners() const {
  const double cosine = std::cos(skew), sine = std::sin(skew);
  const double half_end = 0.5 * width / cosine;  // half the end's length, along the skew
  const PlaneVector normal{-cosine, sine};       // from the wall into the deck
  return {{{0.5 * length + half_end * sine, half_end * cosine}, normal},
          {{0.5 * length - half_end * sine, -half_end * cosine}, normal}};
}

PlanImpact skewed_deck_impact(const SkewedDeck& deck, double restitution, double friction) {
  if (!(deck.length > 0.0) || !(deck.width > 0.0) || !(std::abs(deck.skew) < 1.5))
    throw std::invalid_argument("a deck needs a positive length and width and a skew below 86 deg");
  return simultaneous_impact(deck.body(), {deck.speed, 0.0, 0.0}, deck.corners(), restitution,
                             friction);
}

}  // namespace pound::verification
