// Contact in 3-D scenes (issue 17's 3-D part, without friction): two free masses meeting through a
// hard contact along an inclined axis leave as the rigid-body impulse solution says, under the
// implicit and the explicit integrator. Normal to the contact, Newton's law: the relative normal
// velocity turns to -e times the approach, momentum kept; across it, each mass keeps its
// velocity (no friction).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace pound {
namespace {

using nlohmann::json;
using testing::read_text;

class SpaceContact : public testing::PoundProcess {};

// The last row of a node recorder's velocities (v_x, v_y, v_z) of node `id`.
Eigen::Vector3d final_velocity(const std::string& csv, const std::string& id) {
  std::istringstream lines(csv);
  std::string line, last;
  std::getline(lines, line);
  std::vector<std::string> header;
  for (std::istringstream cells(line); std::getline(cells, line, ',');) header.push_back(line);
  while (std::getline(lines, line))
    if (!line.empty()) last = line;
  std::vector<double> row;
  for (std::istringstream cells(last); std::getline(cells, line, ',');)
    row.push_back(std::stod(line));
  Eigen::Vector3d velocity;
  for (int k = 0; k < 3; ++k) {
    const std::string name = fmt::format("{}.v_{} [m/s]", id, "xyz"[k]);
    const auto at = std::find(header.begin(), header.end(), name) - header.begin();
    velocity[k] = row.at(static_cast<std::size_t>(at));
  }
  return velocity;
}

TEST_F(SpaceContact, HardContactAlongAnInclinedAxisGivesTheImpulseSolution) {
  const Eigen::Vector3d normal = Eigen::Vector3d(1.0, 2.0, 2.0) / 3.0;
  const Eigen::Vector3d across_1 = Eigen::Vector3d(2.0, -1.0, 0.0).normalized();
  const Eigen::Vector3d across_2 = normal.cross(across_1);
  const double mass_1 = 2000.0, mass_2 = 5000.0, restitution = 0.6;
  const Eigen::Vector3d velocity_1 = 1.0 * normal + 0.3 * across_1 - 0.2 * across_2;
  const Eigen::Vector3d velocity_2 = -0.5 * normal + 0.1 * across_2;
  // The exact velocities after the impact.
  const double approach = (velocity_1 - velocity_2).dot(normal);
  const double impulse = (1.0 + restitution) * approach * mass_1 * mass_2 / (mass_1 + mass_2);
  const Eigen::Vector3d after_1 = velocity_1 - impulse / mass_1 * normal;
  const Eigen::Vector3d after_2 = velocity_2 + impulse / mass_2 * normal;
  for (const char* integrator : {"newmark_average_acceleration", "central_difference"}) {
    SCOPED_TRACE(integrator);
    // 3 m apart along the normal with a 0.05 m gap: contact at t = 0.05 / 1.5, over by 0.2 s.
    const json model = {
        {"dimension", 3},
        {"nodes",
         {{{"id", "a"}, {"x", 0.0}, {"y", 0.0}, {"z", 0.0}},
          {{"id", "b"}, {"x", 1.0}, {"y", 2.0}, {"z", 2.0}}}},
        {"masses", {{{"node", "a"}, {"mass", mass_1}}, {{"node", "b"}, {"mass", mass_2}}}},
        {"initial_velocities",
         {{{"node", "a"}, {"x", velocity_1.x()}, {"y", velocity_1.y()}, {"z", velocity_1.z()}},
          {{"node", "b"}, {"x", velocity_2.x()}, {"y", velocity_2.y()}, {"z", velocity_2.z()}}}},
        {"links",
         {{{"id", "contact"},
           {"nodes", {"a", "b"}},
           {"gap", 0.05},
           {"law", {{"type", "hard_contact"}, {"restitution", restitution}}}}}},
        {"analysis", {{"integrator", integrator}, {"time_step", 1e-3}, {"duration", 0.2}}},
        {"recorders", {{{"type", "node"}, {"nodes", {"a", "b"}}, {"file", "nodes.csv"}}}}};
    const std::string name = std::string(integrator);
    std::ofstream(path(name + ".json")) << model.dump(1);
    const testing::Outcome outcome =
        pound({"run", path(name + ".json").string(), "--quiet", "--out", path(name).string()});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
    const std::string csv = read_text(path(name) / "nodes.csv");
    const double error = std::max((final_velocity(csv, "a") - after_1).norm(),
                                  (final_velocity(csv, "b") - after_2).norm()) /
                         approach;
    const json summary = json::parse(read_text(path(name) / "summary.json"));
    std::printf("  %s: velocities after the impact within %.2e of the approach speed, %d impact\n",
                integrator, error, summary["links"][0]["impacts"].get<int>());
    // Newmark solves the contact's step to its Newton tolerance (1e-10 of the forces); central
    // difference's forward increment is exact to rounding.
    EXPECT_LT(error, std::string(integrator) == "central_difference" ? 1e-14 : 1e-10);
    EXPECT_EQ(summary["links"][0]["impacts"], 1);
  }
}

}  // namespace
}  // namespace pound
