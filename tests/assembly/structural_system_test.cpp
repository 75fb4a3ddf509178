#include "assembly/structural_system.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "assembly/band_ordering.hpp"
#include "assembly/banded_ldlt.hpp"
#include "assembly/beam.hpp"
#include "assembly/not_positive_definite.hpp"
#include "assembly/truss.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "core/packets.hpp"
#include "io/model_reader.hpp"
#include "links/gap_spring.hpp"
#include "support/elements.hpp"

namespace pound::assembly {
namespace {

// A truss between nodes i and j of `m` (already placed).
std::shared_ptr<const model::Element> truss(const model::Model& m, Index i, Index j,
                                            double youngs_modulus, double area, double density) {
  const auto end = [&m](Index node) {
    return model::ElementNode{node, m.nodes[static_cast<std::size_t>(node)].position};
  };
  return std::make_shared<const Truss>(
      fmt::format("e{}_{}", i, j), std::array{end(i), end(j)}, m.dimension,
      Truss::Section{.youngs_modulus = youngs_modulus, .area = area, .density = density},
      std::nullopt);
}

model::Link link(Index i, Index j, model::Coordinates axis, double gap = 0.0) {
  return {.id = fmt::format("l{}_{}", i, j),
          .node_i = i,
          .node_j = j,
          .axis = axis,
          .gap = gap,
          .make_law = [](const links::LinkContext&) {
            return std::make_unique<links::GapSpring>(1.0);
          }};
}

// x = 0, 1, 3, 4.5; node 0 fixed, a lumped mass on node 3. Element stiffnesses E A / L:
// 100 * 2 / 1 = 200, 200 * 1 / 2 = 100, 50 * 3 / 1.5 = 100; half masses rho A L / 2: 1, 0.5, 4.5.
model::Model chain() {
  model::Model m;
  m.dimension = 1;
  for (double x : {0.0, 1.0, 3.0, 4.5})
    m.nodes.push_back({fmt::format("n{}", m.nodes.size()), {x, 0.0}});
  m.elements = {truss(m, 0, 1, 100.0, 2.0, 1.0), truss(m, 1, 2, 200.0, 1.0, 0.5),
                truss(m, 2, 3, 50.0, 3.0, 2.0)};
  m.supports = {{.node = 0, .fixed = {true, false}}};
  m.masses = {{.node = 3, .mass = 7.0}};
  return m;
}

// One truss of length 2 at 30 degrees, E A / L = 10 * 3 / 2 = 15, rho A L / 2 = 0.5 * 3 * 2 / 2.
constexpr double kAxial = 15.0, kHalfMass = 1.5;
const double kCos = std::cos(std::numbers::pi / 6), kSin = std::sin(std::numbers::pi / 6);

model::Model inclined_truss() {
  model::Model m;
  m.dimension = 2;
  m.nodes = {{"a", {0.0, 0.0}}, {"b", {2.0 * kCos, 2.0 * kSin}}};
  m.elements = {truss(m, 0, 1, 10.0, 3.0, 0.5)};
  return m;
}

double relative_difference(const Matrix& actual, const Matrix& expected) {
  return (actual - expected).norm() / expected.norm();
}

Vector random_vector(Index n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Vector v(n);
  for (Index i = 0; i < n; ++i) v[i] = value(rng);
  return v;
}

// Solves (c_m M + c_k K) x = b with system.factor and compares with a dense Cholesky solve.
double factor_error(const StructuralSystem& system, double c_m, double c_k) {
  const Matrix effective =
      c_m * Matrix(system.lumped_mass()->asDiagonal()) + c_k * Matrix(system.stiffness());
  const Vector rhs = random_vector(system.size(), 42);
  Vector x;
  system.factor(c_m, 0.0, c_k)->solve(rhs, x);
  const Vector expected = effective.llt().solve(rhs);
  return (x - expected).norm() / expected.norm();
}

TEST(StructuralSystem, ChainStiffnessAndMassAreTheHandAssembledOnes) {
  const StructuralSystem system(chain());
  ASSERT_EQ(system.size(), 3);
  Matrix stiffness(3, 3);
  stiffness << 300, -100, 0,  //
      -100, 200, -100,        //
      0, -100, 100;
  const Vector mass = Vector{{1.5, 5.0, 11.5}};
  const double k_error = relative_difference(Matrix(system.stiffness()), stiffness);
  const double m_error = relative_difference(*system.lumped_mass(), mass);
  std::cout << "K relative error " << k_error << ", M relative error " << m_error << "\n";
  EXPECT_LE(k_error, 1e-14);
  EXPECT_LE(m_error, 1e-14);

  // The operators agree with the matrices.
  const Vector x = random_vector(3, 1);
  Vector y;
  system.multiply_stiffness(x, y);
  EXPECT_LE((y - stiffness * x).norm(), 1e-12 * (stiffness * x).norm());
  system.multiply_mass(x, y);
  EXPECT_LE((y - mass.cwiseProduct(x)).norm(), 1e-14 * mass.cwiseProduct(x).norm());
}

TEST(StructuralSystem, InclinedTrussHasTheRotatedStiffness) {
  const StructuralSystem system(inclined_truss());
  ASSERT_EQ(system.size(), 4);
  Matrix rotation(2, 2);
  rotation << kCos * kCos, kCos * kSin,  //
      kCos * kSin, kSin * kSin;
  Matrix stiffness(4, 4);
  stiffness << rotation, -rotation, -rotation, rotation;
  stiffness *= kAxial;
  const double k_error = relative_difference(Matrix(system.stiffness()), stiffness);
  const double m_error = relative_difference(*system.lumped_mass(), Vector::Constant(4, kHalfMass));
  std::cout << "K relative error " << k_error << ", M relative error " << m_error << "\n";
  EXPECT_LE(k_error, 1e-14);
  EXPECT_LE(m_error, 1e-14);
}

TEST(StructuralSystem, SupportsRemoveEquations) {
  model::Model m = inclined_truss();
  m.supports = {{.node = 0, .fixed = {true, true}}, {.node = 1, .fixed = {false, true}}};
  const StructuralSystem system(m);
  ASSERT_EQ(system.size(), 1);
  EXPECT_EQ(system.dofs().own_equation(0, 0), -1);
  EXPECT_EQ(system.dofs().own_equation(0, 1), -1);
  EXPECT_EQ(system.dofs().own_equation(1, 0), 0);
  EXPECT_EQ(system.dofs().own_equation(1, 1), -1);
  EXPECT_NEAR(Matrix(system.stiffness())(0, 0), kAxial * kCos * kCos, 1e-14 * kAxial);
  EXPECT_DOUBLE_EQ((*system.lumped_mass())[0], kHalfMass);
}

TEST(StructuralSystem, LumpedMassActsInEveryDirection) {
  model::Model m = inclined_truss();
  m.masses = {{.node = 1, .mass = 2.0}};
  const StructuralSystem system(m);
  EXPECT_DOUBLE_EQ((*system.lumped_mass())[2], kHalfMass + 2.0);
  EXPECT_DOUBLE_EQ((*system.lumped_mass())[3], kHalfMass + 2.0);
}

TEST(StructuralSystem, FreeNodeWithoutMassIsAnInputError) {
  model::Model m = chain();
  m.nodes.push_back({"loose", {9.0, 0.0}});
  try {
    const StructuralSystem system(m);
    FAIL() << "no exception";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_EQ(error.where(), "/nodes/4");
    EXPECT_NE(error.reason().find("'loose'"), std::string::npos) << error.what();
  }
}

// A massless end of an element has a static equation (its stiffness), which is fine...
TEST(StructuralSystem, MasslessElementEndIsAStaticDof) {
  model::Model m = chain();
  m.elements[2] = truss(m, 2, 3, 50.0, 3.0, 0.0);
  m.masses.clear();
  EXPECT_NO_THROW(StructuralSystem{m});
}

// ...but a free node with neither mass nor stiffness makes the equations singular.
TEST(StructuralSystem, NodeWithNeitherMassNorStiffnessIsRefused) {
  model::Model m = chain();
  m.nodes.push_back({"loose", {9.0, 0.0}});
  try {
    StructuralSystem system(m);
    FAIL() << "accepted a node without mass or stiffness";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "/nodes/4");
    EXPECT_NE(error.reason().find("'loose' has neither mass nor stiffness"), std::string::npos)
        << error.what();
  }
}

TEST(StructuralSystem, LinkRowsCarryTheAxisWithOppositeSigns) {
  model::Model m;
  m.dimension = 2;
  m.nodes = {{"p", {0.0, 0.0}}, {"q", {3.0, 4.0}}, {"wall", {5.0, 4.0}}};
  m.masses = {{.node = 0, .mass = 1.0}, {.node = 1, .mass = 1.0}};
  m.supports = {{.node = 2, .fixed = {true, true}}};
  m.links = {link(0, 1, {0.6, 0.8}, 0.01), link(1, 2, {1.0, 0.0}), link(2, 0, {0.0, 1.0})};
  StructuralSystem system(m);
  ASSERT_EQ(system.size(), 4);
  const integrators::LinkSet& links = system.links();
  ASSERT_EQ(links.size(), 3);
  Matrix expected(3, 4);
  expected << 0.6, 0.8, -0.6, -0.8,  // +n at i, -n at j
      0.0, 0.0, 1.0, 0.0,            // the wall's term is dropped
      0.0, -1.0, 0.0, 0.0;           // i is the wall: only -n at j
  EXPECT_EQ(Matrix(links.connectivity()), expected);
  EXPECT_EQ(links.gaps(), (Vector{{0.01, 0.0, 0.0}}));
}

TEST(StructuralSystem, FactorSolvesTheEffectiveMatrix) {
  // A chain (tridiagonal), a plane truss (band 3) and a chain closed by an element from its first
  // to its last node (band 38, renumbered to a band of 2): each kind of factor StructuralSystem
  // chooses.
  model::Model ring;
  ring.dimension = 1;
  for (int i = 0; i < 40; ++i) ring.nodes.push_back({fmt::format("r{}", i), {1.0 * i, 0.0}});
  for (Index i = 0; i + 1 < 40; ++i)
    ring.elements.push_back(truss(ring, i, i + 1, 100.0, 1.0, 0.1));
  ring.elements.push_back(truss(ring, 0, 39, 100.0, 1.0, 0.1));
  ring.supports = {{.node = 20, .fixed = {true, false}}};

  model::Model plane = inclined_truss();
  plane.nodes.push_back({"c", {4.0, 0.0}});
  plane.elements.push_back(truss(plane, 1, 2, 10.0, 3.0, 0.5));
  plane.supports = {{.node = 0, .fixed = {true, true}}};

  const model::Model models[] = {chain(), plane, ring};
  const char* names[] = {"chain", "plane truss", "closed chain"};
  // Twisted tridiagonal, banded LDL^T, banded LDL^T in reverse Cuthill-McKee order.
  const Index bands[] = {1, 3, 38};
  for (int k = 0; k < 3; ++k) {
    const StructuralSystem system(models[k]);
    EXPECT_EQ(BandedLdlt::bandwidth_of(system.stiffness()), bands[k]) << names[k];
    for (const auto& [c_m, c_k] : {std::pair{4.0e4, 1.0}, std::pair{1.0, 0.5}}) {
      const double error = factor_error(system, c_m, c_k);
      std::cout << names[k] << " (" << system.size() << " DOFs, band "
                << BandedLdlt::bandwidth_of(system.stiffness()) << "), c_m " << c_m << ", c_k "
                << c_k << ": relative error " << error << "\n";
      EXPECT_LE(error, 1e-12) << names[k];
    }
  }
}

// A braced portal with an outrigger, nothing supported: columns 0-1 and 2-3 (lumped mass), a
// girder 1-2 (consistent mass, extra mass per length), a brace 0-2 and an outrigger 2-4
// (trusses; node 4 does not turn), point masses on nodes 1 and 4. The damping is every part's
// own, the same a0 and a1 everywhere.
constexpr double kA0 = 0.3, kA1 = 0.002;
model::Model free_portal() {
  model::Model m;
  m.dimension = 2;
  m.nodes = {{"0", {0.0, 0.0}},
             {"1", {0.0, 3.0}},
             {"2", {4.0, 3.0}},
             {"3", {4.0, 0.0}},
             {"4", {6.0, 3.0}}};
  const model::RayleighDamping damping{kA0, kA1};
  const auto end = [&m](Index node) {
    return model::ElementNode{node, m.nodes[static_cast<std::size_t>(node)].position};
  };
  const auto member = [&](Index i, Index j, double extra_mass, bool consistent) {
    return std::make_shared<const Beam>(fmt::format("b{}_{}", i, j), std::array{end(i), end(j)},
                                        Beam::Section{.youngs_modulus = 3.0e4,
                                                      .area = 0.2,
                                                      .inertia = 0.004,
                                                      .density = 2.5,
                                                      .extra_mass = extra_mass},
                                        consistent, damping);
  };
  const auto bar = [&](Index i, Index j) {
    return std::make_shared<const Truss>(
        fmt::format("t{}_{}", i, j), std::array{end(i), end(j)}, 2,
        Truss::Section{.youngs_modulus = 2.0e5, .area = 0.01, .density = 7.8}, damping);
  };
  m.elements = {member(0, 1, 0.0, false), member(1, 2, 1.5, true), member(2, 3, 0.0, false),
                bar(0, 2), bar(2, 4)};
  m.masses = {{.node = 1, .mass = 5.0, .rotary_inertia = {0.0, 0.0, 1.0}, .damping = damping},
              {.node = 4, .mass = 2.0, .damping = damping}};
  return m;
}

// The rigid motions of the portal's free DOFs: translations along x and y, and a rotation about
// the origin (u = -theta y, v = theta x, theta where the node turns).
std::vector<Vector> rigid_motions(const model::Model& m, const model::DofMap& dofs) {
  std::vector<Vector> motions(3, Vector::Zero(dofs.size()));
  for (Index node = 0; node < static_cast<Index>(m.nodes.size()); ++node) {
    const model::Coordinates& p = m.nodes[static_cast<std::size_t>(node)].position;
    const double rotation[3] = {-p[1], p[0], 1.0};
    for (int d = 0; d < 3; ++d)
      if (const Index row = dofs.own_equation(node, d); row >= 0) {
        if (d < 2) motions[static_cast<std::size_t>(d)][row] = 1.0;
        motions[2][row] = rotation[d];
      }
  }
  return motions;
}

// Link rows folded into the factored matrix (integrators/newmark.hpp): factor_with_links solves
// c_m M + c_k K + B^T D B, here with links between nodes of a chain apart, one joining its ends
// (band 38), which the reverse Cuthill-McKee order brings back to a band of 2.
// Every node of 36 joined to every other (a band of 35 in any order: the general sparse LDL^T),
// nodes 0 and 1 also by a strut `ratio` times stiffer than the rest: at 1e20 one of their pivots
// is round-off and the factorisation refuses it, naming that equation; at 1e10 it solves.
TEST(StructuralSystem, SparseFactorRefusesAPivotCancelledToRoundOff) {
  for (const double ratio : {1e20, 1e10}) {
    model::Model m;
    m.dimension = 1;
    for (int i = 0; i < 36; ++i) m.nodes.push_back({fmt::format("n{}", i), {1.25 * i, 0.0}});
    for (Index i = 0; i < 36; ++i)
      for (Index j = i + 1; j < 36; ++j)
        m.elements.push_back(truss(m, i, j, 100.0 * (i == 0 && j == 1 ? ratio : 1.0), 1.0, 0.1));
    m.supports = {{.node = 20, .fixed = {true, false}}};
    const StructuralSystem system(m);
    if (ratio > 1e15) {
      try {
        system.factor(1.0, 0.0, 1.0);
        ADD_FAILURE() << "no exception";
      } catch (const NotPositiveDefinite& error) {
        std::cout << error.what() << "\n";
        EXPECT_TRUE(error.cancelled()) << error.what();
        EXPECT_TRUE(error.equation() == 0 || error.equation() == 1) << error.what();
      }
      continue;
    }
    const Eigen::SparseMatrix<double> matrix = system.stiffness() + system.mass_matrix();
    const Vector rhs = Vector::LinSpaced(matrix.rows(), 1.0, 2.0);
    Vector x;
    system.factor(1.0, 0.0, 1.0)->solve(rhs, x);
    // Cholesky, not Eigen's dense LDL^T: its unit-lower solve, instantiated here at the tests'
    // -Og, would replace the -O3 one PivotedLu's Eigen path is compared with to the bit.
    const Vector reference = Matrix(matrix).llt().solve(rhs);
    const double error = (x - reference).norm() / reference.norm();
    std::cout << "strut 1e10 x: relative difference from dense Cholesky " << error << "\n";
    EXPECT_LT(error, 1e10 * 1e-15);
  }
}

TEST(StructuralSystem, FactorWithLinksSolvesTheMatrixWithTheLinksFolded) {
  model::Model m;
  m.dimension = 1;
  for (int i = 0; i < 40; ++i) m.nodes.push_back({fmt::format("r{}", i), {1.0 * i, 0.0}});
  for (Index i = 0; i + 1 < 40; ++i) m.elements.push_back(truss(m, i, i + 1, 100.0, 1.0, 0.1));
  m.supports = {{.node = 20, .fixed = {true, false}}};
  m.links = {link(0, 2, {1.0, 0.0}), link(5, 8, {1.0, 0.0}), link(0, 39, {1.0, 0.0}),
             link(10, 11, {1.0, 0.0})};
  const StructuralSystem system(m);
  const Matrix connectivity(system.links().connectivity());
  const Vector folded{{3.0e3, 0.0, 5.0e2, 7.0}};  // a row not folded: 0
  const double c_m = 4.0e4, c_k = 1.0;
  const Matrix effective = c_m * Matrix(system.lumped_mass()->asDiagonal()) +
                           c_k * Matrix(system.stiffness()) +
                           connectivity.transpose() * folded.asDiagonal() * connectivity;
  const Eigen::SparseMatrix<double> sparse = effective.sparseView();
  const std::vector<Index> order = reverse_cuthill_mckee(sparse);
  const Index renumbered = BandedLdlt::bandwidth_of(permuted(sparse, order));
  const Vector rhs = random_vector(system.size(), 7);
  Vector x;
  system.factor_with_links(c_m, 0.0, c_k, folded)->solve(rhs, x);
  const Vector expected = effective.llt().solve(rhs);
  const double error = (x - expected).norm() / expected.norm();
  std::cout << "band " << BandedLdlt::bandwidth_of(sparse) << ", renumbered " << renumbered
            << ": relative error " << error << "\n";
  EXPECT_EQ(BandedLdlt::bandwidth_of(sparse), 38);
  EXPECT_LE(renumbered, 3);
  EXPECT_LE(error, 1e-12);
}

// n nodes on a line, every node joined to the next `band` ones by trusses of different
// stiffnesses: a full band of half-width `band`, which K x takes by diagonals.
model::Model banded_chain(Index n, Index band) {
  model::Model m;
  m.dimension = 1;
  for (Index i = 0; i < n; ++i)
    m.nodes.push_back({fmt::format("n{}", i), {static_cast<double>(i) * 1.25, 0.0}});
  for (Index i = 0; i < n; ++i)
    for (Index j = i + 1; j <= std::min(n - 1, i + band); ++j)
      m.elements.push_back(truss(m, i, j, 100.0 + 7.0 * static_cast<double>(i + 3 * j), 1.0, 1.0));
  m.supports = {{.node = 0, .fixed = {true, false}}};
  return m;
}

// Two chains that nothing joins (two buildings whose only link is a contact, not folded): the
// factored matrix solves to round-off whether their equations come one chain after the other
// (each factored part of the band, both solved side by side in place), scrambled (a wide band:
// renumbered, the chains then one after the other, solved side by side through the order) or
// interleaved (one band of both).
TEST(StructuralSystem, FactorSolvesTwoStructuresApartSideBySide) {
  enum class Numbering { one_after_the_other, scrambled, interleaved };
  for (const Numbering numbering :
       {Numbering::one_after_the_other, Numbering::scrambled, Numbering::interleaved}) {
    // Chain 0 of 40 nodes and chain 1 of 27, each node joined to its next three; node k of chain
    // c at place(c, k).
    const auto place = [numbering](int chain, Index k) -> Index {
      switch (numbering) {
        case Numbering::one_after_the_other:
          return chain == 0 ? k : 40 + k;
        case Numbering::scrambled:
          return chain == 0 ? k : 40 + (7 * k) % 27;
        case Numbering::interleaved:
          break;
      }
      return k < 27 ? 2 * k + chain : 27 + k;
    };
    model::Model m;
    m.dimension = 1;
    m.nodes.resize(67);
    for (int chain = 0; chain < 2; ++chain)
      for (Index k = 0; k < (chain == 0 ? 40 : 27); ++k)
        m.nodes[static_cast<std::size_t>(place(chain, k))] = {fmt::format("c{}n{}", chain, k),
                                                              {static_cast<double>(k) * 1.25, 0.0}};
    for (int chain = 0; chain < 2; ++chain) {
      const Index length = chain == 0 ? 40 : 27;
      for (Index k = 0; k < length; ++k)
        for (Index l = k + 1; l <= std::min(length - 1, k + 3); ++l)
          m.elements.push_back(truss(m, place(chain, k), place(chain, l),
                                     100.0 + 7.0 * static_cast<double>(k + 3 * l + chain), 1.0,
                                     1.0));
      m.supports.push_back({.node = place(chain, 0), .fixed = {true, false}});
    }
    const StructuralSystem system(m);
    const auto solver = system.factor(4.0, 0.5, 1.0);
    const Vector rhs = random_vector(system.size(), 7);
    Vector x;
    solver->solve(rhs, x);
    const Matrix effective = Matrix(system.stiffness()) + 4.0 * Matrix(system.mass_matrix());
    const Vector reference = effective.llt().solve(rhs);
    const double error = (x - reference).norm() / reference.norm();
    std::cout << "numbering " << static_cast<int>(numbering) << ": relative error " << error
              << "\n";
    EXPECT_LE(error, 1e-14);
  }
}

// K x with each row's terms summed from +0 in column order, one rounding per multiply-add where
// the machine fuses them: the order every product of K keeps (core/packets.hpp).
Vector row_sums(const Eigen::SparseMatrix<double>& k, const Vector& x) {
  const Eigen::SparseMatrix<double, Eigen::RowMajor> rows = k;
  Vector y(k.rows());
  for (Index i = 0; i < k.rows(); ++i) {
    double sum = 0.0;
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator term(rows, i); term; ++term)
      sum = multiply_add(term.value(), x[term.col()], sum);
    y[i] = sum;
  }
  return y;
}

