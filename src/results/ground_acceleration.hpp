#pragma once
// The ground's acceleration (assembly::StructuralSystem's), which recorders and monitors add to
// the relative accelerations the equations of motion carry, for absolute ones. One object serves
// every observer of a run: the frame's acceleration at the free DOFs is made once per step.
#include <functional>
#include <limits>

#include "core/types.hpp"
#include "integrators/integrator.hpp"

namespace pound::results {

class GroundAcceleration {
 public:
  using Frame = std::function<void(double time, Vector& free_dofs)>;  // added to a there
  using Support = std::function<double(Index node, int direction, double time)>;  // fixed DOF

  GroundAcceleration(Frame frame, Support support)
      : frame_(std::move(frame)), support_(std::move(support)) {}

  // The absolute acceleration along `direction` of `node` in `state`, its equation there being
  // `equation` (-1 where fixed: the ground's own).
  double absolute(const integrators::State& state, Index equation, Index node, int direction) {
    if (equation < 0) return support_(node, direction, state.time);
    if (!(state.time == frame_time_)) {
      frame_(state.time, frame_now_);
      frame_time_ = state.time;
    }
    return state.acceleration[equation] + frame_now_[equation];
  }

 private:
  Frame frame_;
  Support support_;
  double frame_time_ = std::numeric_limits<double>::quiet_NaN();  // of frame_now_
  Vector frame_now_;
};

}  // namespace pound::results
