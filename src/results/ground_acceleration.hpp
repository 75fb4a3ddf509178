#pragma once
// The ground's acceleration (assembly::StructuralSystem's), which recorders and monitors add to
// the relative accelerations the equations of motion carry, for absolute ones. One object serves
// every observer of a run: the frame's acceleration at the free DOFs is made once per step.
#include <functional>
#include <limits>

#include "core/types.hpp"
#include "integrators/integrator.hpp"
#include "model/dof_term.hpp"

namespace pound::results {

// How a recorded DOF is read from a state: its terms (model::DofMap::terms), none where fixed.
using DofReading = std::vector<model::DofTerm>;

class GroundAcceleration {
 public:
  using Frame = std::function<void(double time, Vector& free_dofs)>;  // added to a there
  using Support = std::function<double(Index node, int direction, double time)>;  // fixed DOF

  GroundAcceleration(Frame frame, Support support)
      : frame_(std::move(frame)), support_(std::move(support)) {}

  // The absolute acceleration along `direction` of `node` in `state`, read there through
  // `reading` (none where fixed: the ground's own).
  double absolute(const integrators::State& state, const DofReading& reading, Index node,
                  int direction) {
    if (reading.empty()) return support_(node, direction, state.time);
    update_frame(state.time);
    const auto at = [&](const model::DofTerm& term) {
      return term.coefficient * (state.acceleration[term.equation] + frame_now_[term.equation]);
    };
    double acceleration = at(reading[0]);
    for (std::size_t k = 1; k < reading.size(); ++k) acceleration += at(reading[k]);
    return acceleration;
  }
  // The frame's acceleration at every free DOF at `time` (absolute() adds it to a there).
  const Vector& frame(double time) {
    update_frame(time);
    return frame_now_;
  }

 private:
  void update_frame(double time) {
    if (!(time == frame_time_)) {
      frame_(time, frame_now_);
      frame_time_ = time;
    }
  }

  Frame frame_;
  Support support_;
  double frame_time_ = std::numeric_limits<double>::quiet_NaN();  // of frame_now_
  Vector frame_now_;
};

}  // namespace pound::results
