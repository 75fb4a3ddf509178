#include "assembly/structural_system.hpp"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

#include "assembly/band_ordering.hpp"
#include "assembly/banded_ldlt.hpp"
#include "assembly/not_positive_definite.hpp"
#include "assembly/twisted_tridiagonal.hpp"
#include "core/errors.hpp"
#include "core/packets.hpp"
#include "core/sparse_rows.hpp"

namespace pound::assembly {
namespace {

// Bands up to kUnrolledBand have their substitution unrolled (BandedLdlt::substitute); up to
// kBandedLimit a band LDL^T beats the general sparse one.
constexpr Index kUnrolledBand = BandedLdlt::kUnrolledBand, kBandedLimit = 32;

template <typename Factor>
class FactorSolver final : public integrators::LinearSolver {
 public:
  explicit FactorSolver(const Eigen::SparseMatrix<double>& matrix) : factor_(matrix) {}
  explicit FactorSolver(Factor factor) : factor_(std::move(factor)) {}
  void solve(const Vector& rhs, Vector& solution) const override { factor_.solve(rhs, solution); }

 private:
  Factor factor_;
};

// Rows i, ..., i + 3 of a band product (Band = 0: the bandwidth b at run time) into out[0, 4),
// their sums in one packet, each row's terms from 0 in column order (the bits of the former
// diagonal-by-diagonal product). `bands` holds diagonal b + k at bands + (b + k) rows; `in` is x
// with b zeros before and after it.
template <Index Band>
void band_rows(const double* __restrict__ bands, Index rows, Index b, const double* in, Index i,
               double* __restrict__ out) {
  const Index width = Band > 0 ? Band : b;
  Packet4 sums{};
  for (Index k = -width; k <= width; ++k)
    sums = multiply_add(load_packet(bands + (width + k) * rows + i), load_packet(in + i + k), sums);
  store_packet(sums, out);
}

// Rows i, ..., i + 7: two packets' chains side by side, so that one's multiply-adds fill the
// other's latency (each row's terms in the same order as band_rows).
template <Index Band>
void band_rows_in_pairs(const double* __restrict__ bands, Index rows, Index b, const double* in,
                        Index i, double* __restrict__ out) {
  const Index width = Band > 0 ? Band : b;
  Packet4 first{}, second{};
  for (Index k = -width; k <= width; ++k) {
    const double* diagonal = bands + (width + k) * rows + i;
    first = multiply_add(load_packet(diagonal), load_packet(in + i + k), first);
    second = multiply_add(load_packet(diagonal + 4), load_packet(in + i + 4 + k), second);
  }
  store_packet(first, out);
  store_packet(second, out + 4);
}

template <Index Band>
void multiply_band_rows(const double* __restrict__ bands, Index rows, Index b, const double* in,
                        double* __restrict__ out, Index first, Index last) {
  constexpr Index kRows = 4;
  Index i = first;
  for (; i + 2 * kRows <= last; i += 2 * kRows)
    band_rows_in_pairs<Band>(bands, rows, b, in, i, out + i);
  for (; i + kRows <= last; i += kRows) band_rows<Band>(bands, rows, b, in, i, out + i);
  if (i == last) return;
  std::array<double, kRows> tail{};  // the rows past `last` read stale input: dropped
  band_rows<Band>(bands, rows, b, in, i, tail.data());
  std::copy(tail.begin(), tail.begin() + (last - i), out + i);
}

// A band made narrow by renumbering: LDL^T of P A P^T, the right-hand side and solution permuted
// on the way in and out.
class PermutedBandSolver final : public integrators::LinearSolver {
 public:
  PermutedBandSolver(BandedLdlt factor, std::vector<Index> order)
      : factor_(std::move(factor)),
        order_(std::move(order)),
        permuted_rhs_(factor_.size()),
        permuted_solution_(factor_.size()) {}
  void solve(const Vector& rhs, Vector& solution) const override {
    const Index n = permuted_rhs_.size();
    for (Index k = 0; k < n; ++k) permuted_rhs_[k] = rhs[order_[static_cast<std::size_t>(k)]];
    factor_.solve(permuted_rhs_, permuted_solution_);
    solution.resize(n);
    for (Index k = 0; k < n; ++k)
      solution[order_[static_cast<std::size_t>(k)]] = permuted_solution_[k];
  }

 private:
  BandedLdlt factor_;
  std::vector<Index> order_;
  mutable Vector permuted_rhs_, permuted_solution_;
};

// LDL^T of P A P^T (`order`: P's); a pivot that is not positive names the model's equation, not
// its place in the new order.
BandedLdlt factor_in_order(const Eigen::SparseMatrix<double>& renumbered,
                           const std::vector<Index>& order) {
  try {
    return BandedLdlt(renumbered);
  } catch (const NotPositiveDefinite& failure) {
    throw NotPositiveDefinite(order[static_cast<std::size_t>(failure.equation())], failure.pivot(),
                              failure.diagonal());
  }
}

// Structures that only unfolded links join (two buildings that pound) are apart in the matrix:
// its connected components, each contiguous in the band's order, in two groups of about equal
// size, each group's factors taken from the band's (BandedLdlt::restricted), both solved side by
// side (BandedLdlt::solve_pair, or solve_pair_in_place where a group is not one range of
// equations). The solution is the band's own, to the bit.
class PairedBandSolver final : public integrators::LinearSolver {
 public:
  using Orders = std::array<std::vector<Index>, 2>;
  PairedBandSolver(std::array<BandedLdlt, 2> factors, Orders orders)
      : factors_(std::move(factors)), orders_(std::move(orders)) {
    for (std::size_t g = 0; g < 2; ++g) {
      scratch_[g].resize(static_cast<Index>(orders_[g].size()));
      const std::vector<Index>& order = orders_[g];
      for (std::size_t k = 1; k < order.size() && first_[g] >= 0; ++k)
        if (order[k] != order[k - 1] + 1) first_[g] = -1;
      if (first_[g] >= 0) first_[g] = order.front();
    }
  }
  void solve(const Vector& rhs, Vector& solution) const override {
    solution.resize(rhs.size());
    if (first_[0] >= 0 && first_[1] >= 0) {  // each group one range of equations: in place
      BandedLdlt::solve_pair(factors_[0], rhs.data() + first_[0], solution.data() + first_[0],
                             factors_[1], rhs.data() + first_[1], solution.data() + first_[1]);
      return;
    }
    // Interleaved groups, read and written at their places by the sweeps (paired_band_solver
    // makes only pairs of one band, 2 to kUnrolledBand, each group larger than it).
    const BandedLdlt::PairPlaces places{orders_[0].data(), orders_[1].data(), solution.data()};
    if (!BandedLdlt::solve_pair_in_place(factors_[0], factors_[1], places, rhs.data(),
                                         scratch_[0].data(), scratch_[1].data()))
      throw std::logic_error("PairedBandSolver: groups that cannot be solved side by side");
  }