// The band product (blocks of four rows, its ends through zero padding) sums every row as
// row_sums does, to the bit, for every bandwidth, length and block of an explicit step. (The
// tridiagonal product has its own three-term form: within a rounding.)
// With P-Delta, Rayleigh damping's a1 K is the first-order K (the geometric stiffness under the
// column's weight does not damp): C x = a0 M x + a1 K_elastic x, to round-off of the dense
// product, and not a1 times the K of the products (which the weight softens).
TEST(StructuralSystem, DampingUnderPDeltaIsProportionalToTheFirstOrderStiffness) {
  const StructuralSystem system(builder::build(io::parse_model(R"({
    "dimension": 2,
    "nodes": [{"id": "base", "x": 0, "y": 0}, {"id": "n1", "x": 0, "y": 3}, {"id": "n2", "x": 0, "y": 6},
              {"id": "top", "x": 0, "y": 9}],
    "materials": [{"id": "c", "youngs_modulus": 3e10, "density": 2500}],
    "elements": [{"id": "e1", "type": "beam", "nodes": ["base", "n1"], "material": "c", "area": 0.5, "inertia": 0.02},
                 {"id": "e2", "type": "beam", "nodes": ["n1", "n2"], "material": "c", "area": 0.5, "inertia": 0.02},
                 {"id": "e3", "type": "beam", "nodes": ["n2", "top"], "material": "c", "area": 0.5, "inertia": 0.02}],
    "masses": [{"node": "top", "mass": 4e5}],
    "supports": [{"node": "base", "fix": ["x", "y", "rz"]}],
    "gravity": {"acceleration": 9.81, "p_delta": "chord"},
    "damping": {"mass_coefficient": 0.4, "stiffness_coefficient": 0.003},
    "analysis": {"time_step": 0.01, "duration": 1}
  })",
                                                               "column.json"))
                                    .model);
  ASSERT_EQ(system.rayleigh(), nullptr);  // a1 K is not the products' K
  const Matrix elastic(system.elastic_stiffness()), second_order(system.stiffness());
  ASSERT_GT((second_order - elastic).norm(), 1e-6 * elastic.norm());  // the weight's K_G
  Matrix mass(system.size(), system.size());
  for (Index i = 0; i < system.size(); ++i) {
    Vector column;
    system.multiply_mass(Vector::Unit(system.size(), i), column);
    mass.col(i) = column;
  }
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> value(-1.0, 1.0);
  Vector x(system.size()), y;
  for (Index i = 0; i < x.size(); ++i) x[i] = value(rng);
  system.multiply_damping(x, y);
  const Vector expected = 0.4 * mass * x + 0.003 * elastic * x;
  const double error = (y - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
  const double softened =
      (0.4 * mass * x + 0.003 * second_order * x - expected).cwiseAbs().maxCoeff() /
      expected.cwiseAbs().maxCoeff();
  std::cout << "C x under P-Delta against a0 M x + a1 K_elastic x: " << error
            << " (a1 times the second-order K would be off by " << softened << ")\n";
  EXPECT_LE(error, 1e-15);
  EXPECT_GT(softened, 1e3 * error);
}

