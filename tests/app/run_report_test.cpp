// What `pound run` prints: every number with its unit in the model's units, forces, moments and
// energies only where the model names a mass unit, and a hinge's moment never reported as a
// force.
#include "app/run_report.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/model_run.hpp"
#include "support/process.hpp"

namespace pound::app {
namespace {

RunOutcome run_bundled(const std::string& name) {
  RunRequest request;
  request.model_path = std::string(POUND_SOURCE_DIR) + "/models/" + name;
  request.histories = false;
  RunOutcome outcome = run_model(request);
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  return outcome;
}

// A model given as text (`name` for its messages), histories off.
RunOutcome run_text(const std::string& name, const std::string& text) {
  RunRequest request;
  request.model_path = name;
  request.model_text = text;
  request.histories = false;
  return run_model(request);
}

// The report's line that starts with `start` (after its indent), or "".
std::string line_of(const std::string& report, const std::string& start) {
  std::istringstream lines(report);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("  " + start)) return line;
  return "";
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// kg, m and s: forces in N, energies in N*m, impulses in N*s, accelerations in m/s^2; each
// contact's force is summary.json's.
TEST(RunReport, TheBridgesNumbersCarryTheirUnits) {
  const RunOutcome outcome = run_bundled("three_span_bridge.json");
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  std::cout << line_of(outcome.report, "contact bridge.joint1:") << "\n"
            << line_of(outcome.report, "joint bridge.joint1.left_end:") << "\n"
            << line_of(outcome.report, "energy") << "\n";
  int contacts = 0;
  for (const nlohmann::json& link : summary["links"]) {
    if (link["role"] != "contact") continue;
    ++contacts;
    // Each link names its law's type (the joints and abutments Hertz-damp, the backfills).
    EXPECT_TRUE(link["law"] == "hertz_damp" || link["law"] == "backfill") << link;
    const std::string line = line_of(outcome.report, fmt::format("contact {}:", link["id"]));
    EXPECT_TRUE(has(line, fmt::format("peak force {:.6g} N, peak penetration ",
                                      link["peak_force"].get<double>())))
        << line;
    EXPECT_TRUE(has(line, " m, impulse ") && has(line, " N*s")) << line;
    // The backfill's soil keeps a permanent deformation once pushed past its elastic range.
    if (link.contains("permanent_deformation"))
      EXPECT_TRUE(line.ends_with(fmt::format(" N*s, permanent deformation {:.4g} m",
                                             link["permanent_deformation"].get<double>())))
          << line;
    else
      EXPECT_TRUE(line.ends_with(" N*s")) << line;
  }
  EXPECT_EQ(contacts, 6);
  const std::string joint = line_of(outcome.report, "joint bridge.joint1.left_end:");
  EXPECT_TRUE(has(joint, " m on its seat (seat 0.6 m, margin ")) << joint;
  EXPECT_TRUE(joint.ends_with(" m/s^2 (absolute)")) << joint;
  const std::string pier = line_of(outcome.report, "pier bridge.p1:");
  EXPECT_TRUE(has(pier, " m (0.") && has(pier, " % of 8 m), residual ")) << pier;
  EXPECT_TRUE(has(pier, " N, base moment ") && pier.ends_with(" N*m")) << pier;
  EXPECT_TRUE(line_of(outcome.report, "energy [N*m]: input ") != "") << outcome.report;
  EXPECT_TRUE(
      has(line_of(outcome.report, "bilinear_spring bridge.g0.n4.bearing_x yielded:"), " N*m"));
}

// The Takeda bridge's pier hinges: their moments apart from the bearings' forces (a moment of
// 6.6e6 was once the "largest force" of the springs). The model names no mass unit.
// The warnings found before a run are handed to before_solve once, as RunOutcome::warnings starts
// with them (`pound run` prints them then, and the rest after the run).
TEST(RunReport, WarningsFoundBeforeTheRunAreHandedOverBeforeTheSolve) {
  RunRequest request;
  request.model_path = "coarse_step.json";
  request.model_text = R"({
    "dimension": 1,
    "nodes": [{"id": "ground", "x": 0}, {"id": "mass", "x": 1}],
    "supports": [{"node": "ground", "fix": ["x"]}],
    "masses": [{"node": "mass", "mass": 1}],
    "initial_velocities": [{"node": "mass", "x": 1}],
    "links": [{"id": "spring", "nodes": ["ground", "mass"], "axis": [1],
               "law": {"type": "elastic_spring", "stiffness": 100}}],
    "analysis": {"time_step": 0.02, "duration": 0.1}})";
  request.histories = false;
  std::vector<std::string> handed;
  int calls = 0;
  request.before_solve = [&](const std::vector<std::string>& warnings) {
    handed = warnings;
    ++calls;
  };
  const RunOutcome outcome = run_model(request);
  EXPECT_EQ(calls, 1);
  ASSERT_FALSE(handed.empty());
  EXPECT_TRUE(has(handed[0], "more than a tenth of the duration")) << handed[0];
  ASSERT_GE(outcome.warnings.size(), handed.size());
  EXPECT_TRUE(std::equal(handed.begin(), handed.end(), outcome.warnings.begin()));
}