 private:
  std::array<BandedLdlt, 2> factors_;
  Orders orders_;
  std::array<Index, 2> first_{0, 0};       // a group's first equation when it is one range, else -1
  mutable std::array<Vector, 2> scratch_;  // each group's forward sweep
};

// Each component's place in two groups of about equal size: the largest first, each into the
// smaller group.
std::vector<int> balanced_groups(const Components& components) {
  std::vector<Index> sizes(static_cast<std::size_t>(components.count), 0);
  for (const int component : components.of) ++sizes[static_cast<std::size_t>(component)];
  std::vector<int> by_size(sizes.size());
  std::iota(by_size.begin(), by_size.end(), 0);
  std::stable_sort(by_size.begin(), by_size.end(), [&](int p, int q) {
    return sizes[static_cast<std::size_t>(p)] > sizes[static_cast<std::size_t>(q)];
  });
  std::vector<int> group(sizes.size());
  std::array<Index, 2> group_size{};
  for (const int component : by_size) {
    const int smaller = group_size[1] < group_size[0] ? 1 : 0;
    group[static_cast<std::size_t>(component)] = smaller;
    group_size[static_cast<std::size_t>(smaller)] += sizes[static_cast<std::size_t>(component)];
  }
  return group;
}

// The paired solver of `matrix` from its band factors `whole` in `order` (whole(k) is equation
// order[k]), when it has two components or more, each contiguous in that order, and both groups
// are larger than the band (2 to kUnrolledBand); else none.
std::unique_ptr<integrators::LinearSolver> paired_band_solver(
    const Eigen::SparseMatrix<double>& matrix, const BandedLdlt& whole,
    const std::vector<Index>& order) {
  const Index band = whole.bandwidth();
  if (band < 2 || band > kUnrolledBand) return nullptr;
  const Components components = connected_components(matrix);
  if (components.count < 2) return nullptr;
  const auto component_at = [&](std::size_t k) {
    return components.of[static_cast<std::size_t>(order[k])];
  };
  std::vector<char> seen(static_cast<std::size_t>(components.count), 0);
  for (std::size_t k = 0; k < order.size(); ++k) {
    if (k > 0 && component_at(k) == component_at(k - 1)) continue;
    if (seen[static_cast<std::size_t>(component_at(k))]) return nullptr;  // not contiguous
    seen[static_cast<std::size_t>(component_at(k))] = 1;
  }
  const std::vector<int> group = balanced_groups(components);
  std::array<std::vector<Index>, 2> places;
  PairedBandSolver::Orders orders;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto g = static_cast<std::size_t>(group[static_cast<std::size_t>(component_at(k))]);
    places[g].push_back(static_cast<Index>(k));
    orders[g].push_back(order[k]);
  }
  for (const std::vector<Index>& each : places)
    if (static_cast<Index>(each.size()) <= band) return nullptr;
  return std::make_unique<PairedBandSolver>(
      std::array<BandedLdlt, 2>{whole.restricted(places[0]), whole.restricted(places[1])},
      std::move(orders));
}

// Wide bands (unlucky numbering) go to a general sparse LDL^T with fill-reducing ordering.
class SparseSolver final : public integrators::LinearSolver {
 public:
  explicit SparseSolver(const Eigen::SparseMatrix<double>& matrix) : factor_(matrix) {
    // LDL^T of P A P^T: pivot d_k belongs to equation P^-1 k, whose diagonal is A's there.
    const Vector& pivots = factor_.vectorD();
    for (Index k = 0; k < pivots.size(); ++k) {
      const Index equation = factor_.permutationPinv().indices()[k];
      const double diagonal = matrix.coeff(equation, equation);
      if (!pivot_holds(pivots[k], diagonal))
        throw NotPositiveDefinite(equation, pivots[k], diagonal);
    }
    if (factor_.info() != Eigen::Success) throw NotPositiveDefinite(0, 0.0);  // no pivot says where
  }
  void solve(const Vector& rhs, Vector& solution) const override { solution = factor_.solve(rhs); }

 private:
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor_;
};

// A DOF's terms (model::DofMap::terms): none where fixed, one of coefficient 1 where free.
using DofTerms = std::span<const model::DofTerm>;

// An element's block over its DOFs' terms, T^T B T, into the equations' triplets (zeros left out).
void scatter(std::vector<Eigen::Triplet<double>>& into, const Matrix& block,
             const std::vector<DofTerms>& rows) {
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (const model::DofTerm& row : rows[a])
      for (std::size_t b = 0; b < rows.size(); ++b) {
        const double value = block(static_cast<Index>(a), static_cast<Index>(b));
        if (value == 0.0) continue;
        for (const model::DofTerm& col : rows[b])
          into.emplace_back(row.equation, col.equation, row.coefficient * col.coefficient * value);
      }
}

// The elements' and nodal masses' share of the equations, gathered over the free DOFs (fixed
// ones dropped) in the model's order: K, M (lumped and consistent parts) and the damping of
// those that damp on their own, C = sum a0_e M_e + a1_e K_e (the model's a0, a1 for the others).
// A DOF tied by a constraint scatters through its master's equations (T^T K_e T): a lumped mass
// with a lever arm to its master couples them, and joins the consistent part.
struct ElementAssembly {
  ElementAssembly(const model::DofMap& dofs, const model::Model& model);
  void add(const model::Element& element);
  void add(const model::NodalMass& mass);

  // K_fs, stiffness between free DOFs and fixed ones, by fixed DOF (node * dpn + direction).
  using SupportCoupling = std::map<Index, std::vector<std::pair<Index, double>>>;

  std::vector<Eigen::Triplet<double>> stiffness, consistent_mass, damping;
  Vector lumped_mass, damping_diagonal;  // damping_diagonal: a0 m of the lumped masses
  bool has_consistent_mass = false;
  bool own_damping = false;  // some element or mass has its own coefficients
  // Only gathered when supports move differently (multi-support excitation).
  SupportCoupling support_coupling;
  // The a0 of every mass and the a1 of every stiffness on each equation (NaN: none yet), and
  // whether each equation has one of each: C is then diag(a0) M + diag(a1) K.
  Vector mass_coefficients, stiffness_coefficients;
  bool damped_by_dof = true;

 private:
  model::RayleighDamping coefficients(const std::optional<model::RayleighDamping>& own);
  // Notes the coefficient `value` of a contribution to `equation` (one per equation, or none).
  void note(Vector& coefficients, Index equation, double value);
  void couple(const Matrix& block, const std::vector<model::ElementDof>& dofs,
              const std::vector<DofTerms>& rows);
  void add_mass(DofTerms row, double value, double mass_coefficient);

