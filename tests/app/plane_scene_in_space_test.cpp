// Issue 18's first verification: a 3-D model of an existing 2-D scene that moves only in its
// plane gives the 2-D result. Each bundled plane frame (bridges with gap links, hinges and
// gravity, adjacent buildings) is expanded, written again as a 3-D scene (z = 0, the beams as
// 3-D beams oriented by +z, the out-of-plane directions held at every node, links and records
// along their plane vectors) and run beside the original: the histories and the summary must be
// the same to the last digit (the 3-D beam rounds its in-plane terms as the plane beam does, and
// held directions leave the equations as they were). Also a mass on an inclined spring in space
// against its closed form, and `pound check` counting the six directions.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_text;

// The plane model written as a 3-D one moving in the x-y plane.
json in_space(json model) {
  model["dimension"] = 3;
  const auto plus_zero = [](json& vector) { vector.push_back(0.0); };
  for (json& node : model["nodes"]) node["z"] = 0.0;
  for (const char* list : {"materials", "elements"})
    if (!model.contains(list)) model[list] = json::array();
  for (json& material : model["materials"])
    material["shear_modulus"] = material["youngs_modulus"].get<double>() / 2.6;
  for (json& element : model["elements"]) {
    if (element["type"] != "beam") continue;
    const double inertia = element["inertia"].get<double>();
    element.erase("inertia");
    element["inertia_z"] = inertia;  // in-plane bending, about z' = z
    element["inertia_y"] = inertia;
    element["torsion"] = 2.0 * inertia;
    element["orientation"] = {0.0, 0.0, 1.0};
  }
  if (model.contains("masses"))
    for (json& mass : model["masses"])
      if (mass.contains("rotary_inertia"))
        mass["rotary_inertia"] = {0.0, 0.0, mass["rotary_inertia"]};
  std::map<std::string, json*> supports;
  for (json& support : model["supports"]) supports[support["node"]] = &support;
  json added = json::array();
  for (const json& node : model["nodes"]) {
    const std::string id = node["id"];
    json* support = supports.count(id) ? supports[id] : nullptr;
    if (!support) {
      added.push_back({{"node", id}, {"fix", json::array()}});
      support = &added.back();
    }
    for (const char* out_of_plane : {"z", "rx", "ry"}) (*support)["fix"].push_back(out_of_plane);
  }
  for (json& support : added) model["supports"].push_back(support);
  if (model.contains("links"))
    for (json& link : model["links"]) {
      if (link.contains("axis")) plus_zero(link["axis"]);
      if (link.value("dof", "") == "rotation") link["axis"] = {0.0, 0.0, 1.0};
    }
  if (model.contains("excitations"))
    for (json& excitation : model["excitations"])
      if (excitation.contains("direction")) plus_zero(excitation["direction"]);
  if (model.contains("gravity") && model["gravity"].contains("direction"))
    plus_zero(model["gravity"]["direction"]);
  return model;
}

// An envelope of 3-D beam end forces as the plane beam names them: Vy, Mz become V, M; the
// out-of-plane ones (Vz, T, My) must be 0 throughout and are left out. Other files unchanged.
std::string plane_names(const std::string& csv) {
  if (csv.find(".Vy_i,") == std::string::npos) return csv;
  std::istringstream lines(csv);
  std::string result;
  for (std::string line; std::getline(lines, line);) {
    const std::string name = line.substr(0, line.find(','));
    const std::string rest = line.substr(name.size());
    const std::string quantity = name.substr(name.rfind('.') + 1);
    const std::string element = name.substr(0, name.rfind('.') + 1);
    if (quantity.starts_with("Vz_") || quantity.starts_with("T_") || quantity.starts_with("My_")) {
      EXPECT_EQ(rest.substr(rest.find(',', 1)), ",0,0,0,0,0") << line;  // after the unit
      continue;
    }
    if (quantity.starts_with("Vy_") || quantity.starts_with("Mz_"))
      result += element + quantity.substr(0, 1) + quantity.substr(2) + rest + "\n";
    else
      result += line + "\n";
  }
  return result;
}

