// A column on a plastic hinge that bends about both axes across it (a rotational link with a
// "shear", links/coupled_shear.hpp): under a record along the plan diagonal a circular column's
// hinge yields as one uniaxial hinge about the axis across the diagonal, at M_y (two uniaxial
// hinges about x and y would reach sqrt(2) M_y); a rectangular column's hinge (an ellipse, each
// axis its own k and M_y) under a record along x or y alone is that axis's uniaxial hinge. The
// girder_bridge generator makes each pier's base such a hinge in space, and its drift monitors
// take their curvature ductility from its bending about their own axis.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "app/model_loading.hpp"
#include "support/hinged_column.hpp"
#include "support/input_error.hpp"
#include "support/model_summary.hpp"

namespace pound::app {
namespace {

using nlohmann::json;

const std::string kPath = std::string(POUND_SOURCE_DIR) + "/models/column.json";
// A 8 m column of 1,000 t on a hinge ten times as stiff as the column (3 E I / h), yielding at
// about a third of its elastic demand.
constexpr double kHingeStiffness =
    10.0 * 3.0 * testing::kColumnYoungs * testing::kColumnInertia / testing::kColumnHeight;
constexpr double kYield = 8.0e6;

json bilinear(double stiffness, double yield_moment) {
  return {{"type", "bilinear_spring"}, {"stiffness", stiffness}, {"yield_force", yield_moment}};
}
json elastic(double stiffness) { return {{"type", "elastic_spring"}, {"stiffness", stiffness}}; }

// A rotational link from the hinge node to the fixed base, about `axis`.
json hinge(const std::string& id, std::array<double, 3> axis, json law) {
  return {{"id", id},
          {"nodes", {"hinge", "base"}},
          {"dof", "rotation"},
          {"axis", axis},
          {"law", std::move(law)}};
}

// The coupled hinge: its torsion (held anyway) and its bending about x (t_1) and y (t_2).
json coupled(json about_x, std::optional<json> about_y = std::nullopt) {
  json link = hinge("hinge", {0, 0, 1}, elastic(kHingeStiffness));
  link["shear"] = std::move(about_x);
  if (about_y) link["shear_2"] = std::move(*about_y);
  return link;
}

json column(const std::vector<json>& links, std::array<double, 3> direction) {
  return testing::hinged_column(links, direction);
}

const json& entry(const json& summary, const char* list, const std::string& id) {
  for (const json& item : summary[list])
    if (item["id"] == id) return item;
  throw std::runtime_error("no " + id);
}
double number(const json& item, const char* key) { return item[key].get<double>(); }

constexpr double kHalfRoot2 = 0.5 * std::numbers::sqrt2;

TEST(CoupledHinge, ACircularColumnUnderADiagonalRecordYieldsAsOneHingeAcrossTheDiagonal) {
  const std::array<double, 3> diagonal{kHalfRoot2, kHalfRoot2, 0.0};
  const json summary = testing::model_summary(
      column({coupled(bilinear(kHingeStiffness, kYield))}, diagonal).dump(), kPath);
  const json& shear = entry(summary, "links", "hinge")["shear"];
  // The reference: a hinge about (-1, 1, 0) / sqrt(2), across the diagonal, and an elastic one
  // about the diagonal, which never turns.
  const json reference = testing::model_summary(
      column({hinge("across", {-kHalfRoot2, kHalfRoot2, 0.0}, bilinear(kHingeStiffness, kYield)),
              hinge("about", {kHalfRoot2, kHalfRoot2, 0.0}, elastic(kHingeStiffness))},
             diagonal)
          .dump(),
      kPath);
  const json& across = entry(reference, "links", "across");
  const double rotation_error =
      std::abs(number(shear, "peak_deformation") / number(across, "peak_deformation") - 1.0);
  const double energy_error =
      std::abs(number(shear, "hysteretic_energy") / number(across, "hysteretic_energy") - 1.0);
  const json uncoupled =
      testing::model_summary(column({hinge("x", {1, 0, 0}, bilinear(kHingeStiffness, kYield)),
                                     hinge("y", {0, 1, 0}, bilinear(kHingeStiffness, kYield))},
                                    diagonal)
                                 .dump(),
                             kPath);
  const double pair = std::hypot(number(entry(uncoupled, "links", "x"), "peak_force"),
                                 number(entry(uncoupled, "links", "y"), "peak_force"));
  const double rotation_ratio = number(shear, "peak_deformation") * kHingeStiffness / kYield;
  std::cout << fmt::format(
      "circular column, diagonal record, hinge rotation {:.2f} x yield: coupled against one hinge "
      "across the diagonal: peak rotation {:.1e}, hysteretic energy {:.1e}; peak moment / M_y "
      "coupled {:.12f}, two uniaxial hinges {:.6f}\n",
      rotation_ratio, rotation_error, energy_error, number(shear, "peak_force") / kYield,
      pair / kYield);
  EXPECT_GT(rotation_ratio, 2.0) << "the hinge must yield well";
  EXPECT_FALSE(shear.contains("ductility")) << "a hinge's rotation is no member ductility";
  EXPECT_LT(rotation_error, 1e-9);
  EXPECT_LT(energy_error, 1e-9);
  EXPECT_NEAR(number(shear, "peak_force") / kYield, 1.0, 1e-12);
  EXPECT_NEAR(pair / kYield, std::numbers::sqrt2, 1e-9);
  EXPECT_LT(number(summary["energy"], "balance_error"), 1e-9);
}

// A rectangular column's hinge: about y (bending along x) three times as stiff and twice as strong
// as about x. A record along x bends it about y alone: the uniaxial hinge with y's numbers; along
// y, about x with x's.
TEST(CoupledHinge, ARectangularColumnAlongEachAxisIsThatAxissUniaxialHinge) {
  const json about_x = bilinear(kHingeStiffness, kYield);
  const json about_y = bilinear(3.0 * kHingeStiffness, 2.0 * kYield);
  double worst = 0.0;
  for (const auto& [direction, axis, law] :
       {std::tuple{std::array<double, 3>{1, 0, 0}, std::array<double, 3>{0, 1, 0}, about_y},
        {std::array<double, 3>{0, 1, 0}, std::array<double, 3>{1, 0, 0}, about_x}}) {
    const json summary =
        testing::model_summary(column({coupled(about_x, about_y)}, direction).dump(), kPath);
    const json& shear = entry(summary, "links", "hinge")["shear"];
    const json reference =
        testing::model_summary(column({hinge("bend", axis, law)}, direction).dump(), kPath);
    const json& bend = entry(reference, "links", "bend");
    const std::size_t about = axis[0] == 1.0 ? 0 : 1;  // t_1 = x, t_2 = y
    const double plastic = shear["peak_plastic_deformations"][about].get<double>();
    const double error = std::max(
        std::abs(number(shear, "peak_deformation") / number(bend, "peak_deformation") - 1.0),
        std::abs(plastic / number(bend, "peak_plastic_deformation") - 1.0));
    std::cout << fmt::format(
        "rectangular column, record along ({:g}, {:g}): coupled against the uniaxial hinge about "
        "({:g}, {:g}): peak rotation and plastic rotation {:.1e} (plastic {:.3e} rad)\n",
        direction[0], direction[1], axis[0], axis[1], error, plastic);
    EXPECT_GT(plastic, 0.5 * number(law, "yield_force") / number(law, "stiffness"));
    EXPECT_EQ(shear["peak_plastic_deformations"][1 - about].get<double>(), 0.0);
    EXPECT_EQ(shear["yield_deformations"].size(), 2u);
    worst = std::max(worst, error);
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(CoupledHinge, BadHingesAreRefusedAtTheirPath) {
  const auto refused = [&](json link, const std::string& where, const std::string& phrase,
                           int dimension = 3) {
    json model = column({std::move(link)}, {1, 0, 0});
    model["dimension"] = dimension;
    testing::expect_input_error([&] { load_model_text(model.dump(), kPath); }, where, phrase);
  };
  json other_type = coupled(bilinear(kHingeStiffness, kYield), elastic(kHingeStiffness));
  refused(other_type, "/links/0/shear_2/type", "takes the first's law");
  json hardening = coupled(bilinear(kHingeStiffness, kYield), bilinear(kHingeStiffness, kYield));
  hardening["shear_2"]["hardening_ratio"] = 0.05;
  refused(hardening, "/links/0/shear_2", "one ratio");
  json alone = hinge("hinge", {0, 0, 1}, elastic(kHingeStiffness));
  alone["shear_2"] = bilinear(kHingeStiffness, kYield);
  refused(alone, "/links/0/shear_2", "give `shear` too");
}

// girder_bridge in space: one hinge `<pier>.hinge` per pier base bending about x (across the
// bridge, E I_lateral, M_y lateral) and y (along it), unless "none" is asked for; the drift
// monitors along and across the bridge take theta_p about y and about x.
TEST(CoupledHinge, TheBridgeGeneratorCouplesItsPierHingesInSpace) {
  std::ifstream file(std::string(POUND_SOURCE_DIR) + "/models/skewed_bridge_3d.json");
  json model = json::parse(file);
  json& bridge = model["generators"][0];
  bridge.erase("pier_yield_displacement");
  bridge["pier_hinge"] = {{"yield_curvature", 0.004},
                          {"yield_curvature_lateral", 0.003},
                          {"plastic_hinge_length", 0.6},
                          {"law", {{"type", "bilinear_spring"}, {"hardening_ratio", 0.02}}}};
  const LoadedModel loaded = load_model_text(model.dump(), kPath);
  const model::Link& link = loaded.built.model.links[loaded.built.link_index.at("bridge.p1.hinge")];
  ASSERT_TRUE(link.shear);
  EXPECT_TRUE(link.rotational);
  const double e = 3.0e10;  // the pier's, with I 0.8 along the bridge and 1.2 across
  EXPECT_DOUBLE_EQ(link.shear->numbers[0].yield_force, e * 1.2 * 0.003);  // about x: across
  EXPECT_DOUBLE_EQ(link.shear->numbers[1].yield_force, e * 0.8 * 0.004);  // about y: along
  EXPECT_FALSE(loaded.built.link_index.contains("bridge.p1.hinge.across"));
  int directions = 0;
  for (const builder::DriftMonitor& monitor : loaded.built.drift_monitors)
    if (monitor.curvature) directions += monitor.curvature->hinge_direction;
  EXPECT_EQ(directions, 2 * 3);  // each pier: 2 along, 1 across
  bridge["pier_hinge"]["interaction"] = "none";
  const LoadedModel none = load_model_text(model.dump(), kPath);
  EXPECT_TRUE(none.built.link_index.contains("bridge.p1.hinge.across"));
  bridge["pier_hinge"]["interaction"] = "elliptic";
  bridge["pier_hinge"]["damping"] = "initial";  // the hinge's bending damped with the model's a1
  const LoadedModel damped = load_model_text(model.dump(), kPath);
  const model::Link& damped_hinge =
      damped.built.model.links[damped.built.link_index.at("bridge.p1.hinge")];
  ASSERT_TRUE(damped_hinge.shear && damped_hinge.shear->damping);
  EXPECT_GT(damped_hinge.shear->damping->stiffness_coefficient, 0.0);
  bridge["pier_hinge"].erase("damping");
  // A Bouc-Wen hinge yields at the section's M_y too: its beta and gamma give the loop's shape.
  bridge["pier_hinge"]["law"] = {
      {"type", "bouc_wen"}, {"sharpness", 2.0}, {"beta", 1.0}, {"gamma", 1.0}};
  const LoadedModel smooth = load_model_text(model.dump(), kPath);
  const model::Link& smooth_hinge =
      smooth.built.model.links[smooth.built.link_index.at("bridge.p1.hinge")];
  ASSERT_TRUE(smooth_hinge.shear && smooth_hinge.shear->numbers[0].smooth);
  EXPECT_NEAR(smooth_hinge.shear->numbers[0].yield_force / (e * 1.2 * 0.003), 1.0, 1e-14);
  EXPECT_NEAR(smooth_hinge.shear->numbers[1].yield_force / (e * 0.8 * 0.004), 1.0, 1e-14);
  bridge["pier_hinge"]["interaction"] = "none";
  const LoadedModel smooth_none = load_model_text(model.dump(), kPath);
  const model::Link& along =
      smooth_none.built.model.links[smooth_none.built.link_index.at("bridge.p1.hinge")];
  const double rotation = *along.make_law({})->yield_deformation();
  EXPECT_NEAR(rotation * along.make_law({})->set_trial({}).stiffness / (e * 0.8 * 0.004), 1.0,
              1e-14);
  bridge["pier_hinge"]["interaction"] = "elliptic";
  bridge["pier_hinge"]["law"] = {
      {"type", "takeda"}, {"hardening_ratio", 0.03}, {"unloading_exponent", 0.4}};
  testing::expect_input_error([&] { load_model_text(model.dump(), kPath); },
                              "/generators/0/pier_hinge/interaction", "no coupled form");
}

}  // namespace
}  // namespace pound::app
