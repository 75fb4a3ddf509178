#include "results/monitors.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace pound::results {
namespace {
// A sum read as the summaries have always written it: +0, never -0, where it vanishes.
double plus_zero(double sum) { return 0.0 + sum; }

// A sum of terms, so read.
double sum_of(const std::vector<Term>& terms, const Vector& v) {
  return plus_zero(model::value_of(terms, v));
}

// The displacements monitors judge by: with moving supports their total motion (SupportMotion).
const Vector& displacements_of(SupportMotion* support, const integrators::State& state) {
  return support ? support->total(state) : state.displacement;
}

}  // namespace

DriftMonitors::DriftMonitors(std::vector<Where> storeys, GroundAcceleration& ground,
                             SupportMotion* support)
    : storeys_(std::move(storeys)),
      ground_(ground),
      support_(support),
      peaks_(storeys_.size()),
      turning_(storeys_.size()) {
  for (const Where& w : storeys_) {
    Places& at = places_.emplace_back();
    if (w.drift.empty()) {
      at.top = displacement_sums_.add(w.top);
      at.bottom = displacement_sums_.add(w.bottom);
    } else {
      at.drift = displacement_sums_.add(w.drift);
    }
    at.corners = displacement_sums_.size();
    for (const std::vector<Term>& corner : w.corners) displacement_sums_.add(corner);
    at.twist = displacement_sums_.add(w.twist);
    if (w.top_along.size() > at.along_acceleration.size())
      throw std::invalid_argument("a drift monitor reads its top along at most three axes");
    at.top_acceleration = acceleration_sums_.add(w.top);
    for (std::size_t d = 0; d < w.top_along.size(); ++d)
      at.along_acceleration[d] = acceleration_sums_.add(w.top_along[d].first);
  }
  displacements_.resize(displacement_sums_.size());
  sum_peaks_.assign(displacement_sums_.size(), 0.0);
  sum_times_.assign(displacement_sums_.size(), 0.0);
  accelerations_.resize(acceleration_sums_.size());
}

// The largest corner drift and the twist of a storey (3-D floors), from its sums' peaks: as if
// each step's corners were compared in order with the largest so far, the first corner and step
// to reach the largest (the earliest time of the corners that reach it, then the first of them).
void DriftMonitors::record_plan(const Where& w, const Places& at, DriftPeak& p) const {
  p.peak_corner_drift = 0.0;
  p.corner = 0;
  p.corner_time = 0.0;
  for (std::size_t c = 0; c < w.corners.size(); ++c) {
    const double peak = sum_peaks_[at.corners + c], time = sum_times_[at.corners + c];
    if (peak > p.peak_corner_drift || (peak == p.peak_corner_drift && time < p.corner_time)) {
      p.peak_corner_drift = peak;
      p.corner = c;
      p.corner_time = time;
    }
  }
  p.peak_twist = sum_peaks_[at.twist];
  p.twist_time = sum_times_[at.twist];
}

const std::vector<DriftPeak>& DriftMonitors::peaks() const {
  if (!read_current_)
    for (std::size_t k = 0; k < storeys_.size(); ++k) {
      if (!storeys_[k].corners.empty()) record_plan(storeys_[k], places_[k], peaks_[k]);
      if (swing_window_ > 0.0) peaks_[k].end_swing = windows_[k].half_range();
    }
  read_current_ = true;
  return peaks_;
}

// |a_abs| of the storey's top along the drift. A free top along the drift (every storey of a
// plane frame, or along x or y) is its sum alone, taken here without a call;
// fixed_or_along_axis the others.
double DriftMonitors::absolute_acceleration(const Where& w, const Places& at,
                                            const integrators::State& state) {
  if (w.top_along.empty() && !w.top.empty()) return std::abs(accelerations_[at.top_acceleration]);
  return fixed_or_along_axis(w, at, state);
}

// A fixed top's is the ground's own; along an axis, the top's translations weighted.
double DriftMonitors::fixed_or_along_axis(const Where& w, const Places& at,
                                          const integrators::State& state) {
  const auto reading = [&](const DofReading& dof, std::size_t place, int direction) {
    return dof.empty() ? ground_.absolute(state, dof, w.top_node, direction)
                       : accelerations_[place];
  };
  if (w.top_along.empty()) return std::abs(reading(w.top, at.top_acceleration, w.direction));
  double acceleration = 0.0;
  for (std::size_t d = 0; d < w.top_along.size(); ++d)
    if (const auto& [dof, weight] = w.top_along[d]; weight != 0.0)
      acceleration += weight * reading(dof, at.along_acceleration[d], static_cast<int>(d));
  return std::abs(acceleration);
}

