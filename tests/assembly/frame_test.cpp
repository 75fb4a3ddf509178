// 2-D beam-columns against Euler-Bernoulli closed forms, and Rayleigh damping from two periods.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"

namespace pound {
namespace {

constexpr double kE = 2.0e11, kArea = 0.01, kInertia = 1.0e-4, kDensity = 7850.0, kLength = 5.0;

// A cantilever of `elements` beams along (dx, dy), `length` long, fixed at its first node.
std::string cantilever(int elements, const std::string& mass, double dx, double dy,
                       double length = kLength) {
  std::string nodes, beams;
  for (int i = 0; i <= elements; ++i)
    nodes += fmt::format("{}{{\"id\": \"n{}\", \"x\": {}, \"y\": {}}}", i ? ", " : "", i,
                         dx * length * i / elements, dy * length * i / elements);
  for (int e = 0; e < elements; ++e)
    beams += fmt::format(
        "{}{{\"id\": \"b{}\", \"type\": \"beam\", \"nodes\": [\"n{}\", \"n{}\"], "
        "\"material\": \"steel\", \"area\": {}, \"inertia\": {}, \"mass\": \"{}\"}}",
        e ? ", " : "", e, e, e + 1, kArea, kInertia, mass);
  return fmt::format(R"({{"dimension": 2, "nodes": [{}],
    "materials": [{{"id": "steel", "youngs_modulus": {}, "density": {}}}],
    "elements": [{}], "supports": [{{"node": "n0", "fix": ["x", "y", "rz"]}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}}})",
                     nodes, kE, kDensity, beams);
}

assembly::StructuralSystem system_of(const std::string& text) {
  return assembly::StructuralSystem(builder::build(io::parse_model(text, "frame.json")).model);
}

// Euler-Bernoulli cantilever: w_k = (beta_k L)^2 sqrt(EI / (m L^4)), beta_1 L = 1.875104,
// beta_2 L = 4.694091; axial w = (pi / 2) sqrt(E A / (m L^2)).
struct CantileverFrequencies {
  double bending_1, bending_2, axial;
};
CantileverFrequencies exact_cantilever(double length = kLength) {
  const double m = kDensity * kArea;
  const double scale = std::sqrt(kE * kInertia / (m * std::pow(length, 4)));
  return {1.875104068711961 * 1.875104068711961 * scale,
          4.694091132974175 * 4.694091132974175 * scale,
          std::numbers::pi / 2 * std::sqrt(kE * kArea / (m * length * length))};
}

double frequency_error(const assembly::Modes& modes, double exact) {
  double best = 1e300;
  for (Index k = 0; k < modes.omega_squared.size(); ++k)
    best = std::min(best, std::abs(std::sqrt(modes.omega_squared[k]) / exact - 1.0));
  return best;
}

TEST(Frame, ConsistentMassCantileverFrequencies) {
  const CantileverFrequencies exact = exact_cantilever();
  for (auto [dx, dy] : {std::pair{1.0, 0.0}, std::pair{0.0, 1.0}, std::pair{0.6, 0.8}}) {
    const assembly::Modes modes =
        assembly::modal_analysis(system_of(cantilever(10, "consistent", dx, dy)));
    const double first = std::abs(std::sqrt(modes.omega_squared[0]) / exact.bending_1 - 1.0);
    const double second = frequency_error(modes, exact.bending_2);
    const double axial = frequency_error(modes, exact.axial);
    std::cout << "direction (" << dx << ", " << dy << "): bending 1 error " << first
              << ", bending 2 error " << second << ", axial error " << axial << "\n";
    EXPECT_LT(first, 1e-5);
    EXPECT_LT(second, 1e-4);
    EXPECT_LT(axial, 5e-3);  // linear axial elements: the discretisation error at n = 10
  }
}

TEST(Frame, LumpedMassCantileverConverges) {
  const CantileverFrequencies exact = exact_cantilever();
  double previous = 1.0;
  for (int elements : {5, 10, 20}) {
    const assembly::Modes modes =
        assembly::modal_analysis(system_of(cantilever(elements, "lumped", 1, 0)));
    const double error = std::abs(std::sqrt(modes.omega_squared[0]) / exact.bending_1 - 1.0);
    std::cout << elements << " lumped elements: first frequency error " << error << "\n";
    EXPECT_LT(error, previous);
    previous = error;
  }
  EXPECT_LT(previous, 2e-3);
}