TEST(RunReport, HingeMomentsAreNotSpringForces) {
  const RunOutcome outcome = run_bundled("three_span_bridge_takeda.json");
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  double moment = 0.0, force = 0.0;
  int hinges = 0, springs = 0;
  for (const nlohmann::json& link : summary["links"]) {
    if (link["role"] != "spring") continue;
    const bool hinge = link.value("rotational", false);  // summary.json marks hinges
    EXPECT_EQ(hinge, link["id"].get<std::string>().ends_with(".hinge")) << link["id"];
    double& largest = hinge ? moment : force;
    (hinge ? hinges : springs) += 1;
    largest = std::max(largest, link["peak_force"].get<double>());
    if (link.contains("peak_tension"))
      largest = std::max(largest, link["peak_tension"].get<double>());
  }
  const std::string spring_line =
      line_of(outcome.report, fmt::format("{} spring link(s)", springs));
  const std::string hinge_line =
      line_of(outcome.report, fmt::format("{} rotational spring(s) (hinges, bearings", hinges));
  std::cout << spring_line << "\n" << hinge_line << "\n";
  EXPECT_EQ(hinges, 2);
  EXPECT_GT(moment, force);
  EXPECT_TRUE(spring_line.ends_with(fmt::format("largest force {:.6g} N", force))) << spring_line;
  EXPECT_TRUE(hinge_line.ends_with(fmt::format("largest moment {:.6g} N*m", moment))) << hinge_line;
  EXPECT_TRUE(has(line_of(outcome.report, "takeda bridge.p1.hinge yielded:"), "peak rotation "))
      << outcome.report;
  EXPECT_TRUE(has(line_of(outcome.report, "takeda bridge.p1.hinge yielded:"), " rad (plastic "));
}

// A hinge's history is a moment and a rotation, in their units (its CSV columns said N and m).
TEST(RunReport, AHingesHistoryIsInMomentAndRotationUnits) {
  const std::string path = std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_takeda.json";
  nlohmann::json model = nlohmann::json::parse(std::ifstream(path));
  model["units"]["mass"] = "kg";
  RunRequest request;
  request.model_path = path;
  request.model_text = model.dump();
  request.max_steps = 10;
  const RunOutcome outcome = run_model(request);
  bool found = false;
  for (const auto& [file, table] : outcome.histories) {
    for (std::size_t c = 0; c < table.columns.size(); ++c) {
      if (table.columns[c] == "bridge.p1.hinge.force") {
        EXPECT_EQ(table.units[c], "N*m");
        found = true;
      }
      if (table.columns[c] == "bridge.p1.hinge.penetration") {
        EXPECT_EQ(table.units[c], "rad");
      }
      if (table.columns[c] == "bridge.joint1.force") {
        EXPECT_EQ(table.units[c], "N");
      }
    }
  }
  EXPECT_TRUE(found);
}

