#include "assembly/modal_analysis.hpp"

#include <Spectra/MatOp/SparseSymMatProd.h>
#include <Spectra/MatOp/SymShiftInvert.h>
#include <Spectra/SymGEigsShiftSolver.h>
#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <optional>
#include <stdexcept>

#include "assembly/not_positive_definite.hpp"

namespace pound::assembly {

namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

constexpr const char* kNotConverged =
    "the eigen-solver did not converge (are masses or stiffnesses many orders of magnitude apart, "
    "or extreme?)";

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

// The massless DOFs must be held by stiffness alone: the first pivot of K_00 = L D L^T at
// round-off level of K_00's largest diagonal (a massless mechanism), or the first of a failed
// factorisation, is refused, naming its DOF (row k of P K_00 P^T is massless[(P i)_k]).
template <typename Permutation>
void refuse_massless_mechanism(const Vector& pivots, const Permutation& permutation, bool factored,
                               double scale, const std::vector<Index>& massless) {
  const Vector order =
      permutation * Vector::LinSpaced(pivots.size(), 0.0, static_cast<double>(pivots.size() - 1));
  for (Index k = 0; k < pivots.size(); ++k)
    if (!factored || !(pivots[k] > 1e-13 * scale))
      throw NotPositiveDefinite(massless[static_cast<std::size_t>(order[k])], pivots[k]);
}

// K_00^-1 rhs for the massless DOFs.
Matrix condensed_solve(const Matrix& k00, const std::vector<Index>& massless, const Matrix& rhs) {
  const Eigen::LDLT<Matrix> factor(k00);
  refuse_massless_mechanism(factor.vectorD(), factor.transpositionsP(),
                            factor.info() == Eigen::Success, k00.diagonal().cwiseAbs().maxCoeff(),
                            massless);
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

void refuse_non_finite(bool finite) {
  if (!finite)
    throw ModalAnalysisError("the stiffness or mass matrix holds values that are not finite");
}

// The DOFs with mass (a nonzero in their row of M) and those without, and the largest |M_ij|.
struct MassSplit {
  std::vector<Index> with_mass, massless;
  double largest = 0.0;
};

MassSplit split_by_mass(const SparseMatrix& mass) {
  Vector row_mass = Vector::Zero(mass.rows());  // the largest |M_ij| of each row
  for (Index col = 0; col < mass.outerSize(); ++col)
    for (SparseMatrix::InnerIterator term(mass, col); term; ++term)
      row_mass[term.row()] = std::max(row_mass[term.row()], std::abs(term.value()));
  MassSplit split;
  for (Index i = 0; i < mass.rows(); ++i)
    (row_mass[i] > 0.0 ? split.with_mass : split.massless).push_back(i);
  split.largest = row_mass.size() ? row_mass.maxCoeff() : 0.0;
  return split;
}

// K_ii / M_ii past 1e150 (w > 1e75 rad/s) over the DOFs with mass is no structure's, and the
// solvers' squares of it overflow: the dense one iterated for a minute before failing.
void refuse_overflowing_ratios(const Vector& stiffness_diagonal, const Vector& mass_diagonal,
                               const std::vector<Index>& with_mass) {
  for (const Index i : with_mass)
    if (!(std::abs(stiffness_diagonal[i]) / mass_diagonal[i] <= 1e150))
      throw ModalAnalysisError(
          "a stiffness-to-mass ratio overflows the number range (a stiffness or mass far beyond "
          "physical ones)");
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
  const SparseMatrix sparse_mass = system.mass_matrix();
  const Matrix mass = Matrix(sparse_mass);
  refuse_non_finite(stiffness.allFinite() && mass.allFinite());
  // Split DOFs with and without mass; condense the massless ones statically.
  const auto [with_mass, massless, largest_mass] = split_by_mass(sparse_mass);
  if (with_mass.empty()) return Modes{Vector(0), Matrix::Zero(n, 0)};
  refuse_overflowing_ratios(stiffness.diagonal(), mass.diagonal(), with_mass);
  const Condensed condensed = condense(stiffness, with_mass, massless);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(
      condensed.reduced, submatrix(mass, with_mass, with_mass));
  if (solver.info() != Eigen::Success || !solver.eigenvalues().allFinite())
    throw ModalAnalysisError(kNotConverged);
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

namespace {

// K + B^T diag(k_rest) B: the linear elements and every link at its initial tangent, sparse.
SparseMatrix sparse_stiffness_with_links(const StructuralSystem& system) {
  const integrators::LinkSet& links = system.links();
  const SparseMatrix connectivity = links.connectivity();
  const SparseMatrix weighted = links.rest_stiffness().asDiagonal() * connectivity;
  return SparseMatrix(system.stiffness()) + SparseMatrix(connectivity.transpose() * weighted);
}

bool all_finite(const SparseMatrix& matrix) {
  return std::all_of(matrix.valuePtr(), matrix.valuePtr() + matrix.nonZeros(),
                     [](double value) { return std::isfinite(value); });
}

// A rigid-body (or mechanism) mode stores no strain energy: phi^T K phi is round-off against the
// sum of its terms' sizes |phi|^T |K| |phi| (about 1e-16 of it), or w^2 is 1e-14 of the smallest
// positive K_ii / M_ii or less (a free mass has no terms, and the solvers mix a little of the
// structure into such modes). A test of w^2 against the highest mode's, as before, took the
// first mode of a cantilever of 90 consistent-mass beams for rigid (w1^2 is 5e-11 of the highest
// there); its energy ratio is 4e-9 (3e-11 at 300 beams, 3e-13 at 1,000), and w1^2 is 1e-10 of
// the smallest diagonal ratio.
struct RigidTest {
  const SparseMatrix& stiffness;
  double least_omega_squared;
  bool stores_strain_energy(const Vector& shape, double omega_squared) const {
    if (!(omega_squared > least_omega_squared)) return false;
    double terms = 0.0;
    for (Index col = 0; col < stiffness.outerSize(); ++col)
      for (SparseMatrix::InnerIterator term(stiffness, col); term; ++term)
        terms += std::abs(term.value() * shape[term.row()] * shape[col]);
    return shape.dot(stiffness * shape) > 1e-12 * terms;
  }
};

// 1e-14 of the smallest positive K_ii / M_ii over the DOFs with mass (0 if none).
double least_omega_squared(const SparseMatrix& stiffness, const SparseMatrix& mass) {
  const Vector stiffness_diagonal = stiffness.diagonal(), mass_diagonal = mass.diagonal();
  double smallest = 0.0;
  for (Index i = 0; i < stiffness.rows(); ++i) {
    const double ratio = stiffness_diagonal[i] / mass_diagonal[i];
    if (mass_diagonal[i] > 0.0 && ratio > 0.0 && (smallest == 0.0 || ratio < smallest))
      smallest = ratio;
  }
  return 1e-14 * smallest;
}

// Columns of `modes` that store strain energy, at most `count`.
Modes vibrating(const Modes& modes, const RigidTest& rigid, int count) {
  std::vector<Index> kept;
  for (Index k = 0; k < modes.omega_squared.size() && static_cast<int>(kept.size()) < count; ++k)
    if (rigid.stores_strain_energy(modes.shapes.col(k), modes.omega_squared[k])) kept.push_back(k);
  Modes result{Vector(static_cast<Index>(kept.size())),
               Matrix(modes.shapes.rows(), static_cast<Index>(kept.size()))};
  for (std::size_t c = 0; c < kept.size(); ++c) {
    result.omega_squared[static_cast<Index>(c)] = modes.omega_squared[kept[c]];
    result.shapes.col(static_cast<Index>(c)) = modes.shapes.col(kept[c]);
  }
  return result;
}

// The massless DOFs' static equations K_00 x_0 = -K_0m x_m, factored once (sparse LDL^T), which
// must hold them as the dense path's condensation asks.
class MasslessCondensation {
 public:
  MasslessCondensation(const SparseMatrix& stiffness, std::vector<Index> massless)
      : stiffness_(stiffness), massless_(std::move(massless)) {
    const Index m = static_cast<Index>(massless_.size());
    if (m == 0) return;
    select_.resize(m, stiffness.rows());
    for (Index r = 0; r < m; ++r) select_.insert(r, massless_[static_cast<std::size_t>(r)]) = 1.0;
    const SparseMatrix k00 = select_ * stiffness * SparseMatrix(select_.transpose());
    factor_.compute(k00);
    // A failed factorisation stops at a zero pivot, which the scan refuses (the pivots after it
    // are never read).
    refuse_massless_mechanism(factor_.vectorD(), factor_.permutationP(), true,
                              k00.diagonal().cwiseAbs().maxCoeff(), massless_);
  }

  // The massless entries of `shape` from the others, as the dense path recovers them (the
  // Lanczos shapes hold whatever the tiny masses there let through).
  void recover(Vector& shape) const {
    if (massless_.empty()) return;
    for (const Index i : massless_) shape[i] = 0.0;
    const Vector loads = select_ * (stiffness_ * shape);
    const Vector massless_part = factor_.solve(-loads);
    for (std::size_t r = 0; r < massless_.size(); ++r)
      shape[massless_[r]] = massless_part[static_cast<Index>(r)];
  }

 private:
  const SparseMatrix& stiffness_;
  std::vector<Index> massless_;
  SparseMatrix select_;
  Eigen::SimplicialLDLT<SparseMatrix> factor_;
};

// Models up to this many DOFs take the dense solve (every mode, in well under a second); so do
// models up to modal_analysis's 4,000 when a quarter of their modes or more, or more than the
// Lanczos solve's most, is asked for. Past 4,000 DOFs at most 500 modes are found (a few seconds
// at 5,000 DOFs; all of them would take the Lanczos basis to the model's size, and minutes).
constexpr Index kDenseModalDofs = 300;

// The pencil (K, M) of the sparse path: M with a mass 1e-12 of the largest on each massless
// DOF, so that it is positive definite as the Lanczos inner product needs (their modes go past
// 1e12 times the highest; the shapes' massless entries are recovered statically afterwards).
struct Pencil {
  const SparseMatrix& stiffness;
  SparseMatrix mass;
  const MasslessCondensation& condensation;
};

// One step of subspace iteration on the Lanczos shapes, Y = (K - shift M)^-1 M X, their massless
// entries recovered statically, then Rayleigh-Ritz on (Y^T K Y, Y^T M Y): ascending,
// mass-normalised modes whose w^2 are Rayleigh quotients of the real pencil (Spectra's own values
// are those of the shifted solves, 1e-8 off w^2 on the tests' rigid-body chain), the traces of
// far higher modes divided by the ratio of the frequencies, the neighbouring ones sorted out.
template <typename ShiftInvert>
Modes refined(const Pencil& pencil, const ShiftInvert& inverse, const Matrix& shapes) {
  Matrix iterated(shapes.rows(), shapes.cols());
  for (Index k = 0; k < shapes.cols(); ++k) {
    const Vector load = pencil.mass * shapes.col(k);
    Vector shape(shapes.rows());
    inverse.perform_op(load.data(), shape.data());
    pencil.condensation.recover(shape);
    iterated.col(k) = shape / shape.norm();
  }
  const Matrix projected_stiffness = iterated.transpose() * (pencil.stiffness * iterated);
  const Matrix projected_mass = iterated.transpose() * (pencil.mass * iterated);
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> ritz(projected_stiffness, projected_mass);
  if (ritz.info() != Eigen::Success || !ritz.eigenvalues().allFinite())
    throw ModalAnalysisError(kNotConverged);
  return Modes{ritz.eigenvalues(), iterated * ritz.eigenvectors()};
}

// The ascending `wanted` modes nearest above `shift`: shift-invert Lanczos (Spectra), refined.
Modes lanczos_modes(const Pencil& pencil, double shift, Index wanted) {
  using ShiftInvert = Spectra::SymShiftInvert<double, Eigen::Sparse, Eigen::Sparse>;
  using MassProduct = Spectra::SparseSymMatProd<double>;
  const Index n = pencil.stiffness.rows();
  ShiftInvert inverse(pencil.stiffness, pencil.mass);
  MassProduct mass_product(pencil.mass);
  const Index vectors = std::min(n, std::max<Index>(2 * wanted + 1, wanted + 20));
  Matrix shapes;
  try {
    Spectra::SymGEigsShiftSolver<ShiftInvert, MassProduct, Spectra::GEigsMode::ShiftInvert> solver(
        inverse, mass_product, wanted, vectors, shift);
    solver.init();
    solver.compute(Spectra::SortRule::LargestMagn, 1000, 1e-11);
    if (solver.info() != Spectra::CompInfo::Successful || !solver.eigenvalues().allFinite())
      throw ModalAnalysisError("");
    shapes = solver.eigenvectors();
  } catch (const std::exception&) {  // Spectra's failed shift factorisation, or no convergence
    throw ModalAnalysisError(kNotConverged);
  }
  return refined(pencil, inverse, shapes);
}

// The sparse path of vibration_modes: nothing when the rigid-body modes, which come out first,
// crowd out so many that the dense solve is the one to take.
std::optional<Modes> sparse_vibration_modes(const StructuralSystem& system, int count) {
  const SparseMatrix stiffness = sparse_stiffness_with_links(system);
  SparseMatrix mass = system.mass_matrix();
  refuse_non_finite(all_finite(stiffness) && all_finite(mass));
  const Index n = stiffness.rows();
  const auto [with_mass, massless, largest_mass] = split_by_mass(mass);
  if (with_mass.empty()) return Modes{Vector(0), Matrix::Zero(n, 0)};
  refuse_overflowing_ratios(stiffness.diagonal(), mass.diagonal(), with_mass);
  const MasslessCondensation condensation(stiffness, massless);
  const RigidTest rigid{stiffness, least_omega_squared(stiffness, mass)};
  // 1e-12 of the smallest positive K_ii / M_ii below 0: K - shift M is regular with rigid-body
  // modes, and the shift far below the first vibration mode (the diagonal ratios exceed its w^2
  // by about the square of the elements per wavelength).
  const double shift = rigid.least_omega_squared > 0.0 ? -100.0 * rigid.least_omega_squared : -1.0;
  for (const Index i : massless) mass.coeffRef(i, i) = 1e-12 * largest_mass;
  const Pencil pencil{stiffness, std::move(mass), condensation};
  // Lanczos finds at most n - 1 modes; nearly all of them take the dense solve, where it can.
  // Past it the basis stops at 2,000 modes (more rigid-body modes than that leave fewer listed).
  Index available = std::min(static_cast<Index>(with_mass.size()), n - 1);
  if (n > kLargestDenseModalDofs) available = std::min<Index>(available, kLanczosBasis);
  for (Index extra = 6;; extra *= 4) {
    if (count + extra >= available && n <= kLargestDenseModalDofs) return {};
    const Index wanted = std::min<Index>(count + extra, available);
    Modes modes = vibrating(lanczos_modes(pencil, shift, wanted), rigid, count);
    if (modes.omega_squared.size() >= count || wanted == available) return modes;
  }
}

Modes dense_vibration_modes(const StructuralSystem& system, int count) {
  const SparseMatrix stiffness = sparse_stiffness_with_links(system);
  const RigidTest rigid{stiffness, least_omega_squared(stiffness, system.mass_matrix())};
  return vibrating(modal_analysis(system, kLargestDenseModalDofs), rigid, count);
}

}  // namespace

Modes vibration_modes(const StructuralSystem& system, int count) {
  const Index n = system.size();
  const bool many = 4 * (Index{count} + 6) >= n || count > kMostLanczosModes;
  if (n <= kDenseModalDofs || (n <= kLargestDenseModalDofs && many))
    return dense_vibration_modes(system, count);
  std::optional<Modes> modes = sparse_vibration_modes(system, std::min(count, kMostLanczosModes));
  return modes ? *modes : dense_vibration_modes(system, count);
}

std::string fewer_modes_reason(Index dofs, Index dofs_with_mass, int asked, Index found) {
  if (found >= asked) return {};
  if (dofs > kLargestDenseModalDofs && asked > kMostLanczosModes && found == kMostLanczosModes)
    return fmt::format("past {} DOFs at most the first {} modes are found", kLargestDenseModalDofs,
                       kMostLanczosModes);
  if (found == dofs_with_mass)
    return fmt::format("the model has {} DOF{} with mass, hence {} mode{}", dofs_with_mass,
                       dofs_with_mass == 1 ? "" : "s", dofs_with_mass,
                       dofs_with_mass == 1 ? "" : "s");
  if (dofs > kLargestDenseModalDofs && dofs_with_mass > kLanczosBasis)
    return fmt::format(
        "past {} DOFs the search stops at {} modes, and the others among them are rigid-body or "
        "mechanism modes (no strain energy), which are not listed",
        kLargestDenseModalDofs, kLanczosBasis);
  const Index rigid = dofs_with_mass - found;
  return fmt::format(
      "{} of the model's {} modes (one per DOF with mass) {} no strain energy (a part free to "
      "move as a whole, or a mechanism) and {} not listed",
      rigid, dofs_with_mass, rigid == 1 ? "stores" : "store", rigid == 1 ? "is" : "are");
}

std::vector<double> natural_periods(const StructuralSystem& system, int count) {
  const Modes modes = vibration_modes(system, count);
  std::vector<double> periods;
  for (const double omega_squared : modes.omega_squared)
    periods.push_back(2.0 * std::numbers::pi / std::sqrt(omega_squared));
  return periods;
}

}  // namespace pound::assembly
