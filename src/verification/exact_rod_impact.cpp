#include "verification/exact_rod_impact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

// Method. Both rods are described with the axial force N = sigma*A (tension positive) and the
// approach velocity u = n*v, where n is the outward normal of the rod's contact face (+1 for the
// left rod, -1 for the right one), so one set of equations serves both rods. With Z = rho*C0*A,
//   O = N + Z*u  is constant along the characteristic leaving the contact face,
//   I = N - Z*u  is constant along the characteristic arriving at it.
// The face emits O(t); it reaches the far end at t + L/C and comes back at t + 2L/C as I = -O
// (free end, N = 0) or I = +O (fixed end, u = 0). Before 2L/C the face receives the initial
// data (N = 0, u = u0: I = -Z*u0), and for a fixed end with u0 != 0 the wave the end emits at
// t = 0 (I = +Z*u0 from L/C on). So the incoming I at each face is a known piecewise constant
// function of the face's own past, and an event loop over its breakpoints (plus the instants
// the gap closes) solves the interface exactly:
//   faces stuck: u_left + u_right = 0 and equal N, so N = Z_eff*(I_left/Z_left + I_right/Z_right)
//                with Z_eff = Z_left*Z_right/(Z_left + Z_right);
//   faces apart: N = 0, u = -I/Z, gap rate -(u_left + u_right) = I_left/Z_left + I_right/Z_right.
// So the stuck force is Z_eff times the free gap rate: touching faces stay in contact exactly
// when they would otherwise close. Either way the face emits O = 2N - I.

namespace pound::verification {

double ExactRod::wave_speed() const { return std::sqrt(youngs_modulus / density); }
double ExactRod::impedance() const { return density * wave_speed() * area; }
double ExactRod::mass() const { return density * area * length; }

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Events closer than this fraction of the time scale are one event: sums of travel times
// taken in different orders differ in the last bits and must not split a state in two.
constexpr double kRelativeTimeTolerance = 1e-12;
// A stuck-interface force this small (relative to Z_eff * |relative velocity|) is rounding of
// an exact zero; it neither keeps nor makes contact.
constexpr double kRelativeForceTolerance = 1e-12;
// Guards against a t_end so long that the event list would exhaust memory.
constexpr std::size_t kMaxEvents = 20'000'000;

// State of one rod's contact face on [start, next segment's start).
struct FaceSegment {
  double start = 0.0;
  double axial_force = 0.0;  // N at the face
  double outgoing = 0.0;     // O = N + Z*u emitted into the rod
  // Integrals from 0 to start, for the impulse (centre-of-mass velocity).
  double axial_force_integral = 0.0;
  double outgoing_integral = 0.0;
};

// Interface state on [start, next phase's start).
struct Phase {
  double start = 0.0;
  bool in_contact = false;
  double contact_force = 0.0;  // compressive, >= 0
  double gap_at_start = 0.0;
  double gap_rate = 0.0;
};

template <class Item>
std::size_t index_at(const std::vector<Item>& items, double time) {
  // Last item with start <= time; items[0].start == 0 and time >= 0.
  const auto after = std::upper_bound(items.begin(), items.end(), time,
                                      [](double t, const Item& item) { return t < item.start; });
  return static_cast<std::size_t>(std::max<std::ptrdiff_t>(after - items.begin() - 1, 0));
}

void require_positive(double value, const std::string& what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw std::invalid_argument("ExactRodImpact: " + what + " must be positive and finite, got " +
                                std::to_string(value));
  }
}

class RodHistory {
 public:
  RodHistory(const ExactRod& rod, double face_normal, double face_position)
      : rod_(rod),
        face_normal_(face_normal),
        face_position_(face_position),
        wave_speed_(rod.wave_speed()),
        impedance_(rod.impedance()),
        transit_time_(rod.length / wave_speed_),
        round_trip_(2.0 * transit_time_),
        initial_approach_velocity_(face_normal * rod.initial_velocity) {}

  double impedance() const { return impedance_; }
  double round_trip() const { return round_trip_; }
  const ExactRod& rod() const { return rod_; }

