#pragma once
// The transient run the benchmarks share: the integrator and step settings the built model asks
// for, on its structural system.
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "integrators/transient_analysis.hpp"

namespace pound::verification {

// The state at t = 0: no displacement, the model's initial velocities.
integrators::State initial_state(const builder::BuiltModel& built,
                                 const assembly::StructuralSystem& system);

// Runs the built model's analysis from `state` to its end time.
integrators::TransientStatistics run_analysis(const builder::BuiltModel& built,
                                              assembly::StructuralSystem& system,
                                              integrators::State& state,
                                              const integrators::StepObserver& observer);

}  // namespace pound::verification
