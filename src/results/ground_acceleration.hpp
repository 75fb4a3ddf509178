#pragma once
// The ground's acceleration (assembly::StructuralSystem's), which recorders and monitors add to
// the relative accelerations the equations of motion carry, for absolute ones. One object serves
// every observer of a run: the ground's values are read once per step, and the frame's
// acceleration formed only at the DOFs read (a bridge's monitors read a few girders).
#include <functional>
#include <limits>
#include <vector>

#include "core/types.hpp"
#include "integrators/integrator.hpp"
#include "model/dof_term.hpp"

namespace pound::results {

// How a recorded DOF is read from a state: its terms (model::DofMap::terms), none where fixed.
using DofReading = std::vector<model::DofTerm>;

class GroundAcceleration {
 public:
  // The frame's acceleration at the free DOFs is sum_j scale_j(t) shape_j (an excitation's
  // record times its influence vector, a moving support's): `scales` gives them at a time.
  using Scales = std::function<void(double time, std::vector<double>& scales)>;
  using Support = std::function<double(Index node, int direction, double time)>;  // fixed DOF

  // `size`: the free DOFs (the shapes' length, and the frame's where there are none).
  GroundAcceleration(Index size, Scales scales, std::vector<Vector> shapes, Support support)
      : scales_(std::move(scales)),
        shapes_(std::move(shapes)),
        support_(std::move(support)),
        frame_now_(Vector::Zero(size)) {}

  // The absolute acceleration along `direction` of `node` in `state`, read there through
  // `reading` (none where fixed: the ground's own). Only the frame's entries read are formed,
  // each as frame() forms it.
  double absolute(const integrators::State& state, const DofReading& reading, Index node,
                  int direction) {
    if (reading.empty()) return support_(node, direction, state.time);
    update_scales(state.time);
    // The frame made at this time already (for a building's storeys) is read, not formed again.
    const bool made = frame_time_ == state.time;
    const auto at = [&](const model::DofTerm& term) {
      const double frame = made ? frame_now_[term.equation] : frame_at(term.equation);
      return term.coefficient * (state.acceleration[term.equation] + frame);
    };
    double acceleration = at(reading[0]);
    for (std::size_t k = 1; k < reading.size(); ++k) acceleration += at(reading[k]);
    return acceleration;
  }
  // The frame's acceleration at every free DOF at `time` (absolute() adds it to a there).
  const Vector& frame(double time) {
    update_scales(time);
    if (!(frame_time_ == time) && !shapes_.empty()) {
      double* const frame = frame_now_.data();
      const Index n = frame_now_.size();
      for (std::size_t j = 0; j < shapes_.size(); ++j) {  // a shape at a time, as frame_at adds
        const double scale = scale_now_[j], *const shape = shapes_[j].data();
        if (j == 0)
          for (Index e = 0; e < n; ++e) frame[e] = scale * shape[e];
        else
          for (Index e = 0; e < n; ++e) frame[e] += scale * shape[e];
      }
      frame_time_ = time;
    }
    return frame_now_;
  }

 private:
  void update_scales(double time) {
    if (!(time == scales_time_)) {
      scales_(time, scale_now_);
      scales_time_ = time;
    }
  }
  // The first shape's term written, then the others added in order.
  double frame_at(Index equation) const {
    if (shapes_.empty()) return 0.0;
    double frame = scale_now_[0] * shapes_[0][equation];
    for (std::size_t j = 1; j < shapes_.size(); ++j) frame += scale_now_[j] * shapes_[j][equation];
    return frame;
  }

  Scales scales_;
  std::vector<Vector> shapes_;
  Support support_;
  double scales_time_ = std::numeric_limits<double>::quiet_NaN();  // of scale_now_
  std::vector<double> scale_now_;
  double frame_time_ = std::numeric_limits<double>::quiet_NaN();  // of frame_now_
  Vector frame_now_;
};

}  // namespace pound::results