  // Incoming characteristic I at the contact face at `time` (the value after a jump).
  double incoming(double time) const {
    const double initial_incoming = -impedance_ * initial_approach_velocity_;
    if (time < transit_time_) return initial_incoming;
    if (time < round_trip_) return rod_.far_end_fixed ? -initial_incoming : initial_incoming;
    return reflection() * outgoing_at_face(time - round_trip_);
  }

  // First instant after `time` where incoming() may jump (infinity if none is known yet; any
  // jump still unknown comes from a face change after `time`, so at least 2L/C later).
  double next_incoming_change(double time) const {
    if (time < transit_time_ && rod_.far_end_fixed) return transit_time_;
    if (time < round_trip_) return round_trip_;
    const std::size_t next = index_at(face_, time - round_trip_) + 1;
    return next < face_.size() ? face_[next].start + round_trip_ : kInfinity;
  }

  double outgoing_at_face(double time) const {
    // Only reachable without a recorded face when the rod's times lose all precision (a length
    // or wave speed at the ends of the number range).
    if (face_.empty())
      throw std::range_error("ExactRodImpact: the rod's travel times are beyond double precision");
    return face_[index_at(face_, time)].outgoing;
  }

  void record_face(double time, double axial_force, double outgoing) {
    if (face_.empty()) {
      face_.push_back({time, axial_force, outgoing, 0.0, 0.0});
      return;
    }
    const FaceSegment& last = face_.back();
    if (last.axial_force == axial_force && last.outgoing == outgoing) return;
    const double elapsed = time - last.start;
    face_.push_back({time, axial_force, outgoing,
                     last.axial_force_integral + last.axial_force * elapsed,
                     last.outgoing_integral + last.outgoing * elapsed});
  }

  RodState state(double x, double time) const {
    const double distance = clamped_distance_from_face(x);
    if (distance == 0.0) {
      // The face state as the event loop solved it, so that it matches contact_force and gap
      // exactly, also at an event whose time has been rounded.
      const FaceSegment& face = face_[index_at(face_, time)];
      return {face_normal_ * (face.outgoing - face.axial_force) / impedance_,
              face.axial_force / rod_.area};
    }
    const double travel = distance / wave_speed_;
    const double departure = time - travel;
    const double outgoing =
        departure < 0.0 ? impedance_ * initial_approach_velocity_ : outgoing_at_face(departure);
    const double incoming_value = incoming(time + travel);
    const double axial_force = 0.5 * (outgoing + incoming_value);
    const double approach_velocity = (outgoing - incoming_value) / (2.0 * impedance_);
    return {face_normal_ * approach_velocity, axial_force / rod_.area};
  }

  // Momentum / mass: d(momentum)/dt = n * (N_face - N_far_end), N_far_end = 0 at a free end and
  // the arriving O at a fixed one (I = O there, so N = (O + I)/2 = O).
  double centre_of_mass_velocity(double time) const {
    double impulse = integral(time, &FaceSegment::axial_force, &FaceSegment::axial_force_integral);
    if (rod_.far_end_fixed) {
      impulse -= impedance_ * initial_approach_velocity_ * std::min(time, transit_time_);
      if (time > transit_time_) {
        impulse -=
            integral(time - transit_time_, &FaceSegment::outgoing, &FaceSegment::outgoing_integral);
      }
    }
    return rod_.initial_velocity + face_normal_ * impulse / rod_.mass();
  }

 private:
  double reflection() const { return rod_.far_end_fixed ? 1.0 : -1.0; }

  double integral(double time, double FaceSegment::*value,
                  double FaceSegment::*integral_before) const {
    const FaceSegment& segment = face_[index_at(face_, time)];
    return segment.*integral_before + segment.*value * (time - segment.start);
  }

  double clamped_distance_from_face(double x) const {
    const double distance = face_normal_ * (face_position_ - x);
    const double slack = 1e-12 * rod_.length;
    if (distance < -slack || distance > rod_.length + slack) {
      throw std::out_of_range("ExactRodImpact::state: x = " + std::to_string(x) +
                              " is outside the rod");
    }
    return std::clamp(distance, 0.0, rod_.length);
  }

  ExactRod rod_;
  double face_normal_;
  double face_position_;  // undeformed x of the contact face
  double wave_speed_;
  double impedance_;
  double transit_time_;  // L / C
  double round_trip_;    // 2L / C
  double initial_approach_velocity_;
  std::vector<FaceSegment> face_;
};

}  // namespace

