#include "assembly/quad.hpp"

#include <cmath>

namespace pound::assembly {
namespace {

constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
const double kGauss = 1.0 / std::sqrt(3.0);

struct ShapeAt {
  Eigen::Vector4d n;
  Eigen::Matrix<double, 2, 4> dn_dx;  // rows d/dx, d/dy
  double jacobian = 0.0;
};

ShapeAt shape_at(const QuadCorners& corners, double xi, double eta) {
  ShapeAt s;
  Eigen::Matrix<double, 2, 4> dn_dparent;
  for (int a = 0; a < 4; ++a) {
    s.n[a] = 0.25 * (1 + xi * kXi[a]) * (1 + eta * kEta[a]);
    dn_dparent(0, a) = 0.25 * kXi[a] * (1 + eta * kEta[a]);
    dn_dparent(1, a) = 0.25 * kEta[a] * (1 + xi * kXi[a]);
  }
  Eigen::Matrix2d j = Eigen::Matrix2d::Zero();  // J(r, c) = d x_c / d parent_r
  for (int a = 0; a < 4; ++a)
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c) j(r, c) += dn_dparent(r, a) * corners[a][c];
  s.jacobian = j.determinant();
  s.dn_dx = j.inverse() * dn_dparent;
  return s;
}

Eigen::Matrix<double, 3, 8> strain_matrix(const ShapeAt& s) {
  Eigen::Matrix<double, 3, 8> b = Eigen::Matrix<double, 3, 8>::Zero();
  for (int a = 0; a < 4; ++a) {
    b(0, 2 * a) = s.dn_dx(0, a);
    b(1, 2 * a + 1) = s.dn_dx(1, a);
    b(2, 2 * a) = s.dn_dx(1, a);
    b(2, 2 * a + 1) = s.dn_dx(0, a);
  }
  return b;
}

constexpr int kDirections[] = {0, 1};

}  // namespace

Quad::Quad(std::string id, const std::array<model::ElementNode, 4>& corners,
           const Material& material, bool consistent_mass,
           std::optional<model::RayleighDamping> damping)
    : Element(std::move(id),
              {corners[0].index, corners[1].index, corners[2].index, corners[3].index}, damping),
      corners_{corners[0].position, corners[1].position, corners[2].position, corners[3].position},
      material_(material),
      consistent_mass_(consistent_mass) {}

std::span<const int> Quad::directions() const { return kDirections; }

Eigen::Matrix3d Quad::elasticity() const {
  const double e = material_.youngs_modulus, nu = material_.poisson_ratio;
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (material_.plane_strain) {
    const double f = e / ((1 + nu) * (1 - 2 * nu));
    d << 1 - nu, nu, 0, nu, 1 - nu, 0, 0, 0, (1 - 2 * nu) / 2;
    return f * d;
  }
  const double f = e / (1 - nu * nu);
  d << 1, nu, 0, nu, 1, 0, 0, 0, (1 - nu) / 2;
  return f * d;
}

Matrix Quad::stiffness() const {
  const Eigen::Matrix3d d = elasticity();
  Matrix8 k = Matrix8::Zero();
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const ShapeAt s = shape_at(corners_, xi, eta);
      const Eigen::Matrix<double, 3, 8> b = strain_matrix(s);
      k.noalias() += b.transpose() * d * b * (s.jacobian * material_.thickness);
    }
  // Exactly symmetric, so that K x by rows and the factorisations see one matrix.
  const Matrix8 symmetric = 0.5 * (k + k.transpose());
  return symmetric;
}

model::ElementMass Quad::mass() const {
  const Matrix8 m = consistent_mass();
  if (consistent_mass_) return {.consistent = m};
  const Eigen::Matrix<double, 8, 1> row_sums = m.rowwise().sum();
  return {.lumped = row_sums};
}

Matrix8 Quad::consistent_mass() const {
  Matrix8 m = Matrix8::Zero();
  for (double xi : {-kGauss, kGauss})
    for (double eta : {-kGauss, kGauss}) {
      const ShapeAt s = shape_at(corners_, xi, eta);
      const double w = material_.density * material_.thickness * s.jacobian;
      for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) {
          m(2 * a, 2 * b) += w * s.n[a] * s.n[b];
          m(2 * a + 1, 2 * b + 1) += w * s.n[a] * s.n[b];
        }
    }
  return m;
}

Eigen::Vector3d quad_strain(const QuadCorners& corners, const Eigen::Matrix<double, 8, 1>& u,
                            double xi, double eta) {
  return strain_matrix(shape_at(corners, xi, eta)) * u;
}

double quad_smallest_jacobian(const QuadCorners& corners) {
  double smallest = shape_at(corners, kXi[0], kEta[0]).jacobian;
  for (int a = 1; a < 4; ++a)
    smallest = std::min(smallest, shape_at(corners, kXi[a], kEta[a]).jacobian);
  return smallest;
}

double quad_area(const QuadCorners& corners) {
  double twice = 0.0;  // shoelace
  for (int a = 0; a < 4; ++a) {
    const auto& p = corners[a];
    const auto& q = corners[(a + 1) % 4];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * twice;
}

}  // namespace pound::assembly
