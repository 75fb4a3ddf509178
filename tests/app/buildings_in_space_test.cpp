// adjacent_buildings in a 3-D scene (issue 18): rigid floors with three DOFs at their mass
// centres, storey columns at the stiffness centres. Without eccentricity, with one pounding point
// per contact height and the record along x, the pair moves as the plane pair (elastic with
// mid-storey contacts, yielding with gravity and P-Delta); an eccentric storey's modes are the
// closed form's; mirrored eccentricities give the mirrored motion; the summary's corner drifts
// and twists are the floors' motion; bad plan input is refused where it stands.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/model_loading.hpp"
#include "app/model_run.hpp"
#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "support/input_error.hpp"
#include "support/model_summary.hpp"
#include "support/node_motion.hpp"

namespace pound::builder {
namespace {

using Json = nlohmann::json;

const std::string kModels = std::string(POUND_SOURCE_DIR) + "/models/";

Json bundled(const std::string& name) {
  std::ifstream file(kModels + name);
  Json model = Json::parse(file);
  model.erase("recorders");
  return model;
}

// The same pair in space: plans side by side along x, the record along x.
Json in_space(Json model, int contact_points) {
  model["dimension"] = 3;
  Json& pair = model["generators"][0];
  pair["left"]["plan"] = {12.0, 10.0};
  pair["right"]["plan"] = {15.0, 10.0};
  pair["contact_points"] = contact_points;
  for (Json& excitation : model["excitations"]) excitation["direction"] = {1.0, 0.0, 0.0};
  if (model.contains("gravity")) model["gravity"].erase("direction");
  return model;
}

BuiltModel build(const Json& model) {
  return app::load_model_text(model.dump(), kModels + "buildings.json").built;
}

std::vector<std::string> floors(const Json& model) {
  std::vector<std::string> ids;
  for (const char* side : {"left", "right"})
    for (std::size_t f = 1; f <= model["generators"][0][side]["storeys"].size(); ++f)
      ids.push_back(fmt::format("pair.{}.f{}", side, f));
  return ids;
}

// Largest |difference| of the floors' x over the largest |x|, and the largest |y| or |theta_z|.
std::array<double, 3> against_plane(const Json& plane_model) {
  const Json space_model = in_space(plane_model, 1);
  const std::vector<std::string> ids = floors(plane_model);
  const testing::NodeMotion plane = testing::run_node_motion(build(plane_model), ids, {0});
  const testing::NodeMotion space = testing::run_node_motion(build(space_model), ids, {0, 1, 5});
  EXPECT_EQ(plane.time.size(), space.time.size());
  double largest = 0.0, difference = 0.0, out_of_plane = 0.0;
  for (std::size_t k = 0; k < std::min(plane.time.size(), space.time.size()); ++k)
    for (std::size_t n = 0; n < ids.size(); ++n) {
      largest = std::max(largest, std::abs(plane.values[k][n]));
      difference = std::max(difference, std::abs(space.values[k][3 * n] - plane.values[k][n]));
      out_of_plane = std::max({out_of_plane, std::abs(space.values[k][3 * n + 1]),
                               std::abs(space.values[k][3 * n + 2])});
    }
  return {difference / largest, largest, out_of_plane};
}

// The whole record, pounding included: the DOFs are numbered otherwise, so the sums are taken
// in another order, and the impacts amplify those rounding differences (to ~5e-12 of the
// largest displacement here; the bridge's do far more, issue 20). 1e-10 is still far below the
// Newton tolerance of the yielding pair.
TEST(BuildingsInSpace, WithoutEccentricityThePairMovesAsThePlanePair) {
  for (const char* name : {"adjacent_buildings.json", "adjacent_buildings_yielding.json"}) {
    const auto [difference, largest, out_of_plane] = against_plane(bundled(name));
    std::cout << fmt::format(
        "{} in space (one point per contact height): x of every floor {:.1e} of the largest "
        "{:.3e} m over the record; y and twist {:.1e}\n",
        name, difference, largest, out_of_plane);
    EXPECT_GT(largest, 0.01);
    EXPECT_LT(difference, 1e-10);
    EXPECT_EQ(out_of_plane, 0.0);
  }
}

// A one-storey building on each side, both eccentric: the left one's mass centre off along y
// (x and the twist coupled), the right one's off along x with its stiffness centre the other way
// (y and the twist coupled). The left storey's column is cut where the right floor meets it.
Json eccentric_pair() {
  return Json::parse(R"({
    "dimension": 3,
    "generators": [{"type": "adjacent_buildings", "id": "pair", "separation": 0.05,
      "left": {"plan": [12, 8], "mass_centre": [0, 1.5],
               "storeys": [{"height": 3.5, "mass": 2e5, "stiffness": 1e8, "stiffness_y": 1.5e8,
                            "torsional_stiffness": 3e9}]},
      "right": {"plan": [10, 10], "mass_centre": [1.2, 0], "stiffness_centre": [-0.8, 0],
                "storeys": [{"height": 3.0, "mass": 1.5e5, "stiffness": 8e7,
                             "rotary_inertia": 2e6}]},
      "law": {"type": "gap_spring", "stiffness": 1e9}}],
    "analysis": {"time_step": 0.01, "duration": 1}})");
}

// The two roots w^2 of a storey whose lateral stiffness k along one axis is coupled with the
// twist by the stiffness centre's distance s across it (Chopra 2012, 9.5):
// det [[k - w^2 m, k s], [k s, K_tt - w^2 I]] = 0, K_tt = k_theta + k s^2.
std::array<double, 2> coupled(double k, double s, double k_theta, double m, double inertia) {
  const double k_tt = k_theta + k * s * s;
  const double a = m * inertia, b = m * k_tt + inertia * k, c = k * k_tt - k * k * s * s;
  const double root = std::sqrt(b * b - 4.0 * a * c);
  return {(b - root) / (2.0 * a), (b + root) / (2.0 * a)};
}

TEST(BuildingsInSpace, AnEccentricStoreysModesAreTheClosedForm) {
  const BuiltModel built = build(eccentric_pair());
  const assembly::StructuralSystem system(built.model);
  const assembly::Modes modes = assembly::modal_analysis(system);
  // Left: s = (0, -1.5) from the mass centre; right: s = (-2, 0), k_theta from the plan.
  const double left_inertia = 2e5 * (144.0 + 64.0) / 12.0;
  const double right_theta = (8e7 * 100.0 + 8e7 * 100.0) / 12.0;
  const std::array<double, 2> left = coupled(1e8, -1.5, 3e9, 2e5, left_inertia);
  const std::array<double, 2> right = coupled(8e7, -2.0, right_theta, 1.5e5, 2e6);
  std::vector<double> expected{left[0], left[1], 1.5e8 / 2e5, right[0], right[1], 8e7 / 1.5e5};
  std::sort(expected.begin(), expected.end());
  ASSERT_EQ(modes.omega_squared.size(), 6);
  double worst = 0.0;
  for (std::size_t k = 0; k < 6; ++k)
    worst = std::max(
        worst, std::abs(modes.omega_squared[static_cast<Index>(k)] - expected[k]) / expected[k]);
  std::cout << fmt::format(
      "eccentric one-storey buildings: the six w^2 against the closed form, worst {:.1e} "
      "(periods {:.4f} ... {:.4f} s)\n",
      worst, 2.0 * M_PI / std::sqrt(expected.front()), 2.0 * M_PI / std::sqrt(expected.back()));
  EXPECT_LT(worst, 1e-12);
}

// The bundled pair with eccentric floors and offset plans, and its mirror image in y.
Json eccentric_bundled(double sign, double duration) {
  Json model = in_space(bundled("adjacent_buildings.json"), 2);
  Json& pair = model["generators"][0];
  pair["left"]["mass_centre"] = {0.0, sign * 1.5};
  pair["right"]["mass_centre"] = {1.0, -sign * 1.0};
  pair["right"]["stiffness_centre"] = {-1.0, sign * 0.5};
  pair["offset"] = sign * 2.0;
  model["analysis"]["duration"] = duration;
  return model;
}

// Until pounding has amplified rounding (the first 6 s here) the mirrored pair moves as the
// mirror image: x the same, y and the twist of the opposite sign; an eccentric pair twists.
TEST(BuildingsInSpace, MirroredEccentricitiesGiveTheMirroredMotion) {
  const Json model = eccentric_bundled(1.0, 6.0);
  const std::vector<std::string> ids = floors(model);
  const testing::NodeMotion motion = testing::run_node_motion(build(model), ids, {0, 1, 5});
  const testing::NodeMotion mirrored =
      testing::run_node_motion(build(eccentric_bundled(-1.0, 6.0)), ids, {0, 1, 5});
  ASSERT_EQ(motion.time.size(), mirrored.time.size());
  double largest = 0.0, difference = 0.0, twist = 0.0;
  for (std::size_t k = 0; k < motion.time.size(); ++k)
    for (std::size_t n = 0; n < 3 * ids.size(); ++n) {
      const double sign = n % 3 == 0 ? 1.0 : -1.0;
      largest = std::max(largest, std::abs(motion.values[k][n]));
      difference =
          std::max(difference, std::abs(mirrored.values[k][n] - sign * motion.values[k][n]));
      if (n % 3 == 2) twist = std::max(twist, std::abs(motion.values[k][n]));
    }
  std::cout << fmt::format(
      "eccentric pair and its mirror image, 6 s: difference {:.1e} of the largest {:.3e}; "
      "largest twist {:.2e} rad\n",
      difference / largest, largest, twist);
  EXPECT_GT(twist, 1e-4);
  // Rounding, amplified by the impacts: 1.8e-12 measured (8,000 ulp).
  EXPECT_LT(difference / largest, 1e-11);
}

// A storey's corner drift along x is u_x - theta_z (y_c - y_m) of its floor less the floor's
// below (one plan: the same mass centre y_m), along y u_y + theta_z (x_c - x_m).
TEST(BuildingsInSpace, TheSummarysCornerDriftsAndTwistAreTheFloorsMotion) {
  const Json model = eccentric_bundled(1.0, 8.0);
  const Json summary = testing::model_summary(model.dump(), kModels + "buildings.json");
  // The right building: plan 15 x 10, mass centre (1, -1) from the plan's centre.
  const testing::NodeMotion motion =
      testing::run_node_motion(build(model), {"pair.right.f2", "pair.right.f3"}, {0, 1, 5});
  const std::array<std::array<double, 2>, 4> corners{{{-7.5 - 1.0, -5.0 + 1.0},
                                                      {7.5 - 1.0, -5.0 + 1.0},
                                                      {7.5 - 1.0, 5.0 + 1.0},
                                                      {-7.5 - 1.0, 5.0 + 1.0}}};
  std::array<double, 2> peak{};
  std::array<std::size_t, 2> which{};
  double twist = 0.0;
  for (const std::vector<double>& u : motion.values) {
    twist = std::max(twist, std::abs(u[5] - u[2]));
    for (std::size_t c = 0; c < 4; ++c) {
      const double along_x = (u[3] - u[5] * corners[c][1]) - (u[0] - u[2] * corners[c][1]);
      const double along_y = (u[4] + u[5] * corners[c][0]) - (u[1] + u[2] * corners[c][0]);
      for (std::size_t d = 0; d < 2; ++d) {
        const double drift = std::abs(d == 0 ? along_x : along_y);
        if (drift > peak[d]) {
          peak[d] = drift;
          which[d] = c;
        }
      }
    }
  }
  double worst = 0.0;
  for (const Json& storey : summary["storeys"]) {
    const std::size_t d = storey["id"] == "pair.right.s3"     ? 0
                          : storey["id"] == "pair.right.s3.y" ? 1
                                                              : 2;
    if (d == 2) continue;
    const double reported = storey["peak_corner_drift"].get<double>();
    std::cout << fmt::format(
        "{}: corner drift {:.6e} m at corner {} (reported {:.6e} at {}), twist {:.6e} rad "
        "(reported {:.6e})\n",
        storey["id"].get<std::string>(), peak[d], which[d], reported, storey["corner"].get<int>(),
        twist, storey["peak_twist"].get<double>());
    EXPECT_EQ(storey["corner"].get<std::size_t>(), which[d]);
    worst = std::max({worst, std::abs(reported - peak[d]) / peak[d],
                      std::abs(storey["peak_twist"].get<double>() - twist) / twist});
    EXPECT_GT(peak[d], 1e-3);
  }
  EXPECT_LT(worst, 1e-12);
}

void expect_refused(const Json& model, const std::string& where, const std::string& phrase) {
  testing::expect_input_error([&] { (void)build(model); }, where, phrase);
}

// A yielding storey stiffer along y yields there at a smaller drift: its monitor along y takes
// F_y / k_y, the one along x F_y / k_x.
TEST(BuildingsInSpace, AYieldingStoreysDriftMonitorsYieldAtEachDirectionsDrift) {
  Json model = in_space(bundled("adjacent_buildings_yielding.json"), 1);
  Json& storey = model["generators"][0]["left"]["storeys"][0];
  storey["stiffness_y"] = 2.0 * storey["stiffness"].get<double>();
  const double yield_force = storey["law"]["yield_force"].get<double>();
  const BuiltModel built = build(model);
  int found = 0;
  for (const DriftMonitor& monitor : built.drift_monitors) {
    if (monitor.id != "pair.left.s1" && monitor.id != "pair.left.s1.y") continue;
    const double stiffness =
        storey[monitor.direction == 0 ? "stiffness" : "stiffness_y"].get<double>();
    EXPECT_NEAR(*monitor.yield_drift / (yield_force / stiffness), 1.0, 1e-15) << monitor.id;
    ++found;
  }
  EXPECT_EQ(found, 2);
}

// The yielding pair in space with bilinear storeys, 1 m apart (no pounding), under the record
// along x: each storey is one link whose x and y shears yield together (the default for a
// bilinear law) or a link per direction ("none"). Along x alone the two move alike (the coupled
// law along one direction is the uniaxial one to rounding); the drift monitors take the storey
// shear from the coupled link's force along their own direction.
TEST(BuildingsInSpace, ACoupledStoreyAlongXIsTheUncoupledOne) {
  Json model = in_space(bundled("adjacent_buildings_yielding.json"), 1);
  Json& pair = model["generators"][0];
  pair["separation"] = 1.0;
  for (const char* side : {"left", "right"})
    for (Json& storey : pair[side]["storeys"]) {
      const double yield_force = storey["law"]["yield_force"].get<double>();
      storey["law"] = {
          {"type", "bilinear_spring"}, {"yield_force", yield_force}, {"hardening_ratio", 0.05}};
      storey["stiffness_y"] = 1.5 * storey["stiffness"].get<double>();
    }
  const BuiltModel coupled = build(model);
  const model::Link& storey = coupled.model.links[coupled.link_index.at("pair.left.s1")];
  ASSERT_TRUE(storey.shear);
  EXPECT_FALSE(coupled.link_index.contains("pair.left.s1.y"));
  EXPECT_DOUBLE_EQ(storey.shear->numbers[1].stiffness / storey.shear->numbers[0].stiffness, 1.5);
  const Json summary = testing::model_summary(model.dump(), kModels + "buildings.json");
  pair["left"]["storey_interaction"] = "none";
  pair["right"]["storey_interaction"] = "none";
  EXPECT_TRUE(build(model).link_index.contains("pair.left.s1.y"));
  const Json uncoupled = testing::model_summary(model.dump(), kModels + "buildings.json");
  double worst = 0.0, largest = 0.0;
  for (std::size_t k = 0; k < summary["storeys"].size(); ++k) {
    const Json& mine = summary["storeys"][k];
    const Json& theirs = uncoupled["storeys"][k];
    ASSERT_EQ(mine["id"], theirs["id"]);
    if (mine.contains("direction") && mine["direction"] == "y") continue;
    largest = std::max(largest, mine["ductility"].get<double>());
    for (const char* key : {"peak_drift", "peak_shear"})
      worst = std::max(worst, std::abs(mine[key].get<double>() / theirs[key].get<double>() - 1.0));
  }
  std::cout << fmt::format(
      "yielding pair in space, record along x: coupled storeys against uncoupled: peak drifts and "
      "storey shears to {:.1e} (largest storey ductility {:.2f})\n",
      worst, largest);
  EXPECT_GT(largest, 1.5) << "the storeys must yield";
  EXPECT_LT(worst, 1e-9);
  Json takeda = in_space(bundled("adjacent_buildings_yielding.json"), 1);
  takeda["generators"][0]["left"]["storey_interaction"] = "elliptic";
  testing::expect_input_error([&] { build(takeda); }, "/generators/0/left/storey_interaction",
                              "no coupled form");
}

// The same coupled pair with a circular storey law (stiffness_y = stiffness), 1 m apart, under the
// record along the plan's diagonal: each storey sways along it, its drifts along x and y equal,
// and yields where its resultant drift reaches F_y / k, when each is 1/sqrt(2) of it. Both of its
// drift monitors keep their own direction's ductility, peak drift / yield drift, and give the
// resultant's, sqrt(2) times that, which the case's largest ductility takes (audit 71: a storey
// at 1.27 x its yield showed 0.90 alone, and a batch fragility found no case past 1).
TEST(BuildingsInSpace, ACoupledStoreyGivesItsResultantDuctility) {
  Json model = in_space(bundled("adjacent_buildings_yielding.json"), 1);
  Json& pair = model["generators"][0];
  pair["separation"] = 1.0;
  for (const char* side : {"left", "right"}) {
    pair[side]["plan"] = {10.0, 10.0};
    for (Json& storey : pair[side]["storeys"]) {
      const double yield_force = storey["law"]["yield_force"].get<double>();
      storey["law"] = {
          {"type", "bilinear_spring"}, {"yield_force", yield_force}, {"hardening_ratio", 0.05}};
    }
  }
  for (Json& excitation : model["excitations"])
    excitation["direction"] = {std::sqrt(0.5), std::sqrt(0.5), 0.0};
  const Json summary = testing::model_summary(model.dump(), kModels + "buildings.json");
  int yielded = 0;
  for (const Json& storey : summary["storeys"]) {
    const std::string id = storey["id"];
    if (id.rfind("pair.left.", 0) != 0 || id.ends_with(".y")) continue;
    const Json& across = *std::find_if(summary["storeys"].begin(), summary["storeys"].end(),
                                       [&](const Json& s) { return s["id"] == id + ".y"; });
    const Json& spec = pair["left"]["storeys"][std::stoul(id.substr(id.rfind('s') + 1)) - 1];
    const double yield_drift =
        spec["law"]["yield_force"].get<double>() / spec["stiffness"].get<double>();
    const double drift = storey["peak_drift"].get<double>();
    const double resultant = std::sqrt(2.0) * drift / yield_drift;
    const double ductility = storey["resultant_ductility"].get<double>();
    std::cout << fmt::format(
        "{}: peak drift along x {:.6g}, along y {:.6g}; ductility {:.6g}, "
        "resultant {:.6g}, sqrt(2) drift / yield drift {:.6g}\n",
        id, drift, across["peak_drift"].get<double>(), storey["ductility"].get<double>(), ductility,
        resultant);
    EXPECT_NEAR(across["peak_drift"].get<double>() / drift, 1.0, 1e-9) << id;
    EXPECT_NEAR(storey["ductility"].get<double>(), drift / yield_drift, 1e-12 * drift / yield_drift)
        << id;
    EXPECT_NEAR(ductility / resultant, 1.0, 1e-6) << id;
    EXPECT_EQ(across["resultant_ductility"].get<double>(), ductility) << id;
    yielded += ductility > 1.0;
  }
  EXPECT_GT(yielded, 0) << "a storey must yield";
  // Eccentric (its mass centre off the stiffness centre, where the link stands): the resultant
  // is of the drifts at the mass centre, where each direction's ductility is measured, so it is
  // never below either (the link's own read 0.87 beside a direction's 1.02: audit 71 recheck).
  pair["left"]["mass_centre"] = {1.0, 1.5};
  for (Json& storey : pair["left"]["storeys"])
    storey["stiffness_y"] = 1.7 * storey["stiffness"].get<double>();
  const Json eccentric = testing::model_summary(model.dump(), kModels + "buildings.json");
  int above = 0;
  for (const Json& storey : eccentric["storeys"]) {
    if (!storey.contains("resultant_ductility")) continue;
    const double resultant = storey["resultant_ductility"].get<double>();
    std::cout << fmt::format("eccentric {}: ductility {:.4f}, resultant {:.4f}\n",
                             storey["id"].get<std::string>(), storey["ductility"].get<double>(),
                             resultant);
    EXPECT_GE(resultant, storey["ductility"].get<double>()) << storey["id"];
    above += resultant > storey["ductility"].get<double>() * (1.0 + 1e-9);
  }
  EXPECT_GT(above, 0);
}

TEST(BuildingsInSpace, MeaninglessPlanInputIsRefusedWithItsPath) {
  const Json good = eccentric_pair();
  ASSERT_NO_THROW((void)build(good));
  Json no_plan = good;
  no_plan["generators"][0]["left"].erase("plan");
  expect_refused(no_plan, "/generators/0/left/plan", "required");
  Json flat = good;
  flat["generators"][0]["right"]["plan"] = {10.0, 0.0};
  expect_refused(flat, "/generators/0/right/plan/1", "> 0");
  Json outside = good;
  outside["generators"][0]["left"]["mass_centre"] = {0.0, 4.5};
  expect_refused(outside, "/generators/0/left/mass_centre", "within the plan");
  Json apart = good;
  apart["generators"][0]["offset"] = 9.0;
  expect_refused(apart, "/generators/0/offset", "do not face each other");
  Json no_points = good;
  no_points["generators"][0]["contact_points"] = 0;
  expect_refused(no_points, "/generators/0/contact_points", ">= 1");
  Json plane = bundled("adjacent_buildings.json");
  plane["generators"][0]["left"]["plan"] = {12.0, 10.0};
  expect_refused(plane, "/generators/0/left/plan", "dimension is 3");
  plane = bundled("adjacent_buildings.json");
  plane["generators"][0]["left"]["storeys"][0]["stiffness_y"] = 1e8;
  expect_refused(plane, "/generators/0/left/storeys/0/stiffness_y", "dimension is 3");
}

}  // namespace
}  // namespace pound::builder