// A link history as a plane scene names it: the 3-D friction link's slide along t_1 (the plane
// tangent) is the plane one's, and along t_2 (z, held) it must stay 0 and is left out.
std::string plane_link_columns(const std::string& csv) {
  if (csv.find(".slide_1") == std::string::npos) return csv;
  std::istringstream lines(csv);
  std::string result;
  std::vector<bool> kept;
  for (std::string line; std::getline(lines, line);) {
    std::vector<std::string> cells;
    std::istringstream cut(line);
    for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
    if (kept.empty())
      for (std::string& name : cells) {
        kept.push_back(name.find("_2") == std::string::npos);
        for (const std::string along : {"tangential_force", "slide"})
          if (const auto at = name.find(along + "_1"); at != std::string::npos)
            name.erase(at + along.size(), 2);
      }
    std::string row;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (!kept[k]) {
        if (!result.empty()) {
          EXPECT_EQ(cells[k], "0") << line;
        }
        continue;
      }
      row += (row.empty() ? "" : ",") + cells[k];
    }
    result += row + "\n";
  }
  return result;
}

class PlaneSceneInSpace : public testing::PoundProcess {
 protected:
  json run(const fs::path& model, const std::string& out) {
    const testing::Outcome outcome =
        pound({"run", model.string(), "--quiet", "--out", path(out).string()});
    EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
    return json::parse(read_text(path(out) / "summary.json"));
  }

  // Runs the plane model at `plane` and its 3-D form: the same summary and histories.
  void expect_the_same_in_space(const fs::path& plane, const std::string& name) {
    const fs::path space = path(name + "_3d.json");
    std::ofstream(space) << in_space(json::parse(read_text(plane))).dump(1);
    json in_plane = run(plane, name + ".plane");
    json in_3d = run(space, name + ".space");
    EXPECT_EQ(in_3d["dofs"], in_plane["dofs"]);
    for (json* summary : {&in_plane, &in_3d})
      for (const char* key : {"model", "run_time_s"}) summary->erase(key);
    EXPECT_EQ(in_3d, in_plane) << json::diff(in_plane, in_3d).dump(1).substr(0, 2000);
    // Every history with the same columns (an element's end forces have more in 3-D: Vy, Vz,
    // T, My, Mz) is the same file.
    int compared = 0;
    for (const fs::directory_entry& csv : fs::directory_iterator(path(name + ".plane"))) {
      if (csv.path().extension() != ".csv") continue;
      const std::string before = read_text(csv.path());
      const std::string after = read_text(path(name + ".space") / csv.path().filename());
      const std::string header = plane_link_columns(after);
      if (before.substr(0, before.find('\n')) != header.substr(0, header.find('\n'))) continue;
      EXPECT_EQ(plane_names(plane_link_columns(after)), before) << csv.path().filename();
      ++compared;
    }
    std::printf("  %s: summary and %d histories identical in 3-D (%ld DOFs)\n", name.c_str(),
                compared, in_plane["dofs"].get<long>());
    EXPECT_GT(compared, 0);
  }
};

TEST_F(PlaneSceneInSpace, BundledPlaneFramesGiveTheSameNumbersInSpace) {
  for (const char* name :
       {"three_span_bridge", "three_span_bridge_takeda", "three_span_bridge_hard_contact",
        "adjacent_buildings", "adjacent_buildings_yielding", "block_on_floor",
        "sliding_block_pendulum"}) {
    SCOPED_TRACE(name);
    const fs::path plane = path(std::string(name) + ".json");
    ASSERT_EQ(pound({"expand", POUND_SOURCE_DIR "/models/" + std::string(name) + ".json", "--out",
                     plane.string()})
                  .exit_code,
              0);
    expect_the_same_in_space(plane, name);
  }
}

// Hard contacts with friction (issue 17): a block thrown along a hard floor into a hard wall
// (e = 0.5), rubbing on both, under Newmark and central difference. In space each link's second
// tangent is z, held: no constraint, and the first is the plane scene's tangent.
TEST_F(PlaneSceneInSpace, HardContactsWithFrictionGiveTheSameNumbersInSpace) {
  for (const char* integrator : {"newmark_average_acceleration", "central_difference"}) {
    SCOPED_TRACE(integrator);
    const json model = json::parse(R"({
      "dimension": 2,
      "nodes": [{"id": "block", "x": 0, "y": 0}, {"id": "floor", "x": 0, "y": 0},
                {"id": "wall", "x": 0, "y": 0}],
      "masses": [{"node": "block", "mass": 10}],
      "supports": [{"node": "floor", "fix": ["x", "y"]}, {"node": "wall", "fix": ["x", "y"]}],
      "loads": [{"node": "block", "x": 20, "y": -98.1}],
      "initial_velocities": [{"node": "block", "x": 1.5, "y": 0.2}],
      "links": [
        {"id": "floor", "nodes": ["block", "floor"], "axis": [0, -1],
         "law": {"type": "hard_contact", "restitution": 0}, "friction": {"coefficient": 0.4}},
        {"id": "wall", "nodes": ["block", "wall"], "axis": [1, 0], "gap": 0.1,
         "law": {"type": "hard_contact", "restitution": 0.5}, "friction": {"coefficient": 0.3}}],
      "analysis": {"time_step": 1e-4, "duration": 0.5}
    })");
    json plane_model = model;
    plane_model["analysis"]["integrator"] = integrator;
    const std::string name = std::string("hard_block_") + integrator;
    const fs::path plane = path(name + ".json");
    std::ofstream(plane) << plane_model.dump(1);
    expect_the_same_in_space(plane, name);
  }
}