// A restrainer that yields says so, with its permanent elongation (its line said only how often
// it went taut): a 1 t mass at 1 m/s pulls a cable (k = 1e6 N/m, 10 mm slack, T_y = 10 kN, no
// hardening) that stores T_y^2 / 2k = 50 J and dissipates the rest of the 500 J by stretching
// p = 450 J / T_y = 45 mm.
// A friction link gives its slide: the bundled block launched at 2 m/s on a floor (mu = 0.5)
// slides v0^2 / (2 mu g) and stays there, its friction taking all its kinetic energy m v0^2 / 2
// (20 J) at mu R_n (49.05 N sliding; at least that at its peak, when R_n overshoots as it lands); a
// block on a friction pendulum under the bundled record gives its peak and residual slide.
TEST(RunReport, AFrictionLinkGivesItsSlideAndWhatItDissipated) {
  const RunOutcome outcome = run_bundled("block_on_floor.json");
  const nlohmann::json friction =
      nlohmann::json::parse(outcome.summary.dump())["links"][0]["friction"];
  const double distance = 2.0 * 2.0 / (2 * 0.5 * 9.81);
  std::cout << line_of(outcome.report, "  friction:") << "\n"
            << "slide against v0^2/(2 mu g): "
            << friction["peak_slide"].get<double>() / distance - 1
            << ", work against m v0^2 / 2: " << friction["work"].get<double>() / 20.0 - 1 << "\n";
  EXPECT_NEAR(friction["peak_slide"].get<double>() / distance, 1.0, 1e-4);
  EXPECT_NEAR(friction["residual_slide"].get<double>() / distance, 1.0, 1e-4);
  EXPECT_NEAR(friction["work"].get<double>() / 20.0, 1.0, 1e-4);
  EXPECT_GE(friction["peak_tangential_force"].get<double>(), 0.5 * 10 * 9.81 * (1 - 1e-9));
  EXPECT_FALSE(friction.contains("peak_slides"));  // one tangent in a plane
  EXPECT_TRUE(has(line_of(outcome.report, "  friction:"), "peak slide 0.4078 m")) << outcome.report;
  const RunOutcome pendulum = run_bundled("sliding_block_pendulum.json");
  const nlohmann::json bearing =
      nlohmann::json::parse(pendulum.summary.dump())["links"][0]["friction"];
  EXPECT_GT(bearing["peak_slide"].get<double>(), bearing["residual_slide"].get<double>());
  EXPECT_GT(bearing["work"].get<double>(), 0.0);
}

// A friction pendulum (W = 9.81 kN, R = 2 m, mu = 0.06) whose stick spring is soft against its
// dish is told so with the bound on its residual's error, 2 sqrt(mu R d_y) (d_y = mu W / k_t),
// and the stick_stiffness that keeps it under 2 % of mu R (1e4 W / R); a stiff one is not. One
// launched so fast that it slides past R / 5 is told how far its small-displacement restoring
// force N s / R falls short of the spherical dish's, 1 - sqrt(1 - (s / R)^2).
TEST(RunReport, ASoftStickSpringOrALongSlideOnAFrictionPendulumIsWarnedOf) {
  const auto pendulum = [](const char* stick_stiffness, double launch) {
    return run_text("pendulum.json", fmt::format(R"({{
      "dimension": 2, "units": {{"length": "m", "time": "s", "mass": "kg"}},
      "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "seat", "x": 0, "y": 0}}],
      "masses": [{{"node": "block", "mass": 1000}}],
      "supports": [{{"node": "seat", "fix": ["x", "y"]}}],
      "loads": [{{"node": "block", "y": -9810}}],
      "initial_velocities": [{{"node": "block", "x": {}}}],
      "links": [{{"id": "bearing", "nodes": ["block", "seat"], "axis": [0, -1],
                  "law": {{"type": "gap_spring", "stiffness": 1e9}},
                  "friction": {{"coefficient": 0.06, "radius": 2,
                                "stick_stiffness": {}}}}}],
      "analysis": {{"time_step": 1e-3, "duration": 4, "initial_state": "static"}}}})",
                                                 launch, stick_stiffness));
  };
  const auto warnings_of = [](const RunOutcome& outcome) {
    std::vector<std::string> found;
    for (const std::string& warning : outcome.warnings)
      if (warning.starts_with("friction pendulum bearing:")) found.push_back(warning);
    return found;
  };
  const RunOutcome soft = pendulum("1e6", 0.5);
  ASSERT_TRUE(soft.failure.empty()) << soft.failure;
  ASSERT_EQ(warnings_of(soft).size(), 1u);
  const std::string line = warnings_of(soft)[0];
  std::cout << line << "\n";
  EXPECT_TRUE(has(line, "slides d_y = 0.000589 m ")) << line;
  EXPECT_TRUE(has(line, "2 sqrt(mu R d_y) = 0.0168 m (14.0 % of mu R)")) << line;
  EXPECT_TRUE(has(line, "at least 1e4 x N/R = 4.91e+07 N/m")) << line;
  // Launched so slowly that it never slides past d_y (amplitude v0 / omega = 0.45 mm): it never
  // slipped, so no reversal to bound.
  const RunOutcome stuck = pendulum("1e6", 0.001);
  ASSERT_TRUE(stuck.failure.empty()) << stuck.failure;
  EXPECT_TRUE(warnings_of(stuck).empty());
  const RunOutcome stiff = pendulum("1e8", 0.5);
  ASSERT_TRUE(stiff.failure.empty()) << stiff.failure;
  EXPECT_TRUE(warnings_of(stiff).empty());
  const RunOutcome fast = pendulum("1e8", 2.0);
  ASSERT_TRUE(fast.failure.empty()) << fast.failure;
  ASSERT_EQ(warnings_of(fast).size(), 1u);
  const std::string far = warnings_of(fast)[0];
  const double slide =
      nlohmann::json::parse(fast.summary.dump())["links"][0]["friction"]["peak_slide"]
          .get<double>();
  const double ratio = slide / 2.0;
  std::cout << far << "\n";
  EXPECT_TRUE(
      has(far, fmt::format("it slid {:.4g} m, {:.2f} of its radius R = 2 m,", slide, ratio)))
      << far;
  EXPECT_TRUE(
      has(far, fmt::format("falls {:.1f} % short", 100 * (1 - std::sqrt(1 - ratio * ratio)))))
      << far;
  EXPECT_GT(ratio, 0.3);
}

