#include "assembly/static_equilibrium.hpp"

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "assembly/static_hard_contacts.hpp"
#include "core/errors.hpp"

namespace pound::assembly {

void hold_unheld_dofs(Eigen::SparseMatrix<double>& tangent) {
  if (tangent.size() == 0) return;
  const double largest = tangent.diagonal().cwiseAbs().maxCoeff();
  for (Index i = 0; i < tangent.rows(); ++i)
    if (tangent.coeff(i, i) == 0.0) tangent.coeffRef(i, i) = 1e-12 * largest;
}

std::vector<Index> unheld_dofs(const StructuralSystem& system, const Matrix& link_tangent) {
  const Eigen::SparseMatrix<double>& b = system.links().connectivity();
  const Eigen::SparseMatrix<double> tangent =
      system.stiffness() +
      Eigen::SparseMatrix<double>(b.transpose() * link_tangent.sparseView() * b);
  std::vector<Index> unheld;
  for (Index i = 0; i < tangent.rows(); ++i)
    if (tangent.coeff(i, i) == 0.0) unheld.push_back(i);
  return unheld;
}

Eigen::SparseMatrix<double> static_tangent(const StructuralSystem& system,
                                           const Matrix& link_tangent, bool hold_link_held) {
  const Eigen::SparseMatrix<double>& b = system.links().connectivity();
  Eigen::SparseMatrix<double> tangent =
      system.stiffness() +
      Eigen::SparseMatrix<double>(b.transpose() * link_tangent.sparseView() * b);
  hold_unheld_dofs(tangent);
  if (hold_link_held && tangent.size() > 0) {
    const double largest = tangent.diagonal().cwiseAbs().maxCoeff();
    const Vector elements = system.stiffness().diagonal();
    for (Index i = 0; i < tangent.rows(); ++i)
      if (elements[i] == 0.0) tangent.coeffRef(i, i) += 1e-12 * largest;
  }
  tangent.makeCompressed();
  return tangent;
}

bool solve_static(const std::function<Eigen::SparseMatrix<double>(bool)>& matrix, const Vector& rhs,
                  Vector& solution) {
  for (const bool hold_link_held : {false, true}) {
    Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
    solver.compute(matrix(hold_link_held));
    if (solver.info() != Eigen::Success) continue;
    solution = solver.solve(rhs);
    if (solution.allFinite()) return true;
  }
  return false;
}

namespace {

// Newton's correction du (with hard contacts, their new multipliers too); false: a mechanism.
bool newton_correction(const StaticHardContacts& hard, const StructuralSystem& system,
                       const Matrix& link_tangent, const Vector& residual, const Vector& delta,
                       Vector& correction, Vector& multipliers) {
  if (hard.any())
    return hard.solve(static_tangent(system, link_tangent), residual, delta, correction,
                      multipliers);
  return solve_static(
      [&](bool hold_link_held) { return static_tangent(system, link_tangent, hold_link_held); },
      residual, correction);
}

// What a model with friction links is told when its loads find no equilibrium.
std::string friction_hint(const integrators::LinkSet& links) {
  for (Index k = 0; k < links.count(); ++k)
    if (links.has_friction(k))
      return "; friction holds no more than mu R_n, and a load past it slides the structure away";
  return "";
}

// Friction that slips is friction_overload's: here it holds (or there is none), except under a
// moving surface (`sliding`), where it slips by design and must be held.
SolveError mechanism(double time, bool sliding) {
  return SolveError(
      time, fmt::format("static equilibrium: the structure is not held under the initial loads (a "
                        "mechanism: add supports, or links in contact{})",
                        sliding ? "; a moving surface drags what rests on it at mu R_n, which "
                                  "supports, springs or links must hold"
                                : ""));
}

// The links whose friction slips at mu R_n in the links' last trial state (a hard contact's: in
// the state the active set chose), quoted and joined.
std::string slipping_links(const StructuralSystem& system, const StaticHardContacts& hard) {
  const integrators::LinkSet& links = system.links();
  std::string names;
  for (Index k = 0; k < links.count(); ++k) {
    const links::CoulombFriction* friction = links.friction(k);
    if (!friction) continue;
    bool slips = friction->trial_slipping();
    for (Index row = links.row(k) + 1; row < links.row(k) + links.rows(k); ++row)
      slips = slips || hard.slips(row);  // a row no hard contact holds stays free
    if (slips) names += fmt::format("{}'{}'", names.empty() ? "" : ", ", system.link_id(k));
  }
  return names;
}

// Loads that no static state holds because friction slips at its limit where they push (a block
// pushed harder than mu W): under loads applied in proportion, the limit is passed at the first
// increment as at the last, so Newton's failure there is not one of convergence. Named with the
// links that slip; none slip: not this failure.
std::optional<SolveError> friction_overload(double time, const StructuralSystem& system,
                                            const StaticHardContacts& hard) {
  const std::string names = slipping_links(system, hard);
  if (names.empty()) return std::nullopt;
  return SolveError(
      time, fmt::format("static equilibrium: the initial loads ask more of friction than it "
                        "holds: it slips at its limit mu R_n at link(s) {} and no static state "
                        "is found, so the structure would slide away (lower the loads, or hold "
                        "it with supports, springs or links)",
                        names));
}

// `delta` with the links that touch (delta = 0, no hard contact holds them) nudged closed, in
// `nudged`; false where none touches.
bool nudge_touching(const integrators::LinkSet& links, const StaticHardContacts& hard,
                    const Vector& delta, Vector& nudged) {
  nudged = delta;
  bool any = false;
  for (Index k = 0; k < links.count(); ++k) {
    const Index row = links.row(k);
    if (delta[row] != 0.0 || hard.constrains(row)) continue;
    nudged[row] = std::numeric_limits<double>::min();
    any = true;
  }
  return any;
}

}  // namespace

StaticEquilibrium static_equilibrium(StructuralSystem& system, double time,
                                     double relative_tolerance, int max_iterations) {
  const Index n = system.size();
  integrators::LinkSet& links = system.links();
  const Index m = links.size();
  Vector load = Vector::Zero(n);
  if (system.has_external_force()) system.external_force(time, load);
  Vector offset = Vector::Zero(m), offset_rate, offset_acceleration;
  if (system.has_link_motion()) system.link_motion(time, offset, offset_rate, offset_acceleration);
  const Eigen::SparseMatrix<double> b = links.connectivity();
  const Vector zero = Vector::Zero(m);
  // Links move at the rates their moving sides give them (a belt slides under the structure,
  // which is at rest): friction there slips, in the belt's direction.
  const Vector rate = offset_rate.size() == m ? offset_rate : zero;

  StaticEquilibrium result;
  Vector& u = result.displacement;
  u = Vector::Zero(n);
  Vector delta(m), force(m), stiffness_force(n), nudged;
  Matrix tangent, nudged_tangent;
  bool first = true;
  StaticHardContacts hard(system, rate, offset - links.gaps());
  // Unbalanced force at u under `applied` without the hard contacts' forces, leaving the links
  // at that trial state.
  auto unbalanced = [&](const Vector& at, const Vector& applied, Vector& residual) {
    links.penetration(at, delta);
    delta += offset;
    // Links touching at the start (delta = 0: a block set on a floor) are taken as closed for
    // the first tangent, so that it holds the structure; their forces are those at delta = 0,
    // so no round-off of the nudge reaches the displacements (a hinge kept a 1e-316 N m
    // moment). (A hard contact holds without one: StaticHardContacts::choose.)
    Matrix* tangent_out = &tangent;
    if (std::exchange(first, false) && nudge_touching(links, hard, delta, nudged)) {
      links.set_trial(nudged, rate, zero, 0.0, 0.0, force, tangent);
      tangent_out = &nudged_tangent;
    }
    links.set_trial(delta, rate, zero, 0.0, 0.0, force, *tangent_out);
    hard.leave_out(force);  // what the hard laws return is what was imposed on them last
    system.multiply_stiffness(at, stiffness_force);
    const Vector link_force = b.transpose() * force;
    residual = applied - stiffness_force - link_force;
    return std::max(applied.norm(), link_force.norm());
  };
  // The hard contacts' load on the structure, B^T lambda (zero without them).
  auto hard_load = [&]() { return Vector(b.transpose() * hard.multipliers()); };

  // The loads in increments, each committed: friction links follow the loading path, as in a
  // structure loaded slowly; a line search keeps Newton from cycling between contact states.
  // Under a moving belt the surfaces slide all along the loading, so friction is mu R_n
  // wherever they touch: one increment, in which every such link slips.
  const bool sliding = rate.size() > 0 && rate.any();
  const int increments = sliding ? 1 : 10;
  // Where friction slips at the failure (not by design under a belt), the loads passed it.
  const auto throw_if_friction_overloaded = [&] {
    if (sliding) return;
    if (std::optional<SolveError> overload = friction_overload(time, system, hard)) throw *overload;
  };
  Vector residual(n), trial_residual(n), trial(n), correction(n), multipliers;
  for (int increment = 1; increment <= increments; ++increment) {
    const Vector applied = (static_cast<double>(increment) / increments) * load;
    double scale = std::max(load.norm(), unbalanced(u, applied, residual));
    for (int iteration = 0;; ++iteration) {
      const bool settled = hard.choose(delta);
      const Vector hard_force = hard_load();
      scale = std::max(scale, hard_force.norm());
      result.unbalanced_force = (residual - hard_force).norm();
      const double violation = hard.violation(delta);
      if (settled && result.unbalanced_force <= relative_tolerance * scale &&
          violation <= relative_tolerance * scale)
        break;
      if (iteration == max_iterations) {
        throw_if_friction_overloaded();
        throw SolveError(time, fmt::format("static equilibrium under the initial loads did not "
                                           "converge in {} iterations at {} % of the loads "
                                           "(unbalanced force {:.3g} of {:.3g}{})",
                                           max_iterations, 100 * increment / increments,
                                           std::max(result.unbalanced_force, violation), scale,
                                           friction_hint(links)));
      }
      if (!newton_correction(hard, system, tangent, residual, delta, correction, multipliers)) {
        throw_if_friction_overloaded();
        throw mechanism(time, sliding);
      }
      const Vector start_multipliers = hard.multipliers();
      const double merit = result.unbalanced_force + violation;
      double step = 1.0;
      for (int halving = 0;; ++halving) {
        trial = u + step * correction;
        scale = std::max(load.norm(), unbalanced(trial, applied, trial_residual));
        if (hard.any()) {
          hard.set_multipliers(start_multipliers + step * (multipliers - start_multipliers));
          hard.follow_slides(delta);
        }
        const double trial_merit = (trial_residual - hard_load()).norm() + hard.violation(delta);
        // A step that changes the contacts' states solves a new problem: taken whole, as a
        // primal-dual active-set step is (the merit, which does not see a sticking force past
        // mu R_n, may be zero before it). A slip's turn alone is searched on the true residual.
        if ((!settled && !hard.only_turning()) || trial_merit < merit || halving == 12) break;
        step *= 0.5;
      }
      u = trial;
      residual = trial_residual;
      ++result.iterations;
    }
    hard.impose();
    links.commit();
    hard.commit(delta);
  }
  // The dynamics starts with the structure moving as the belts do: the friction forces found
  // here must hold at zero relative rate.
  links.anchor_friction_at_rest(force);
  return result;
}

}  // namespace pound::assembly
