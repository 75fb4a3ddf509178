// Linear structures under a real record against exact references: an SDOF against the
// piecewise-linear exact solution (Nigam & Jennings), and a damped frame against modal
// superposition of Nigam-Jennings modal responses. Newmark's error must fall as dt^2.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <numbers>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"
#include "model/ground_motion.hpp"
#include "support/shared_records.hpp"

namespace pound {
namespace {

// Runs `text` under the record and returns the relative displacement history of `node` in x at
// the record's samples.
std::vector<double> response(const std::string& text, const model::GroundMotion& motion,
                             const std::string& node, double dt) {
  const builder::BuiltModel built =
      builder::build(io::parse_model(text, "structure.json"), {motion});
  assembly::StructuralSystem system(built.model);
  auto integrator = builder::make_integrator(built.analysis);
  auto settings = builder::make_transient_settings(built.analysis);
  settings.time_step = dt;
  integrators::TransientAnalysis analysis(system, *integrator, settings);
  const Index x = system.dofs().own_equation(built.node_index.at(node), 0);
  const long per_sample = std::lround(motion.time_step / dt);
  std::vector<double> history;
  long step = 0;
  integrators::State state;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    if (step++ % per_sample == 0) history.push_back(s.displacement[x]);
  });
  return history;
}

double relative_error(const std::vector<double>& a, const std::vector<double>& b) {
  double error = 0.0, peak = 0.0;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k) {
    error = std::max(error, std::abs(a[k] - b[k]));
    peak = std::max(peak, std::abs(b[k]));
  }
  return error / peak;
}

TEST(SeismicResponse, SdofMatchesNigamJenningsAtSecondOrder) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const model::GroundMotion motion = testing::el_centro(1000);  // the strong part, 10 s
  const double mass = 1.0e5, period = 0.8, zeta = 0.05;
  const double omega = 2 * std::numbers::pi / period, stiffness = mass * omega * omega;
  // A mass on a 1 m truss with E A = k; mass-proportional Rayleigh damping a0 = 2 zeta w.
  const std::string text = fmt::format(R"({{
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "mass", "x": 1}}],
    "materials": [{{"id": "spring", "youngs_modulus": {}, "density": 0}}],
    "elements": [{{"id": "k", "type": "truss", "nodes": ["ground", "mass"], "material": "spring", "area": 1}}],
    "masses": [{{"node": "mass", "mass": {}}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}],
    "damping": {{"mass_coefficient": {}}},
    "excitations": [{{"record": "unused.AT2"}}],
    "analysis": {{"time_step": 0.01}}
  }})",
                                       stiffness, mass, 2 * zeta * omega);
  const model::SdofResponse exact = model::sdof_response(motion, period, zeta);
  const double coarse = relative_error(response(text, motion, "mass", 0.005), exact.displacement);
  const double fine = relative_error(response(text, motion, "mass", 0.0025), exact.displacement);
  std::cout << "max error / peak: dt = 0.005 -> " << coarse << ", dt = 0.0025 -> " << fine
            << ", order " << std::log2(coarse / fine) << "\n";
  EXPECT_LT(fine, 2e-3);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.2);
}

TEST(SeismicResponse, DampedFrameMatchesModalSuperposition) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const model::GroundMotion motion = testing::el_centro(1000);  // the strong part, 10 s
  // A three-storey, one-bay frame (fixed bases, lumped floor masses) with Rayleigh damping;
  // Rayleigh damping is classical, so each mode is an independent SDOF.
  std::string nodes = R"({"id": "a0", "x": 0, "y": 0}, {"id": "b0", "x": 6, "y": 0})", elements,
              masses;
  for (int floor = 1; floor <= 3; ++floor) {
    nodes +=
        fmt::format(R"(, {{"id": "a{0}", "x": 0, "y": {1}}}, {{"id": "b{0}", "x": 6, "y": {1}}})",
                    floor, 3.5 * floor);
    for (const char* column : {"a", "b"})
      elements += fmt::format(
          R"({{"id": "{0}c{1}", "type": "beam", "nodes": ["{0}{2}", "{0}{1}"], "material": "concrete", "area": 0.25, "inertia": 5.2e-3}}, )",
          column, floor, floor - 1);
    elements += fmt::format(
        R"({{"id": "beam{0}", "type": "beam", "nodes": ["a{0}", "b{0}"], "material": "concrete", "area": 0.3, "inertia": 9e-3}}{1})",
        floor, floor < 3 ? ", " : "");
    masses += fmt::format(R"({{"node": "a{0}", "mass": 3e4}}, {{"node": "b{0}", "mass": 3e4}}{1})",
                          floor, floor < 3 ? ", " : "");
  }
  const std::string text = fmt::format(R"({{"dimension": 2, "nodes": [{}],
    "materials": [{{"id": "concrete", "youngs_modulus": 3e10, "density": 0}}],
    "elements": [{}], "masses": [{}],
    "supports": [{{"node": "a0", "fix": ["x", "y", "rz"]}}, {{"node": "b0", "fix": ["x", "y", "rz"]}}],
    "damping": {{"ratio": 0.05, "modes": [1, 2]}},
    "excitations": [{{"record": "unused.AT2"}}],
    "analysis": {{"time_step": 0.01}}}})",
                                       nodes, elements, masses);
  const builder::BuiltModel built = builder::build(io::parse_model(text, "frame.json"), {motion});
  const assembly::StructuralSystem system(built.model);
  const assembly::Modes modes = assembly::modal_analysis(system);
  const Index roof = system.dofs().own_equation(built.node_index.at("a3"), 0);
  // iota: 1 on every x translation.
  Vector influence = Vector::Zero(system.size());
  for (const auto& [id, node] : built.node_index)
    if (const Index row = system.dofs().own_equation(node, 0); row >= 0) influence[row] = 1.0;
  const Vector participation = modes.shapes.transpose() * (system.mass_matrix() * influence);
  std::vector<double> superposed(motion.acceleration.size(), 0.0);
  for (Index k = 0; k < modes.omega_squared.size(); ++k) {
    const double omega = std::sqrt(modes.omega_squared[k]);
    const double zeta = system.damping().mass_coefficient / (2 * omega) +
                        system.damping().stiffness_coefficient * omega / 2;
    const model::SdofResponse q = model::sdof_response(motion, 2 * std::numbers::pi / omega, zeta);
    for (std::size_t s = 0; s < superposed.size(); ++s)
      superposed[s] += modes.shapes(roof, k) * participation[k] * q.displacement[s];
  }
  const double coarse = relative_error(response(text, motion, "a3", 0.002), superposed);
  const double fine = relative_error(response(text, motion, "a3", 0.001), superposed);
  std::cout << modes.omega_squared.size() << " modes; roof max error / peak: dt = 0.002 -> "
            << coarse << ", dt = 0.001 -> " << fine << ", order " << std::log2(coarse / fine)
            << "\n";
  EXPECT_LT(fine, 5e-3);
  EXPECT_NEAR(std::log2(coarse / fine), 2.0, 0.3);
}

}  // namespace
}  // namespace pound