// A turning point where the drift's change between steps changes sign; the swing is half the
// range between the last maximum and the last minimum (consecutive, so the maximum is above).
void DriftMonitors::track_swing(Turning& turning, double drift, DriftPeak& peak) {
  const double change = drift - turning.previous;
  const int slope = (change > 0.0) - (change < 0.0);
  if (slope != 0) {
    if (turning.slope > 0 && slope < 0) {
      turning.maximum = turning.previous;
      turning.has_maximum = true;
    } else if (turning.slope < 0 && slope > 0) {
      turning.minimum = turning.previous;
      turning.has_minimum = true;
    }
    turning.slope = slope;
  }
  turning.previous = drift;
  if (turning.has_maximum && turning.has_minimum)
    peak.end_swing = 0.5 * (turning.maximum - turning.minimum);
}

void DriftMonitors::RecentDrifts::add(double time, double drift, double start) {
  std::size_t mask = ring_.size() - 1;
  while (size_ > 0 && ring_[head_].first < start) {
    head_ = (head_ + 1) & mask;
    --size_;
  }
  if (size_ == ring_.size()) {
    std::vector<std::pair<double, double>> larger(2 * ring_.size());
    for (std::size_t k = 0; k < size_; ++k) larger[k] = ring_[(head_ + k) & mask];
    ring_ = std::move(larger);
    head_ = 0;
    mask = ring_.size() - 1;
  }
  ring_[(head_ + size_) & mask] = {time, drift};
  ++size_;
}

double DriftMonitors::RecentDrifts::half_range() const {
  if (size_ == 0) return 0.0;
  const std::size_t mask = ring_.size() - 1;
  double largest = ring_[head_].second, smallest = largest;
  for (std::size_t k = 1; k < size_; ++k) {
    const double drift = ring_[(head_ + k) & mask].second;
    largest = std::max(largest, drift);
    smallest = std::min(smallest, drift);
  }
  return 0.5 * (largest - smallest);
}

void DriftMonitors::record(const integrators::State& state) {
  if (storeys_.empty()) return;
  read_current_ = false;
  displacement_sums_.evaluate(displacements_of(support_, state), displacements_.data());
  acceleration_sums_.evaluate(state.acceleration, ground_.frame(state.time), accelerations_.data());
  // Every sum's peak, without branches (a tie is no new peak; NaN none).
  const double time = state.time;
  const std::size_t sums = displacements_.size();
  const double* __restrict__ values = displacements_.data();
  double* __restrict__ peaks = sum_peaks_.data();
  double* __restrict__ times = sum_times_.data();
  for (std::size_t s = 0; s < sums; ++s) {
    const double size = std::abs(plus_zero(values[s]));
    const bool larger = size > peaks[s];
    peaks[s] = larger ? size : peaks[s];
    times[s] = larger ? time : times[s];
  }
  for (std::size_t k = 0; k < storeys_.size(); ++k) {
    const Where& w = storeys_[k];
    const Places& at = places_[k];
    DriftPeak& p = peaks_[k];
    const double signed_drift = w.drift.empty() ? displacements_[at.top] - displacements_[at.bottom]
                                                : plus_zero(displacements_[at.drift]);
    p.residual_drift = signed_drift;
    if (swing_window_ > 0.0)
      windows_[k].add(state.time, signed_drift, state.time - swing_window_);
    else
      track_swing(turning_[k], signed_drift, p);
    if (std::abs(signed_drift) > p.peak_drift) {
      p.peak_drift = std::abs(signed_drift);
      p.time = state.time;
    }
    const double acceleration = absolute_acceleration(w, at, state);
    if (acceleration > p.peak_acceleration) {
      p.peak_acceleration = acceleration;
      p.acceleration_time = state.time;
    }
  }
  for (const ResultantPair& pair : pairs_) {
    DriftPeak &first = peaks_[pair.first], &second = peaks_[pair.second];
    const double ratio = std::hypot(first.residual_drift / pair.first_yield,
                                    second.residual_drift / pair.second_yield);
    first.peak_resultant_ratio = std::max(first.peak_resultant_ratio, ratio);
    second.peak_resultant_ratio = first.peak_resultant_ratio;
  }
}

void JointMonitors::record(const integrators::State& state) {
  const Vector& displacement = displacements_of(support_, state);
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const Where& w = joints_[k];
    const double closing = state.link_penetration[w.link_row] + w.gap;
    JointPeak& p = peaks_[k];
    p.peak_closing = std::max(p.peak_closing, closing);
    p.peak_opening = std::max(p.peak_opening, -closing);
    p.residual_opening = -closing;
    double movement = 0.0;
    if (w.movement.empty())
      movement =
          model::value_of(w.girder_x, displacement) - model::value_of(w.seat_x, displacement);
    movement += sum_of(w.movement, displacement);
    p.peak_seat_movement = std::max(p.peak_seat_movement, std::abs(movement));
    p.peak_unseating_movement =
        std::max(p.peak_unseating_movement,
                 w.opening_sign != 0.0 ? w.opening_sign * movement : std::abs(movement));
    p.peak_plan_rotation =
        std::max(p.peak_plan_rotation, std::abs(sum_of(w.plan_rotation, displacement)));
    p.peak_girder_acceleration = std::max(
        p.peak_girder_acceleration, std::abs(ground_.absolute(state, w.girder_x, w.girder, 0)));
  }
}

}  // namespace pound::results
