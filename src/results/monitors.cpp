#include "results/monitors.hpp"

#include <algorithm>
#include <cmath>

namespace pound::results {
namespace {
double value_at(const Vector& v, Index equation) { return equation < 0 ? 0.0 : v[equation]; }
}  // namespace

void DriftMonitors::record(const integrators::State& state) {
  for (std::size_t k = 0; k < equations_.size(); ++k) {
    const double signed_drift = value_at(state.displacement, equations_[k].second) -
                                value_at(state.displacement, equations_[k].first);
    peaks_[k].residual_drift = signed_drift;
    if (std::abs(signed_drift) > peaks_[k].peak_drift)
      peaks_[k] = {std::abs(signed_drift), state.time, signed_drift};
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
    p.peak_seat_movement =
        std::max(p.peak_seat_movement, std::abs(value_at(state.displacement, w.girder_x) -
                                                value_at(state.displacement, w.seat_x)));
  }
}

}  // namespace pound::results
