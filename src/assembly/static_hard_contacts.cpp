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
  tangent_ = std::move(rows.tangent);
  pair_ = std::move(rows.pair);
  const Index m = system.links().size();
  state_.assign(static_cast<std::size_t>(m), Row::kFree);
  multiplier_ = Vector::Zero(m);
  direction_ = Vector::Zero(m);
  turn_ = Vector::Zero(m);
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
  // A contact plane's trial is a vector: one scale for both tangents, so that a slipping force
  // lies along the trial (the larger, as a stiffer row's).
  for (Index r = 0; r + 1 < m; ++r)
    if (pair_[static_cast<std::size_t>(r)] && tangent_[static_cast<std::size_t>(r)] == 0)
      scale_[r] = scale_[r + 1] = std::max(scale_[r], scale_[r + 1]);
}

Index StaticHardContacts::normal_of(Index t) const {
  return t - 1 - tangent_[static_cast<std::size_t>(t)];
}

bool StaticHardContacts::in_plane(Index t) const { return pair_[static_cast<std::size_t>(t)] != 0; }

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
  turned_ = false;
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
  changed_ = !settled;
  return settled && !turned_;
}

StaticHardContacts::Row StaticHardContacts::friction_state(Index t, const Vector& delta) {
  if (state_[static_cast<std::size_t>(normal_of(t))] != Row::kHeld) return Row::kFree;
  if (in_plane(t)) return friction_state_in_plane(t, delta);
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

// A contact plane's two rows (first t, then t + 1 takes the same state): the trial
// tau = lambda_t + c (s - s_0) against the circle mu (lambda_n + c_n delta_n). Slipping, along the
// belt's motion under a moving surface, else along the slide s - s_0 (tau's direction where
// there is none yet), with Newton's kappa = mu lambda_n / |s - s_0| for the direction's turn
// (solve), so that the direction converges with the displacements.
StaticHardContacts::Row StaticHardContacts::friction_state_in_plane(Index t, const Vector& delta) {
  const Index first = t - tangent_[static_cast<std::size_t>(t)];
  if (t != first) return state_[static_cast<std::size_t>(first)];
  const Index normal = first - 1;
  Eigen::Vector2d along;
  const bool belt = belt_rate_.size() > 0 && (belt_rate_[t] != 0.0 || belt_rate_[t + 1] != 0.0);
  if (belt) {
    along = belt_rate_.segment<2>(t);
  } else {
    along = multiplier_.segment<2>(t) + scale_[t] * (delta.segment<2>(t) - anchor_.segment<2>(t));
    const double limit =
        coefficient(t) * std::max(0.0, multiplier_[normal] + scale_[normal] * delta[normal]);
    if (along.norm() <= limit) return Row::kStick;
    const Eigen::Vector2d slide = delta.segment<2>(t) - anchor_.segment<2>(t);
    const double length = slide.norm();
    turn_[t] = 0.0;
    if (length > 1e-12 * std::max(delta.segment<2>(t).norm(), anchor_.segment<2>(t).norm())) {
      along = slide;
      turn_[t] = coefficient(t) * std::max(0.0, multiplier_[normal]) / length;
    }
  }
  const Eigen::Vector2d direction = along / along.norm();
  // A slip whose direction still turns is not settled.
  turned_ = turned_ || (direction - direction_.segment<2>(t)).norm() > 1e-12;
  direction_.segment<2>(t) = direction;
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
    // A held row whose friction slips carries it: B_n^T + sum over its tangents of e mu B_t^T.
    for (Index below = r + 1; state == Row::kHeld && below <= std::min(r + 2, m - 1); ++below) {
      const auto row = static_cast<std::size_t>(below);
      if (!frictions_[row] || normal_of(below) != r || state_[row] != Row::kSlip) continue;
      for (RowIterator term(connectivity_, below); term; ++term)
        entries.emplace_back(term.col(), k, direction_[below] * coefficient(below) * term.value());
    }
    right[k] = target(r) - delta[r];
  }
  add_turn_entries(entries);
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
      multipliers[t] = direction_[t] * coefficient(t) * multipliers[normal_of(t)];
  add_turn_forces(step, multipliers);
  return true;
}

// A slipping contact plane's turn: lambda_t = mu lambda_n e + kappa P B_t du, P = I - e e^T
// (Newton's linearisation of mu lambda_n (s - s_0) / |s - s_0| about the current slide, along
// which P vanishes). Its stiffness kappa B_t^T P B_t joins K_t.
void StaticHardContacts::add_turn_entries(std::vector<Eigen::Triplet<double>>& entries) const {
  for_each_turning_pair([&](Index t, const Eigen::Matrix2d& turn) {
    for (Index a = 0; a < 2; ++a)
      for (Index b = 0; b < 2; ++b)
        for (RowIterator i(connectivity_, t + a); i; ++i)
          for (RowIterator j(connectivity_, t + b); j; ++j)
            entries.emplace_back(i.col(), j.col(), turn(a, b) * i.value() * j.value());
  });
}

void StaticHardContacts::follow_slides(const Vector& delta) {
  for_each_turning_pair([&](Index t, const Eigen::Matrix2d&) {
    const Eigen::Vector2d slide = delta.segment<2>(t) - anchor_.segment<2>(t);
    if (slide.norm() > 0.0)
      multiplier_.segment<2>(t) = coefficient(t) * multiplier_[normal_of(t)] * slide / slide.norm();
  });
}

void StaticHardContacts::add_turn_forces(const Vector& step, Vector& multipliers) const {
  for_each_turning_pair([&](Index t, const Eigen::Matrix2d& turn) {
    Eigen::Vector2d slide_step;
    for (Index a = 0; a < 2; ++a) {
      slide_step[a] = 0.0;
      for (RowIterator term(connectivity_, t + a); term; ++term)
        slide_step[a] += term.value() * step[term.col()];
    }
    multipliers.segment<2>(t) += turn * slide_step;
  });
}

template <typename Visit>
void StaticHardContacts::for_each_turning_pair(Visit visit) const {
  for (Index t = 0; t + 1 < multiplier_.size(); ++t) {
    const auto row = static_cast<std::size_t>(t);
    if (state_[row] != Row::kSlip || !pair_[row] || tangent_[row] != 0 || turn_[t] == 0.0) continue;
    const Eigen::Vector2d e = direction_.segment<2>(t);
    visit(t, Eigen::Matrix2d(turn_[t] * (Eigen::Matrix2d::Identity() - e * e.transpose())));
  }
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
      frictions_[row]->impose_tangential(tangent_[row], multiplier_[r], state_[row] == Row::kSlip);
  }
}

}  // namespace pound::assembly
