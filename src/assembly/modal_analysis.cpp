#include "assembly/modal_analysis.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <numbers>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {
namespace {

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

}  // namespace

Modes modal_analysis(const StructuralSystem& system, Index max_dofs) {
  const Index n = system.size();
  if (n > max_dofs)
    throw std::length_error(
        fmt::format("modal analysis of {} DOFs: the dense eigen-solver is "
                    "limited to {} DOFs",
                    n, max_dofs));
  Matrix stiffness = Matrix(system.stiffness());
  const Matrix mass = Matrix(system.mass_matrix());
  if (!stiffness.allFinite() || !mass.allFinite())
    throw ModalAnalysisError("the stiffness or mass matrix holds values that are not finite");
  // Links at their initial tangent (penetration -gap, at rest), on copies of their laws.
  const integrators::LinkSet& links = system.links();
  const Matrix connectivity = Matrix(links.connectivity());
  for (Index k = 0; k < links.count(); ++k) {
    const Index row = links.row(k);
    auto law = links.law(k).clone();
    const double tangent = law->set_trial({-links.gaps()[row], 0.0, 0.0}).stiffness;
    if (tangent != 0.0)
      stiffness += tangent * connectivity.row(row).transpose() * connectivity.row(row);
  }
  // Split DOFs with and without mass; condense the massless ones statically.
  std::vector<Index> with_mass, massless;
  for (Index i = 0; i < n; ++i)
    (mass.row(i).cwiseAbs().maxCoeff() > 0.0 ? with_mass : massless).push_back(i);
  const auto m_count = static_cast<Index>(with_mass.size()),
             z_count = static_cast<Index>(massless.size());
  if (m_count == 0) return Modes{Vector(0), Matrix::Zero(n, 0)};
  auto block = [](const Matrix& a, const std::vector<Index>& rows, const std::vector<Index>& cols) {
    Matrix out(rows.size(), cols.size());
    for (std::size_t r = 0; r < rows.size(); ++r)
      for (std::size_t c = 0; c < cols.size(); ++c) out(r, c) = a(rows[r], cols[c]);
    return out;
  };
  Matrix reduced = block(stiffness, with_mass, with_mass);
  Matrix recovery(z_count, m_count);  // x_0 = recovery x_m
  if (z_count > 0) {
    recovery = -condensed_solve(block(stiffness, massless, massless), massless,
                                block(stiffness, massless, with_mass));
    reduced += block(stiffness, with_mass, massless) * recovery;
  }
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(reduced,
                                                                block(mass, with_mass, with_mass));
  if (solver.info() != Eigen::Success || !solver.eigenvalues().allFinite())
    throw ModalAnalysisError(
        "the eigen-solver did not converge (are masses or stiffnesses many orders of magnitude "
        "apart, or extreme?)");
  Modes modes;
  modes.omega_squared = solver.eigenvalues();
  modes.shapes = Matrix::Zero(n, m_count);
  for (Index r = 0; r < m_count; ++r) modes.shapes.row(with_mass[r]) = solver.eigenvectors().row(r);
  if (z_count > 0) {
    const Matrix recovered = recovery * solver.eigenvectors();
    for (Index r = 0; r < z_count; ++r) modes.shapes.row(massless[r]) = recovered.row(r);
  }
  return modes;
}

std::vector<double> natural_periods(const StructuralSystem& system, int count) {
  const Modes modes = modal_analysis(system);
  const double largest = modes.omega_squared.size() ? modes.omega_squared.maxCoeff() : 0.0;
  std::vector<double> periods;
  for (Index k = 0; k < modes.omega_squared.size() && static_cast<int>(periods.size()) < count; ++k)
    if (modes.omega_squared[k] > 1e-10 * largest)  // rigid-body modes have no period
      periods.push_back(2.0 * std::numbers::pi / std::sqrt(modes.omega_squared[k]));
  return periods;
}

}  // namespace pound::assembly