  const model::DofMap& dofs_;
  model::RayleighDamping model_damping_;
  bool gather_coupling_;
};

ElementAssembly::ElementAssembly(const model::DofMap& dofs, const model::Model& model)
    : lumped_mass(Vector::Zero(dofs.size())),
      damping_diagonal(Vector::Zero(dofs.size())),
      mass_coefficients(Vector::Constant(dofs.size(), NAN)),
      stiffness_coefficients(Vector::Constant(dofs.size(), NAN)),
      dofs_(dofs),
      model_damping_(model.damping.value_or(model::RayleighDamping{})),
      gather_coupling_(!model.support_excitations.empty()) {}

void ElementAssembly::add(const model::Element& element) {
  const std::vector<model::ElementDof> dofs = element.dofs();
  std::vector<DofTerms> rows;  // terms of each element DOF
  for (const model::ElementDof& dof : dofs) rows.push_back(dofs_.terms(dof.node, dof.direction));
  const Matrix element_stiffness = element.stiffness();
  scatter(stiffness, element_stiffness, rows);
  if (gather_coupling_) couple(element_stiffness, dofs, rows);
  const model::RayleighDamping c = coefficients(element.damping());
  if (c.stiffness_coefficient != 0.0)
    scatter(damping, c.stiffness_coefficient * element_stiffness, rows);
  if (element_stiffness.any())
    for (const DofTerms& row : rows)
      for (const model::DofTerm& term : row)
        note(stiffness_coefficients, term.equation, c.stiffness_coefficient);
  const model::ElementMass mass = element.mass();
  if (mass.is_consistent()) {
    has_consistent_mass = true;
    scatter(consistent_mass, mass.consistent, rows);
    if (c.mass_coefficient != 0.0) scatter(damping, c.mass_coefficient * mass.consistent, rows);
    if (mass.consistent.any())
      for (const DofTerms& row : rows)
        for (const model::DofTerm& term : row)
          note(mass_coefficients, term.equation, c.mass_coefficient);
  } else {
    for (std::size_t k = 0; k < rows.size(); ++k)
      add_mass(rows[k], mass.lumped[static_cast<Index>(k)], c.mass_coefficient);
  }
}

void ElementAssembly::add(const model::NodalMass& mass) {
  const double a0 = coefficients(mass.damping).mass_coefficient;
  for (int d = 0; d < dofs_.dofs_per_node(); ++d) {
    const model::Direction along = model::direction(d, dofs_.dimension());
    add_mass(dofs_.terms(mass.node, d),
             along.rotation ? mass.rotary_inertia[static_cast<std::size_t>(along.axis)] : mass.mass,
             a0);
  }
}

void ElementAssembly::note(Vector& coefficients, Index equation, double value) {
  double& noted = coefficients[equation];
  if (std::isnan(noted))
    noted = value;
  else if (noted != value)
    damped_by_dof = false;
}

model::RayleighDamping ElementAssembly::coefficients(
    const std::optional<model::RayleighDamping>& own) {
  own_damping = own_damping || own.has_value();
  return own.value_or(model_damping_);
}

// The fixed DOFs are the supports' (a tied DOF is never fixed: the builder refuses supports on
// slaves and on their masters' tied directions).
void ElementAssembly::couple(const Matrix& block, const std::vector<model::ElementDof>& dofs,
                             const std::vector<DofTerms>& rows) {
  for (std::size_t a = 0; a < rows.size(); ++a)
    for (const model::DofTerm& row : rows[a])
      for (std::size_t b = 0; b < rows.size(); ++b)
        if (rows[b].empty())
          support_coupling[dofs[b].node * dofs_.dofs_per_node() + dofs[b].direction].emplace_back(
              row.equation, row.coefficient * block(static_cast<Index>(a), static_cast<Index>(b)));
}

void ElementAssembly::add_mass(DofTerms row, double value, double mass_coefficient) {
  if (row.empty()) return;  // fixed: the support carries it
  if (value != 0.0)
    for (const model::DofTerm& term : row) note(mass_coefficients, term.equation, mass_coefficient);
  if (row.size() == 1) {  // a DOF of its own, or tied with no lever arm: M stays diagonal
    const double weight = row[0].coefficient * row[0].coefficient;
    lumped_mass[row[0].equation] += weight * value;
    damping_diagonal[row[0].equation] += mass_coefficient * (weight * value);
    return;
  }
  if (value == 0.0) return;
  has_consistent_mass = true;
  for (const model::DofTerm& a : row)
    for (const model::DofTerm& b : row) {
      const double share = a.coefficient * b.coefficient * value;
      consistent_mass.emplace_back(a.equation, b.equation, share);
      if (mass_coefficient != 0.0)
        damping.emplace_back(a.equation, b.equation, mass_coefficient * share);
    }
}

// A free DOF needs mass or element stiffness: massless DOFs with stiffness (rotations
// without rotary inertia, contact points on a column) have static equations; one with neither
// would make the equations singular.
void check_every_free_dof_is_held(const model::Model& model, const model::DofMap& dofs,
                                  const ElementAssembly& elements) {
  Vector diagonal_mass = elements.lumped_mass;
  if (elements.has_consistent_mass) {
    for (const auto& entry : elements.consistent_mass)
      if (entry.row() == entry.col()) diagonal_mass[entry.row()] += entry.value();
  }
  Vector diagonal_stiffness = Vector::Zero(dofs.size());
  for (const auto& entry : elements.stiffness)
    if (entry.row() == entry.col()) diagonal_stiffness[entry.row()] += entry.value();
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < dofs.dofs_per_node(); ++d)
      if (const Index row = dofs.own_equation(node, d);
          !model::direction(d, model.dimension).rotation && row >= 0 &&
          !(diagonal_mass[row] > 0.0) && !(diagonal_stiffness[row] > 0.0))
        throw InputError(
            "", fmt::format("/nodes/{}", node),
            fmt::format("node '{}' has neither mass nor stiffness in direction {} (add "
                        "a mass, an element, or a support)",
                        model.nodes[static_cast<std::size_t>(node)].id,
                        model::direction(d, model.dimension).words));
}

// The matrix of `entries` plus diag(diagonal) (whose nonzero entries are appended to `entries`).
Eigen::SparseMatrix<double> with_diagonal(std::vector<Eigen::Triplet<double>>& entries,
                                          const Vector& diagonal) {
  const Index n = diagonal.size();
  for (Index i = 0; i < n; ++i)
    if (diagonal[i] != 0.0) entries.emplace_back(i, i, diagonal[i]);
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  return matrix;
}

// A vector at a node (a force, a velocity, a ground motion's direction) over the node's
// translations.
using NodeVector = std::array<double, 6>;
NodeVector translations(const model::Coordinates& vector, const model::DofMap& dofs) {
  return model::over_directions(vector, false, dofs.dimension());
}

// Adds a force at `node` into `into`: through a tied DOF's terms onto its master (with its
// moment about it).
void add_force_at_node(Vector& into, const model::DofMap& dofs, Index node,
                       const NodeVector& force) {
  for (int d = 0; d < dofs.dofs_per_node(); ++d)
    for (const model::DofTerm& term : dofs.terms(node, d))
      into[term.equation] += term.coefficient * force[static_cast<std::size_t>(d)];
}

// Sets a motion at `node` in `into`, on the node's own DOFs (a tied DOF follows its master's).
void set_motion_at_node(Vector& into, const model::DofMap& dofs, Index node,
                        const NodeVector& motion) {
  for (int d = 0; d < dofs.dofs_per_node(); ++d)
    if (const Index row = dofs.own_equation(node, d); row >= 0)
      into[row] = motion[static_cast<std::size_t>(d)];
}

// The constant nodal forces on the free DOFs.
Vector nodal_loads(const model::Model& model, const model::DofMap& dofs) {
  Vector loads = Vector::Zero(dofs.size());
  for (const model::NodalLoad& load : model.loads)
    add_force_at_node(loads, dofs, load.node, translations(load.force, dofs));
  return loads;
}

