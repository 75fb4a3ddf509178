#include "assembly/modal_analysis.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {

namespace {

// K with every link row at its initial tangent (penetration -gap, at rest).
Matrix stiffness_with_links(const StructuralSystem& system) {
  Matrix stiffness = Matrix(system.stiffness());
  const integrators::LinkSet& links = system.links();
  const Matrix connectivity = Matrix(links.connectivity());
  const Vector tangent = links.rest_stiffness();
  for (Index row = 0; row < links.size(); ++row)
    if (tangent[row] != 0.0)
      stiffness += tangent[row] * connectivity.row(row).transpose() * connectivity.row(row);
  return stiffness;
}

Matrix submatrix(const Matrix& a, const std::vector<Index>& rows, const std::vector<Index>& cols) {
  Matrix out(rows.size(), cols.size());
  for (std::size_t r = 0; r < rows.size(); ++r)
    for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = a(rows[r], cols[c]);
  return out;
}

// K_00^-1 rhs for the massless DOFs, which must be held by stiffness alone: a pivot at round-off
// level (a massless mechanism) is refused, naming its DOF (row k of P K_00 P^T is (P i)_k).
Matrix condensed_solve(const Matrix& k00, const std::vector<Index>& massless, const Matrix& rhs) {
  const Eigen::LDLT<Matrix> factor(k00);
  const Vector& pivots = factor.vectorD();
  const double scale = k00.diagonal().cwiseAbs().maxCoeff();
  Vector order = Vector::LinSpaced(k00.rows(), 0.0, static_cast<double>(k00.rows() - 1));
  order = factor.transpositionsP() * order;
  for (Index k = 0; k < pivots.size(); ++k)
    if (factor.info() != Eigen::Success || !(pivots[k] > 1e-13 * scale))
      throw NotPositiveDefinite(massless[static_cast<std::size_t>(order[k])], pivots[k]);
  return factor.solve(rhs);
}

// Static condensation of the massless DOFs: K_mm - K_m0 K_00^-1 K_0m, and x_0 = recovery x_m.
struct Condensed {
  Matrix reduced;
  Matrix recovery;
};

Condensed condense(const Matrix& stiffness, const std::vector<Index>& with_mass,
                   const std::vector<Index>& massless) {
  Condensed c{submatrix(stiffness, with_mass, with_mass),
              Matrix(static_cast<Index>(massless.size()), static_cast<Index>(with_mass.size()))};
  if (!massless.empty()) {
    c.recovery = -condensed_solve(submatrix(stiffness, massless, massless), massless,
                                  submatrix(stiffness, massless, with_mass));
    c.reduced += submatrix(stiffness, with_mass, massless) * c.recovery;
  }
  return c;
}

}  // namespace

Vector stiffness_diagonal_with_links(const StructuralSystem& system) {
  Vector diagonal = system.stiffness().diagonal();
  const integrators::LinkSet& links = system.links();
  const Vector tangent = links.rest_stiffness();
  for (Index row = 0; row < links.size(); ++row) {
    if (tangent[row] == 0.0) continue;
    for (integrators::LinkSet::SparseRowMatrix::InnerIterator term(links.connectivity(), row); term;
         ++term)
      diagonal[term.col()] += tangent[row] * term.value() * term.value();
  }
  return diagonal;
}

Modes modal_analysis(const StructuralSystem& system, Index max_dofs) {
  const Index n = system.size();
  if (n > max_dofs)
    throw std::length_error(
        fmt::format("modal analysis of {} DOFs: the dense eigen-solver is "
                    "limited to {} DOFs",
                    n, max_dofs));
  const Matrix stiffness = stiffness_with_links(system);
  const Matrix mass = Matrix(system.mass_matrix());
  if (!stiffness.allFinite() || !mass.allFinite())
    throw ModalAnalysisError("the stiffness or mass matrix holds values that are not finite");
  // Split DOFs with and without mass; condense the massless ones statically.
  std::vector<Index> with_mass, massless;
  for (Index i = 0; i < n; ++i)
    (mass.row(i).cwiseAbs().maxCoeff() > 0.0 ? with_mass : massless).push_back(i);
  if (with_mass.empty()) return Modes{Vector(0), Matrix::Zero(n, 0)};
  // w^2 past 1e150 (w > 1e75 rad/s) is no structure's, and the solver's squares of it overflow:
  // it would iterate for a minute before failing.
  for (const Index i : with_mass)
    if (!(std::abs(stiffness(i, i)) / mass(i, i) <= 1e150))
      throw ModalAnalysisError(
          "a stiffness-to-mass ratio overflows the number range (a stiffness or mass far beyond "
          "physical ones)");
  const Condensed condensed = condense(stiffness, with_mass, massless);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(
      condensed.reduced, submatrix(mass, with_mass, with_mass));
  if (solver.info() != Eigen::Success || !solver.eigenvalues().allFinite())
    throw ModalAnalysisError(
        "the eigen-solver did not converge (are masses or stiffnesses many orders of magnitude "
        "apart, or extreme?)");
  Modes modes;
  modes.omega_squared = solver.eigenvalues();
  modes.shapes = Matrix::Zero(n, static_cast<Index>(with_mass.size()));
  for (std::size_t r = 0; r < with_mass.size(); ++r)
    modes.shapes.row(with_mass[r]) = solver.eigenvectors().row(static_cast<Index>(r));
  if (!massless.empty()) {
    const Matrix recovered = condensed.recovery * solver.eigenvectors();
    for (std::size_t r = 0; r < massless.size(); ++r)
      modes.shapes.row(massless[r]) = recovered.row(static_cast<Index>(r));
  }
  return modes;
}

std::vector<double> natural_periods(const StructuralSystem& system, int count, Index max_dofs) {
  const Modes modes = modal_analysis(system, max_dofs);
  const double largest = modes.omega_squared.size() ? modes.omega_squared.maxCoeff() : 0.0;
  std::vector<double> periods;
  for (Index k = 0; k < modes.omega_squared.size() && static_cast<int>(periods.size()) < count; ++k)
    if (modes.omega_squared[k] > 1e-10 * largest)  // rigid-body modes have no period
      periods.push_back(2.0 * std::numbers::pi / std::sqrt(modes.omega_squared[k]));
  return periods;
}

}  // namespace pound::assembly
