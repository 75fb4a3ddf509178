#pragma once
// A one-DOF system m u'' + c u' + k u + F_links = f(t) for testing integrators without a model.
#include <Eigen/Dense>
#include <functional>
#include <optional>

#include "integrators/second_order_system.hpp"

namespace pound::testing {

class Oscillator final : public integrators::SecondOrderSystem {
 public:
  Oscillator(double mass, double damping, double stiffness,
             integrators::LinkSet links = integrators::LinkSet(1),
             std::function<double(double)> force = {})
      : mass_(mass),
        damping_(damping),
        stiffness_(stiffness),
        links_(std::move(links)),
        force_(std::move(force)),
        lumped_(Vector::Constant(1, mass)) {}

  Index size() const override { return 1; }
  void multiply_mass(const Vector& x, Vector& y) const override { y = mass_ * x; }
  const Vector* lumped_mass() const override { return &lumped_; }
  bool has_damping() const override { return damping_ != 0.0; }
  void multiply_damping(const Vector& x, Vector& y) const override { y = damping_ * x; }
  void multiply_stiffness(const Vector& x, Vector& y) const override { y = stiffness_ * x; }
  bool has_external_force() const override { return static_cast<bool>(force_); }
  void external_force(double time, Vector& force) const override {
    force = Vector::Constant(1, force_(time));
  }
  std::unique_ptr<integrators::LinearSolver> factor(double c_m, double c_c,
                                                    double c_k) const override {
    return std::make_unique<Scalar>(c_m * mass_ + c_c * damping_ + c_k * stiffness_);
  }
  // With the links' row stiffnesses folded in: + sum_r b_r^2 k_r. Off: the integrator iterates on
  // every link row.
  std::unique_ptr<integrators::LinearSolver> factor_with_links(
      double c_m, double c_c, double c_k, const Vector& link_stiffness) const override {
    if (!folds_links_) return nullptr;
    const Vector b = Matrix(links_.connectivity()).col(0);
    return std::make_unique<Scalar>(c_m * mass_ + c_c * damping_ + c_k * stiffness_ +
                                    b.cwiseProduct(b).dot(link_stiffness));
  }
  void set_folds_links(bool folds) { folds_links_ = folds; }
  integrators::LinkSet& links() override { return links_; }
  // Its damping as a0 m + a1 k, said so (as a Rayleigh-damped structure does).
  void set_rayleigh(double a0, double a1) {
    damping_ = a0 * mass_ + a1 * stiffness_;
    rayleigh_ = Rayleigh{Vector::Constant(1, a0), Vector::Constant(1, a1), a1 != 0.0};
  }
  const Rayleigh* rayleigh() const override { return rayleigh_ ? &*rayleigh_ : nullptr; }

 private:
  struct Scalar final : integrators::LinearSolver {
    explicit Scalar(double diagonal) : value(diagonal) {}
    void solve(const Vector& rhs, Vector& solution) const override { solution = rhs / value; }
    double value;
  };
  double mass_, damping_, stiffness_;
  integrators::LinkSet links_;
  std::function<double(double)> force_;
  Vector lumped_;
  std::optional<Rayleigh> rayleigh_;
  bool folds_links_ = true;
};

}  // namespace pound::testing