// Uniform excitation: the influence vector iota picks the translations along the direction.
Vector uniform_influence(const model::Model& model, const model::DofMap& dofs,
                         const model::Coordinates& direction) {
  Vector influence = Vector::Zero(dofs.size());
  const NodeVector along = translations(direction, dofs);
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    set_motion_at_node(influence, dofs, node, along);
  return influence;
}

// The directions of a link's rows over a node's DOFs: along the axis, or for a rotational link
// the rotation about it (about z in a plane); with friction or a shear, along or about the
// tangents of its contact plane (model::contact_tangents), a hinge's bending across its axis.
NodeVector row_direction(const model::Link& link, const model::Coordinates& along, int dimension) {
  if (link.rotational)
    return model::over_directions(dimension == 3 ? along : model::Coordinates{0.0, 0.0, 1.0}, true,
                                  dimension);
  return model::over_directions(along, false, dimension);
}
std::vector<model::Coordinates> tangents(const model::Link& link, int dimension) {
  if (!link.friction && !link.shear) return {};
  if (link.tangent) return {*link.tangent, model::cross(link.axis, *link.tangent)};
  return model::contact_tangents(link.axis, dimension);
}

// A row's direction over the DOFs of node i and of node j (the same unless the ends are offset).
struct EndDirections {
  NodeVector i, j;
};

// Rotational rows act on the rotations alone. A translation row along d moves an end offset by r
// as d . (u + theta x r) = d . u + theta . (r x d): r x d on the end's rotations.
EndDirections row_directions(const model::Link& link, const model::Coordinates& along,
                             int dimension) {
  if (link.rotational) {
    const NodeVector direction = row_direction(link, along, dimension);
    return {direction, direction};
  }
  const auto at = [&](const model::Coordinates& r) {
    NodeVector direction = model::over_directions(along, false, dimension);
    if (r == model::Coordinates{}) return direction;
    const NodeVector turn = model::over_directions(model::cross(r, along), true, dimension);
    for (std::size_t d = 0; d < direction.size(); ++d) direction[d] += turn[d];
    return direction;
  };
  return {at(link.offsets[0]), at(link.offsets[1])};
}

// Adds weight x the DOF's terms to a row; a tied DOF's equation may already be there (two
// slaves of one master), and is summed into its first entry.
void add_to_row(std::vector<integrators::LinkSet::Term>& row, DofTerms terms, double weight) {
  for (const model::DofTerm& term : terms) {
    const double value = term.coefficient * weight;
    const auto same = std::ranges::find_if(
        row, [&](const integrators::LinkSet::Term& t) { return t.dof == term.equation; });
    if (same == row.end())
      row.push_back({term.equation, value});
    else
      same->coefficient += value;
  }
}

// Row of a direction d: +d at node i, -d at node j (fixed DOFs dropped); for a point inside a
// segment j-k, -(1 - w) d at node j and -w d at node k.
std::vector<integrators::LinkSet::Term> link_row(const model::DofMap& dofs, const model::Link& link,
                                                 const EndDirections& direction) {
  std::vector<integrators::LinkSet::Term> row;
  for (int d = 0; d < dofs.dofs_per_node(); ++d) {
    const double at_i = direction.i[static_cast<std::size_t>(d)];
    const double at_j = direction.j[static_cast<std::size_t>(d)];
    if (at_i != 0.0) add_to_row(row, dofs.terms(link.node_i, d), at_i);
    if (at_j == 0.0) continue;
    const double weight_j = link.segment_end ? 1.0 - link.segment_weight : 1.0;
    if (weight_j != 0.0) add_to_row(row, dofs.terms(link.node_j, d), -weight_j * at_j);
    if (link.segment_end && link.segment_weight != 0.0)
      add_to_row(row, dofs.terms(*link.segment_end, d), -link.segment_weight * at_j);
  }
  // Ties can cancel a DOF out of a row (two points of one rigid floor along their line).
  std::erase_if(row, [](const integrators::LinkSet::Term& t) { return t.coefficient == 0.0; });
  return row;
}

// Whether a constraint ties the node through lever arms (a point of a rigid floor): a DOF of it
// is a combination of its master's, not one of them as it is (an equal-DOF tie).
bool tied_with_lever_arms(const model::DofMap& dofs, Index node) {
  for (int d = 0; d < dofs.dofs_per_node(); ++d) {
    const DofTerms terms = dofs.terms(node, d);
    if (terms.size() > 1 || (terms.size() == 1 && terms[0].coefficient != 1.0)) return true;
  }
  return false;
}

// The mass along a row of its part at one end, 1 / (b^T M^-1 b) over the DOFs with mass (M's
// diagonal), or `fallback` where none has mass.
double row_mass(const model::DofMap& dofs, const Vector& lumped,
                const Eigen::SparseMatrix<double>& consistent, Index node,
                const NodeVector& direction, double fallback) {
  std::vector<integrators::LinkSet::Term> part;
  for (int d = 0; d < dofs.dofs_per_node(); ++d)
    if (const double n_d = direction[static_cast<std::size_t>(d)]; n_d != 0.0)
      add_to_row(part, dofs.terms(node, d), n_d);
  double compliance = 0.0;  // b^T M^-1 b over the DOFs with mass
  for (const integrators::LinkSet::Term& term : part) {
    const double mass =
        consistent.size() > 0 ? consistent.coeff(term.dof, term.dof) : lumped[term.dof];
    if (mass > 0.0) compliance += term.coefficient * term.coefficient / mass;
  }
  return compliance > 0.0 ? 1.0 / compliance : fallback;
}

// The stick penalty defaults to the normal law's tangent at first touch.
links::StickPenalty stick_penalty(const links::LinkLaw& law, const model::LinkFriction& friction) {
  const auto probe = law.clone();
  const links::LawResponse touch = probe->set_trial({1e-12, 1e-12, 0.0});
  return {friction.stick_stiffness.value_or(touch.stiffness),
          friction.stick_damping.value_or(touch.damping), friction.stick_mass.value_or(touch.mass)};
}

// A link's rows and gap, with its law, inside a Coulomb friction law when it has friction or a
// bearing's coupled shear when it has one.
integrators::LinkSet::Link link_entry(const model::DofMap& dofs, const model::Link& link,
                                      std::unique_ptr<links::LinkLaw> law) {
  integrators::LinkSet::Link entry;
  entry.normal_row = link_row(dofs, link, row_directions(link, link.axis, dofs.dimension()));
  entry.gap = link.gap;
  if (!link.friction && !link.shear) {
    entry.law = std::move(law);
    return entry;
  }
  const std::vector<model::Coordinates> along = tangents(link, dofs.dimension());
  for (const model::Coordinates& tangent : along)
    entry.tangential_rows.push_back(
        link_row(dofs, link, row_directions(link, tangent, dofs.dimension())));
  if (link.shear) {
    entry.shear = std::make_unique<links::CoupledShear>(std::move(law), link.shear->numbers,
                                                        static_cast<int>(along.size()));
    if (link.shear->damping) entry.shear->set_damping(*link.shear->damping);
    return entry;
  }
  const links::StickPenalty stick = stick_penalty(*law, *link.friction);
  entry.friction = std::make_unique<links::CoulombFriction>(
      std::move(law), link.friction->coefficient, stick, link.friction->radius,
      static_cast<int>(along.size()));
  return entry;
}

