#include "verification/two_element.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

#include "assembly/structural_system.hpp"
#include "assembly/truss.hpp"
#include "links/extended_penalty.hpp"

namespace pound::verification {
namespace {

// Larger root first from the sum, smaller from the product: no cancellation for stiff alpha0.
std::pair<double, double> roots(double half_sum, double product) {
  const double larger = half_sum + std::sqrt(half_sum * half_sum - product);
  return {product / larger, larger};
}

model::Model two_element_model(const TwoElementCase& c) {
  model::Model m;
  m.dimension = 1;
  m.nodes = {{"support_1", {-1.0, 0.0}},
             {"mass_1", {0.0, 0.0}},
             {"mass_2", {0.0, 0.0}},
             {"support_2", {1.0, 0.0}}};
  // Unit-length massless trusses with E A = k.
  auto spring = [&m](const char* id, Index i, Index j, double k) {
    return std::make_shared<const assembly::Truss>(
        id,
        std::array<model::ElementNode, 2>{{{i, m.nodes[static_cast<std::size_t>(i)].position},
                                           {j, m.nodes[static_cast<std::size_t>(j)].position}}},
        1, assembly::Truss::Section{.youngs_modulus = k, .area = 1.0, .density = 0.0},
        std::nullopt);
  };
  m.elements = {spring("spring_1", 0, 1, c.k1), spring("spring_2", 2, 3, c.k2)};
  m.masses = {{1, c.m1}, {2, c.m2}};
  m.supports = {{0, {true, false}}, {3, {true, false}}};
  const links::ExtendedPenalty::Numbers numbers{c.alpha0, 0.0, c.alpha2};
  m.links = {{.id = "contact",
              .node_i = 1,
              .node_j = 2,
              .axis = {1.0, 0.0},
              .gap = 0.0,
              .make_law = [numbers](const links::LinkContext&) {
                return std::make_unique<links::ExtendedPenalty>(numbers);
              }}};
  return m;
}

}  // namespace

TwoElementResult solve_two_element(const TwoElementCase& c) {
  assembly::StructuralSystem system(two_element_model(c));
  // The link in contact (closing, penetrating) contributes its tangents: dF/d(delta) to K and
  // dF/d(delta_ddot) to M, read as the total tangent with acceleration factor 0 and 1.
  integrators::LinkSet& links = system.links();
  const Vector penetration = Vector::Constant(1, 1e-6), rate = Vector::Constant(1, 1.0);
  Vector force;
  Matrix link_stiffness, stiffness_and_mass;
  links.set_trial(penetration, rate, Vector::Zero(1), 0.0, 0.0, force, link_stiffness);
  links.set_trial(penetration, rate, Vector::Zero(1), 0.0, 1.0, force, stiffness_and_mass);
  const Matrix b = Matrix(links.connectivity());
  const Matrix stiffness = Matrix(system.stiffness()) + link_stiffness(0, 0) * b.transpose() * b;
  const Matrix mass = Matrix(system.lumped_mass()->asDiagonal()) +
                      (stiffness_and_mass(0, 0) - link_stiffness(0, 0)) * b.transpose() * b;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> solver(stiffness, mass);

  TwoElementResult r{
      c, solver.eigenvalues()[0], solver.eigenvalues()[1], 0, 0, (c.k1 + c.k2) / (c.m1 + c.m2), 0};
  if (c.alpha2 == 0.0) {  // eq. 4
    const double sum = (c.k1 + c.alpha0) / c.m1 + (c.k2 + c.alpha0) / c.m2;
    const double product = (c.k1 * c.k2 + c.alpha0 * (c.k1 + c.k2)) / (c.m1 * c.m2);
    std::tie(r.closed_omega1_squared, r.closed_omega2_squared) = roots(0.5 * sum, product);
  } else {  // eqs. 23-24
    const double a = c.m1 * c.m2 + c.alpha2 * (c.m1 + c.m2);
    const double b_term =
        c.m1 * c.k2 + c.m2 * c.k1 + c.alpha0 * (c.m1 + c.m2) + c.alpha2 * (c.k1 + c.k2);
    const double c_term = c.k1 * c.k2 + c.alpha0 * (c.k1 + c.k2);
    std::tie(r.closed_omega1_squared, r.closed_omega2_squared) =
        roots(b_term / (2 * a), c_term / a);
  }
  r.relative_error = std::max(std::abs(r.omega1_squared / r.closed_omega1_squared - 1.0),
                              std::abs(r.omega2_squared / r.closed_omega2_squared - 1.0));
  return r;
}

std::vector<TwoElementResult> two_element_sweep() {
  std::vector<TwoElementResult> results;
  const double k1 = 100.0, m1 = 2.0;
  for (double stiffness_ratio : {1.0, 0.1, 3.0})
    for (double mass_ratio : {1.0, 0.5, 4.0})
      for (double penalty : {1.0, 10.0, 100.0, 1e3, 1e4})
        for (double mass_penalty : {0.0, 0.1, 1.0, 10.0}) {
          const double k2 = stiffness_ratio * k1, m2 = mass_ratio * m1, alpha0 = penalty * k1;
          const double alpha2 = mass_penalty * alpha0 * (m1 + m2) / (k1 + k2);  // eq. 29 times
          results.push_back(solve_two_element({k1, k2, m1, m2, alpha0, alpha2}));
        }
  return results;
}

}  // namespace pound::verification
