// `pound pushover`: the capacity curve of the bundled hinged bridge, written with its summary;
// bad requests, and models with hard contacts, are refused before anything is written.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "support/hinged_column.hpp"
#include "support/process.hpp"

namespace pound::testing {
namespace {

class PushoverCommand : public PoundProcess {};

const std::string kModel = std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_takeda.json";

TEST_F(PushoverCommand, WritesTheCapacityCurveAndFindsTheFirstYield) {
  const Outcome outcome = pound({"pushover", kModel, "--node", "bridge.p1.top", "--to", "0.02",
                                 "--increments", "50", "--out", path("out").string()});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::cout << outcome.out;
  const std::string csv = read_text(path("out") / "pushover.csv");
  // Each column with its unit, as every run CSV has.
  EXPECT_TRUE(contains(csv,
                       "displacement [m],base_shear [N],iterations,bridge.p1.hinge.deformation "
                       "[rad],"))
      << csv.substr(0, 200);
  const std::string summary = read_text(path("out") / "pushover.json");
  EXPECT_TRUE(contains(summary, "\"status\": \"completed\""));
  // Its numbers name their units, in the console and in pushover.json, as summary.json does.
  EXPECT_TRUE(contains(outcome.out, " N/m, final slope ") &&
              contains(outcome.out, " m, base shear ") &&
              contains(outcome.out, " N at displacement "))
      << outcome.out;
  const nlohmann::json units = nlohmann::json::parse(summary)["units"];
  EXPECT_EQ(units["force"], "N");
  EXPECT_EQ(units["length"], "m");
  // The pier yields near its top displacement M_y h^2 / (3 E I) = 3.556 mm (the deck on its
  // bearings takes a little of the pier's bending), found between the 0.4 mm increments as a push
  // in 20,000 increments finds it.
  EXPECT_TRUE(contains(summary, "\"link\": \"bridge.p1.hinge\"")) << summary;
  const double found = nlohmann::json::parse(summary)["first_yield"]["displacement"].get<double>();
  const nlohmann::json fine =
      nlohmann::json::parse(pound({"pushover", kModel, "--node", "bridge.p1.top", "--to", "0.02",
                                   "--increments", "20000", "--json"})
                                .out);
  const double finely = fine["first_yield"]["displacement"].get<double>();
  const double cantilever = 4.0e6 * 64.0 / (3.0 * 3.0e10 * 0.8);
  std::cout << "first yield at " << found << " m, " << finely << " m with 1 um increments, "
            << cantilever << " m for the pier alone\n";
  EXPECT_NEAR(found, finely, 1e-9 * finely);
  EXPECT_NEAR(found, cantilever, 2e-3 * cantilever);
}

// A cantilever on a bilinear base hinge under its weight W with chord P-Delta, pushed to 0.8 m in
// the default 100 increments (8 mm, more than twice its yield displacement) and in one: the
// initial stiffness 3 E I / h^3 - W / h, the first yield at M_y h^2 / (3 E I) with base shear
// (3 E I / h^3 - W / h) times it, to round-off, as with fine increments (read at the increments'
// ends they were 46 % low and at 8 mm); without hardening the curve softens from the first
// yield, which is then its peak. Pushed down, it reaches the target from the gravity state.
TEST_F(PushoverCommand, TheSummaryIsExactBetweenCoarseIncrements) {
  constexpr double ei = 3.0e10 * 0.88, h = 8.0, weight = 1.0e6 * 9.80665, m_y = 4.0e6;
  const auto column = [&](double hardening) {
    nlohmann::json model = {
        {"dimension", 2},
        {"nodes",
         {{{"id", "base"}, {"x", 0}, {"y", 0}},
          {{"id", "hinge"}, {"x", 0}, {"y", 0}},
          {{"id", "top"}, {"x", 0}, {"y", h}}}},
        {"materials", {{{"id", "c"}, {"youngs_modulus", 3.0e10}, {"density", 0}}}},
        {"elements",
         {{{"id", "pier"},
           {"type", "beam"},
           {"nodes", {"hinge", "top"}},
           {"material", "c"},
           {"area", 3.0},
           {"inertia", 0.88}}}},
        {"masses", {{{"node", "top"}, {"mass", 1.0e6}}}},
        {"supports",
         {{{"node", "base"}, {"fix", {"x", "y", "rz"}}}, {{"node", "hinge"}, {"fix", {"x", "y"}}}}},
        {"links",
         {{{"id", "hinge"},
           {"nodes", {"hinge", "base"}},
           {"dof", "rotation"},
           {"law",
            {{"type", "bilinear_spring"},
             {"stiffness", 9.9e10},
             {"yield_force", m_y},
             {"hardening_ratio", hardening}}}}}},
        {"gravity", {{"p_delta", "chord"}}},
        {"analysis", {{"time_step", 0.005}, {"duration", 1.0}}}};
    std::ofstream(path("column.json")) << model.dump();
    return path("column.json").string();
  };
  // The series of the hinge and the beam: 1 / (h^2 / k_h + h^3 / (3 E I)).
  const double elastic = 1.0 / (h * h / 9.9e10 + h * h * h / (3 * ei));
  const double stiffness = elastic - weight / h, yield = m_y / (elastic * h);
  for (const char* increments : {"100", "1"}) {
    const Outcome outcome = pound({"pushover", column(0.01), "--node", "top", "--to", "0.8",
                                   "--increments", increments, "--json"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const nlohmann::json summary = nlohmann::json::parse(outcome.out);
    const double k0 = summary["initial_stiffness"].get<double>();
    const double at = summary["first_yield"]["displacement"].get<double>();
    const double shear = summary["first_yield"]["base_shear"].get<double>();
    std::cout << increments << " increment(s): initial stiffness " << k0 << " against " << stiffness
              << ", first yield at " << at << " against " << yield << ", base shear " << shear
              << " against " << stiffness * yield << "\n";
    EXPECT_NEAR(k0, stiffness, 1e-9 * stiffness);
    EXPECT_NEAR(at, yield, 1e-9 * yield);
    EXPECT_NEAR(shear, stiffness * yield, 1e-9 * stiffness * yield);
  }
  const nlohmann::json softening = nlohmann::json::parse(
      pound({"pushover", column(0.0), "--node", "top", "--to", "0.5", "--json"}).out);
  EXPECT_NEAR(softening["peak_base_shear"].get<double>(), stiffness * yield,
              1e-9 * stiffness * yield);
  EXPECT_LT(softening["final_slope"].get<double>(), 0.0);
  const nlohmann::json down =
      nlohmann::json::parse(pound({"pushover", column(0.01), "--node", "top", "--to", "-0.001",
                                   "--direction", "y", "--json"})
                                .out);
  EXPECT_NEAR(down["reached"].get<double>(), -0.001, 1e-12);
}

// A column on a biaxial hinge (a rotational link with a coupled shear, M_y 8 MN m) pushed along x
// at its 8 m top: the hinge's two bending directions are recorded, and it yields when its
// moment about y reaches M_y, at a base shear of M_y / h = 1 MN and the top displacement
// V_y (h^2 / k_h + h^3 / (3 E I)) = 0.1252 m, found between the 1 mm increments.
TEST_F(PushoverCommand, FindsTheFirstYieldOfABiaxialHinge) {
  const double height = kColumnHeight, youngs = kColumnYoungs, inertia = kColumnInertia;
  const double yield = 8.0e6, hinge_stiffness = 10.0 * 3.0 * youngs * inertia / height;
  const nlohmann::json law = {
      {"type", "bilinear_spring"}, {"stiffness", hinge_stiffness}, {"yield_force", yield}};
  const nlohmann::json model =
      hinged_column({{{"id", "hinge"},
                      {"nodes", {"hinge", "base"}},
                      {"dof", "rotation"},
                      {"axis", {0, 0, 1}},
                      {"law", {{"type", "elastic_spring"}, {"stiffness", hinge_stiffness}}},
                      {"shear", law}}},
                    {1.0, 0.0, 0.0});
  std::ofstream(path("column.json")) << model.dump(2);
  const Outcome outcome =
      pound({"pushover", path("column.json").string(), "--node", "top", "--to", "0.2",
             "--increments", "200", "--out", path("out").string(), "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const std::string csv = read_text(path("out") / "pushover.csv");
  EXPECT_TRUE(contains(csv, "hinge.deformation_1 [rad],hinge.deformation_2 [rad]"))
      << csv.substr(0, 200);
  const nlohmann::json summary = nlohmann::json::parse(read_text(path("out") / "pushover.json"));
  const nlohmann::json& first = summary["first_yield"];
  const double shear = yield / height;
  const double displacement = shear * (height * height / hinge_stiffness +
                                       height * height * height / (3 * youngs * inertia));
  std::cout << fmt::format(
      "biaxial hinge pushed along x: first yield at {:.4f} m (closed form {:.4f} m, 1 mm steps), "
      "base shear {:.6e} against M_y / h {:.6e}\n",
      first["displacement"].get<double>(), displacement, first["base_shear"].get<double>(), shear);
  EXPECT_EQ(first["link"], "hinge");
  EXPECT_NEAR(first["displacement"].get<double>(), displacement, 1e-9 * displacement);
  EXPECT_NEAR(first["base_shear"].get<double>() / shear, 1.0, 1e-6);
}

// The bundled 3-D bridge unskewed, its deck curved in plan (R 150 m, and 1e7 m: straight but for
// 1e-5 rad), with gravity. A curved bridge's far backwall is held across its turned tangent by
// a guide link, and along it by its backfill, open at rest: a direction no support or link
// holds, not one of the node's axes, so the static tangent was singular and neither the gravity
// state nor the push could start. Now the DOFs only links hold get the 1e-12 spring a DOF with
// no stiffness gets (only where the tangent does not factor without it): the R 1e7 m bridge
// gives the straight bridge's curve (whose backwall slides on supports) to second order in its
// 1e-5 rad turn.
TEST_F(PushoverCommand, ACurvedBridgeStandsUnderGravityAndIsPushed) {
  std::ifstream file(std::string(POUND_SOURCE_DIR) + "/models/skewed_bridge_3d.json");
  nlohmann::json model = nlohmann::json::parse(file);
  model["generators"][0]["skew"] = 0.0;
  model["gravity"] = nlohmann::json::object();
  for (nlohmann::json& excitation : model["excitations"]) {
    excitation["record"] = std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_firm_01.AT2";
    excitation["pair"]["record"] =
        std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_soft_01.AT2";
  }
  const auto push = [&](const std::string& name, std::optional<double> radius) {
    if (radius) model["generators"][0]["plan_radius"] = *radius;
    std::ofstream(path(name + ".json")) << model.dump(2);
    const Outcome outcome =
        pound({"pushover", path(name + ".json").string(), "--node", "bridge.g1.n2", "--to", "0.1",
               "--increments", "50", "--out", path(name).string(), "--json"});
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return nlohmann::json::parse(read_text(path(name) / "pushover.json"));
  };
  const nlohmann::json straight = push("straight", std::nullopt);
  const nlohmann::json nearly = push("nearly", 1e7);
  const nlohmann::json curved = push("curved", 150.0);
  const auto relative = [&](const std::string& key) {
    return std::abs(nearly[key].get<double>() / straight[key].get<double>() - 1.0);
  };
  std::cout << fmt::format(
      "3-D bridge under gravity pushed 0.1 m: R 1e7 m against straight: initial stiffness "
      "{:.1e}, peak base shear {:.1e}; R 150 m: {} (peak base shear {:.4g})\n",
      relative("initial_stiffness"), relative("peak_base_shear"),
      curved["status"].get<std::string>(), curved["peak_base_shear"].get<double>());
  EXPECT_EQ(nearly["status"], "completed");
  EXPECT_EQ(curved["status"], "completed");
  EXPECT_LT(relative("initial_stiffness"), 1e-8);
  EXPECT_LT(relative("peak_base_shear"), 1e-8);
}

TEST_F(PushoverCommand, BadRequestsAreRefusedAndNothingIsWritten) {
  const auto run = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> arguments{"pushover", kModel, "--out", path("out").string()};
    arguments.insert(arguments.end(), extra.begin(), extra.end());
    return pound(arguments);
  };
  Outcome outcome = run({"--node", "no_such_node", "--to", "0.01"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err, "--node")) << outcome.err;
  outcome = run({"--node", "bridge.p1.base", "--to", "0.01"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err, "fixed along x")) << outcome.err;
  outcome = run({"--node", "bridge.p1.top", "--to", "0"});
  EXPECT_EQ(outcome.exit_code, 1);
  outcome = run({"--node", "bridge.p1.top", "--to", "0.01", "--pattern", "wavy"});
  EXPECT_EQ(outcome.exit_code, 1);
  // A target the model cannot resolve (its loads underflowed at 1e-320: "initial stiffness 0").
  outcome = run({"--node", "bridge.p1.top", "--to", "1e-320"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err, "--to: 9.99989e-321 is below what the model resolves"))
      << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

// A hard contact has no force law for the push's Newton: the bundled hard-contact bridge was
// pushed 0.3 m through its joints (peak base shear 3.1 MN against 15.1 MN with its gap springs).
// Refused with the file, the link's entry and a way out, and nothing written.
TEST_F(PushoverCommand, AModelWithHardContactsIsRefusedNamingTheLink) {
  const Outcome outcome = pound(
      {"pushover", std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge_hard_contact.json",
       "--node", "bridge.g1.n2", "--to", "0.3", "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_TRUE(contains(outcome.err,
                       "three_span_bridge_hard_contact.json: /generators/0: link "
                       "'bridge.joint1' is a hard_contact"))
      << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

// A mass that nothing holds as the push starts: Newton, which holds such a DOF by a 1e-12 spring,
// throws it off before a link can hold it. The push stops at once, exit 3 with the curve up to
// there, naming the mass and what to do. Here a block that only a slack restrainer ties to the
// girder: it belongs to the girder's structure, a mass pattern loads it, and pushed toward the
// girder nothing holds it. Tied by a contact alone, it is a body of its own, which the girder's
// mass pattern does not load. (The bundled bridges' backwalls, on their backfill, are such.)
constexpr const char* kFreeBlock = R"({
  "dimension": 1,
  "nodes": [{"id": "ground", "x": 0}, {"id": "girder", "x": 1}, {"id": "block", "x": 2}],
  "materials": [{"id": "pier", "youngs_modulus": 1e7, "density": 0}],
  "elements": [{"id": "pier", "type": "truss", "nodes": ["ground", "girder"], "material": "pier",
                "area": 1}],
  "masses": [{"node": "girder", "mass": 1000}, {"node": "block", "mass": 100}],
  "supports": [{"node": "ground", "fix": ["x"]}],
  "links": [{"id": "tie", "nodes": ["girder", "block"], "axis": [1],
             "law": {"type": "restrainer", "stiffness": 1e8, "slack": 0.05}}],
  "analysis": {"time_step": 0.01, "duration": 1}})";

TEST_F(PushoverCommand, AMassThatNothingHoldsIsNamedWhenThePushStops) {
  const std::string model = path("free_block.json").string();
  std::ofstream(model) << kFreeBlock;
  const Outcome outcome = pound({"pushover", model, "--node", "girder", "--to", "-0.04",
                                 "--pattern", "mass", "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 3);
  std::cout << outcome.err;
  EXPECT_TRUE(contains(outcome.err,
                       "The pattern loads node 'block', direction x, which nothing held as the "
                       "increment started"))
      << outcome.err;
  EXPECT_TRUE(contains(outcome.err, "Push with the point pattern, or restrain it"));
  EXPECT_TRUE(std::filesystem::exists(path("out") / "pushover.csv"));
  // The point pattern loads the girder alone: the same push reaches its target.
  const Outcome point = pound(
      {"pushover", model, "--node", "girder", "--to", "-0.04", "--out", path("point").string()});
  EXPECT_EQ(point.exit_code, 0) << point.err;
  // Against the girder through a contact only, the block is not the girder's structure.
  std::string apart = kFreeBlock;
  apart.replace(
      apart.find(R"("law": {"type": "restrainer", "stiffness": 1e8, "slack": 0.05})"),
      std::string(R"("law": {"type": "restrainer", "stiffness": 1e8, "slack": 0.05})").size(),
      R"("gap": 0.05, "law": {"type": "gap_spring", "stiffness": 1e8})");
  std::ofstream(path("apart.json")) << apart;
  const Outcome contact = pound({"pushover", path("apart.json").string(), "--node", "girder",
                                 "--to", "0.04", "--pattern", "mass", "--json"});
  EXPECT_EQ(contact.exit_code, 0) << contact.err;
}

// The bundled bridges' backwalls are held toward the span by the abutment's stem: a mass pattern
// now pushes the whole bridge to its target.
TEST_F(PushoverCommand, TheBundledBridgesTakeAMassPattern) {
  for (const char* bridge : {"three_span_bridge.json", "three_span_bridge_takeda.json"}) {
    const Outcome outcome = pound({"pushover", std::string(POUND_SOURCE_DIR) + "/models/" + bridge,
                                   "--node", "bridge.p1.top", "--to", "0.04", "--pattern", "mass",
                                   "--out", path(bridge).string()});
    EXPECT_EQ(outcome.exit_code, 0) << bridge << ": " << outcome.err;
  }
}

// A three-storey shear building beside a one-storey neighbour 10 m away (an open gap), pushed at
// its roof by its masses or a triangle: the pattern loads the pushed building alone. Elastic,
// its mass pattern's initial stiffness is 1 / sum_i s_i / k_i with s_i the share of the
// building's mass above storey i (1, 0.6, 0.267), 1.7143e8; and the curve does not change when
// the neighbour's mass does. The neighbour's share of the pattern made the base shear 1.4x (mass)
// and 1.2x (triangle) the building's (audit 71).
TEST_F(PushoverCommand, AMassPatternLoadsThePushedBuildingOnly) {
  const auto model = [&](double neighbour_mass) {
    const std::string text = fmt::format(
        R"({{"dimension": 2, "units": {{"length": "m", "time": "s", "mass": "kg"}},
  "generators": [{{"type": "adjacent_buildings", "id": "pair", "separation": 10.0,
    "left": {{"damping_ratio": 0.05, "storeys": [
      {{"height": 3.2, "mass": 300000.0, "stiffness": 4e8,
        "law": {{"type": "bilinear_spring", "yield_force": 3e6, "hardening_ratio": 0.05}}}},
      {{"height": 3.5, "mass": 250000.0, "stiffness": 3e8,
        "law": {{"type": "bilinear_spring", "yield_force": 2e6, "hardening_ratio": 0.05}}}},
      {{"height": 3.0, "mass": 200000.0, "stiffness": 2e8,
        "law": {{"type": "bilinear_spring", "yield_force": 1.2e6, "hardening_ratio": 0.05}}}}]}},
    "right": {{"damping_ratio": 0.05, "storeys": [
      {{"height": 3.2, "mass": {}, "stiffness": 4e8}}]}},
    "law": {{"type": "gap_spring", "stiffness": 1e9}}}}],
  "excitations": [{{"record": "{}/ground_motions/synthetic_firm_01.AT2"}}],
  "analysis": {{"time_step": 0.005, "duration": 12}}}})",
        neighbour_mass, POUND_SOURCE_DIR);
    const std::string file = path(fmt::format("pair_{:g}.json", neighbour_mass)).string();
    std::ofstream(file) << text;
    return file;
  };
  const double elastic = 1.0 / (1.0 / 4e8 + 0.6 / 3e8 + (2.0 / 7.5) / 2e8);
  for (const char* pattern : {"mass", "triangular"}) {
    std::optional<nlohmann::json> first;
    for (const double neighbour : {3e5, 3e6}) {
      const Outcome outcome =
          pound({"pushover", model(neighbour), "--node", "pair.left.f3", "--to", "0.15",
                 "--pattern", pattern, "--increments", "300", "--json"});
      ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
      const nlohmann::json result = nlohmann::json::parse(outcome.out);
      std::cout << pattern << ", neighbour " << neighbour << " kg: initial stiffness "
                << result["initial_stiffness"] << ", base shear at 0.15 m "
                << result["peak_base_shear"] << "\n";
      if (std::string(pattern) == "mass") {
        EXPECT_NEAR(result["initial_stiffness"].get<double>() / elastic, 1.0, 1e-9);
      }
      if (!first) {
        first = result;
        continue;
      }
      EXPECT_EQ(result["initial_stiffness"], (*first)["initial_stiffness"]) << pattern;
      EXPECT_EQ(result["peak_base_shear"], (*first)["peak_base_shear"]) << pattern;
    }
  }
}

// A one-storey building on an elastic-perfectly-plastic storey (F_y = 2e6 N, h = 3.2 m) carrying
// its floor's weight W = 3e5 kg x g with chord P-Delta: past the yield its base shear is
// F_y - W d / h, zero at d = F_y h / W = 2.1754 m, where it has no lateral strength left. The
// push went on to 3 m and a negative base shear, exit 0, saying nothing (audit 71); it now gives
// that displacement, to round-off of the closed form (the branch is straight between
// increments), and says it is a collapse.
TEST_F(PushoverCommand, AStrengthLostToPDeltaIsFoundWhereTheBaseShearIsZero) {
  const std::string model = path("epp.json").string();
  std::ofstream(model) << fmt::format(
      R"({{"dimension": 2, "units": {{"length": "m", "time": "s", "mass": "kg"}},
  "generators": [{{"type": "adjacent_buildings", "id": "pair", "separation": 10.0,
    "left": {{"damping_ratio": 0.0, "storeys": [{{"height": 3.2, "mass": 3e5, "stiffness": 4e8,
      "law": {{"type": "elastic_perfectly_plastic", "yield_force": 2e6}}}}]}},
    "right": {{"damping_ratio": 0.0, "storeys": [{{"height": 3.2, "mass": 3e5, "stiffness": 4e8}}]}},
    "law": {{"type": "gap_spring", "stiffness": 1e9}}}}],
  "gravity": {{"p_delta": "chord"}},
  "excitations": [{{"record": "{}/ground_motions/synthetic_firm_01.AT2"}}],
  "analysis": {{"time_step": 0.005, "duration": 12}}}})",
      POUND_SOURCE_DIR);
  const Outcome outcome =
      pound({"pushover", model, "--node", "pair.left.f1", "--to", "3", "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const nlohmann::json result = nlohmann::json::parse(outcome.out);
  const double exact = 2e6 * 3.2 / (3e5 * 9.80665);
  const double found = result["zero_shear_displacement"].get<double>();
  std::cout << "zero base shear at " << found << " m, F_y h / W = " << exact << " m\n";
  EXPECT_NEAR(found, exact, 1e-12 * exact);
  const Outcome text = pound(
      {"pushover", model, "--node", "pair.left.f1", "--to", "3", "--out", path("out").string()});
  EXPECT_TRUE(contains(text.out, "the base shear falls to zero at displacement 2.17539"))
      << text.out;
  EXPECT_TRUE(contains(text.out, "a collapse")) << text.out;
  // Pushed short of it, there is none.
  const Outcome short_of =
      pound({"pushover", model, "--node", "pair.left.f1", "--to", "2", "--json"});
  EXPECT_FALSE(nlohmann::json::parse(short_of.out).contains("zero_shear_displacement"));
}

// A 1-D model's DOF map has x only: --direction y read the next node's x (wrong numbers) or, at
// the last node, past the map's end (a crash).
TEST_F(PushoverCommand, AOneDimensionalModelIsPushedAlongXOnly) {
  const std::string model = std::string(POUND_SOURCE_DIR) + "/models/two_sdof_girders.json";
  for (const char* node : {"girder_1", "ground_2"}) {
    const Outcome outcome = pound({"pushover", model, "--node", node, "--to", "0.05", "--direction",
                                   "y", "--out", path("out").string()});
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_TRUE(contains(outcome.err, "--direction: the model is 1-D: its nodes move along x only"))
        << outcome.err;
  }
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

}  // namespace
}  // namespace pound::testing