TEST(StructuralSystem, BandProductSumsEachRowInColumnOrder) {
  int cases = 0;
  double tridiagonal_error = 0.0;
  for (Index band = 1; band <= 9; ++band) {
    for (const Index n : {band + 2, band + 5, 2 * band + 7, 61 + band}) {
      const StructuralSystem system(banded_chain(n, band));
      ASSERT_EQ(BandedLdlt::bandwidth_of(system.stiffness()), band);
      for (const unsigned seed : {1u, 2u}) {
        Vector x = random_vector(system.size(), seed), y;
        if (seed == 2) x.head(std::min<Index>(3, x.size())).setZero();  // sums of zeros: +0
        system.multiply_stiffness(x, y);
        const Vector expected = row_sums(system.stiffness(), x);
        if (band == 1) {
          tridiagonal_error =
              std::max(tridiagonal_error, (y - expected).cwiseAbs().maxCoeff() / expected.norm());
          continue;
        }
        for (Index i = 0; i < system.size(); ++i) {
          EXPECT_EQ(y[i], expected[i]) << "b = " << band << ", n = " << n << ", row " << i;
          EXPECT_EQ(std::signbit(y[i]), std::signbit(expected[i])) << "row " << i;
        }
        ++cases;
      }
    }
  }
  // A diagonal K (each mass on its own spring to the ground: oscillators that only links join).
  for (const Index n : {1, 2, 7}) {
    model::Model m;
    m.dimension = 1;
    for (Index i = 0; i < n; ++i) {
      m.nodes.push_back({fmt::format("ground{}", i), {2.0 * static_cast<double>(i), 0.0}});
      m.nodes.push_back({fmt::format("mass{}", i), {2.0 * static_cast<double>(i) + 1.0, 0.0}});
      m.elements.push_back(
          truss(m, 2 * i, 2 * i + 1, 100.0 + 7.0 * static_cast<double>(i), 1.0, 1.0));
      m.supports.push_back({.node = 2 * i, .fixed = {true, true}});
    }
    const StructuralSystem system(m);
    ASSERT_EQ(system.size(), n);
    ASSERT_EQ(BandedLdlt::bandwidth_of(system.stiffness()), 0);
    Vector x = random_vector(n, 4), y;
    x[0] = 0.0;
    system.multiply_stiffness(x, y);
    const Vector expected = row_sums(system.stiffness(), x);
    for (Index i = 0; i < n; ++i) {
      EXPECT_EQ(y[i], expected[i]) << "diagonal, n = " << n << ", row " << i;
      EXPECT_EQ(std::signbit(y[i]), std::signbit(expected[i])) << "row " << i;
    }
    ++cases;
  }
  // An explicit step's blocks of 256 rows, each made just before it is needed.
  for (const Index band : {2, 5, 8}) {
    const StructuralSystem system(banded_chain(700, band));  // three blocks
    const Vector x_whole = random_vector(system.size(), 3);
    Vector x = Vector::Constant(system.size(), std::numeric_limits<double>::quiet_NaN()), y;
    Index made = 0;
    std::vector<std::pair<Index, Index>> used;
    system.multiply_stiffness_by_blocks(
        x, y,
        [&](Index first, Index last) {
          EXPECT_EQ(first, made);
          x.segment(first, last - first) = x_whole.segment(first, last - first);
          made = last;
        },
        [&](Index first, Index last) { used.emplace_back(first, last); });
    const Vector expected = row_sums(system.stiffness(), x_whole);
    EXPECT_EQ(made, system.size());
    EXPECT_EQ(used.size(), 3u);
    for (Index i = 0; i < system.size(); ++i) ASSERT_EQ(y[i], expected[i]) << "row " << i;
    ++cases;
  }
  std::cout << cases << " band products (b = 0, 2 ... 9) equal to the row sums in every bit; "
            << "tridiagonal within " << tridiagonal_error << "\n";
  EXPECT_LE(tridiagonal_error, 4e-16);
}