// For each link row: its link and direction, to see how belts and moving supports deform it.
struct LinkRowGeometry {
  const model::Link* link;
  NodeVector direction;            // over a node's directions
  model::Coordinates translation;  // (x, y, z); 0 for a rotational row
};

std::vector<LinkRowGeometry> link_row_geometry(const model::Model& model) {
  std::vector<LinkRowGeometry> rows;
  for (const model::Link& link : model.links) {
    rows.push_back({&link, row_direction(link, link.axis, model.dimension),
                    link.rotational ? model::Coordinates{} : link.axis});
    for (const model::Coordinates& tangent : tangents(link, model.dimension))
      rows.push_back({&link, row_direction(link, tangent, model.dimension),
                      link.rotational ? model::Coordinates{} : tangent});
  }
  return rows;
}

double dot(const model::Coordinates& a, const model::Coordinates& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// Rows whose j side moves on its own (a belt): delta gains -(velocity_j . direction) t.
Vector surface_rates(const std::vector<LinkRowGeometry>& rows) {
  Vector rates = Vector::Zero(static_cast<Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const model::Coordinates& velocity_j = rows[r].link->velocity_j;
    rates[static_cast<Index>(r)] = -dot(velocity_j, rows[r].translation);
  }
  return rates;
}

// K_fs for a support moving along the direction.
Vector support_coupling(const ElementAssembly::SupportCoupling& by_fixed_dof,
                        const model::DofMap& dofs, Index node,
                        const model::Coordinates& direction) {
  const int dpn = dofs.dofs_per_node();
  const NodeVector along = translations(direction, dofs);
  Vector coupling = Vector::Zero(dofs.size());
  for (int d = 0; d < dpn; ++d)
    if (auto found = by_fixed_dof.find(node * dpn + d); found != by_fixed_dof.end())
      for (const auto& [row, value] : found->second)
        coupling[row] += along[static_cast<std::size_t>(d)] * value;
  return coupling;
}

// Links attached to the support itself move with it: d(delta) / d(u_support) of their rows.
Vector attached_link_coefficients(const std::vector<LinkRowGeometry>& rows, Index node,
                                  const model::Coordinates& direction) {
  Vector direct = Vector::Zero(static_cast<Index>(rows.size()));
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double along = dot(rows[r].translation, direction);
    if (rows[r].link->node_i == node) direct[static_cast<Index>(r)] += along;
    if (rows[r].link->node_j == node) direct[static_cast<Index>(r)] -= along;
  }
  return direct;
}

// K + B^T k_0 B: the structure held by its links at rest; DOFs nothing holds even then (a
// backwall behind open backfill) are regularised with 1e-12 of the largest diagonal.
Eigen::SparseMatrix<double> held_by_links(const Eigen::SparseMatrix<double>& stiffness,
                                          const integrators::LinkSet& links,
                                          const Vector& initial_tangent) {
  const Matrix b(links.connectivity());
  Eigen::SparseMatrix<double> held = stiffness;
  held += (b.transpose() * initial_tangent.asDiagonal() * b).sparseView();
  const double largest = held.size() > 0 ? held.diagonal().cwiseAbs().maxCoeff() : 0.0;
  for (Index i = 0; i < held.rows(); ++i)
    if (!(std::abs(held.coeff(i, i)) > 0.0)) held.coeffRef(i, i) = 1e-12 * largest;
  return held;
}

// Any influence matrix R gives exact equations if the static term -(K_ff R + K_fs) u_s(t) is
// loaded too; R is chosen as the quasi-static influence of the supports on the structure with
// its links at their initial tangent (bearings hold the girders), so that u_dyn stays small.
// DOFs nothing holds even then (a backwall behind open backfill) are regularised: r = 0.
class SupportInfluence {
 public:
  SupportInfluence(const Eigen::SparseMatrix<double>& stiffness, const integrators::LinkSet& links);
  // r of a support with coupling K_fs and the links attached to it.
  Vector influence(const Vector& coupling, const Vector& direct) const {
    const Vector held_coupling = coupling + b_.transpose() * initial_tangent_.cwiseProduct(direct);
    return -held_factor_.solve(held_coupling);
  }
  // d(delta) / d(u_support) of every link row: through r, and directly.
  Vector link_coefficients(const Vector& influence, const Vector& direct) const {
    return b_ * influence + direct;
  }

 private:
  Matrix b_;
  Vector initial_tangent_;  // k_0: the normal rows' stiffness at rest
  // K + B^T k_0 B, its zero diagonal entries regularised
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> held_factor_;
};

SupportInfluence::SupportInfluence(const Eigen::SparseMatrix<double>& stiffness,
                                   const integrators::LinkSet& links)
    : b_(Matrix(links.connectivity())), initial_tangent_(links.rest_stiffness()) {
  held_factor_.compute(held_by_links(stiffness, links, initial_tangent_));
  if (held_factor_.info() != Eigen::Success)
    throw InputError("", "/excitations",
                     "multi-support excitation: the structure's stiffness "
                     "could not be factored to find the supports' influence");
}

}  // namespace

StructuralSystem::StructuralSystem(const model::Model& model) : dofs_(model) {
  const Index n = dofs_.size();
  ElementAssembly elements(dofs_, model);
  for (const auto& element : model.elements) elements.add(*element);
  for (const model::NodalMass& mass : model.masses) elements.add(mass);
  check_every_free_dof_is_held(model, dofs_, elements);
  mass_ = std::move(elements.lumped_mass);
  if (elements.has_consistent_mass) mass_matrix_ = with_diagonal(elements.consistent_mass, mass_);

  stiffness_.resize(n, n);
  stiffness_.setFromTriplets(elements.stiffness.begin(), elements.stiffness.end());
  stiffness_.prune(0.0);
  store_stiffness_for_products();

  if (model.damping) damping_ = *model.damping;
  set_rayleigh(elements.own_damping, elements.damped_by_dof, elements.mass_coefficients,
               elements.stiffness_coefficients);
  if (elements.own_damping) {
    // Elements damp with their own coefficients: C is assembled, not a0 M + a1 K.
    damping_matrix_ = with_diagonal(elements.damping, elements.damping_diagonal);
    damping_matrix_.prune(0.0);
    damping_rows_ = damping_matrix_;
    damping_rows_.makeCompressed();  // multiply_rows reads its arrays
  }

  loads_ = nodal_loads(model, dofs_);
  if (model.gravity) {
    Vector weight(n);
    multiply_mass(uniform_influence(model, dofs_, model.gravity->direction), weight);
    loads_ += model.gravity->acceleration * weight;
  }
  has_loads_ = loads_.any();
  for (const model::UniformExcitation& excitation : model.excitations) {
    Vector inertia(n), influence = uniform_influence(model, dofs_, excitation.direction);
    multiply_mass(influence, inertia);
    excitations_.push_back(
        {excitation.motion, std::move(inertia), std::move(influence), excitation.direction});
  }

  std::vector<integrators::LinkSet::Link> links;
  for (const model::Link& link : model.links) {
    links.push_back(link_entry(dofs_, link, link.make_law(link_context(link))));
    link_ids_.push_back(link.id);
  }
  links_ = integrators::LinkSet(n, std::move(links));
  const std::vector<LinkRowGeometry> rows = link_row_geometry(model);
  surface_rate_ = surface_rates(rows);
  if (model.gravity && model.gravity->p_delta)
    add_geometric_stiffness(model, *model.gravity->p_delta);

  has_link_motion_ = find_link_motion();
  if (model.support_excitations.empty()) return;
  const SupportInfluence supports(stiffness_, links_);
  for (const model::SupportExcitation& excitation : model.support_excitations)
    for (const auto& [node, delay] : excitation.supports) {
      const Vector coupling =
          support_coupling(elements.support_coupling, dofs_, node, excitation.direction);
      const Vector direct = attached_link_coefficients(rows, node, excitation.direction);
      const Vector influence = supports.influence(coupling, direct);
      MovingSupport moving{model::GroundKinematics(excitation.motion, delay),
                           Vector(n),
                           supports.link_coefficients(influence, direct),
                           Vector(n),
                           influence,
                           node,
                           excitation.direction};
      multiply_mass(influence, moving.inertia);
      moving.static_load = -(stiffness_ * influence + coupling);
      moving_supports_.push_back(std::move(moving));
    }
  has_link_motion_ = find_link_motion();
}

