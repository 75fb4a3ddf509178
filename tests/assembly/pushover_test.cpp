// Pushover of a cantilever pier with a bilinear base hinge against its closed-form capacity
// curve, with and without P-Delta under its weight; the Euler load of a column from the
// consistent geometric stiffness; a column loaded past it is refused.
#include "assembly/pushover.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <iostream>
#include <numbers>

#include "assembly/static_equilibrium.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"

namespace pound::assembly {
namespace {

// Pier: h = 8 m, E I = 3e10 x 0.8; hinge k_h = 5e10 N m, M_y = 2e7 N m, b = 0.05; deck weight
// W = m g with m = 5e5 kg and g = 10.
constexpr double kHeight = 8.0, kEi = 3e10 * 0.8, kHinge = 5e10, kYieldMoment = 2e7,
                 kHardening = 0.05, kMass = 5e5, kGravity = 10.0;

std::string pier_model(const std::string& p_delta, const std::string& hardening, int elements) {
  std::string nodes = R"({"id": "base", "x": 0, "y": 0}, {"id": "hinge", "x": 0, "y": 0})";
  std::string beams;
  std::string previous = "hinge";
  for (int e = 1; e <= elements; ++e) {
    const std::string node = e == elements ? "top" : fmt::format("n{}", e);
    nodes += fmt::format(R"(, {{"id": "{}", "x": 0, "y": {}}})", node, kHeight * e / elements);
    beams += fmt::format(R"({}{{"id": "e{}", "type": "beam", "nodes": ["{}", "{}"], "material": "c",
                          "area": 3.0, "inertia": 0.8}})",
                         e > 1 ? ", " : "", e, previous, node);
    previous = node;
  }
  const std::string gravity =
      p_delta.empty() ? std::string()
                      : fmt::format(R"("gravity": {{"acceleration": {}, "p_delta": "{}"}},)",
                                    kGravity, p_delta);
  return fmt::format(R"({{
    "dimension": 2,
    "nodes": [{}],
    "materials": [{{"id": "c", "youngs_modulus": 3e10, "density": 0}}],
    "elements": [{}],
    "masses": [{{"node": "top", "mass": {}}}],
    "supports": [{{"node": "base", "fix": ["x", "y", "rz"]}}, {{"node": "hinge", "fix": ["x", "y"]}}],
    "links": [{{"id": "hinge", "nodes": ["hinge", "base"], "dof": "rotation",
               "law": {{"type": "bilinear_spring", "stiffness": {}, "yield_force": {},
                        "hardening_ratio": {}}}}}],
    {}
    "analysis": {{"time_step": 0.01, "duration": 1}}
  }})",
                     nodes, beams, kMass, kHinge, kYieldMoment, hardening, gravity);
}

StructuralSystem system_of(const std::string& text) {
  return StructuralSystem(builder::build(io::parse_model(text, "pier.json")).model);
}

// Lateral force at the top against its displacement (point load), from the loaded state.
PushoverResult push(StructuralSystem& system, double target, int increments) {
  const Vector start = system.has_external_force() ? static_equilibrium(system, 0.0).displacement
                                                   : Vector::Zero(system.size());
  // The top node is the last one: its x is the third-last equation (x, y, rz).
  PushoverControl control{.equation = system.size() - 3, .increments = increments};
  control.target = start[control.equation] + target;
  control.pattern = Vector::Zero(system.size());
  control.pattern[control.equation] = 1.0;
  return pushover(system, start, control);
}

// The bilinear curve: K0 = 1 / (h^3 / 3EI + h^2 / k_h), yield when the hinge moment V_E h
// reaches M_y (V_E: the elastic part's shear, K0 Delta), post-yield 1 / (h^3 / 3EI + h^2 / (b
// k_h)); P-Delta lowers both slopes by W / h and leaves the yield displacement where it was.
double exact_base_shear(double displacement, double hardening, double weight) {
  const double column = std::pow(kHeight, 3) / (3 * kEi), lever = kHeight * kHeight;
  const double initial = 1.0 / (column + lever / kHinge);
  const double post_yield = hardening > 0 ? 1.0 / (column + lever / (hardening * kHinge)) : 0.0;
  const double yield_displacement = kYieldMoment / kHeight / initial;
  const double softening = weight / kHeight;
  if (displacement <= yield_displacement) return (initial - softening) * displacement;
  return (initial - softening) * yield_displacement +
         (post_yield - softening) * (displacement - yield_displacement);
}