// f(t) = -M iota a_g(t) at any time, asked for in any order (the last one is kept for the
// step's second request).
TEST(StructuralSystem, ExternalForceIsTheRecordsAtEveryTimeAskedFor) {
  model::Model m = chain();
  m.excitations.push_back(
      {.motion = {.name = "ramp", .time_step = 0.5, .acceleration = {0, 2, -4}}});
  const StructuralSystem system(m);
  ASSERT_TRUE(system.has_external_force());
  const Vector mass = *system.lumped_mass();
  for (const double time : {0.25, 0.25, 0.75, 0.25, 1.0, 1.0, 0.0, 2.0, 0.75}) {
    const double ground = time <= 0.5 ? 4.0 * time : 2.0 - 12.0 * (time - 0.5);
    Vector force;
    system.external_force(time, force);
    const Vector expected = -(time <= 1.0 ? ground : 0.0) * mass;
    EXPECT_LE((force - expected).norm(), 1e-15 * (1.0 + expected.norm())) << "t = " << time;
  }
}

TEST(StructuralSystem, AssemblyLosesNothing) {
  const model::Model m = free_portal();
  const StructuralSystem system(m);
  ASSERT_EQ(system.size(), 5 * 3 - 1);  // node 4 does not turn
  const Matrix k = Matrix(system.stiffness()), mass = Matrix(system.mass_matrix());
  EXPECT_LE((k - k.transpose()).norm(), 1e-15 * k.norm());
  EXPECT_LE((mass - mass.transpose()).norm(), 1e-15 * mass.norm());

  // Rigid motions strain nothing, and carry the whole mass: rho A L of each element, the
  // girder's extra mass per length, the point masses.
  const std::vector<Vector> rigid = rigid_motions(m, system.dofs());
  for (const Vector& u : rigid) EXPECT_LE((k * u).norm(), 1e-13 * k.norm() * u.norm());
  const double total =
      2.5 * 0.2 * (3.0 + 4.0 + 3.0) + 1.5 * 4.0 + 7.8 * 0.01 * (5.0 + 2.0) + 5.0 + 2.0;
  for (int d = 0; d < 2; ++d) {
    const Vector& u = rigid[static_cast<std::size_t>(d)];
    EXPECT_NEAR(u.dot(mass * u), total, 1e-14 * total) << model::direction(d, m.dimension).words;
  }

  // The assembled energy is the elements' own, for any displacements.
  const Vector u = random_vector(system.size(), 7);
  double element_energy = 0.0;
  for (const auto& element : m.elements) {
    const Vector u_e = testing::element_displacements(system.dofs(), *element, u);
    element_energy += u_e.dot(element->stiffness() * u_e);
  }
  EXPECT_NEAR(u.dot(k * u), element_energy, 1e-13 * element_energy);

  // Every part damps with its own a0, a1, all equal: C = a0 M + a1 K.
  ASSERT_TRUE(system.has_damping());
  Vector c_u, k_u, m_u;
  system.multiply_damping(u, c_u);
  system.multiply_stiffness(u, k_u);
  system.multiply_mass(u, m_u);
  const Vector expected = kA0 * m_u + kA1 * k_u;
  EXPECT_LE((c_u - expected).norm(), 1e-14 * expected.norm());
  // The parts' own damping, the same everywhere: C = diag(a0) M + diag(a1) K by DOF (a0 0 where
  // no mass is, a rotation without rotary inertia).
  const auto* rayleigh = system.rayleigh();
  ASSERT_TRUE(rayleigh);
  EXPECT_TRUE(rayleigh->stiffness);
  for (Index i = 0; i < system.size(); ++i) {
    EXPECT_EQ(rayleigh->stiffness_coefficient[i], kA1);
    if (mass(i, i) != 0.0) {
      EXPECT_EQ(rayleigh->mass_coefficient[i], kA0) << i;
    }
  }
}

