#pragma once
// Static pushover under displacement control: the constant loads f_0 (gravity, nodal loads) stay
// on, a lateral load pattern p grows with a load factor lambda, and one DOF c (the control node
// in the control direction) is moved to its targets in equal increments:
//
//   K u + B^T F(B u - gap) = f_0 + lambda p,     u_c = target
//
// solved at each increment by Newton on (u, lambda) with the bordered tangent
//   [K + B^T k_t B   -p] [du     ]   [residual      ]
//   [e_c^T            0] [dlambda] = [target - u_c  ]
// (sparse LU), so the capacity curve passes its peak and descends (a softening hinge, P-Delta)
// where load control would stop; the links' states are committed at each converged increment,
// so hysteretic laws follow the loading path (OpenSees' DisplacementControl integrator). With
// p normalised so that its components along the push direction sum to 1, lambda is the base
// shear. An increment that does not converge is halved, up to `max_cuts` times; then the push
// ends there (a mechanism, or a target past the model's reach) and says so.
#include <functional>
#include <string>
#include <vector>

#include "assembly/structural_system.hpp"

namespace pound::assembly {

struct PushoverControl {
  Index equation = 0;    // c
  double target = 0.0;   // final u_c [L]
  int increments = 100;  // equal steps to the target
  Vector pattern;        // p over the free DOFs
  double relative_tolerance = 1e-10;
  int max_iterations = 30;
  int max_cuts = 8;
};

struct PushoverPoint {
  double displacement = 0.0;  // u_c
  double load_factor = 0.0;   // lambda
  int iterations = 0;
};

struct PushoverResult {
  std::vector<PushoverPoint> curve;  // from the start state (lambda = 0)
  Vector displacement;               // u at the last converged point
  std::string stopped;               // why the push ended before the target; empty when reached
  // When it stopped: the DOFs the pattern loads that nothing held as the last increment started
  // (no element, their links open or pulled apart), the likely cause: Newton moves such a DOF
  // by the load over a 1e-12 stiffness (hold_unheld_dofs) before its contact can hold it.
  std::vector<Index> unheld_loaded;
};

// Called after each converged point with the state, before the next increment.
using PushoverObserver = std::function<void(const PushoverPoint&, const Vector& u)>;

// From `start` (the static state under f_0, links committed there) to the target.
PushoverResult pushover(StructuralSystem& system, const Vector& start,
                        const PushoverControl& control, const PushoverObserver& observe = {});

}  // namespace pound::assembly
