#pragma once
// A time integrator advances a SecondOrderSystem by one step and says whether the step
// converged; the driver (TransientAnalysis) decides what to do when it did not.
#include <string>
#include <utility>

#include "core/types.hpp"
#include "integrators/second_order_system.hpp"

namespace pound::integrators {

struct State {
  double time = 0.0;
  Vector displacement;
  Vector velocity;
  Vector acceleration;
  Vector link_penetration;  // delta of every link
  Vector link_force;        // F of every link (compression > 0)
};

// Member by member: each vector's buffers change hands (std::swap's three moves through a
// temporary cost 40 instructions more, 1.4 % of a two-DOF step).
inline void swap(State& a, State& b) noexcept {
  std::swap(a.time, b.time);
  a.displacement.swap(b.displacement);
  a.velocity.swap(b.velocity);
  a.acceleration.swap(b.acceleration);
  a.link_penetration.swap(b.link_penetration);
  a.link_force.swap(b.link_force);
}

// Equilibrium iteration stops when the unbalanced force is small against the forces present:
//   ||R|| <= relative_tolerance * max(||f_ext||, ||B^T F||) + absolute_tolerance,
// or, when a very stiff penalty keeps the residual at its round-off (stiffness x eps x
// displacement), once the Newton correction itself is below 1e-14 of the link forces. Kawashima
// (1980) used a relative tolerance of 1e-3; the default is much tighter because the condensed
// iteration is cheap.
struct ConvergenceTest {
  double relative_tolerance = 1e-10;
  double absolute_tolerance = 0.0;  // [F]
  int max_iterations = 25;
};

struct StepResult {
  bool converged = false;
  int iterations = 0;           // linearised corrections made
  double unbalanced_force = 0;  // ||R|| at the accepted iterate [F]
  std::string failure;          // why not, when !converged
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  virtual std::string name() const = 0;
  // Completes `state` (acceleration, link state) at its time from u and v; `first_step` is the
  // size of the step to come (central difference enforces hard contacts over it).
  virtual void initialize(SecondOrderSystem& system, State& state, double first_step) = 0;
  // Tries one step of size dt from `from` into `to`, which is at time `end` (from.time + dt up
  // to rounding: a run's steps end on its grid of k dt, and the loads are taken there, at the
  // time the step is reported at); links are left at the trial state.
  virtual StepResult advance(SecondOrderSystem& system, const State& from, double dt, double end,
                             State& to) = 0;
};

}  // namespace pound::integrators