// A bearing seated under the weight is reported as one, with its normal force, and is not a
// pounding contact: the case summary (a batch row) counts no impacts and no pounding force.
TEST(RunReport, ASeatedBearingIsNoPoundingContact) {
  const RunOutcome outcome = run_bundled("sliding_block_pendulum.json");
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const std::string line = line_of(outcome.report, "bearing bearing:");
  std::cout << line << "\n";
  EXPECT_TRUE(has(line, "seated under the weight, peak normal force ")) << outcome.report;
  EXPECT_TRUE(has(line, "never lifted off")) << line;
  EXPECT_EQ(line_of(outcome.report, "contact bearing:"), "");
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  EXPECT_EQ(summary["links"][0]["seated"], true);
  EXPECT_FALSE(outcome.case_summary.impacts.has_value());
  EXPECT_FALSE(outcome.case_summary.max_pounding_force.has_value());
}

// Two soft pendulums in one model make one warning: the worse one's numbers, the other named.
TEST(RunReport, SoftStickSpringsOfSeveralPendulumsMakeOneWarning) {
  const RunOutcome outcome = run_text("pendulums.json", R"({
    "dimension": 2, "units": {"length": "m", "time": "s", "mass": "kg"},
    "nodes": [{"id": "block_1", "x": 0, "y": 0}, {"id": "seat_1", "x": 0, "y": 0},
              {"id": "block_2", "x": 5, "y": 0}, {"id": "seat_2", "x": 5, "y": 0}],
    "masses": [{"node": "block_1", "mass": 1000}, {"node": "block_2", "mass": 1000}],
    "supports": [{"node": "seat_1", "fix": ["x", "y"]}, {"node": "seat_2", "fix": ["x", "y"]}],
    "loads": [{"node": "block_1", "y": -9810}, {"node": "block_2", "y": -9810}],
    "initial_velocities": [{"node": "block_1", "x": 0.5}, {"node": "block_2", "x": 0.5}],
    "links": [
      {"id": "bearing_1", "nodes": ["block_1", "seat_1"], "axis": [0, -1],
       "law": {"type": "gap_spring", "stiffness": 1e9},
       "friction": {"coefficient": 0.06, "radius": 2, "stick_stiffness": 4e6}},
      {"id": "bearing_2", "nodes": ["block_2", "seat_2"], "axis": [0, -1],
       "law": {"type": "gap_spring", "stiffness": 1e9},
       "friction": {"coefficient": 0.06, "radius": 2, "stick_stiffness": 1e6}}],
    "analysis": {"time_step": 1e-3, "duration": 4, "initial_state": "static"}})");
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  std::vector<std::string> found;
  for (const std::string& warning : outcome.warnings)
    if (warning.starts_with("friction pendulum")) found.push_back(warning);
  ASSERT_EQ(found.size(), 1u);
  std::cout << found[0] << "\n";
  EXPECT_TRUE(
      found[0].starts_with("friction pendulum bearing_2: its stick spring (stick_stiffness "
                           "1e+06 N/m)"))
      << found[0];
  EXPECT_TRUE(found[0].ends_with("(the same for bearing_1, less far off)")) << found[0];
}

