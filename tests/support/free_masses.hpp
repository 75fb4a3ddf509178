#pragma once
// Two free masses (no springs) joined by link rows, for testing impacts between bodies with any
// integrator without a model; and a single hard-contact row.
#include <memory>
#include <utility>
#include <vector>

#include "integrators/second_order_system.hpp"
#include "links/hard_contact.hpp"

namespace pound::testing {

class FreeMassPair final : public integrators::SecondOrderSystem {
 public:
  FreeMassPair(double mass_0, double mass_1, integrators::LinkSet links)
      : mass_(Vector{{mass_0, mass_1}}), links_(std::move(links)) {}
  Index size() const override { return 2; }
  void multiply_mass(const Vector& x, Vector& y) const override { y = mass_.cwiseProduct(x); }
  const Vector* lumped_mass() const override { return &mass_; }
  bool has_damping() const override { return false; }
  void multiply_damping(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  void multiply_stiffness(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  bool has_external_force() const override { return false; }
  void external_force(double, Vector& force) const override { force.setZero(2); }
  // c_m M: no stiffness or damping to add.
  std::unique_ptr<integrators::LinearSolver> factor(double c_m, double, double) const override {
    return std::make_unique<Diagonal>(c_m * mass_);
  }
  integrators::LinkSet& links() override { return links_; }

 private:
  struct Diagonal final : integrators::LinearSolver {
    explicit Diagonal(Vector d) : diagonal(std::move(d)) {}
    void solve(const Vector& rhs, Vector& solution) const override {
      solution = rhs.cwiseQuotient(diagonal);
    }
    Vector diagonal;
  };
  Vector mass_;
  integrators::LinkSet links_;
};

// One hard-contact link on the row `row` (B u - gap).
inline integrators::LinkSet hard_contact_row(std::vector<integrators::LinkSet::Term> row,
                                             double gap, double restitution) {
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::HardContact>(restitution));
  return integrators::LinkSet(static_cast<Index>(row.size()), {row}, {gap}, std::move(laws));
}

}  // namespace pound::testing
