#include "verification/transient_run.hpp"

namespace pound::verification {

integrators::State initial_state(const builder::BuiltModel& built,
                                 const assembly::StructuralSystem& system) {
  integrators::State state;
  state.velocity = system.initial_velocity(built.model);
  return state;
}

integrators::TransientStatistics run_analysis(const builder::BuiltModel& built,
                                              assembly::StructuralSystem& system,
                                              integrators::State& state,
                                              const integrators::StepObserver& observer) {
  auto integrator = builder::make_integrator(built.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          builder::make_transient_settings(built.analysis));
  return analysis.run(state, observer);
}

}  // namespace pound::verification