// The model's Rayleigh damping is said to be so (the energy balance then takes C x from K x and
// M x); none without damping.
TEST(StructuralSystem, ModelRayleighDampingIsSaidToBeSo) {
  model::Model m = chain();
  EXPECT_FALSE(StructuralSystem(m).rayleigh());
  m.damping = model::RayleighDamping{0.3, 0.002};
  const StructuralSystem system(m);
  const auto* rayleigh = system.rayleigh();
  ASSERT_TRUE(rayleigh);
  EXPECT_EQ(rayleigh->mass_coefficient, Vector::Constant(system.size(), 0.3));
  EXPECT_EQ(rayleigh->stiffness_coefficient, Vector::Constant(system.size(), 0.002));
  EXPECT_TRUE(rayleigh->stiffness);
}

// Two bars that share no node (two structures that only links would join), each damped with
// its own a0 and a1: C = diag(a0) M + diag(a1) K by DOF, C x the assembled C's to round-off.
// Joined at a node, the node's equation has two of each: C is assembled and none is said; and a
// mass-proportional C needs no a1 at all.
TEST(StructuralSystem, StructuresDampedEachWithItsOwnGiveRayleighByDof) {
  const auto bar = [](const model::Model& m, Index i, Index j, double a0, double a1) {
    const auto end = [&m](Index node) {
      return model::ElementNode{node, m.nodes[static_cast<std::size_t>(node)].position};
    };
    return std::make_shared<const Truss>(
        fmt::format("t{}_{}", i, j), std::array{end(i), end(j)}, 1,
        Truss::Section{.youngs_modulus = 100.0, .area = 1.0, .density = 2.0},
        model::RayleighDamping{a0, a1});
  };
  model::Model apart;
  apart.dimension = 1;
  for (double x : {0.0, 1.0, 3.0, 4.0}) apart.nodes.push_back({fmt::format("n{}", x), {x, 0.0}});
  apart.elements = {bar(apart, 0, 1, 0.3, 0.002), bar(apart, 2, 3, 0.5, 0.004)};
  apart.supports = {{.node = 0, .fixed = {true, false}}, {.node = 3, .fixed = {true, false}}};
  apart.masses = {{.node = 1, .mass = 4.0, .damping = model::RayleighDamping{0.3, 0.0}},
                  {.node = 2, .mass = 6.0, .damping = model::RayleighDamping{0.5, 0.0}}};
  const StructuralSystem system(apart);
  const auto* rayleigh = system.rayleigh();
  ASSERT_TRUE(rayleigh);
  EXPECT_EQ(rayleigh->mass_coefficient, (Vector{{0.3, 0.5}}));
  EXPECT_EQ(rayleigh->stiffness_coefficient, (Vector{{0.002, 0.004}}));
  // Masses 4 + 1 and 6 + 1 (each bar's half, rho A L / 2 = 1), bars E A / L = 100:
  // C = diag(0.3 * 5 + 0.002 * 100, 0.5 * 7 + 0.004 * 100).
  const Vector u{{0.7, -1.3}};
  Vector c_u;
  system.multiply_damping(u, c_u);
  const Vector by_dof{{1.7 * 0.7, 3.9 * -1.3}};
  EXPECT_LE((c_u - by_dof).norm(), 1e-15 * by_dof.norm());

  // A bar 1-2 (E A / L = 50, half mass 2, a0 0.3, a1 0.002): C's rows 0.3 * 7 + 0.3, -0.1 and
  // -0.1, 0.5 * 7 + 0.3 * 2 + 0.5.
  model::Model joined = apart;
  joined.elements.push_back(bar(joined, 1, 2, 0.3, 0.002));
  const StructuralSystem shared(joined);
  EXPECT_FALSE(shared.rayleigh());
  shared.multiply_damping(u, c_u);
  const Vector assembled{{2.4 * 0.7 - 0.1 * -1.3, -0.1 * 0.7 + 4.6 * -1.3}};
  EXPECT_LE((c_u - assembled).norm(), 1e-15 * assembled.norm());

  model::Model by_mass = apart;
  by_mass.elements = {bar(by_mass, 0, 1, 0.3, 0.0), bar(by_mass, 2, 3, 0.5, 0.0)};
  const StructuralSystem damped_by_mass(by_mass);
  const auto* mass_only = damped_by_mass.rayleigh();  // the system's own: it must outlive this
  ASSERT_TRUE(mass_only);
  EXPECT_FALSE(mass_only->stiffness);
}

}  // namespace
}  // namespace pound::assembly