// A finely meshed 10 m cantilever with consistent masses: its highest w^2 (the rotations' tiny
// rotary inertia) is 5e-11 of the first at 90 beams and 7e-12 at 150, and the former test of
// rigid-body modes (w^2 below 1e-10 of the highest) dropped its first mode: `pound modes` listed
// the second (0.0565 s) as the first. Both paths of natural_periods (90 beams, 270 DOFs: the
// dense solve; 150: Lanczos) now give the Euler-Bernoulli period within the mesh's error and the
// round-off of a w^2 range of 1e11 (1e-6).
TEST(Frame, AFineConsistentMassCantileverKeepsItsFirstMode) {
  const double exact = 2.0 * std::numbers::pi / exact_cantilever(10.0).bending_1;
  for (const int elements : {90, 150}) {
    const std::vector<double> periods =
        assembly::natural_periods(system_of(cantilever(elements, "consistent", 1, 0, 10.0)), 2);
    ASSERT_EQ(periods.size(), 2u);
    std::cout << elements << " beams: first period " << periods[0] << ", Euler-Bernoulli " << exact
              << ", relative error " << periods[0] / exact - 1.0 << "\n";
    EXPECT_NEAR(periods[0] / exact, 1.0, 1e-6) << elements << " beams";
  }
}

// One cubic element is exact for a tip load: delta = P L^3 / (3 E I), theta = P L^2 / (2 E I).
TEST(Frame, TipLoadDeflectionIsExact) {
  const assembly::StructuralSystem system = system_of(cantilever(1, "lumped", 0.6, 0.8));
  // A unit force perpendicular to the axis at the tip, in global components.
  Vector force = Vector::Zero(system.size());
  force[0] = -0.8;
  force[1] = 0.6;
  Vector displacement;
  system.factor(0.0, 0.0, 1.0)->solve(force, displacement);
  const double deflection = -0.8 * displacement[0] + 0.6 * displacement[1];
  const double expected = std::pow(kLength, 3) / (3 * kE * kInertia);
  std::cout << "tip deflection error " << deflection / expected - 1.0 << "\n";
  EXPECT_NEAR(deflection / expected, 1.0, 1e-12);
  EXPECT_NEAR(displacement[2] / (kLength * kLength / (2 * kE * kInertia)), 1.0, 1e-12);
}

// A portal frame with a (nearly) rigid beam and axially rigid columns: lateral stiffness
// 24 E I / h^3 of two fixed-fixed columns (the shear-building idealisation).
TEST(Frame, PortalFrameWithRigidBeamHasTheShearBuildingStiffness) {
  const double h = 3.0;
  const std::string text = fmt::format(R"({{"dimension": 2,
    "nodes": [{{"id": "a", "x": 0, "y": 0}}, {{"id": "b", "x": 0, "y": {h}}},
              {{"id": "c", "x": 6, "y": {h}}}, {{"id": "d", "x": 6, "y": 0}}],
    "materials": [{{"id": "steel", "youngs_modulus": {E}, "density": 0}},
                  {{"id": "rigid", "youngs_modulus": {rigid}, "density": 0}}],
    "elements": [{{"id": "left", "type": "beam", "nodes": ["a", "b"], "material": "steel", "area": 1e4, "inertia": {I}}},
                 {{"id": "beam", "type": "beam", "nodes": ["b", "c"], "material": "rigid", "area": 0.01, "inertia": {I}}},
                 {{"id": "right", "type": "beam", "nodes": ["d", "c"], "material": "steel", "area": 1e4, "inertia": {I}}}],
    "masses": [{{"node": "b", "mass": 1000}}, {{"node": "c", "mass": 1000}}],
    "supports": [{{"node": "a", "fix": ["x", "y", "rz"]}}, {{"node": "d", "fix": ["x", "y", "rz"]}}],
    "analysis": {{"time_step": 0.001, "duration": 1}}}})",
                                       fmt::arg("h", h), fmt::arg("E", kE),
                                       fmt::arg("rigid", kE * 1e6), fmt::arg("I", kInertia));
  const assembly::Modes modes = assembly::modal_analysis(system_of(text));
  const double expected = std::sqrt(24 * kE * kInertia / std::pow(h, 3) / 2000.0);
  const double error = std::sqrt(modes.omega_squared[0]) / expected - 1.0;
  std::cout << "sway frequency error " << error << "\n";
  EXPECT_NEAR(error, 0.0, 1e-4);
}

// Rayleigh damping through two periods: a0 = 2 xi w1 w2 / (w1 + w2), a1 = 2 xi / (w1 + w2), so
// the damping ratio a0 / (2 w) + a1 w / 2 equals xi at both.
TEST(Frame, RayleighDampingMatchesTheRatioAtBothPeriods) {
  std::string text = cantilever(10, "lumped", 1, 0);
  text.insert(text.size() - 1, R"(, "damping": {"ratio": 0.05, "modes": [1, 3]})");
  const builder::BuiltModel built = builder::build(io::parse_model(text, "frame.json"));
  const assembly::StructuralSystem system(built.model);
  const std::vector<double> periods = assembly::natural_periods(system, 3);
  for (int mode : {0, 2}) {
    const double w = 2 * std::numbers::pi / periods[static_cast<std::size_t>(mode)];
    const double ratio = system.damping().mass_coefficient / (2 * w) +
                         system.damping().stiffness_coefficient * w / 2;
    EXPECT_NEAR(ratio, 0.05, 1e-12) << "mode " << mode + 1;
  }
  EXPECT_TRUE(system.has_damping());
}

}  // namespace
}  // namespace pound
