// A rigid floor written two ways gives one motion: the bundled eccentric storey
// (models/eccentric_storey_3d.json, one node at the centre of mass that the columns reach
// through rigid offsets) against the same storey whose floor is the four column tops tied to
// that node by a rigid diaphragm, under the model's pair of records, with and without pounding
// at two corners; and what the run reports at a tied corner (drift monitors, histories) is the
// corner's motion on the rigid floor.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "app/model_loading.hpp"
#include "support/model_summary.hpp"
#include "support/node_motion.hpp"

namespace pound::app {
namespace {

using nlohmann::json;

const std::string kModel = std::string(POUND_SOURCE_DIR) + "/models/eccentric_storey_3d.json";

json bundled_storey() {
  std::ifstream file(kModel);
  std::stringstream text;
  text << file.rdbuf();
  json model = json::parse(text.str());
  model["analysis"]["duration"] = 8.0;  // past the strong motion, a few seconds of CI
  return model;
}

const json& node_named(const json& model, const std::string& id) {
  for (const json& node : model["nodes"])
    if (node["id"] == id) return node;
  throw std::runtime_error("no node " + id);
}

// The floor's columns end at their own top nodes (z, rx, ry held, as the floor node holds them),
// tied to the floor node by a rigid diaphragm; top<k> stands where column<k>'s offset reached.
json with_diaphragm(json model) {
  const json floor = node_named(model, "floor");
  json constraint = {{"type", "rigid_diaphragm"}, {"master", "floor"}, {"slaves", json::array()}};
  for (json& element : model["elements"]) {
    const std::string top = "top" + element["id"].get<std::string>().substr(6);
    const json& offset = element["rigid_offsets"][1];
    model["nodes"].push_back({{"id", top},
                              {"x", floor["x"].get<double>() + offset[0].get<double>()},
                              {"y", floor["y"].get<double>() + offset[1].get<double>()},
                              {"z", floor["z"].get<double>() + offset[2].get<double>()}});
    element["nodes"][1] = top;
    element.erase("rigid_offsets");
    model["supports"].push_back({{"node", top}, {"fix", {"z", "rx", "ry"}}});
    constraint["slaves"].push_back(top);
  }
  model["constraints"] = json::array({constraint});
  return model;
}

// Gap springs from the two right corners (x = 6 m) to a fixed wall 8 mm away: from the floor node
// through rigid offsets, or from the tied corner nodes themselves.
json with_wall(json model, bool tied_corners) {
  for (const int corner : {2, 3}) {
    const json top = node_named(with_diaphragm(model), fmt::format("top{}", corner));
    const std::string wall = fmt::format("wall{}", corner);
    model["nodes"].push_back({{"id", wall}, {"x", 6.5}, {"y", top["y"]}, {"z", top["z"]}});
    model["supports"].push_back({{"node", wall}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}});
    json link = {{"id", fmt::format("pound{}", corner)},
                 {"nodes", {tied_corners ? top["id"].get<std::string>() : "floor", wall}},
                 {"gap", 0.008},
                 {"axis", {1.0, 0.0, 0.0}},
                 {"law", {{"type", "gap_spring"}, {"stiffness", 2.0e9}}}};
    if (!tied_corners)
      link["rigid_offsets"] = {{6.0, top["y"].get<double>(), 0.0}, {0.0, 0.0, 0.0}};
    model["links"].push_back(link);
  }
  return model;
}

testing::NodeMotion floor_motion(const json& model) {
  return testing::run_node_motion(load_model_text(model.dump(), kModel).built, {"floor"},
                                  {0, 1, 5});
}

// The largest difference of two runs' floor motions (x, y and the twist times the floor's half
// diagonal), over the largest corner movement of the first.
double floor_difference(const testing::NodeMotion& a, const testing::NodeMotion& b) {
  EXPECT_EQ(a.time.size(), b.time.size());
  const double reach = std::hypot(6.0, 4.0);
  double largest = 0.0, difference = 0.0;
  for (std::size_t s = 0; s < std::min(a.time.size(), b.time.size()); ++s)
    for (std::size_t d = 0; d < 3; ++d) {
      const double scale = d == 2 ? reach : 1.0;
      largest = std::max(largest, scale * std::abs(a.values[s][d]));
      difference = std::max(difference, scale * std::abs(a.values[s][d] - b.values[s][d]));
    }
  return difference / largest;
}

TEST(DiaphragmFloor, CornersTiedByARigidDiaphragmMoveAsTheFloorReachedThroughRigidOffsets) {
  const json offsets = bundled_storey();
  const double elastic =
      floor_difference(floor_motion(offsets), floor_motion(with_diaphragm(offsets)));
  const json pounding = with_wall(offsets, false);
  const json summary = testing::model_summary(pounding.dump(), kModel);
  const double pounded = floor_difference(floor_motion(pounding),
                                          floor_motion(with_diaphragm(with_wall(offsets, true))));
  const double peak_force = summary["links"][0]["peak_force"].get<double>();
  std::printf(
      "  floor motion, diaphragm against offsets: elastic %.2e, pounding two corners "
      "(peak force %.3g MN) %.2e of the largest corner movement\n",
      elastic, peak_force / 1e6, pounded);
  EXPECT_LT(elastic, 1e-11);
  EXPECT_GT(peak_force, 0.0);  // the corners did pound
  EXPECT_LT(pounded, 1e-9);
}

// A drift monitor whose top is a tied corner reports the corner's drift on the rigid floor,
// u_x - theta_z r_y, as the history of the floor reached through rigid offsets gives it.
TEST(DiaphragmFloor, AMonitorAtATiedCornerReportsTheCornersDrift) {
  json model = with_diaphragm(bundled_storey());
  model["monitors"]["drifts"].push_back(
      {{"id", "corner3_x"}, {"bottom", "base3"}, {"top", "top3"}, {"height", 3.5}});
  const json summary = testing::model_summary(model.dump(), kModel);
  const testing::NodeMotion motion = floor_motion(bundled_storey());
  double expected = 0.0;
  for (const std::vector<double>& row : motion.values)
    expected = std::max(expected, std::abs(row[0] - row[2] * 4.0));  // top3 at (6, 4) from floor
  double reported = -1.0;
  for (const json& storey : summary["storeys"])
    if (storey["id"] == "corner3_x") reported = storey["peak_drift"].get<double>();
  const double error = std::abs(reported / expected - 1);
  std::printf("  corner drift %.6e m reported, %.6e m from the floor's history: error %.1e\n",
              reported, expected, error);
  EXPECT_LT(error, 1e-10);
}

// Every column base moving with the record (multi-support excitation, no delay) is the uniform
// excitation: the support influence of a tied floor is its rigid translation.
TEST(DiaphragmFloor, SupportsMovingTogetherUnderATiedFloorGiveTheUniformExcitationsDrifts) {
  json uniform = with_diaphragm(bundled_storey());
  uniform["excitations"][0].erase("pair");
  uniform["excitations"][0]["direction"] = {1.0, 0.0, 0.0};
  uniform["recorders"] = json::array();  // element forces are not taken under moving supports
  json moving = uniform;
  moving["excitations"][0]["supports"] = {"base0", "base1", "base2", "base3"};
  const json a = testing::model_summary(uniform.dump(), kModel);
  const json b = testing::model_summary(moving.dump(), kModel);
  const double drift = a["storeys"][0]["peak_drift"].get<double>();
  const double error = std::abs(b["storeys"][0]["peak_drift"].get<double>() / drift - 1);
  std::printf("  peak drift %.6e m uniform, multi-support differs by %.1e\n", drift, error);
  EXPECT_GT(drift, 1e-3);
  EXPECT_LT(error, 1e-10);
}

}  // namespace
}  // namespace pound::app
