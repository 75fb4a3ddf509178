#include "model/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace pound::model {
namespace {

// How far past the last sample (in samples) a time still counts as on it: times computed as
// k * dt by callers land a rounding error away from the sample.
constexpr double kSampleTolerance = 1e-9;

void require_samples(const GroundMotion& motion) {
  if (!(motion.time_step > 0.0) || !std::isfinite(motion.time_step))
    throw std::invalid_argument("ground motion '" + motion.name +
                                "': the time step must be positive and finite");
  if (motion.acceleration.empty())
    throw std::invalid_argument("ground motion '" + motion.name + "' has no samples");
}

void require_oscillator(double period, double damping_ratio) {
  if (!(period > 0.0) || !std::isfinite(period))
    throw std::invalid_argument("the SDOF period must be positive and finite");
  if (!(damping_ratio >= 0.0 && damping_ratio < 1.0))
    throw std::invalid_argument("the SDOF damping ratio must be in [0, 1)");
}

// y - sin(y) without the cancellation of the direct difference at small y (long periods give
// w dt ~ 1e-3, where the difference would keep only half the digits).
double y_minus_sin(double y) {
  if (std::abs(y) > 0.1) return y - std::sin(y);
  const double y2 = y * y;
  // y^3/3! - y^5/5! + y^7/7! - y^9/9!: the next term is below 1e-19 of the sum for |y| <= 0.1.
  return y * y2 / 6.0 * (1.0 - y2 / 20.0 * (1.0 - y2 / 42.0 * (1.0 - y2 / 72.0)));
}

// The exact one-step map of u'' + 2 z w u' + w^2 u = -a_g(t) for a ground acceleration that is
// linear within the step (Nigam, N. C. and Jennings, P. C. (1969), "Calculation of response
// spectra from strong-motion earthquake records", BSSA 59(2), 909-922):
//
//   u_{i+1} = a11 u_i + a12 v_i + b11 a_i + b12 a_{i+1}
//   v_{i+1} = a21 u_i + a22 v_i + b21 a_i + b22 a_{i+1}
//
// With E = exp(-z w dt), wd = w sqrt(1 - z^2), S = sin(wd dt), C = cos(wd dt), z' = z/sqrt(1-z^2)
// the free response is
//   a11 = E (C + z' S),  a12 = E S / wd,  a21 = -E w S / sqrt(1 - z^2),  a22 = E (C - z' S).
// Within the step a_g = a_i + (a_{i+1} - a_i) tau/dt has the particular solution P + Q tau with
//   Q = -(a_{i+1} - a_i) / (w^2 dt),  P = -a_i / w^2 - 2 z Q / w,
// and the deviation from it moves freely, so
//   u_{i+1} = a11 u_i + a12 v_i + (1 - a11) P + (dt - a12) Q
//   v_{i+1} = a21 u_i + a22 v_i - a21 P + (1 - a22) Q;
// collecting a_i and a_{i+1} gives Nigam & Jennings' b coefficients. They are applied here as
// b11 a_i + b12 a_{i+1} = (b11 + b12) a_i + b12 (a_{i+1} - a_i), with the step part
// b11 + b12 = -(1 - a11)/w^2 and b21 + b22 = a21/w^2 formed directly: the b's are large and of
// opposite sign for short periods, and their sum rounded separately would lose digits. Likewise
// 1 - a11, 1 - a22 and dt - a12 are formed from expm1, 2 sin^2(y/2) and y - sin y so that long
// periods (w dt << 1) keep theirs.
OscillatorStep nigam_jennings_map(double omega, double zeta, double dt) {
  const double root = std::sqrt(1.0 - zeta * zeta);
  const double omega_d = omega * root;
  const double x = zeta * omega * dt, y = omega_d * dt;
  const double one_minus_e = -std::expm1(-x), e = 1.0 - one_minus_e;
  const double s = std::sin(y), c = std::cos(y);
  const double one_minus_c = 2.0 * std::pow(std::sin(0.5 * y), 2);
  const double one_minus_ec = one_minus_e + one_minus_c - one_minus_e * one_minus_c;
  const double skew = e * zeta / root * s;  // E z' S

  OscillatorStep map{};
  map.a11 = e * c + skew;
  map.a12 = e * s / omega_d;
  map.a21 = -e * omega * s / root;
  map.a22 = e * c - skew;
  const double one_minus_a11 = one_minus_ec - skew;
  const double one_minus_a22 = one_minus_ec + skew;
  const double dt_minus_a12 = (y_minus_sin(y) + one_minus_e * s) / omega_d;

  // dP/da_{i+1} and dQ/da_{i+1}; a step (a_i = a_{i+1}) has P = -a_i/w^2, Q = 0.
  const double w2 = omega * omega;
  const double dq1 = -1.0 / (w2 * dt);
  const double dp1 = -2.0 * zeta * dq1 / omega;
  map.step_u = -one_minus_a11 / w2;
  map.step_v = map.a21 / w2;
  map.ramp_u = one_minus_a11 * dp1 + dt_minus_a12 * dq1;
  map.ramp_v = -map.a21 * dp1 + one_minus_a22 * dq1;
  return map;
}

// One step of the recurrence from (u, v), the base going linearly from a_start to a_end.
void step(const OscillatorStep& m, double a_start, double a_end, double& u, double& v) {
  const double increment = a_end - a_start;
  const double u_next = m.a11 * u + m.a12 * v + m.step_u * a_start + m.ramp_u * increment;
  v = m.a21 * u + m.a22 * v + m.step_v * a_start + m.ramp_v * increment;
  u = u_next;
}

// Runs the recurrence from rest, calling visit(k, u, v) at every sample k.
template <class Visit>
void integrate_sdof(const GroundMotion& motion, double period, double damping_ratio, Visit visit) {
  require_samples(motion);
  require_oscillator(period, damping_ratio);
  const double omega = 2.0 * std::numbers::pi / period;
  const OscillatorStep m = nigam_jennings_map(omega, damping_ratio, motion.time_step);
  const std::vector<double>& a = motion.acceleration;
  double u = 0.0, v = 0.0;
  visit(std::size_t{0}, u, v);
  for (std::size_t k = 0; k + 1 < a.size(); ++k) {
    step(m, a[k], a[k + 1], u, v);
    visit(k + 1, u, v);
  }
}

// A period this far below the step: the oscillator follows its base rigidly, Sa is the peak base
// acceleration (to (T / dt)^2), and w^2 would overflow for periods near 1e-300.
bool follows_base_rigidly(double period, double time_step) { return period < 1e-3 * time_step; }

}  // namespace

