#include "assembly/pushover.hpp"

#include <fmt/format.h>

#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>

#include "assembly/static_equilibrium.hpp"
#include "core/interrupt.hpp"

namespace pound::assembly {
namespace {

// Newton on (u, lambda) at one target of the control DOF.
class BorderedNewton {
 public:
  BorderedNewton(StructuralSystem& system, const PushoverControl& control)
      : system_(system), control_(control), b_(system.links().connectivity()) {
    constant_ = Vector::Zero(system.size());
    if (system.has_external_force()) system.external_force(0.0, constant_);
  }

  // Moves (u, lambda) to equilibrium with u_c = target; false when Newton does not get there.
  bool solve(double target, Vector& u, double& lambda, int& iterations) {
    Vector residual;
    for (iterations = 0; iterations <= control_.max_iterations; ++iterations) {
      const double scale = unbalanced(u, lambda, residual);
      const double offset = target - u[control_.equation];
      if (iterations == 0) start_tangent_ = tangent_;
      if (!residual.allFinite()) return false;
      if (residual.norm() <= control_.relative_tolerance * scale &&
          std::abs(offset) <= 1e-12 * std::max(std::abs(target), 1e-300))
        return true;
      if (iterations == control_.max_iterations) return false;
      Vector rhs(u.size() + 1);
      rhs << residual, offset;
      Vector correction;
      if (!solve_static([this](bool hold) { return bordered_tangent(hold); }, rhs, correction))
        return false;
      u += correction.head(u.size());
      lambda += correction[u.size()];
    }
    return false;
  }

  // The DOFs the pattern loads that nothing held at the start of the last increment tried.
  std::vector<Index> unheld_loaded() const {
    std::vector<Index> loaded;
    for (const Index i : unheld_dofs(system_, start_tangent_))
      if (control_.pattern[i] != 0.0) loaded.push_back(i);
    return loaded;
  }

 private:
  // f_0 + lambda p - K u - B^T F at (u, lambda), the links left at that trial; returns the
  // force scale the tolerance is relative to.
  double unbalanced(const Vector& u, double lambda, Vector& residual) {
    integrators::LinkSet& links = system_.links();
    const Index m = links.size();
    Vector delta(m), force(m), stiffness_force;
    const Vector zero = Vector::Zero(m);
    links.penetration(u, delta);
    links.set_trial(delta, zero, zero, 0.0, 0.0, force, tangent_);
    system_.multiply_stiffness(u, stiffness_force);
    const Vector applied = constant_ + lambda * control_.pattern;
    const Vector link_force = b_.transpose() * force;
    residual = applied - stiffness_force - link_force;
    return std::max({applied.norm(), link_force.norm(), stiffness_force.norm(), 1e-300});
  }

  // `hold_link_held`: as static_tangent's, for a tangent that does not factor without it.
  Eigen::SparseMatrix<double> bordered_tangent(bool hold_link_held) const {
    const Index n = system_.size();
    const Eigen::SparseMatrix<double> structure = static_tangent(system_, tangent_, hold_link_held);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(static_cast<std::size_t>(structure.nonZeros() + 2 * n + 1));
    for (Index col = 0; col < structure.outerSize(); ++col)
      for (Eigen::SparseMatrix<double>::InnerIterator it(structure, col); it; ++it)
        entries.emplace_back(it.row(), it.col(), it.value());
    for (Index i = 0; i < n; ++i)
      if (control_.pattern[i] != 0.0) entries.emplace_back(i, n, -control_.pattern[i]);
    entries.emplace_back(n, control_.equation, 1.0);
    Eigen::SparseMatrix<double> bordered(n + 1, n + 1);
    bordered.setFromTriplets(entries.begin(), entries.end());
    bordered.makeCompressed();
    return bordered;
  }

  StructuralSystem& system_;
  const PushoverControl& control_;
  Eigen::SparseMatrix<double> b_;
  Vector constant_;
  Matrix tangent_, start_tangent_;  // the links' at the last trial, and at the increment's start
};

}  // namespace

PushoverResult pushover(StructuralSystem& system, const Vector& start,
                        const PushoverControl& control, const PushoverObserver& observe) {
  BorderedNewton newton(system, control);
  PushoverResult result;
  result.displacement = start;
  double lambda = 0.0, reached = start[control.equation];
  result.curve.push_back({reached, 0.0, 0});
  if (observe) observe(result.curve.back(), start);
  const double nominal = (control.target - reached) / control.increments;
  double step = nominal;
  int cuts = 0;
  while (std::abs(control.target - reached) > 1e-12 * std::abs(nominal) * control.increments) {
    throw_if_interrupted();  // Ctrl-C or SIGTERM: a push of a million increments stops here
    const double next =
        std::abs(control.target - reached) < std::abs(step) ? control.target : reached + step;
    Vector u = result.displacement;
    double trial_lambda = lambda;
    int iterations = 0;
    if (newton.solve(next, u, trial_lambda, iterations)) {
      system.links().commit();
      result.displacement = u;
      lambda = trial_lambda;
      reached = next;
      result.curve.push_back({reached, lambda, iterations});
      if (observe) observe(result.curve.back(), u);
      if (std::abs(step) < std::abs(nominal)) step *= 2.0;  // back to the nominal increment
      continue;
    }
    system.links().revert();
    if (cuts == control.max_cuts) {
      result.stopped = fmt::format(
          "no equilibrium beyond a control displacement of {:.6g} (the increment to {:.6g} did "
          "not converge after {} halvings): a mechanism, or a target past what the model can "
          "carry",
          reached, next, cuts);
      result.unheld_loaded = newton.unheld_loaded();
      break;
    }
    ++cuts;
    step *= 0.5;
  }
  return result;
}

}  // namespace pound::assembly
