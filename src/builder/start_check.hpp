#pragma once
// What makes a run fail at t = 0, found before it starts (by `run` before anything is written,
// and by `check`): the first step is taken once on the assembled system, exactly as the run will
// take it (static equilibrium when asked, the integrator's start and its first factorization),
// and a matrix that is singular or indefinite there is an error naming the node it fails at.
#include <string>

#include "assembly/not_positive_definite.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"

namespace pound::builder {

// Takes the first step of `analysis` (its time step settled) on `system` and reverts it. Throws
// InputError (file `source`, the node's JSON path) when a factorization fails.
void check_first_step(const BuiltModel& built, const AnalysisSpec& analysis,
                      assembly::StructuralSystem& system, const std::string& source);

// "node 'id', direction x" for an equation of `built`'s model ("equation N" for a tied one).
std::string equation_words(const BuiltModel& built, const model::DofMap& dofs, Index equation);

// The error for a factorization that failed at a DOF of `built`'s model: the node, its direction
// and what to do, at the node's JSON path (its generator's, for a generated node). `during`
// says what was being factored.
InputError not_held_error(const BuiltModel& built, const model::DofMap& dofs,
                          const assembly::NotPositiveDefinite& failure, const std::string& during,
                          const std::string& source);

// The error for a modal analysis that failed (`reason`): at the DOF with the largest ratio of
// stiffness to mass, which is where extreme values make the eigenproblem unsolvable.
InputError extreme_mode_error(const BuiltModel& built, const assembly::StructuralSystem& system,
                              const std::string& reason, const std::string& source);

}  // namespace pound::builder