bool moves_with_ground(const GroundMotion& motion, double period, double damping_ratio) {
  const bool rigid = period > 0.0 && follows_base_rigidly(period, motion.time_step) &&
                     damping_ratio >= 0.0 && damping_ratio < 1.0;
  if (period != 0.0 && !rigid) return false;
  require_samples(motion);
  return true;
}

std::vector<double> default_spectrum_periods() {
  constexpr double first = 0.02, last = 10.0;
  constexpr int count = 40;
  std::vector<double> periods;
  for (int k = 0; k < count; ++k)
    periods.push_back(first * std::pow(last / first, static_cast<double>(k) / (count - 1)));
  return periods;
}

ResponseOscillator::ResponseOscillator(double period, double damping_ratio)
    : period_(period), damping_ratio_(damping_ratio) {
  if (period != 0.0) require_oscillator(period, damping_ratio);
  omega_ = period > 0.0 ? 2.0 * std::numbers::pi / period : 0.0;
}

void ResponseOscillator::advance(double base_start, double base_end, double dt) {
  peak_base_ = std::max({peak_base_, std::abs(base_start), std::abs(base_end)});
  if (period_ == 0.0 || follows_base_rigidly(period_, dt)) return;
  // Steps that differ in their last bits (times k dt rounded) share a map: recomputing it would
  // cost more than the step and change Sa by parts in 1e9 at most.
  if (!(std::abs(dt - map_dt_) <= 1e-9 * dt)) {
    map_ = nigam_jennings_map(omega_, damping_ratio_, dt);
    map_dt_ = dt;
  }
  step(map_, base_start, base_end, u_, v_);
  peak_displacement_ = std::max(peak_displacement_, std::abs(u_));
}

double ResponseOscillator::pseudo_acceleration() const {
  if (period_ == 0.0 || (map_dt_ == 0.0 && peak_displacement_ == 0.0)) return peak_base_;
  return omega_ * omega_ * peak_displacement_;
}

double GroundMotion::duration() const {
  return acceleration.empty() ? 0.0 : static_cast<double>(acceleration.size() - 1) * time_step;
}

double GroundMotion::at(double time) const {
  if (acceleration.empty() || !(time_step > 0.0)) return 0.0;
  const double position = time / time_step;
  const std::size_t count = acceleration.size();
  const double last = static_cast<double>(count - 1);
  if (!(position >= -kSampleTolerance && position <= last + kSampleTolerance)) return 0.0;
  // Within the tolerance of either end: that end's sample. Inside, k < count - 1.
  if (position <= 0.0) return acceleration[0];
  if (position >= last) return acceleration[count - 1];
  const auto k = static_cast<std::size_t>(position);
  const double fraction = position - static_cast<double>(k);
  return acceleration[k] + fraction * (acceleration[k + 1] - acceleration[k]);
}

GroundKinematics::GroundKinematics(const GroundMotion& motion, double delay)
    : motion_(motion), delay_(delay) {
  const std::vector<double>& a = motion.acceleration;
  const double dt = motion.time_step;
  velocity_.assign(a.size(), 0.0);
  displacement_.assign(a.size(), 0.0);
  for (std::size_t k = 1; k < a.size(); ++k) {
    velocity_[k] = velocity_[k - 1] + 0.5 * dt * (a[k - 1] + a[k]);
    displacement_[k] =
        displacement_[k - 1] + dt * velocity_[k - 1] + dt * dt * (a[k - 1] / 3.0 + a[k] / 6.0);
  }
}