void StructuralSystem::store_stiffness_for_products() {
  const Index n = stiffness_.rows();
  if (const Index b = BandedLdlt::bandwidth_of(stiffness_);
      n > 0 && (2 * b + 1) * n <= 4 * stiffness_.nonZeros()) {
    stiffness_bandwidth_ = b;
    // But for a tridiagonal band, three rows of zeros past the last: multiply_band's last block
    // of four rows may start at any row.
    stiffness_band_ = Matrix::Zero(b != 1 ? n + 3 : n, 2 * b + 1);
    for (Index col = 0; col < stiffness_.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(stiffness_, col); it; ++it)
        stiffness_band_(it.row(), b + col - it.row()) = it.value();
    // Symmetric to the last bit (elements assemble K(i, j) and K(j, i) from the same terms):
    // the product then streams one off-diagonal, a sixth less memory traffic per explicit step.
    stiffness_symmetric_ = b == 1;
    for (Index i = 1; i < n && stiffness_symmetric_; ++i)
      stiffness_symmetric_ = stiffness_band_(i, 0) == stiffness_band_(i - 1, 2);
  } else {
    stiffness_rows_ = stiffness_;
    stiffness_rows_.makeCompressed();
  }
}

// The axial forces of the linear gravity analysis (K + B^T k_0 B) u = f, then K += K_G(u). A
// structure that K + K_G no longer holds has passed its elastic buckling load under gravity.
void StructuralSystem::add_geometric_stiffness(const model::Model& model,
                                               model::GeometricStiffness kind) {
  const Vector initial_tangent = links_.rest_stiffness();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> gravity_state(
      held_by_links(stiffness_, links_, initial_tangent));
  const Vector u = gravity_state.solve(loads_);
  std::vector<Eigen::Triplet<double>> entries;
  for (const auto& element : model.elements) {
    std::vector<DofTerms> rows;
    Vector element_u = Vector::Zero(static_cast<Index>(element->dofs().size()));
    for (const model::ElementDof& dof : element->dofs()) {
      rows.push_back(dofs_.terms(dof.node, dof.direction));
      element_u[static_cast<Index>(rows.size() - 1)] = model::value_of(rows.back(), u);
    }
    if (const Matrix k = element->geometric_stiffness(element_u, kind); k.size() > 0)
      scatter(entries, k, rows);
  }
  Eigen::SparseMatrix<double> geometric(size(), size());
  geometric.setFromTriplets(entries.begin(), entries.end());
  elastic_stiffness_ = stiffness_;
  elastic_rows_ = elastic_stiffness_;
  elastic_rows_.makeCompressed();  // multiply_rows reads its arrays
  rayleigh_.reset();               // a1 K is the first-order K, not the K of the products
  stiffness_ += geometric;
  stiffness_.prune(0.0);
  store_stiffness_for_products();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> second_order(
      held_by_links(stiffness_, links_, initial_tangent));
  if (second_order.info() != Eigen::Success || !(second_order.vectorD().array() > 0.0).all())
    throw InputError("", "/gravity/p_delta",
                     "the structure is not stable under its own weight with P-Delta: the gravity "
                     "loads exceed its elastic buckling load (with the links at their initial "
                     "stiffness); check the masses, the sections and the supports");
}

bool StructuralSystem::find_link_motion() const {
  if (surface_rate_.size() > 0 && surface_rate_.any()) return true;
  for (const MovingSupport& support : moving_supports_)
    if (support.link_coefficients.size() > 0 && support.link_coefficients.any()) return true;
  return false;
}

void StructuralSystem::link_motion(double time, Vector& offset, Vector& rate,
                                   Vector& acceleration) const {
  offset.setZero(links_.size());
  rate.setZero(links_.size());
  acceleration.setZero(links_.size());
  if (surface_rate_.size() > 0) {
    offset += time * surface_rate_;
    rate += surface_rate_;
  }
  for (const MovingSupport& support : moving_supports_) {
    const model::GroundState ground = support.kinematics.at(time);
    offset += ground.displacement * support.link_coefficients;
    rate += ground.velocity * support.link_coefficients;
    acceleration += ground.acceleration * support.link_coefficients;
  }
}

links::LinkContext StructuralSystem::link_context(const model::Link& link) const {
  links::LinkContext context;
  const NodeVector direction = row_direction(link, link.axis, dofs_.dimension());
  // Mass and diagonal stiffness of one end along the direction: n^T K_nn n over its free DOFs.
  // A tied end counts its master's along the same directions (each DOF's first term): a point of
  // a rigid floor is the floor's, as an offset end is its node's.
  auto end = [&](Index node, double& mass, double& stiffness, bool& fixed) {
    fixed = true;
    for (int d = 0; d < dofs_.dofs_per_node(); ++d) {
      const double n_d = direction[static_cast<std::size_t>(d)];
      const DofTerms rows = dofs_.terms(node, d);
      if (n_d == 0.0 || rows.empty()) continue;
      fixed = false;
      const Index row = rows[0].equation;
      mass = mass_matrix_.size() > 0 ? mass_matrix_.coeff(row, row) : mass_[row];
      for (int e = 0; e < dofs_.dofs_per_node(); ++e)
        if (const DofTerms cols = dofs_.terms(node, e); !cols.empty())
          stiffness += n_d * direction[static_cast<std::size_t>(e)] *
                       stiffness_.coeff(row, cols[0].equation);
    }
  };
  end(link.node_i, context.mass_i, context.stiffness_i, context.fixed_i);
  end(link.node_j, context.mass_j, context.stiffness_j, context.fixed_j);
  if (link.has_offsets() || tied_with_lever_arms(dofs_, link.node_i) ||
      tied_with_lever_arms(dofs_, link.node_j)) {
    // A point off its node (rigid offsets) or of a rigid floor moves with the body's rotation
    // too: its mass along the row is 1 / (b^T M^-1 b) of the end's part b of the row (lever
    // arms and ties included), the body's rotary inertia with its mass. Taken as the node's
    // translational mass alone, a corner's was 171 t for a floor whose corner has 89 t, and a
    // law calibrated to e = 0.65 rebounded at 0.56.
    const EndDirections directions = row_directions(link, link.axis, dofs_.dimension());
    if (!context.fixed_i)
      context.mass_i =
          row_mass(dofs_, mass_, mass_matrix_, link.node_i, directions.i, context.mass_i);
    if (!context.fixed_j && !link.segment_end)
      context.mass_j =
          row_mass(dofs_, mass_, mass_matrix_, link.node_j, directions.j, context.mass_j);
  }
  if (link.segment_end) {
    // A point inside a segment: the ends' numbers interpolated like its displacement.
    double mass_k = 0.0, stiffness_k = 0.0;
    bool fixed_k = true;
    end(*link.segment_end, mass_k, stiffness_k, fixed_k);
    const double w = link.segment_weight;
    context.mass_j = (1 - w) * context.mass_j + w * mass_k;
    context.stiffness_j = (1 - w) * context.stiffness_j + w * stiffness_k;
    context.fixed_j = context.fixed_j && fixed_k;
  }
  return context;
}