double worst_curve_error(const PushoverResult& result, double hardening, double weight) {
  double worst = 0.0;
  for (const PushoverPoint& point : result.curve) {
    const double exact = exact_base_shear(point.displacement, hardening, weight);
    worst = std::max(worst, std::abs(point.load_factor - exact) / (kYieldMoment / kHeight));
  }
  return worst;
}

TEST(Pushover, BaseHingeGivesTheBilinearCurve) {
  StructuralSystem system = system_of(pier_model("", std::to_string(kHardening), 1));
  const PushoverResult result = push(system, 0.2, 50);
  ASSERT_TRUE(result.stopped.empty()) << result.stopped;
  ASSERT_EQ(result.curve.size(), 51u);
  const double error = worst_curve_error(result, kHardening, 0.0);
  std::cout << "bilinear pier: worst base-shear error " << error << " of V_y\n";
  EXPECT_LT(error, 1e-9);
}

// Chord P-Delta of a single-element column: exactly W / h off both slopes.
TEST(Pushover, PDeltaLowersThePostYieldSlopeByWeightOverHeight) {
  const double weight = kMass * kGravity;
  for (double hardening : {kHardening, 0.0}) {
    StructuralSystem system = system_of(pier_model("chord", std::to_string(hardening), 1));
    const PushoverResult result = push(system, 0.2, 40);
    ASSERT_TRUE(result.stopped.empty()) << result.stopped;
    const double error = worst_curve_error(result, hardening, weight);
    const auto& last = result.curve[result.curve.size() - 1];
    const auto& before = result.curve[result.curve.size() - 2];
    const double slope =
        (last.load_factor - before.load_factor) / (last.displacement - before.displacement);
    const double expected =
        exact_base_shear(1.0, hardening, weight) - exact_base_shear(0.9, hardening, weight);
    const double slope_error = std::abs(slope - expected / 0.1) / (weight / kHeight);
    std::cout << "b = " << hardening << ": post-yield slope " << slope << ", expected "
              << expected / 0.1 << " (W/h = " << weight / kHeight << "), error " << slope_error
              << " of W/h; worst base-shear error " << error << " of V_y\n";
    EXPECT_LT(slope_error, 1e-10);
    EXPECT_LT(error, 1e-9);
  }
}

// Elastic buckling of a cantilever column, P_cr = pi^2 E I / (4 h^2): the lowest lambda of
// K_E phi = lambda (-K_G) phi, K_G the geometric stiffness under the weight.
double buckling_load(const std::string& p_delta, int elements) {
  StructuralSystem system = system_of(pier_model(p_delta, "0.05", elements));
  const Matrix elastic(system.elastic_stiffness());
  const Matrix geometric = Matrix(system.stiffness()) - elastic;
  // The hinge's rotation is held by the link: give K_E the hinge's stiffness there.
  Matrix held = elastic;
  held(0, 0) += kHinge;
  const Eigen::GeneralizedSelfAdjointEigenSolver<Matrix> modes(-geometric, held);
  return kMass * kGravity / modes.eigenvalues().maxCoeff();
}

// The pier on its elastic hinge c = k_h: P_cr = EI k^2 with (k h) tan(k h) = c h / EI (the
// Euler cantilever pi^2 EI / (4 h^2) as c grows), the root found by bisection on (0, pi/2).
TEST(Pushover, ConsistentGeometricStiffnessGivesTheEulerLoad) {
  const double ratio = kHinge * kHeight / kEi;
  double low = 0.0, high = std::numbers::pi / 2;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (low + high);
    (mid * std::tan(mid) < ratio ? low : high) = mid;
  }
  const double exact = kEi * std::pow(0.5 * (low + high) / kHeight, 2);
  for (int elements : {2, 4, 8, 16}) {
    const double consistent = buckling_load("consistent", elements);
    const double chord = buckling_load("chord", elements);
    std::cout << elements << " elements: P_cr consistent " << consistent << " (error "
              << std::abs(consistent / exact - 1) << "), chord " << chord << " (error "
              << std::abs(chord / exact - 1) << "); exact " << exact << "\n";
    if (elements == 16) {
      EXPECT_LT(std::abs(consistent / exact - 1), 1e-6);
    }
  }
}

TEST(Pushover, AColumnPastItsBucklingLoadIsRefused) {
  // P_cr is about 7.9e8 N: a weight of 5e9 N passes it.
  std::string text = pier_model("consistent", "0.05", 2);
  const std::string mass = fmt::format(R"("mass": {})", kMass);
  text.replace(text.find(mass), mass.size(), fmt::format(R"("mass": {})", kMass * 1000));
  try {
    system_of(text);
    FAIL() << "no error";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("/gravity/p_delta"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("buckling"), std::string::npos);
  }
}

}  // namespace
}  // namespace pound::assembly