double GroundKinematics::peak_velocity() const {
  double largest = 0.0;
  for (double v : velocity_) largest = std::max(largest, std::abs(v));
  return largest;
}

GroundState GroundKinematics::at(double time) const {
  const double t = time - delay_;
  const std::size_t n = motion_.acceleration.size();
  if (t < 0.0 || n == 0) return {};  // the wave has not arrived yet
  const double dt = motion_.time_step;
  const double end = static_cast<double>(n - 1) * dt;
  if (t >= end) {  // at rest in acceleration; velocity and displacement carry on
    return {0.0, velocity_.back(), displacement_.back() + velocity_.back() * (t - end)};
  }
  const auto k = std::min(static_cast<std::size_t>(t / dt), n - 2);
  const double tau = t - static_cast<double>(k) * dt;
  const double a0 = motion_.acceleration[k], a1 = motion_.acceleration[k + 1];
  const double slope = (a1 - a0) / dt;
  return {
      a0 + slope * tau, velocity_[k] + a0 * tau + 0.5 * slope * tau * tau,
      displacement_[k] + velocity_[k] * tau + 0.5 * a0 * tau * tau + slope * tau * tau * tau / 6.0};
}

double GroundMotion::peak() const {
  double largest = 0.0;
  for (double a : acceleration) largest = std::max(largest, std::abs(a));
  return largest;
}

double GroundMotion::time_of_peak() const {
  const auto largest =
      std::max_element(acceleration.begin(), acceleration.end(),
                       [](double x, double y) { return std::abs(x) < std::abs(y); });
  return largest == acceleration.end()
             ? 0.0
             : static_cast<double>(largest - acceleration.begin()) * time_step;
}

SdofResponse sdof_response(const GroundMotion& motion, double period, double damping_ratio) {
  SdofResponse response;
  const std::size_t n = motion.acceleration.size();
  response.displacement.reserve(n);
  response.velocity.reserve(n);
  response.absolute_acceleration.reserve(n);
  const double omega = 2.0 * std::numbers::pi / period;
  integrate_sdof(motion, period, damping_ratio, [&](std::size_t, double u, double v) {
    response.displacement.push_back(u);
    response.velocity.push_back(v);
    // u'' + a_g = -(2 z w u' + w^2 u): the oscillator's absolute acceleration.
    response.absolute_acceleration.push_back(
        -(2.0 * damping_ratio * omega * v + omega * omega * u));
  });
  return response;
}

double free_vibration_peak(double u, double v, double omega, double damping_ratio) {
  // u(t) = e^(-z w t) (u cos(w_d t) + c sin(w_d t)), c = (v + z w u) / w_d; u'(t) = 0 where
  // v cos(w_d t) = d sin(w_d t), d = z w c + w_d u: the first such w_d t in [0, pi).
  const double omega_d = omega * std::sqrt(1.0 - damping_ratio * damping_ratio);
  const double c = (v + damping_ratio * omega * u) / omega_d;
  const double d = damping_ratio * omega * c + omega_d * u;
  double angle = std::atan2(v, d);
  if (angle < 0.0) angle += std::numbers::pi;
  if (angle >= std::numbers::pi) angle -= std::numbers::pi;
  const double extremum = std::exp(-damping_ratio * omega * angle / omega_d) *
                          (u * std::cos(angle) + c * std::sin(angle));
  return std::max(std::abs(u), std::abs(extremum));
}

double spectral_acceleration(const GroundMotion& motion, double period, double damping_ratio) {
  if (moves_with_ground(motion, period, damping_ratio)) return motion.peak();
  double largest = 0.0, last_u = 0.0, last_v = 0.0;
  integrate_sdof(motion, period, damping_ratio, [&](std::size_t, double u, double v) {
    largest = std::max(largest, std::abs(u));
    last_u = u;
    last_v = v;
  });
  const double omega = 2.0 * std::numbers::pi / period;
  largest = std::max(largest, free_vibration_peak(last_u, last_v, omega, damping_ratio));
  const double sa = omega * omega * largest;
  if (!std::isfinite(sa))
    throw std::invalid_argument("the spectral acceleration of ground motion '" + motion.name +
                                "' at that period overflows the number range");
  return sa;
}

double scale_to_peak(const GroundMotion& motion, double target_peak) {
  const double peak = motion.peak();
  if (!(peak > 0.0))
    throw std::invalid_argument("ground motion '" + motion.name + "' is zero: cannot scale it");
  return target_peak / peak;
}

double scale_to_spectral_acceleration(const GroundMotion& motion, double target, double period,
                                      double damping_ratio) {
  const double sa = spectral_acceleration(motion, period, damping_ratio);
  if (!(sa > 0.0))
    throw std::invalid_argument("ground motion '" + motion.name +
                                "' has no spectral acceleration at that period: cannot scale it");
  return target / sa;
}

void scale(GroundMotion& motion, double factor) {
  for (double& a : motion.acceleration) a *= factor;
}

}  // namespace pound::model
