#pragma once
// Two free masses (no springs) joined by link rows, for testing impacts between bodies with any
// integrator without a model (or one point mass's x and y, under a load); a single hard-contact
// row; a hard contact with Coulomb friction between such a point mass and the ground.
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "integrators/second_order_system.hpp"
#include "links/coulomb_friction.hpp"
#include "links/hard_contact.hpp"

namespace pound::testing {

class FreeMassPair final : public integrators::SecondOrderSystem {
 public:
  // load(t): the two DOFs' external forces; none without it.
  FreeMassPair(double mass_0, double mass_1, integrators::LinkSet links,
               std::function<Vector(double)> load = {})
      : mass_(Vector{{mass_0, mass_1}}), links_(std::move(links)), load_(std::move(load)) {}
  Index size() const override { return 2; }
  void multiply_mass(const Vector& x, Vector& y) const override { y = mass_.cwiseProduct(x); }
  const Vector* lumped_mass() const override { return &mass_; }
  bool has_damping() const override { return false; }
  void multiply_damping(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  void multiply_stiffness(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  bool has_external_force() const override { return static_cast<bool>(load_); }
  void external_force(double time, Vector& force) const override {
    force = load_ ? load_(time) : Vector::Zero(2);
  }
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
  std::function<Vector(double)> load_;
};

// One hard-contact link on the row `row` (B u - gap).
inline integrators::LinkSet hard_contact_row(std::vector<integrators::LinkSet::Term> row,
                                             double gap, double restitution) {
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::HardContact>(restitution));
  return integrators::LinkSet(static_cast<Index>(row.size()), {row}, {gap}, std::move(laws));
}

// A hard contact of a point mass (DOFs x, y) with the ground at y = -gap (penetration -y - gap),
// with Coulomb friction mu along x (slide x).
inline integrators::LinkSet hard_contact_on_the_ground(double gap, double restitution,
                                                       double coefficient) {
  std::vector<integrators::LinkSet::Link> links(1);
  links[0].normal_row = {{1, -1.0}};
  links[0].gap = gap;
  links[0].tangential_rows = {{{0, 1.0}}};
  links[0].friction = std::make_unique<links::CoulombFriction>(
      std::make_unique<links::HardContact>(restitution), coefficient, links::StickPenalty{});
  return integrators::LinkSet(2, std::move(links));
}

}  // namespace pound::testing
