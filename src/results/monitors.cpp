#include "results/monitors.hpp"

#include <algorithm>
#include <cmath>

namespace pound::results {
namespace {
double value_at(const Vector& v, Index equation) { return equation < 0 ? 0.0 : v[equation]; }
}  // namespace

void DriftMonitors::record(const integrators::State& state) {
  for (std::size_t k = 0; k < storeys_.size(); ++k) {
    const Where& w = storeys_[k];
    DriftPeak& p = peaks_[k];
    const double signed_drift =
        value_at(state.displacement, w.top) - value_at(state.displacement, w.bottom);
    p.residual_drift = signed_drift;
    if (std::abs(signed_drift) > p.peak_drift) {
      p.peak_drift = std::abs(signed_drift);
      p.time = state.time;
    }
    const double acceleration = std::abs(ground_.absolute(state, w.top, w.top_node, w.direction));
    if (acceleration > p.peak_acceleration) {
      p.peak_acceleration = acceleration;
      p.acceleration_time = state.time;
    }
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
      movement = value_at(state.displacement, w.girder_x) - value_at(state.displacement, w.seat_x);
    for (const Where::Term& term : w.movement)
      movement += term.coefficient * state.displacement[term.equation];
    p.peak_seat_movement = std::max(p.peak_seat_movement, std::abs(movement));
    p.peak_girder_acceleration = std::max(
        p.peak_girder_acceleration, std::abs(ground_.absolute(state, w.girder_x, w.girder, 0)));
  }
}

}  // namespace pound::results