const Vector* StructuralSystem::lumped_mass() const {
  return mass_matrix_.size() > 0 ? nullptr : &mass_;
}

Eigen::SparseMatrix<double> StructuralSystem::mass_matrix() const {
  if (mass_matrix_.size() > 0) return mass_matrix_;
  Eigen::SparseMatrix<double> mass(size(), size());
  mass.reserve(Eigen::VectorXi::Constant(size(), 1));
  for (Index i = 0; i < size(); ++i)
    if (mass_[i] != 0.0) mass.insert(i, i) = mass_[i];
  return mass;
}

void StructuralSystem::multiply_mass(const Vector& x, Vector& y) const {
  if (mass_matrix_.size() > 0)
    y.noalias() = mass_matrix_ * x;
  else
    y = mass_.cwiseProduct(x);
}

void StructuralSystem::set_rayleigh(bool own, bool by_dof, const Vector& mass_coefficient,
                                    const Vector& stiffness_coefficient) {
  const Index n = dofs_.size();
  Rayleigh rayleigh;
  if (!own) {
    rayleigh.mass_coefficient = Vector::Constant(n, damping_.mass_coefficient);
    rayleigh.stiffness_coefficient = Vector::Constant(n, damping_.stiffness_coefficient);
  } else {
    if (!by_dof) return;
    const auto or_zero = [](double a) { return std::isnan(a) ? 0.0 : a; };
    rayleigh.mass_coefficient = mass_coefficient.unaryExpr(or_zero);
    rayleigh.stiffness_coefficient = stiffness_coefficient.unaryExpr(or_zero);
  }
  rayleigh.stiffness = rayleigh.stiffness_coefficient.any();
  if (!rayleigh.stiffness && !rayleigh.mass_coefficient.any()) return;  // no damping
  rayleigh_ = std::move(rayleigh);
}

const integrators::SecondOrderSystem::Rayleigh* StructuralSystem::rayleigh() const {
  return rayleigh_ ? &*rayleigh_ : nullptr;
}

void StructuralSystem::multiply_damping(const Vector& x, Vector& y) const {
  if (rayleigh_) {
    // C x = a0 (M x) + a1 (K x), by DOF; K x only where some a1 is not 0.
    multiply_mass(x, y);
    y.array() *= rayleigh_->mass_coefficient.array();
    if (rayleigh_->stiffness) {
      multiply_stiffness(x, damping_work_);
      y.array() += rayleigh_->stiffness_coefficient.array() * damping_work_.array();
    }
    return;
  }
  if (damping_matrix_.size() > 0) {
    multiply_rows(damping_rows_, x, y);
    return;
  }
  // C = a0 M + a1 K_elastic (P-Delta: a1 times the first-order K), K_elastic x by rows into kept
  // storage (the column product's sums, without its temporary).
  const double a0 = damping_.mass_coefficient, a1 = damping_.stiffness_coefficient;
  multiply_mass(x, y);
  multiply_rows(elastic_rows_, x, damping_work_);
  y = a0 * y + a1 * damping_work_;
}

void StructuralSystem::multiply_stiffness(const Vector& x, Vector& y) const {
  if (stiffness_bandwidth_ < 0) {
    multiply_rows(stiffness_rows_, x, y);
    return;
  }
  y.resize(x.size());
  multiply_band(x, y, 0, x.size());
}

void StructuralSystem::multiply_stiffness_by_blocks(Vector& x, Vector& y,
                                                    const integrators::BlockFunction& make,
                                                    const integrators::BlockFunction& use) const {
  if (stiffness_bandwidth_ < 0) {
    integrators::SecondOrderSystem::multiply_stiffness_by_blocks(x, y, make, use);
    return;
  }
  // 256 rows: the blocks of an explicit step's ten or so vectors stay in L1 between its passes.
  constexpr Index kBlock = 256;
  const Index n = size();
  y.resize(n);
  Index made = 0;
  for (Index first = 0; first < n; first += kBlock) {
    const Index last = std::min(n, first + kBlock);
    if (const Index needed = std::min(n, last + stiffness_bandwidth_); needed > made) {
      make(made, needed);
      made = needed;
    }
    multiply_band(x, y, first, last);
    use(first, last);
  }
}

void StructuralSystem::multiply_band(const Vector& x, Vector& y, Index first, Index last) const {
  const Index n = x.size(), b = stiffness_bandwidth_;
  const double* __restrict__ in = x.data();
  double* __restrict__ out = y.data();
  // Each row's terms are added in column order, as the product by rows adds them.
  if (b == 0) {  // diagonal: oscillators that only links join
    const double* __restrict__ diagonal = stiffness_band_.data();
    for (Index i = first; i < last; ++i) out[i] = diagonal[i] * in[i];
    return;
  }
  if (b == 1) {
    const double* __restrict__ diagonal = stiffness_band_.col(1).data();
    const double* __restrict__ upper = stiffness_band_.col(2).data();
    const double* __restrict__ lower =
        stiffness_symmetric_ ? upper - 1 : stiffness_band_.col(0).data();
    if (first == 0) out[0] = diagonal[0] * in[0] + upper[0] * in[1];
    const Index end = std::min(last, n - 1);
    for (Index i = std::max<Index>(first, 1); i < end; ++i)
      out[i] = lower[i] * in[i - 1] + diagonal[i] * in[i] + upper[i] * in[i + 1];
    if (last == n) out[n - 1] = lower[n - 1] * in[n - 2] + diagonal[n - 1] * in[n - 1];
    return;
  }
  // x with b zeros before and after it (and past the band's three rows of zeros): the terms past
  // the matrix's ends are 0 x 0, which leave a sum unchanged (sums start at +0, so are never -0).
  // Only the entries these rows read are copied (an explicit step makes x block by block).
  const Index rows = stiffness_band_.rows();
  if (padded_input_.size() != rows + 2 * b) padded_input_.setZero(rows + 2 * b);
  const Index from = std::max<Index>(0, first - b), to = std::min(n, last + b);
  std::copy(in + from, in + to, padded_input_.data() + b + from);
  const double* padded = padded_input_.data() + b;
  const double* __restrict__ bands = stiffness_band_.data();
  switch (b) {
    case 2:
      return multiply_band_rows<2>(bands, rows, b, padded, out, first, last);
    case 3:
      return multiply_band_rows<3>(bands, rows, b, padded, out, first, last);
    case 4:
      return multiply_band_rows<4>(bands, rows, b, padded, out, first, last);
    case 5:
      return multiply_band_rows<5>(bands, rows, b, padded, out, first, last);
    case 6:
      return multiply_band_rows<6>(bands, rows, b, padded, out, first, last);
    default:
      return multiply_band_rows<0>(bands, rows, b, padded, out, first, last);
  }
}

