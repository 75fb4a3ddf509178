#include "assembly/static_hard_contacts.hpp"

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "links/coulomb_friction.hpp"
#include "links/hard_contact.hpp"

namespace pound::assembly {

using RowIterator = integrators::LinkSet::SparseRowMatrix::InnerIterator;

StaticHardContacts::StaticHardContacts(StructuralSystem& system, const Vector& belt_rate,
                                       const Vector& start_delta)
    : connectivity_(system.links().connectivity()), belt_rate_(belt_rate), anchor_(start_delta) {
  integrators::LinkSet::HardRows rows = system.links().hard_rows();
  contacts_ = std::move(rows.contacts);
  frictions_ = std::move(rows.frictions);
  const Index m = system.links().size();
  state_.assign(static_cast<std::size_t>(m), Row::kFree);
  multiplier_ = Vector::Zero(m);
  direction_ = Vector::Zero(m);
  scale_ = Vector::Zero(m);
  const Vector diagonal = system.stiffness().diagonal().cwiseAbs();
  // A row between DOFs that only links hold (a block on a floor) sees the structure's largest
  // stiffness, or 1 in a structure without any: c only weighs delta against lambda.
  const double fallback =
      diagonal.size() > 0 && diagonal.maxCoeff() > 0.0 ? diagonal.maxCoeff() : 1.0;
  for (Index r = 0; r < m; ++r) {
    if (!constrains(r)) continue;
    for (RowIterator term(connectivity_, r); term; ++term)
      scale_[r] += term.value() * term.value() * diagonal[term.col()];
    if (!(scale_[r] > 0.0)) scale_[r] = fallback;
    any_ = true;
  }
}

bool StaticHardContacts::constrains(Index row) const {
  const auto r = static_cast<std::size_t>(row);
  return contacts_[r] || frictions_[r];
}

void StaticHardContacts::leave_out(Vector& force) const {
  for (Index r = 0; r < force.size(); ++r)
    if (constrains(r)) force[r] = 0.0;
}

bool StaticHardContacts::choose(const Vector& delta) {
  bool settled = true;
  for (Index r = 0; r < multiplier_.size(); ++r) {
    const auto row = static_cast<std::size_t>(r);
    if (!constrains(r)) continue;
    Row after;
    if (frictions_[row]) {
      after = friction_state(r, delta);
    } else {
      const bool holds = multiplier_[r] + scale_[r] * delta[r] > 0.0 ||
                         (!started_ && delta[r] == 0.0);  // touching at the start
      after = holds ? Row::kHeld : Row::kFree;
    }
    settled = settled && after == state_[row];
    state_[row] = after;
  }
  started_ = true;
  return settled;
}

StaticHardContacts::Row StaticHardContacts::friction_state(Index t, const Vector& delta) {
  if (state_[static_cast<std::size_t>(t - 1)] != Row::kHeld) return Row::kFree;
  if (belt_rate_.size() > 0 && belt_rate_[t] != 0.0) {
    direction_[t] = belt_rate_[t] > 0.0 ? 1.0 : -1.0;
    return Row::kSlip;
  }
  const double trial = multiplier_[t] + scale_[t] * (delta[t] - anchor_[t]);
  const double limit =
      coefficient(t) * std::max(0.0, multiplier_[t - 1] + scale_[t - 1] * delta[t - 1]);
  if (std::abs(trial) <= limit) return Row::kStick;
  direction_[t] = trial > 0.0 ? 1.0 : -1.0;
  return Row::kSlip;
}

double StaticHardContacts::coefficient(Index t) const {
  return frictions_[static_cast<std::size_t>(t)]->coefficient();
}

double StaticHardContacts::target(Index r) const {
  return frictions_[static_cast<std::size_t>(r)] ? anchor_[r] : 0.0;
}

double StaticHardContacts::violation(const Vector& delta) const {
  double worst = 0.0;
  for (Index r = 0; r < multiplier_.size(); ++r) {
    const auto row = static_cast<std::size_t>(r);
    const bool held = state_[row] == Row::kHeld || state_[row] == Row::kStick;
    const bool penetrating = contacts_[row] && delta[r] > 0.0;
    if (constrains(r) && (held || penetrating))
      worst = std::max(worst, scale_[r] * std::abs(delta[r] - target(r)));
  }
  return worst;
}

bool StaticHardContacts::solve(const Eigen::SparseMatrix<double>& tangent, const Vector& residual,
                               const Vector& delta, Vector& step, Vector& multipliers) const {
  const Index n = tangent.rows(), m = multiplier_.size();
  std::vector<Eigen::Triplet<double>> entries;
  for (Index j = 0; j < tangent.outerSize(); ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator e(tangent, j); e; ++e)
      entries.emplace_back(e.row(), e.col(), e.value());
  std::vector<Index> unknowns;  // the held and sticking rows, in order
  Vector right(n + m);
  right.head(n) = residual;
  for (Index r = 0; r < m; ++r) {
    const Row state = state_[static_cast<std::size_t>(r)];
    if (state != Row::kHeld && state != Row::kStick) continue;
    const Index k = n + static_cast<Index>(unknowns.size());
    unknowns.push_back(r);
    for (RowIterator term(connectivity_, r); term; ++term) {
      entries.emplace_back(term.col(), k, term.value());
      entries.emplace_back(k, term.col(), term.value());
    }
    const auto below = static_cast<std::size_t>(r + 1);
    if (state == Row::kHeld && below < state_.size() && frictions_[below] &&
        state_[below] == Row::kSlip)
      for (RowIterator term(connectivity_, r + 1); term; ++term)
        entries.emplace_back(term.col(), k, direction_[r + 1] * coefficient(r + 1) * term.value());
    right[k] = target(r) - delta[r];
  }
  const Index size = n + static_cast<Index>(unknowns.size());
  Eigen::SparseMatrix<double> matrix(size, size);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  solver.compute(matrix);
  if (solver.info() != Eigen::Success) return false;
  const Vector solution = solver.solve(right.head(size));
  if (!solution.allFinite()) return false;
  step = solution.head(n);
  multipliers = Vector::Zero(m);
  for (std::size_t k = 0; k < unknowns.size(); ++k)
    multipliers[unknowns[k]] = solution[n + static_cast<Index>(k)];
  for (Index t = 0; t < m; ++t)
    if (state_[static_cast<std::size_t>(t)] == Row::kSlip)
      multipliers[t] = direction_[t] * coefficient(t) * multipliers[t - 1];
  return true;
}

void StaticHardContacts::commit(const Vector& delta) {
  for (Index r = 0; r < multiplier_.size(); ++r)
    if (frictions_[static_cast<std::size_t>(r)]) anchor_[r] = delta[r];
}

void StaticHardContacts::impose() const {
  for (Index r = 0; r < multiplier_.size(); ++r) {
    const auto row = static_cast<std::size_t>(r);
    if (contacts_[row]) contacts_[row]->impose(std::max(0.0, multiplier_[r]));
    if (frictions_[row])
      frictions_[row]->impose_tangential(multiplier_[r], state_[row] == Row::kSlip);
  }
}

}  // namespace pound::assembly