TEST(RunReport, AYieldedRestrainerGivesItsPermanentElongation) {
  const RunOutcome outcome = run_text("cable.json", R"({
    "dimension": 1, "units": {"length": "m", "time": "s", "mass": "kg"},
    "nodes": [{"id": "ground", "x": 0}, {"id": "mass", "x": 1}],
    "supports": [{"node": "ground", "fix": ["x"]}],
    "masses": [{"node": "mass", "mass": 1000}],
    "initial_velocities": [{"node": "mass", "x": 1}],
    "links": [{"id": "cable", "nodes": ["ground", "mass"], "axis": [1],
               "law": {"type": "restrainer", "stiffness": 1e6, "slack": 0.01,
                       "yield_force": 1e4}}],
    "analysis": {"time_step": 1e-4, "duration": 0.2}})");
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const std::string line = line_of(outcome.report, "restrainer cable:");
  EXPECT_TRUE(has(line, ", yielded: permanent elongation 0.045")) << line;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  const double elongation = summary["links"][0]["permanent_deformation"].get<double>();
  std::cout << line << "\npermanent elongation " << elongation << " m against 0.045, error "
            << std::abs(elongation - 0.045) << "\n";
  EXPECT_NEAR(elongation, 0.045, 1e-5);
  // Its ductility is its elongation beyond the slack over T_y / k (Caltrans SDC): 500 J of
  // kinetic energy stretch it 0.01 m elastically (50 J) and 0.045 m more at 10 kN (450 J,
  // dissipated), 5.5 x its yield elongation of 0.01 m (audit 70: there was no ductility).
  const nlohmann::json& cable = summary["links"][0];
  std::cout << "yield elongation " << cable["yield_elongation"] << " m, peak "
            << cable["peak_elongation"] << " m, ductility " << cable["ductility"]
            << ", hysteretic energy " << cable["hysteretic_energy"] << " J (450 J)\n";
  EXPECT_DOUBLE_EQ(cable["yield_elongation"].get<double>(), 0.01);
  EXPECT_NEAR(cable["peak_elongation"].get<double>(), 0.055, 1e-5);
  EXPECT_NEAR(cable["ductility"].get<double>(), 5.5, 1e-3);
  EXPECT_NEAR(cable["hysteretic_energy"].get<double>(), 450.0, 0.1);
  EXPECT_TRUE(has(line, "(ductility 5.50)")) << line;
}

// An impulse is force x time: in kg and cm the force is written out, kg*cm/s^2, and the impulse
// kg*cm/s (it said kg*cm/s^2*s).
TEST(RunReport, AnImpulseOfAWrittenOutForceIsMassLengthOverTime) {
  const RunOutcome outcome = run_text("wall.json", R"({
    "dimension": 1, "units": {"length": "cm", "time": "s", "mass": "kg"},
    "nodes": [{"id": "mass", "x": 0}, {"id": "wall", "x": 1}],
    "supports": [{"node": "wall", "fix": ["x"]}],
    "masses": [{"node": "mass", "mass": 1}],
    "initial_velocities": [{"node": "mass", "x": 10}],
    "links": [{"id": "contact", "nodes": ["mass", "wall"], "axis": [1], "gap": 1,
               "law": {"type": "gap_spring", "stiffness": 1e4}}],
    "analysis": {"time_step": 1e-3, "duration": 0.3}})");
  const std::string line = line_of(outcome.report, "contact contact:");
  EXPECT_TRUE(has(line, "peak force ") && has(line, " kg*cm/s^2, ")) << line;
  EXPECT_TRUE(line.ends_with(" kg*cm/s")) << line;  // 2 m v = 20 kg cm/s
}

