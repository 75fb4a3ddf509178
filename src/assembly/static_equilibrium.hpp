#pragma once
// Static equilibrium under the loads at one instant, with the links:
//   K u + B^T F(B u - gap + s(t)) = f(t),
// solved by Newton on the assembled K + B^T (dF/d delta) B (sparse LU: a slipping friction link's
// tangent is not symmetric). The links are at rest (zero rates), as in a structure loaded slowly
// until t = 0 (OpenSees' gravity analysis before the dynamic one); their state at the solution
// is committed, so a dynamic run started from u continues from that state. Hard contacts and their
// friction are constraints with their forces as multipliers (a primal-dual active set inside the
// same Newton iteration: static_equilibrium.cpp). Throws SolveError when Newton does not converge
// or the structure is a mechanism under the loads.
#include <functional>
#include <vector>

#include "assembly/structural_system.hpp"

namespace pound::assembly {

struct StaticEquilibrium {
  Vector displacement;
  int iterations = 0;
  double unbalanced_force = 0.0;  // ||f - K u - B^T F|| at the solution [F]
};

// A DOF that nothing holds at rest (a backwall behind open backfill, held only when the joint
// closes) has a zero diagonal: 1e-12 of the largest one there keeps the tangent regular, and
// the DOF stays where it is unless a load acts on it (then the contact it moves into holds it).
void hold_unheld_dofs(Eigen::SparseMatrix<double>& tangent);

// The DOFs hold_unheld_dofs would hold in K + B^T (dF/d delta) B at the links' trial state:
// no element stiffness, and no link with a tangent there (open, pulled apart, or none).
std::vector<Index> unheld_dofs(const StructuralSystem& system, const Matrix& link_tangent);

// K + B^T (dF/d delta) B with its unheld DOFs held: the static tangent at the links' trial state
// (`link_tangent` as LinkSet::set_trial gives it). `hold_link_held`: also every DOF that only
// links hold (no element stiffness), by the same 1e-12 spring: for a tangent that is singular
// without a zero diagonal, a DOF free along a direction its links leave open that is not one of
// its axes (a curved bridge's backwall, its backfill open, free along the bridge's turned
// tangent). The solvers ask for it only when the plain tangent does not factor, so every other
// solution is unchanged.
Eigen::SparseMatrix<double> static_tangent(const StructuralSystem& system,
                                           const Matrix& link_tangent, bool hold_link_held = false);

// Solves matrix(false) x = rhs, or, where that does not factor or gives a non-finite x,
// matrix(true) x = rhs (the tangent with static_tangent's `hold_link_held`); false when neither
// does (a mechanism).
bool solve_static(const std::function<Eigen::SparseMatrix<double>(bool)>& matrix, const Vector& rhs,
                  Vector& solution);

StaticEquilibrium static_equilibrium(StructuralSystem& system, double time,
                                     double relative_tolerance = 1e-10, int max_iterations = 50);

}  // namespace pound::assembly
