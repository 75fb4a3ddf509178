// The 3-D beam-column against beam theory: a cantilever along a skewed axis under each tip load
// (axial, both shears, torque, both moments; one element is exact for tip loads), rigid-body
// motions that strain nothing (with offsets), rigid offsets as the equivalent longer beam, the
// plane frame beam it must equal in its plane, its masses, and Euler's buckling loads about both
// axes from the consistent geometric stiffness.
#include "assembly/beam_3d.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "assembly/beam.hpp"

namespace pound::assembly {
namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

Beam3d::Section steel_section() {
  Beam3d::Section section;
  section.youngs_modulus = 2.0e11;
  section.shear_modulus = 8.0e10;
  section.area = 0.02;
  section.inertia_y = 3.0e-4;
  section.inertia_z = 1.2e-4;
  section.torsion = 5.0e-5;
  section.density = 7850.0;
  section.extra_mass = 100.0;
  return section;
}

Beam3d make_beam(const Point3& start, const Point3& end, const Point3& orientation,
                 const Point3& start_offset = Point3::Zero(),
                 const Point3& end_offset = Point3::Zero(), bool consistent = false) {
  return Beam3d("beam", {{{0, start, start_offset}, {1, end, end_offset}}}, orientation,
                steel_section(), consistent, std::nullopt);
}

// Node j's displacement and rotation of a cantilever fixed at node i, under `load` at node j.
Vector6 cantilever_tip(const Beam3d& beam, const Vector6& load) {
  const Matrix k = beam.stiffness();
  const Eigen::Matrix<double, 6, 6> free = k.block<6, 6>(6, 6);
  return free.ldlt().solve(load);
}

// Dynamic-size products: GCC 12 reports false -Warray-bounds on AVX loads of fixed 3-vector
// temporaries.
Vector dynamic(const Point3& p) { return Vector{{p.x(), p.y(), p.z()}}; }

// [a; b] of two 3-vectors.
Vector6 stacked(const Vector& a, const Vector& b) {
  Vector6 joined;
  for (int i = 0; i < 3; ++i) {
    joined[i] = a[i];
    joined[i + 3] = b[i];
  }
  return joined;
}

// A global load (force; moment) from local components.
Vector6 global_load(const Beam3d& beam, const Point3& force, const Point3& moment) {
  const Matrix to_global = beam.axes().transpose();
  return stacked(to_global * dynamic(force), to_global * dynamic(moment));
}

Vector cross(const Vector& a, const Vector& b) {
  return Vector{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

double relative_error(double value, double exact) {
  return std::abs(value - exact) / std::abs(exact);
}

TEST(Beam3d, ACantileverAlongASkewedAxisDeflectsAsBeamTheorySays) {
  const Point3 axis = Point3(1.0, 2.0, 2.0) / 3.0;
  const double l = 6.0;
  const Beam3d beam = make_beam(Point3::Zero(), l * axis, Point3(0.0, 0.0, 1.0));
  const Beam3d::Section s = steel_section();
  const double e = s.youngs_modulus;
  struct Case {
    const char* name;
    Point3 force, moment;
    int component;  // of the local tip displacement (0-2) or rotation (3-5) checked
    double exact;
    int second_component;
    double second_exact;
  };
  const double p = 1.0e4, m = 2.0e4;
  const Case cases[] = {
      {"axial N", {p, 0, 0}, {0, 0, 0}, 0, p * l / (e * s.area), 3, 0.0},
      {"shear along y'",
       {0, p, 0},
       {0, 0, 0},
       1,
       p * l * l * l / (3 * e * s.inertia_z),
       5,
       p * l * l / (2 * e * s.inertia_z)},
      {"shear along z'",
       {0, 0, p},
       {0, 0, 0},
       2,
       p * l * l * l / (3 * e * s.inertia_y),
       4,
       -p * l * l / (2 * e * s.inertia_y)},
      {"torque", {0, 0, 0}, {m, 0, 0}, 3, m * l / (s.shear_modulus * s.torsion), 0, 0.0},
      {"moment about y'",
       {0, 0, 0},
       {0, m, 0},
       4,
       m * l / (e * s.inertia_y),
       2,
       -m * l * l / (2 * e * s.inertia_y)},
      {"moment about z'",
       {0, 0, 0},
       {0, 0, m},
       5,
       m * l / (e * s.inertia_z),
       1,
       m * l * l / (2 * e * s.inertia_z)},
  };
  for (const Case& c : cases) {
    const Vector6 tip = cantilever_tip(beam, global_load(beam, c.force, c.moment));
    const Matrix to_local = beam.axes();
    const Vector6 local =
        stacked(to_local * Vector(tip.head<3>()), to_local * Vector(tip.tail<3>()));
    const double error = relative_error(local[c.component], c.exact);
    const double second = c.second_exact == 0.0
                              ? std::abs(local[c.second_component]) / std::abs(c.exact)
                              : relative_error(local[c.second_component], c.second_exact);
    // What else moved, against the largest tip motion.
    Vector6 rest = local;
    rest[c.component] = rest[c.second_component] = 0.0;
    const double coupling = rest.cwiseAbs().maxCoeff() / std::abs(c.exact);
    std::printf("%-16s tip %.6e, error %.1e; companion error %.1e; the rest %.1e\n", c.name,
                local[c.component], error, second, coupling);
    EXPECT_LT(error, 1e-12) << c.name;
    EXPECT_LT(second, 1e-12) << c.name;
    EXPECT_LT(coupling, 1e-12) << c.name;
  }
  // The end forces of the clamped end hold the tip load: N_i = -P for a pull.
  const Vector6 pull = cantilever_tip(beam, global_load(beam, {p, 0, 0}, {0, 0, 0}));
  Vector u = Vector::Zero(12);
  u.tail<6>() = pull;
  const Vector forces = beam.end_forces(u);
  EXPECT_NEAR(forces[0], -p, 1e-8 * p);
  EXPECT_NEAR(forces[6], p, 1e-8 * p);
}

TEST(Beam3d, RigidBodyMotionsStrainNothingWithOffsetsToo) {
  const Point3 start(1.0, -2.0, 0.5), end(4.0, 1.0, 3.0);
  const Beam3d beam =
      make_beam(start, end, Point3(0.3, 1.0, 0.2), Point3(0.0, 0.4, -0.1), Point3(-0.2, 0.0, 0.3));
  const Matrix k = beam.stiffness();
  double worst = 0.0;
  for (int mode = 0; mode < 6; ++mode) {
    Point3 translation = Point3::Zero(), rotation = Point3::Zero();
    (mode < 3 ? translation : rotation)[mode % 3] = 1.0;
    Vector u(12);
    for (int node = 0; node < 2; ++node) {
      const Point3& at = node == 0 ? start : end;
      u.segment<3>(6 * node) = translation + rotation.cross(at);
      u.segment<3>(6 * node + 3) = rotation;
    }
    worst = std::max(worst, (k * u).norm() / (k.norm() * u.norm()));
  }
  std::printf("largest |K u| / (|K| |u|) over the six rigid motions: %.1e\n", worst);
  EXPECT_LT(worst, 1e-14);
  EXPECT_LT((k - k.transpose()).norm(), 1e-15 * k.norm());
}

TEST(Beam3d, ARigidOffsetActsAsTheLongerBeamToItsEnd) {
  // Node j sits `offset` short of the flexible part's end: its motion is that end's, less the
  // end's rotation times the offset, under the load moved to the end with its moment.
  const Point3 start(0.0, 0.0, 0.0), node(5.0, 1.0, 0.0), offset(0.5, 0.3, 0.8);
  const Point3 orientation(0.0, 0.0, 1.0);
  const Beam3d with_offset = make_beam(start, node, orientation, Point3::Zero(), offset);
  const Beam3d to_the_end = make_beam(start, node + offset, orientation);
  const Point3 force(2.0e3, -5.0e3, 7.0e3), moment(1.0e3, 0.0, -3.0e3);
  // The same load carried to the end: its moment less offset x force.
  const Vector6 at_node = stacked(dynamic(force), dynamic(moment));
  const Vector6 at_end =
      stacked(dynamic(force), dynamic(moment) - cross(dynamic(offset), dynamic(force)));
  const Vector6 node_motion = cantilever_tip(with_offset, at_node);
  const Vector6 end_motion = cantilever_tip(to_the_end, at_end);
  const Vector end_rotation = end_motion.tail<3>();
  const Vector6 expected =
      stacked(Vector(end_motion.head<3>()) - cross(end_rotation, dynamic(offset)), end_rotation);
  const double error = (node_motion - expected).norm() / expected.norm();
  std::printf("node motion against the longer beam's end less theta x offset: %.1e\n", error);
  EXPECT_LT(error, 1e-12);
}

TEST(Beam3d, InItsPlaneItIsThePlaneFrameBeam) {
  const Point3 start(1.0, 2.0, 0.0), end(5.0, -1.0, 0.0);
  const Beam3d beam =
      make_beam(start, end, Point3(0.0, 0.0, 1.0), Point3::Zero(), Point3::Zero(), true);
  const Beam3d::Section s = steel_section();
  const Beam plane("beam", {{{0, {start.x(), start.y()}}, {1, {end.x(), end.y()}}}},
                   {s.youngs_modulus, s.area, s.inertia_z, s.density, s.extra_mass}, true,
                   std::nullopt);
  const int in_plane[6] = {0, 1, 5, 6, 7, 11};  // u_x, u_y, theta_z at each node
  const Matrix k3 = beam.stiffness(), m3 = beam.mass().consistent;
  const Matrix k2 = plane.stiffness(), m2 = plane.mass().consistent;
  double k_error = 0.0, m_error = 0.0;
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < 6; ++b) {
      k_error = std::max(k_error, std::abs(k3(in_plane[a], in_plane[b]) - k2(a, b)) / k2.norm());
      m_error = std::max(m_error, std::abs(m3(in_plane[a], in_plane[b]) - m2(a, b)) / m2.norm());
    }
  std::printf("in-plane stiffness %.1e, consistent mass %.1e from the plane frame beam's\n",
              k_error, m_error);
  EXPECT_LT(k_error, 1e-15);
  EXPECT_LT(m_error, 1e-15);
}

TEST(Beam3d, ItsMassesMoveAsTheBeamDoes) {
  const Point3 start(0.0, 1.0, 2.0), end(3.0, 5.0, 2.0);
  const Beam3d::Section s = steel_section();
  const double length = (end - start).norm();
  const double total = (s.density * s.area + s.extra_mass) * length;
  const Beam3d consistent =
      make_beam(start, end, Point3(0.0, 0.0, 1.0), Point3::Zero(), Point3::Zero(), true);
  const Beam3d lumped = make_beam(start, end, Point3(0.0, 0.0, 1.0));
  const Matrix m = consistent.mass().consistent;
  for (int direction = 0; direction < 3; ++direction) {
    Vector u = Vector::Zero(12);
    u[direction] = u[6 + direction] = 1.0;
    EXPECT_LT(relative_error(u.dot(m * u), total), 1e-14) << direction;
    EXPECT_LT(relative_error(u.dot(lumped.mass().lumped.asDiagonal() * u), total), 1e-14);
  }
  // Twisting about its own axis: the polar moment rho (I_y + I_z) L.
  Vector twist = Vector::Zero(12);
  twist.segment<3>(3) = twist.segment<3>(9) = consistent.axes().row(0).transpose();
  const double polar = s.density * (s.inertia_y + s.inertia_z) * length;
  std::printf("twisting inertia %.1e from rho I_p L\n",
              relative_error(twist.dot(m * twist), polar));
  EXPECT_LT(relative_error(twist.dot(m * twist), polar), 1e-14);
  EXPECT_LT((m - m.transpose()).norm(), 1e-15 * m.norm());
}

TEST(Beam3d, ItsConsistentGeometricStiffnessBucklesACantileverAtEulersLoads) {
  // A column of 10 elements along z, fixed at the base: P_cr = pi^2 E I / (4 L^2) about each
  // axis, the lower about the weaker one.
  constexpr int kElements = 10;
  const double height = 8.0, piece = height / kElements;
  const Beam3d::Section s = steel_section();
  const int size = 6 * kElements;  // the free DOFs, nodes 1..n
  Matrix k = Matrix::Zero(size, size), geometric = Matrix::Zero(size, size);
  Vector compressed = Vector::Zero(12);
  compressed[8] = -1.0e-6;  // shortening: a unit compressive force follows from the stiffness
  for (int e = 0; e < kElements; ++e) {
    const Beam3d element =
        make_beam(Point3(0, 0, e * piece), Point3(0, 0, (e + 1) * piece), Point3(1.0, 0.0, 0.0));
    const double axial = element.end_forces(compressed)[6];
    const Matrix ke = element.stiffness();
    // The softening per unit of compression: K_G is linear in N, and N < 0 here.
    const Matrix kg =
        element.geometric_stiffness(compressed, model::GeometricStiffness::consistent) / axial;
    for (int a = 0; a < 12; ++a)
      for (int b = 0; b < 12; ++b) {
        const int row = 6 * (e - 1) + a, column = 6 * (e - 1) + b;
        if (row < 0 || column < 0) continue;  // the base's DOFs
        k(row, column) += ke(a, b);
        geometric(row, column) += kg(a, b);
      }
  }
  // (K - P S) phi = 0 with S the softening: P = 1 / eigenvalue of K^-1 S.
  const Matrix flexibility_times_geometric = k.ldlt().solve(geometric);
  Eigen::EigenSolver<Matrix> solver(flexibility_times_geometric);
  std::vector<double> loads;
  for (int i = 0; i < size; ++i) {
    const auto value = solver.eigenvalues()[i];
    if (value.real() > 1e-12 && std::abs(value.imag()) < 1e-9 * value.real())
      loads.push_back(1.0 / value.real());
  }
  std::sort(loads.begin(), loads.end());
  ASSERT_GE(loads.size(), 2u);
  // With x' along global z and v along x, y' = v x x' = -y and z' = x' x y' = x; I_z is the
  // weaker (1.2e-4 < 3e-4), so the first load is about z'.
  const double euler_weak =
      std::numbers::pi * std::numbers::pi * s.youngs_modulus * s.inertia_z / (4 * height * height);
  const double euler_strong = euler_weak * s.inertia_y / s.inertia_z;
  std::printf("buckling loads %.6e and %.6e N; Euler %.6e and %.6e N; errors %.1e, %.1e\n",
              loads[0], loads[1], euler_weak, euler_strong, relative_error(loads[0], euler_weak),
              relative_error(loads[1], euler_strong));
  EXPECT_LT(relative_error(loads[0], euler_weak), 1e-5);
  EXPECT_LT(relative_error(loads[1], euler_strong), 1e-5);
}

TEST(Beam3d, ItsChordGeometricStiffnessIsTheAxialForceOverTheLengthOnTheDrift) {
  // P-Delta: a tension N with the ends apart by d across the beam gives the transverse end
  // forces N d / L, in both transverse directions, whatever the axis's skew.
  const Point3 start(1.0, 0.0, 2.0), end(4.0, 4.0, 2.0);
  const Beam3d beam = make_beam(start, end, Point3(0.0, 0.0, 1.0));
  Vector stretched = Vector::Zero(12);
  stretched.segment<3>(6) = 1e-5 * (end - start).normalized();
  const double tension = beam.end_forces(stretched)[6];
  const Matrix kg = beam.geometric_stiffness(stretched, model::GeometricStiffness::chord);
  for (int across = 1; across <= 2; ++across) {
    Vector drift = Vector::Zero(12);
    const Point3 direction = beam.axes().row(across).transpose();
    drift.segment<3>(6) = 0.01 * direction;
    const Vector forces = kg * drift;
    const double expected = tension * 0.01 / beam.length();
    const double at_j = forces.segment<3>(6).dot(direction);
    std::printf("transverse %d: force at j %.6e, N d / L %.6e\n", across, at_j, expected);
    EXPECT_LT(relative_error(at_j, expected), 1e-13);
    EXPECT_LT(relative_error(-forces.segment<3>(0).dot(direction), expected), 1e-13);
  }
  EXPECT_GT(tension, 0.0);
}

TEST(Beam3d, AnOrientationThatFixesNoPlaneIsRefused) {
  const Point3 start(0.0, 0.0, 0.0), end(1.0, 1.0, 0.0);
  for (const Point3& orientation : {Point3(2.0, 2.0, 0.0), Point3(0.0, 0.0, 0.0)}) {
    try {
      make_beam(start, end, orientation);
      ADD_FAILURE() << "accepted";
    } catch (const std::invalid_argument& error) {
      std::printf("%s\n", error.what());
      EXPECT_NE(std::string(error.what()).find("orientation vector"), std::string::npos);
    }
  }
  EXPECT_THROW(make_beam(start, start, Point3(0, 0, 1)), std::invalid_argument);
  // Offsets that bring the ends together leave no flexible part.
  EXPECT_THROW(make_beam(start, end, Point3(0, 0, 1), Point3::Zero(), Point3(-1.0, -1.0, 0.0)),
               std::invalid_argument);
}

}  // namespace
}  // namespace pound::assembly