struct ExactRodImpact::Impl {
  Impl(const ExactRod& left, const ExactRod& right, double initial_gap, double end_time)
      : rods{RodHistory(left, 1.0, 0.0), RodHistory(right, -1.0, initial_gap)},
        gap0(initial_gap),
        t_end(end_time),
        time_tolerance(kRelativeTimeTolerance *
                       std::max({end_time, rods[0].round_trip(), rods[1].round_trip()})),
        effective_impedance(rods[0].impedance() * rods[1].impedance() /
                            (rods[0].impedance() + rods[1].impedance())),
        force_tolerance(kRelativeForceTolerance * effective_impedance *
                        (std::abs(left.initial_velocity) + std::abs(right.initial_velocity))) {
    solve();
  }

  // The next event after a phase: when an incoming wave changes or the gap closes first.
  struct Event {
    double time = 0.0;
    bool gap_closes = false;
  };

  void solve();
  Phase phase_from(double time, double gap, const std::array<double, 2>& incoming) const;
  Event next_event(const Phase& phase, double lookup_time) const;
  void list_contacts();
  const Phase& phase_at(double time) const { return phases[index_at(phases, time)]; }
  // Times a rounding error outside [0, t_end] (as from t_end * i / n) are taken as the end.
  double checked_time(double time, const char* query) const {
    if (!(time >= -time_tolerance && time <= t_end + time_tolerance)) {
      throw std::out_of_range(std::string("ExactRodImpact::") + query +
                              ": t = " + std::to_string(time) + " is outside [0, t_end]");
    }
    return std::clamp(time, 0.0, t_end);
  }
  const RodHistory& rod_at(int rod) const {
    if (rod != 0 && rod != 1) {
      throw std::out_of_range("ExactRodImpact: rod must be 0 (left) or 1 (right), got " +
                              std::to_string(rod));
    }
    return rods[static_cast<std::size_t>(rod)];
  }

  std::array<RodHistory, 2> rods;
  double gap0;
  double t_end;
  double time_tolerance;       // events closer than this are one (see kRelativeTimeTolerance)
  double effective_impedance;  // Z_eff = Z_left*Z_right/(Z_left + Z_right)
  double force_tolerance;      // see kRelativeForceTolerance
  std::vector<Phase> phases;
  std::vector<ContactInterval> contact_intervals;
  std::vector<double> breakpoints;
};

void ExactRodImpact::Impl::solve() {
  double time = 0.0;
  double gap_now = gap0;
  for (;;) {
    if (phases.size() >= kMaxEvents) {
      throw std::length_error("ExactRodImpact: more than " + std::to_string(kMaxEvents) +
                              " events before t_end; shorten t_end");
    }
    // Values that hold until the next event: look just past `time` so that jumps a rounding
    // error later count as happening now.
    const double lookup_time = time + time_tolerance;
    const std::array<double, 2> incoming{rods[0].incoming(lookup_time),
                                         rods[1].incoming(lookup_time)};
    phases.push_back(phase_from(time, gap_now, incoming));
    const Phase& phase = phases.back();
    const double face_axial_force = -phase.contact_force;
    for (std::size_t k = 0; k < 2; ++k) {
      rods[k].record_face(time, face_axial_force, 2.0 * face_axial_force - incoming[k]);
    }

    // After recording: what the faces emit now returns 2L/C later.
    const Event next = next_event(phase, lookup_time);
    // An event at t_end (up to rounding) is solved too: queries at t_end return the state
    // after it, as at any other jump.
    if (next.time > t_end + time_tolerance) break;
    const double next_time = std::min(next.time, t_end);
    gap_now = next.gap_closes
                  ? 0.0
                  : std::max(0.0, phase.gap_at_start + phase.gap_rate * (next_time - time));
    time = next_time;
  }
  list_contacts();
}