// Without a mass unit forces, moments and energies have none, but lengths and accelerations do.
TEST(RunReport, WithoutAMassUnitForcesAreBareNumbers) {
  const std::string path =
      std::string(POUND_SOURCE_DIR) + "/models/adjacent_buildings_yielding.json";
  std::ifstream file(path);
  nlohmann::json model = nlohmann::json::parse(file);
  model["units"].erase("mass");
  const RunOutcome outcome = run_text(path, model.dump());
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const std::string storey = line_of(outcome.report, "storey pair.right.s2:");
  std::cout << storey << "\n";
  EXPECT_TRUE(has(storey, " m (") && has(storey, " m/s^2 (absolute), shear ")) << storey;
  EXPECT_FALSE(storey.ends_with(" N") || has(storey, "N*m")) << storey;
  EXPECT_TRUE(line_of(outcome.report, "energy: input ") != "") << outcome.report;
}

// The tests link the code `pound` runs: the bridge's summary from the binary and from a run in
// this process are the same to the bit (run time aside). Its response is chaotic after the first
// impacts, so any difference of rounding between the two would show: when the tests' -Og copies
// of Eigen's kernels stood in for the libraries', its kinetic energy at the end was 156.14 here
// against 157.61 from the binary.
class RunReportProcess : public testing::PoundProcess {};

TEST_F(RunReportProcess, TheBinaryAndTheLibrariesTestedComputeTheSameBits) {
  const std::string model = std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge.json";
  const testing::Outcome binary = pound({"run", model, "--out", path("out").string(), "--quiet"});
  ASSERT_EQ(binary.exit_code, 0) << binary.err;
  nlohmann::json from_binary =
      nlohmann::json::parse(testing::read_text(path("out") / "summary.json"));
  const RunOutcome outcome = run_bundled("three_span_bridge.json");
  nlohmann::json in_process = nlohmann::json::parse(outcome.summary.dump());
  from_binary.erase("run_time_s");
  in_process.erase("run_time_s");
  std::cout << fmt::format("kinetic energy at the end: binary {:.17g}, tests {:.17g}\n",
                           from_binary["energy"]["kinetic"].get<double>(),
                           in_process["energy"]["kinetic"].get<double>());
  // Entry by entry, so that a difference names where it is.
  const nlohmann::json binary_entries = from_binary.flatten(), tested = in_process.flatten();
  int unequal = 0;
  for (const auto& [where, value] : binary_entries.items())
    if (!tested.contains(where) || tested[where] != value)
      ADD_FAILURE() << where << ": binary " << value << ", tests "
                    << (tested.contains(where) ? tested[where].dump() : "none") << " (" << ++unequal
                    << ")";
  EXPECT_EQ(binary_entries.size(), tested.size());
}

}  // namespace
}  // namespace pound::app

namespace pound::app {
namespace {

// A contact that never engages is no pounding link, nor an elastic storey monitor's drift a
// pier's: the case names no link for a pounding force of 0 (it named the first contact), and the
// warning for a drift past a monitor's yield drift where the model does not yield speaks of the
// storey, not of a bridge's pier_hinge (audit 71).
TEST(RunReport, NothingThatDidNotHappenIsNamed) {
  nlohmann::json model = nlohmann::json::parse(
      std::ifstream(std::string(POUND_SOURCE_DIR) + "/models/two_sdof_girders.json"));
  model["links"][0]["gap"] = 10.0;
  model.erase("recorders");
  model["monitors"] = nlohmann::json::parse(
      R"({"drifts": [{"id": "column", "bottom": "ground_1", "top": "girder_1", "height": 5.0,
                      "yield_displacement": 1e-4, "yields": false}]})");
  for (nlohmann::json& excitation : model["excitations"])
    excitation["record"] =
        std::string(POUND_SOURCE_DIR) + "/models/" + excitation["record"].get<std::string>();
  const RunOutcome outcome = run_text("far_apart.json", model.dump());
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  EXPECT_EQ(*outcome.case_summary.max_pounding_force, 0.0);
  EXPECT_EQ(outcome.case_summary.max_pounding_link, "");
  const std::string warnings = outcome.summary.dump();
  std::cout << warnings.substr(warnings.find("\"warnings\"")) << "\n";
  EXPECT_NE(warnings.find("storey column: drift"), std::string::npos);
  EXPECT_EQ(warnings.find("pier_hinge"), std::string::npos);
}

}  // namespace
}  // namespace pound::app
