#include "results/monitors.hpp"

#include <algorithm>
#include <cmath>

namespace pound::results {
namespace {
// A sum of terms; +0, never -0, where it vanishes (as the summaries have always written it).
double sum_of(const std::vector<Term>& terms, const Vector& v) {
  return 0.0 + model::value_of(terms, v);
}

// The largest corner drift and the twist of a storey (3-D floors).
void record_plan(const DriftMonitors::Where& w, const integrators::State& state, DriftPeak& p) {
  for (std::size_t c = 0; c < w.corners.size(); ++c) {
    const double drift = std::abs(sum_of(w.corners[c], state.displacement));
    if (drift > p.peak_corner_drift) {
      p.peak_corner_drift = drift;
      p.corner = c;
      p.corner_time = state.time;
    }
  }
  const double twist = std::abs(sum_of(w.twist, state.displacement));
  if (twist > p.peak_twist) {
    p.peak_twist = twist;
    p.twist_time = state.time;
  }
}
}  // namespace

void DriftMonitors::record(const integrators::State& state) {
  for (std::size_t k = 0; k < storeys_.size(); ++k) {
    const Where& w = storeys_[k];
    DriftPeak& p = peaks_[k];
    const double signed_drift = w.drift.empty() ? model::value_of(w.top, state.displacement) -
                                                      model::value_of(w.bottom, state.displacement)
                                                : sum_of(w.drift, state.displacement);
    p.residual_drift = signed_drift;
    if (std::abs(signed_drift) > p.peak_drift) {
      p.peak_drift = std::abs(signed_drift);
      p.time = state.time;
    }
    double acceleration = 0.0;
    if (w.top_along.empty())
      acceleration = std::abs(ground_.absolute(state, w.top, w.top_node, w.direction));
    else
      for (std::size_t d = 0; d < w.top_along.size(); ++d)
        if (const auto& [reading, weight] = w.top_along[d]; weight != 0.0)
          acceleration +=
              weight * ground_.absolute(state, reading, w.top_node, static_cast<int>(d));
    acceleration = std::abs(acceleration);
    if (acceleration > p.peak_acceleration) {
      p.peak_acceleration = acceleration;
      p.acceleration_time = state.time;
    }
    if (!w.corners.empty()) record_plan(w, state, p);
  }
}

void JointMonitors::record(const integrators::State& state) {
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    const Where& w = joints_[k];
    const double closing = state.link_penetration[w.link_row] + w.gap;
    JointPeak& p = peaks_[k];
    p.peak_closing = std::max(p.peak_closing, closing);
    p.peak_opening = std::max(p.peak_opening, -closing);
    p.residual_opening = -closing;
    double movement = 0.0;
    if (w.movement.empty())
      movement = model::value_of(w.girder_x, state.displacement) -
                 model::value_of(w.seat_x, state.displacement);
    movement += sum_of(w.movement, state.displacement);
    p.peak_seat_movement = std::max(p.peak_seat_movement, std::abs(movement));
    p.peak_plan_rotation =
        std::max(p.peak_plan_rotation, std::abs(sum_of(w.plan_rotation, state.displacement)));
    p.peak_girder_acceleration = std::max(
        p.peak_girder_acceleration, std::abs(ground_.absolute(state, w.girder_x, w.girder, 0)));
  }
}

}  // namespace pound::results