// A mass on an elastic spring link along (1, 2, 2) / 3, nothing else holding it, started along
// the spring: it oscillates along the axis as u = (v / w) sin(w t), w = sqrt(k / m).
TEST_F(PlaneSceneInSpace, MassOnAnInclinedSpringOscillatesAlongIt) {
  const double stiffness = 4.0e4, mass = 100.0, speed = 0.3;
  const double axis[3] = {1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  json model = {
      {"dimension", 3},
      {"nodes",
       {{{"id", "anchor"}, {"x", 0.0}, {"y", 0.0}, {"z", 0.0}},
        {{"id", "mass"}, {"x", 1.0}, {"y", 2.0}, {"z", 2.0}}}},
      {"masses", {{{"node", "mass"}, {"mass", mass}}}},
      {"supports", {{{"node", "anchor"}, {"fix", {"x", "y", "z"}}}}},
      {"initial_velocities",
       {{{"node", "mass"},
         {"x", speed * axis[0]},
         {"y", speed * axis[1]},
         {"z", speed * axis[2]}}}},
      {"links",
       {{{"id", "spring"},
         {"nodes", {"anchor", "mass"}},
         {"law", {{"type", "elastic_spring"}, {"stiffness", stiffness}}}}}},
      {"analysis",
       {{"integrator", "newmark_average_acceleration"}, {"time_step", 1e-4}, {"duration", 0.5}}},
      {"recorders", {{{"type", "node"}, {"nodes", {"mass"}}, {"file", "mass.csv"}}}}};
  std::ofstream(path("spring.json")) << model.dump(1);
  run(path("spring.json"), "out");
  std::istringstream csv(read_text(path("out") / "mass.csv"));
  std::string line;
  std::getline(csv, line);  // time, u_x, v_x, a_rel_x, a_abs_x, u_y, ...
  const double omega = std::sqrt(stiffness / mass);
  double worst = 0.0, off_axis = 0.0;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    const double u[3] = {row[1], row[5], row[9]};
    const double along = u[0] * axis[0] + u[1] * axis[1] + u[2] * axis[2];
    worst = std::max(worst, std::abs(along - speed / omega * std::sin(omega * row[0])));
    off_axis = std::max(off_axis, std::hypot(u[0] - along * axis[0], u[1] - along * axis[1],
                                             u[2] - along * axis[2]));
  }
  // Average acceleration's period error (w dt)^2 / 12 over 1.6 periods: about 1e-4 of the
  // amplitude.
  std::printf("  inclined spring: error %.2e of amplitude %.4g, off the axis %.1e\n", worst,
              speed / omega, off_axis);
  EXPECT_LT(worst, 5e-4 * speed / omega);
  EXPECT_LT(off_axis, 1e-8 * speed / omega);
}

// `pound check` counts the DOFs of each of the six directions of a 3-D scene.
TEST_F(PlaneSceneInSpace, CheckCountsSixDirections) {
  const fs::path plane = path("bridge.json");
  ASSERT_EQ(
      pound({"expand", POUND_SOURCE_DIR "/models/three_span_bridge.json", "--out", plane.string()})
          .exit_code,
      0);
  std::ofstream(path("bridge_3d.json")) << in_space(json::parse(read_text(plane))).dump(1);
  const testing::Outcome outcome = pound({"check", path("bridge_3d.json").string(), "--json"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const json check = json::parse(outcome.out);
  EXPECT_EQ(check["dofs_per_node"], 6);
  long sum = 0;
  for (const char* key : {"dofs_x", "dofs_y", "dofs_z", "dofs_rx", "dofs_ry", "dofs_rz"})
    sum += check[key].get<long>();
  EXPECT_EQ(sum, check["dofs"].get<long>());
  EXPECT_EQ(check["dofs_z"], 0);  // held out of the plane
  EXPECT_GT(check["dofs_rz"].get<long>(), 0);
  EXPECT_FALSE(check.contains("dofs_rotation"));
}

}  // namespace
}  // namespace pound
