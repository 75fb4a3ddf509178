#pragma once
// A 3-D column of 1,000 t on a hinge node at its base (held but for its bending): an 8 m elastic
// beam from the hinge node to its top, the hinge links between the hinge node and the fixed
// base given by the test, excited along `direction` (0.4 g). What the biaxial-hinge tests and the
// pushover of one share.
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pound::testing {

constexpr double kColumnHeight = 8.0, kColumnYoungs = 3.0e10, kColumnInertia = 0.05;
constexpr double kColumnMass = 1.0e6;

inline nlohmann::json hinged_column(const std::vector<nlohmann::json>& links,
                                    std::array<double, 3> direction) {
  return {{"dimension", 3},
          {"nodes",
           {{{"id", "base"}, {"x", 0}, {"y", 0}, {"z", 0}},
            {{"id", "hinge"}, {"x", 0}, {"y", 0}, {"z", 0}},
            {{"id", "top"}, {"x", 0}, {"y", 0}, {"z", kColumnHeight}}}},
          {"materials",
           {{{"id", "concrete"},
             {"youngs_modulus", kColumnYoungs},
             {"density", 0.0},
             {"poisson_ratio", 0.2}}}},
          {"elements",
           {{{"id", "column"},
             {"type", "beam"},
             {"nodes", {"hinge", "top"}},
             {"material", "concrete"},
             {"area", 1.0},
             {"inertia_y", kColumnInertia},
             {"inertia_z", kColumnInertia},
             {"torsion", 2.0 * kColumnInertia},
             {"orientation", {1.0, 0.0, 0.0}}}}},
          {"masses", {{{"node", "top"}, {"mass", kColumnMass}}}},
          {"supports",
           {{{"node", "base"}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}},
            {{"node", "hinge"}, {"fix", {"x", "y", "z", "rz"}}},
            {{"node", "top"}, {"fix", {"z"}}}}},
          {"links", links},
          {"excitations",
           {{{"record", std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_firm_01.AT2"},
             {"units", "g"},
             {"scale", {{"pga", 0.4}}},
             {"direction", direction}}}},
          {"analysis", {{"time_step", 0.005}, {"duration", 12.0}}}};
}

}  // namespace pound::testing