// The interface from `time` on, with `gap` between the faces then and `incoming` arriving at them.
Phase ExactRodImpact::Impl::phase_from(double time, double gap,
                                       const std::array<double, 2>& incoming) const {
  const double free_gap_rate =
      incoming[0] / rods[0].impedance() + incoming[1] / rods[1].impedance();
  const double stuck_contact_force = -effective_impedance * free_gap_rate;
  const bool touching =
      gap <= 0.0 || (free_gap_rate < 0.0 && gap <= -free_gap_rate * time_tolerance);

  Phase phase{time, false, 0.0, touching ? 0.0 : gap, free_gap_rate};
  if (touching && stuck_contact_force > force_tolerance) {
    phase.in_contact = true;
    phase.contact_force = stuck_contact_force;
    phase.gap_rate = 0.0;
  } else if (touching && stuck_contact_force >= -force_tolerance) {
    phase.gap_rate = 0.0;  // no force either way: the faces move on together
  }
  return phase;
}

ExactRodImpact::Impl::Event ExactRodImpact::Impl::next_event(const Phase& phase,
                                                             double lookup_time) const {
  Event next{std::min(rods[0].next_incoming_change(lookup_time),
                      rods[1].next_incoming_change(lookup_time)),
             false};
  if (!phase.in_contact && phase.gap_rate < 0.0) {
    const double closing_time = phase.start + phase.gap_at_start / -phase.gap_rate;
    if (closing_time < next.time) next = {closing_time, true};
  }
  return next;
}

// The contact intervals and the instants the force jumps, from the phases.
void ExactRodImpact::Impl::list_contacts() {
  for (std::size_t i = 0; i < phases.size(); ++i) {
    const double end = i + 1 < phases.size() ? phases[i + 1].start : t_end;
    if (phases[i].start >= t_end) break;  // the state after an event at t_end
    if (i > 0 && phases[i].contact_force != phases[i - 1].contact_force) {
      breakpoints.push_back(phases[i].start);
    }
    if (!phases[i].in_contact) continue;
    if (i > 0 && phases[i - 1].in_contact) {
      contact_intervals.back().end = end;
    } else {
      contact_intervals.push_back({phases[i].start, end});
    }
  }
}

ExactRodImpact::ExactRodImpact(const ExactRod& left, const ExactRod& right, double gap,
                               double t_end) {
  for (const auto& [rod, name] : {std::pair{&left, "left"}, std::pair{&right, "right"}}) {
    const std::string prefix = std::string(name) + " rod ";
    require_positive(rod->youngs_modulus, prefix + "Young's modulus");
    require_positive(rod->density, prefix + "density");
    require_positive(rod->area, prefix + "area");
    require_positive(rod->length, prefix + "length");
    if (!std::isfinite(rod->initial_velocity)) {
      throw std::invalid_argument("ExactRodImpact: " + prefix + "initial velocity must be finite");
    }
  }
  if (!(gap >= 0.0) || !std::isfinite(gap)) {
    throw std::invalid_argument("ExactRodImpact: gap must be >= 0 and finite, got " +
                                std::to_string(gap));
  }
  if (!(t_end >= 0.0) || !std::isfinite(t_end)) {
    throw std::invalid_argument("ExactRodImpact: t_end must be >= 0 and finite, got " +
                                std::to_string(t_end));
  }
  impl_ = std::make_shared<const Impl>(left, right, gap, t_end);
}

const std::vector<ContactInterval>& ExactRodImpact::contacts() const {
  return impl_->contact_intervals;
}

double ExactRodImpact::contact_force(double t) const {
  const double time = impl_->checked_time(t, "contact_force");
  return impl_->phase_at(time).contact_force;
}

std::vector<double> ExactRodImpact::force_breakpoints() const { return impl_->breakpoints; }

double ExactRodImpact::gap(double t) const {
  const double time = impl_->checked_time(t, "gap");
  const Phase& phase = impl_->phase_at(time);
  return phase.gap_at_start + phase.gap_rate * (time - phase.start);
}

RodState ExactRodImpact::state(int rod, double x, double t) const {
  const double time = impl_->checked_time(t, "state");
  return impl_->rod_at(rod).state(x, time);
}

double ExactRodImpact::centre_of_mass_velocity(int rod, double t) const {
  const double time = impl_->checked_time(t, "centre_of_mass_velocity");
  return impl_->rod_at(rod).centre_of_mass_velocity(time);
}

double ExactRodImpact::t_end() const { return impl_->t_end; }

}  // namespace pound::verification
