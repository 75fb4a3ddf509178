#pragma once
// A chain of n masses on springs (each to the next, the first to the ground), with Rayleigh or
// assembled damping, a load on every mass and link rows between them: a system of several DOFs
// for the integrators and recorders without a model. Its mass can be offered as lumped or not,
// so that the paths for a diagonal mass and the general ones can be compared on one system.
#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <memory>
#include <optional>
#include <utility>

#include "integrators/second_order_system.hpp"

namespace pound::testing {

class Chain final : public integrators::SecondOrderSystem {
 public:
  enum class Damping { none, rayleigh, assembled };
  // Masses 1 + 0.1 k, springs 50 + 5 k; damping a0 M + a1 K, said to be Rayleigh's or assembled
  // as a matrix; the load on mass k is amplitude sin(2 t + k).
  Chain(Index masses, Damping damping, integrators::LinkSet links, double amplitude = 1.0)
      : mass_(masses),
        stiffness_(Matrix::Zero(masses, masses)),
        links_(std::move(links)),
        damping_kind_(damping),
        amplitude_(amplitude) {
    for (Index k = 0; k < masses; ++k) {
      mass_[k] = 1.0 + 0.1 * static_cast<double>(k);
      const double spring = 50.0 + 5.0 * static_cast<double>(k);
      stiffness_(k, k) += spring;
      if (k > 0) {
        stiffness_(k - 1, k - 1) += spring;
        stiffness_(k - 1, k) -= spring;
        stiffness_(k, k - 1) -= spring;
      }
    }
    damping_ = kMassCoefficient * Matrix(mass_.asDiagonal()) + kStiffnessCoefficient * stiffness_;
    rayleigh_ = {Vector::Constant(masses, kMassCoefficient),
                 Vector::Constant(masses, kStiffnessCoefficient), true};
  }

  static constexpr double kMassCoefficient = 0.3, kStiffnessCoefficient = 0.002;

  // Cuts the spring between masses first - 1 and first, and damps the masses from `first` on
  // with a0, a1 of their own: two structures that only links join, each with its Rayleigh
  // damping (the coefficients by DOF).
  void split(Index first, double mass_coefficient, double stiffness_coefficient) {
    const double spring = -stiffness_(first - 1, first);
    stiffness_(first - 1, first) = stiffness_(first, first - 1) = 0.0;
    stiffness_(first - 1, first - 1) -= spring;
    stiffness_(first, first) -= spring;
    const Index rest = size() - first;
    rayleigh_.mass_coefficient.tail(rest).setConstant(mass_coefficient);
    rayleigh_.stiffness_coefficient.tail(rest).setConstant(stiffness_coefficient);
    damping_ = rayleigh_.mass_coefficient.asDiagonal() * Matrix(mass_.asDiagonal()) +
               rayleigh_.stiffness_coefficient.asDiagonal() * stiffness_;
  }

  void set_lumped(bool lumped) { lumped_ = lumped; }

  Index size() const override { return mass_.size(); }
  void multiply_mass(const Vector& x, Vector& y) const override { y = mass_.cwiseProduct(x); }
  const Vector* lumped_mass() const override { return lumped_ ? &mass_ : nullptr; }
  bool has_damping() const override { return damping_kind_ != Damping::none; }
  void multiply_damping(const Vector& x, Vector& y) const override {
    if (damping_kind_ == Damping::none)
      y.setZero(x.size());
    else
      y.noalias() = damping_ * x;
  }
  const Rayleigh* rayleigh() const override {
    return damping_kind_ == Damping::rayleigh ? &rayleigh_ : nullptr;
  }
  void multiply_stiffness(const Vector& x, Vector& y) const override {
    y.noalias() = stiffness_ * x;
  }
  bool has_external_force() const override { return amplitude_ != 0.0; }
  void external_force(double time, Vector& force) const override {
    force.resize(size());
    for (Index k = 0; k < size(); ++k)
      force[k] = amplitude_ * std::sin(2.0 * time + static_cast<double>(k));
  }
  std::unique_ptr<integrators::LinearSolver> factor(double c_m, double c_c,
                                                    double c_k) const override {
    return std::make_unique<Dense>(effective(c_m, c_c, c_k));
  }
  std::unique_ptr<integrators::LinearSolver> factor_with_links(
      double c_m, double c_c, double c_k, const Vector& link_stiffness) const override {
    const Matrix b(links_.connectivity());
    return std::make_unique<Dense>(effective(c_m, c_c, c_k) +
                                   b.transpose() * link_stiffness.asDiagonal() * b);
  }
  integrators::LinkSet& links() override { return links_; }

 private:
  Matrix effective(double c_m, double c_c, double c_k) const {
    Matrix a = c_k * stiffness_ + c_m * Matrix(mass_.asDiagonal());
    if (damping_kind_ != Damping::none) a += c_c * damping_;
    return a;
  }
  struct Dense final : integrators::LinearSolver {
    explicit Dense(const Matrix& a) : factors(a) {}
    void solve(const Vector& rhs, Vector& solution) const override {
      solution = factors.solve(rhs);
    }
    // Cholesky, not LDL^T (whose unit-lower solve is the LU's): tests/core/pivoted_lu_test.cpp.
    Eigen::LLT<Matrix> factors;
  };
  Vector mass_;
  Matrix stiffness_, damping_;
  Rayleigh rayleigh_;
  integrators::LinkSet links_;
  Damping damping_kind_;
  double amplitude_;
  bool lumped_ = true;
};

}  // namespace pound::testing