std::vector<Vector> StructuralSystem::frame_shapes() const {
  std::vector<Vector> shapes;
  for (const Excitation& excitation : excitations_) shapes.push_back(excitation.influence);
  for (const MovingSupport& support : moving_supports_) shapes.push_back(support.influence);
  return shapes;
}

void StructuralSystem::frame_scales(double time, std::vector<double>& scales) const {
  // Formed with the external force (compute_external_force): a step's observers ask at the time
  // its integrator formed the force for, so the force is formed here only on a miss.
  if (!(time == last_external_time_)) external_force(time, frame_force_);
  scales = last_scales_;
}

double StructuralSystem::support_acceleration(Index node, int direction, double time) const {
  const model::Direction along = model::direction(direction, dofs_.dimension());
  // The ground does not turn, and moves only in the plane of its records' directions.
  if (along.rotation || along.axis >= static_cast<int>(std::tuple_size_v<model::Coordinates>))
    return 0.0;
  const auto component = static_cast<std::size_t>(along.axis);
  double acceleration = 0.0;
  for (const Excitation& excitation : excitations_)
    acceleration += excitation.motion.at(time) * excitation.direction[component];
  for (const MovingSupport& support : moving_supports_)
    if (support.node == node)
      acceleration += support.kinematics.at(time).acceleration * support.direction[component];
  return acceleration;
}

double StructuralSystem::moving_support_share(std::size_t k, Index node, int direction) const {
  const MovingSupport& support = moving_supports_.at(k);
  const model::Direction along = model::direction(direction, dofs_.dimension());
  if (support.node != node || along.rotation ||
      along.axis >= static_cast<int>(std::tuple_size_v<model::Coordinates>))
    return 0.0;
  return support.direction[static_cast<std::size_t>(along.axis)];
}

void StructuralSystem::moving_support_displacements(double time,
                                                    std::vector<double>& displacements) const {
  displacements.resize(moving_supports_.size());
  for (std::size_t k = 0; k < moving_supports_.size(); ++k)
    displacements[k] = moving_supports_[k].kinematics.at(time).displacement;
}

void StructuralSystem::external_force(double time, Vector& force) const {
  if (time == last_external_time_ && last_external_force_.size() == size()) {
    force = last_external_force_;
    return;
  }
  compute_external_force(time, force);
  last_external_force_ = force;
  last_external_time_ = time;
}

void StructuralSystem::compute_external_force(double time, Vector& force) const {
  // -M iota a_g(t) of each excitation; the first one's with the loads in one pass. The ground's
  // accelerations are kept as the frame's scales at this time (frame_scales).
  last_scales_.clear();
  if (excitations_.empty()) {
    force = loads_;
  } else {
    last_scales_.push_back(excitations_[0].motion.at(time));
    force = loads_ - last_scales_[0] * excitations_[0].inertia;
  }
  for (std::size_t k = 1; k < excitations_.size(); ++k) {
    last_scales_.push_back(excitations_[k].motion.at(time));
    force -= last_scales_[k] * excitations_[k].inertia;
  }
  for (const MovingSupport& support : moving_supports_) {
    const model::GroundState ground = support.kinematics.at(time);
    last_scales_.push_back(ground.acceleration);
    force -= ground.acceleration * support.inertia;      // -M r a_s(t)
    force += ground.displacement * support.static_load;  // -(K_ff r + K_fs) u_s(t)
  }
}

Eigen::SparseMatrix<double> StructuralSystem::effective_matrix(double c_m, double c_c,
                                                               double c_k) const {
  if (damping_matrix_.size() > 0)
    return c_k * stiffness_ + c_m * mass_matrix() + c_c * damping_matrix_;
  // c_m M + c_c (a0 M + a1 K) + c_k K
  const double mass_factor = c_m + c_c * damping_.mass_coefficient;
  const double stiffness_factor = c_k + c_c * damping_.stiffness_coefficient;
  if (elastic_stiffness_.size() > 0)  // a1 K of the damping is the first-order K
    return c_k * stiffness_ + (c_c * damping_.stiffness_coefficient) * elastic_stiffness_ +
           mass_factor * mass_matrix();
  return stiffness_factor * stiffness_ + mass_factor * mass_matrix();
}

std::unique_ptr<integrators::LinearSolver> StructuralSystem::factor_matrix(
    Eigen::SparseMatrix<double> effective) {
  effective.prune(0.0);
  const Index bandwidth = BandedLdlt::bandwidth_of(effective);
  if (bandwidth <= 1) return std::make_unique<FactorSolver<TwistedTridiagonal>>(effective);
  if (bandwidth <= kUnrolledBand) {
    BandedLdlt whole(effective);
    std::vector<Index> natural(static_cast<std::size_t>(effective.rows()));
    std::iota(natural.begin(), natural.end(), Index{0});
    if (auto paired = paired_band_solver(effective, whole, natural)) return paired;
    return std::make_unique<FactorSolver<BandedLdlt>>(std::move(whole));
  }
  // Past the bands whose substitution is unrolled, a renumbering may narrow it.
  std::vector<Index> order = reverse_cuthill_mckee(effective);
  Eigen::SparseMatrix<double> renumbered = permuted(effective, order);
  if (const Index narrowed = BandedLdlt::bandwidth_of(renumbered);
      narrowed < bandwidth && narrowed <= kBandedLimit) {
    BandedLdlt whole = factor_in_order(renumbered, order);
    if (auto paired = paired_band_solver(effective, whole, order)) return paired;
    return std::make_unique<PermutedBandSolver>(std::move(whole), std::move(order));
  }
  if (bandwidth <= kBandedLimit) return std::make_unique<FactorSolver<BandedLdlt>>(effective);
  return std::make_unique<SparseSolver>(effective);
}

std::unique_ptr<integrators::LinearSolver> StructuralSystem::factor(double c_m, double c_c,
                                                                    double c_k) const {
  return factor_matrix(effective_matrix(c_m, c_c, c_k));
}

std::unique_ptr<integrators::LinearSolver> StructuralSystem::factor_with_links(
    double c_m, double c_c, double c_k, const Vector& link_stiffness) const {
  const auto& connectivity = links_.connectivity();
  const Eigen::SparseMatrix<double> folded =
      connectivity.transpose() * link_stiffness.asDiagonal() * connectivity;
  return factor_matrix(effective_matrix(c_m, c_c, c_k) + folded);
}

Vector StructuralSystem::initial_velocity(const model::Model& model) const {
  Vector velocity = Vector::Zero(size());
  if (model.initial_velocity.empty()) return velocity;
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    set_motion_at_node(velocity, dofs_, node,
                       translations(model.initial_velocity[static_cast<std::size_t>(node)], dofs_));
  return velocity;
}

}  // namespace pound::assembly
