// Drift and joint monitors on states made by hand: the peaks and when they happen.
#include "results/monitors.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include "app/model_loading.hpp"
#include "app/model_run.hpp"
#include "builder/generators.hpp"
#include "io/model_reader.hpp"
#include "io/model_writer.hpp"
#include "support/dof_readings.hpp"
#include "support/model_summary.hpp"
#include "support/node_motion.hpp"
#include "support/vectors.hpp"

namespace pound::results {
namespace {

using testing::dof;
using testing::entries;

integrators::State state(double time, const Vector& displacement, const Vector& penetration = {}) {
  integrators::State s;
  s.time = time;
  s.displacement = displacement;
  s.acceleration = Vector::Zero(displacement.size());
  s.link_penetration = penetration;
  return s;
}

// A ground accelerating at 2 t everywhere: its supports' too.
GroundAcceleration ramp_ground() {
  return {3,
          [](double time, std::vector<double>& scales) { scales = {2.0 * time}; },
          {Vector::Ones(3)},
          [](Index, int, double time) { return 2.0 * time; }};
}

TEST(DriftMonitors, KeepTheLargestDriftEitherWayAndItsTime) {
  // Storey 1 from a fixed base (-1) to equation 0; storey 2 from equation 0 to equation 1.
  GroundAcceleration ground = ramp_ground();
  DriftMonitors drifts({{dof(-1), dof(0), 10}, {dof(0), dof(1), 11}}, ground);
  drifts.record(state(0.0, entries({0.0, 0.0})));
  drifts.record(state(0.1, entries({0.25, 0.75})));     // drifts 0.25, 0.5
  drifts.record(state(0.2, entries({-0.5, -0.25})));    // 0.5, 0.25
  drifts.record(state(0.3, entries({0.125, -0.375})));  // 0.125, 0.5: a tie is no new peak
  ASSERT_EQ(drifts.peaks().size(), 2u);
  EXPECT_EQ(drifts.peaks()[0].peak_drift, 0.5);
  EXPECT_EQ(drifts.peaks()[0].time, 0.2);
  EXPECT_EQ(drifts.peaks()[1].peak_drift, 0.5);
  EXPECT_EQ(drifts.peaks()[1].time, 0.1);
}

// A storey swinging about 0.2 with a decaying amplitude, d = 0.2 + e^-t cos(2 pi t) to t = 3:
// its last turning points are the maximum near t = 3 and the minimum near t = 2.5, where
// tan(2 pi t) = -1 / (2 pi); the swing is half their distance. The residual is the last step's.
TEST(DriftMonitors, KeepHowFarTheDriftStillSwingsOverItsLastCycle) {
  GroundAcceleration ground = ramp_ground();
  DriftMonitors drifts({{dof(-1), dof(0), 10}}, ground);
  const double pi = std::numbers::pi, dt = 1e-4;
  const auto drift = [&](double t) { return 0.2 + std::exp(-t) * std::cos(2 * pi * t); };
  for (int k = 0; k <= 30000; ++k) drifts.record(state(k * dt, entries({drift(k * dt)})));
  const double shift = std::atan(1.0 / (2 * pi)) / (2 * pi);
  const double expected = 0.5 * (drift(3.0 - shift) - drift(2.5 - shift));
  const DriftPeak& peak = drifts.peaks()[0];
  std::cout << "swing " << peak.end_swing << " against " << expected << " (relative error "
            << std::abs(peak.end_swing / expected - 1) << ")\n";
  EXPECT_NEAR(peak.end_swing / expected, 1.0, 1e-6);
  EXPECT_NEAR(peak.residual_drift, drift(3.0), 1e-12);
  // A drift that never turned has no swing.
  DriftMonitors ramp({{dof(-1), dof(0), 10}}, ground);
  for (int k = 0; k <= 10; ++k) ramp.record(state(k * 0.1, entries({0.01 * k})));
  EXPECT_EQ(ramp.peaks()[0].end_swing, 0.0);
}

// The same swing with a higher mode's ripple (1 mm at 20 Hz) on top: its turning points come
// every 25 ms, so the last cycle is the ripple's alone (2 mm across, hiding the 0.07 swing); over
// a window of two first-mode periods (2 s) the swing is the first mode's, half the distance
// between the window's extremes (near t = 1 and t = 1.5).
TEST(DriftMonitors, OverTheirWindowAHigherModesRippleDoesNotHideTheSwing) {
  GroundAcceleration ground = ramp_ground();
  const double pi = std::numbers::pi, dt = 1e-4;
  const auto swing = [&](double t) { return 0.2 + std::exp(-t) * std::cos(2 * pi * t); };
  const auto drift = [&](double t) { return swing(t) + 1e-3 * std::cos(2 * pi * 20 * t); };
  DriftMonitors last_cycle({{dof(-1), dof(0), 10}}, ground);
  DriftMonitors windowed({{dof(-1), dof(0), 10}}, ground);
  windowed.set_swing_window(2.0);
  for (int k = 0; k <= 30000; ++k) {
    last_cycle.record(state(k * dt, entries({drift(k * dt)})));
    windowed.record(state(k * dt, entries({drift(k * dt)})));
  }
  // The reference: the window's extremes searched on a grid 100 times finer than the steps.
  double largest = -1e300, smallest = 1e300;
  for (int k = 0; k <= 2000000; ++k) {
    largest = std::max(largest, drift(1.0 + k * 1e-6));
    smallest = std::min(smallest, drift(1.0 + k * 1e-6));
  }
  const double expected = 0.5 * (largest - smallest);
  std::cout << "with a ripple: last cycle " << last_cycle.peaks()[0].end_swing << ", window "
            << windowed.peaks()[0].end_swing << " against " << expected << "\n";
  EXPECT_LT(last_cycle.peaks()[0].end_swing, 2e-3);
  EXPECT_NEAR(windowed.peaks()[0].end_swing / expected, 1.0, 1e-6);
}

// At every step the window's swing is exactly half the range of the drifts recorded in it: a slow
// swing with random noise (long falls and rises fill a queue past its first 16 places, so it
// grows while wrapped around; a tenth of the values repeated, ties it must keep right), windows of
// 50 and 500 steps, searched by brute force.
TEST(DriftMonitors, TheWindowsSwingIsHalfTheRangeOfEveryDriftInIt) {
  GroundAcceleration ground = ramp_ground();
  for (const int window_steps : {50, 500}) {
    DriftMonitors windowed({{dof(-1), dof(0), 10}}, ground);
    const double dt = 0.01;
    windowed.set_swing_window(window_steps * dt - 0.5 * dt);
    std::vector<double> drifts;
    unsigned seed = 12345;
    const auto next = [&] {
      seed = seed * 1103515245u + 12345u;
      return static_cast<double>((seed >> 8) % 1000) / 1000.0 - 0.5;
    };
    int unequal = 0;
    for (int k = 0; k < 5000; ++k) {
      const double drift =
          (k % 10 == 3) ? drifts.back() : std::cos(k / 150.0) + 0.01 * next() * (1.0 + 0.001 * k);
      drifts.push_back(drift);
      windowed.record(state(k * dt, entries({drift})));
      const auto first = drifts.end() - std::min<int>(k + 1, window_steps);
      const auto [smallest, largest] = std::minmax_element(first, drifts.end());
      unequal += windowed.peaks()[0].end_swing != 0.5 * (*largest - *smallest);
    }
    std::cout << "window of " << window_steps << " steps: " << unequal << " of 5000 unequal\n";
    EXPECT_EQ(unequal, 0);
  }
}

// The top node's absolute acceleration: relative plus the ground's, largest either way.
TEST(DriftMonitors, KeepTheTopsLargestAbsoluteAcceleration) {
  GroundAcceleration ground = ramp_ground();
  DriftMonitors drifts({{dof(-1), dof(0), 10}}, ground);
  integrators::State s = state(0.5, entries({0.0}));
  s.acceleration = entries({-4.0});  // absolute -4 + 1 = -3
  drifts.record(s);
  s = state(1.0, entries({0.0}));
  s.acceleration = entries({0.5});  // absolute 2.5
  drifts.record(s);
  EXPECT_EQ(drifts.peaks()[0].peak_acceleration, 3.0);
  EXPECT_EQ(drifts.peaks()[0].acceleration_time, 0.5);
}

// A storey's plan peaks: largest corner drift, its corner and time, twist and its time.
void expect_plan(const DriftPeak& p, double corner_drift, std::size_t corner, double corner_time,
                 double twist, double twist_time) {
  EXPECT_EQ(p.peak_corner_drift, corner_drift);
  EXPECT_EQ(p.corner, corner);
  EXPECT_EQ(p.corner_time, corner_time);
  EXPECT_EQ(p.peak_twist, twist);
  EXPECT_EQ(p.twist_time, twist_time);
}

// A 3-D storey's corners (u -+ 2 theta) and twist: the largest corner drift, the first corner to
// reach it and when (a later tie is no new peak; a tie within a step goes to the first corner).
TEST(DriftMonitors, KeepTheFirstCornerToReachTheLargestDriftAndTheTwist) {
  GroundAcceleration ground = ramp_ground();
  const std::vector<std::vector<Term>> corners = {{{0, 1.0}, {1, -2.0}}, {{0, 1.0}, {1, 2.0}}};
  DriftMonitors::Where turning{dof(-1), dof(0), 10};
  turning.corners = corners;
  turning.twist = {{1, 1.0}};
  DriftMonitors::Where level = turning;  // equations 2 and 3: no twist, both corners alike
  level.top = dof(2);
  level.corners = {{{2, 1.0}, {3, -2.0}}, {{2, 1.0}, {3, 2.0}}};
  level.twist = {{3, 1.0}};
  DriftMonitors drifts({turning, level}, ground);
  drifts.record(state(0.0, entries({0.0, 0.0, 0.0, 0.0})));
  drifts.record(state(0.1, entries({0.0, 0.25, 0.25, 0.0})));   // corners -0.5, 0.5; 0.25 both
  drifts.record(state(0.2, entries({0.5, 0.125, 0.5, 0.0})));   // 0.25, 0.75; 0.5 both
  drifts.record(state(0.3, entries({0.75, 0.0, -0.25, 0.0})));  // 0.75, 0.75: a tie
  const DriftPeak& turned = drifts.peaks()[0];
  expect_plan(turned, 0.75, 1, 0.2, 0.25, 0.1);
  EXPECT_EQ(turned.peak_drift, 0.75);
  EXPECT_EQ(turned.time, 0.3);
  expect_plan(drifts.peaks()[1], 0.5, 0, 0.2, 0.0, 0.0);
  // Read again after another step: folded anew from the sums' peaks, not onto the last fold.
  drifts.record(state(0.4, entries({0.0, -0.5, 0.0, 0.0})));  // corners 1, 1: a new peak at 0.4
  expect_plan(drifts.peaks()[0], 1.0, 0, 0.4, 0.5, 0.4);
  expect_plan(drifts.peaks()[1], 0.5, 0, 0.2, 0.0, 0.0);
}

TEST(JointMonitors, OpeningClosingAndSeatMovementFromTheLinkAndTheGirder) {
  // A joint whose link (row 1) has a 0.05 gap; the girder is equation 2, the seat fixed; a
  // second joint on row 0 with its seat on equation 0.
  GroundAcceleration ground = ramp_ground();
  JointMonitors joints(
      {{.link_row = 1, .gap = 0.05, .girder_x = dof(2), .seat_x = dof(-1), .girder = 5},
       {.link_row = 0, .gap = 0.1, .girder_x = dof(1), .seat_x = dof(0), .girder = 4}},
      ground);
  // delta = -(gap) is the joint as built: neither opened nor closed.
  joints.record(state(0.0, entries({0.0, 0.0, 0.0}), entries({-0.1, -0.05})));
  // Joint 1 closes by 0.03 (delta = -0.02), its girder 0.03 along -x; joint 2 opens by 0.01.
  joints.record(state(0.1, entries({0.01, 0.02, -0.03}), entries({-0.11, -0.02})));
  // Joint 1 opens by 0.04 (delta = -0.09), its girder 0.01 along +x.
  joints.record(state(0.2, entries({0.0, 0.0, 0.01}), entries({-0.1, -0.09})));
  ASSERT_EQ(joints.peaks().size(), 2u);
  const JointPeak& first = joints.peaks()[0];
  EXPECT_NEAR(first.peak_closing, 0.03, 1e-15);
  EXPECT_NEAR(first.peak_opening, 0.04, 1e-15);
  EXPECT_NEAR(first.peak_seat_movement, 0.03, 1e-15);
  const JointPeak& second = joints.peaks()[1];
  EXPECT_NEAR(second.peak_closing, 0.0, 1e-15);
  EXPECT_NEAR(second.peak_opening, 0.01, 1e-15);
  EXPECT_NEAR(second.peak_seat_movement, 0.01, 1e-15);  // |0.02 - 0.01|
  // At rest relative to the ground, the girders' absolute acceleration is the ground's, 2 t.
  EXPECT_NEAR(first.peak_girder_acceleration, 0.4, 1e-15);
}

// Under moving supports the run carries u_dyn = u - R u_s (docs/model_format.md): monitors read
// from it left out the supports' quasi-static motion and a moving seat's or base's own, so the
// bundled wave-passage bridge's seat movements were off by -21 % to +17 % of its bearings'
// deformations (the same two nodes) and its pier drifts by -7 % and +16 % (audit 70). They now add
// both back (SupportMotion), and equal what links between the same nodes measure, links being
// total: each joint's seat movement its bearing's peak deformation, each pier's drift a
// vanishingly soft probe spring's from its base to its top.
TEST(DriftAndJointMonitors, UnderMovingSupportsMeasureTotalMotionAsLinksDo) {
  const std::string path = testing::bundled_model_path("three_span_bridge_wave_passage");
  nlohmann::json model = testing::bundled_model("three_span_bridge_wave_passage");
  model["analysis"]["duration"] = 8.0;
  for (const char* pier : {"p1", "p2"})
    model["links"].push_back(
        {{"id", std::string("probe.") + pier},
         {"nodes",
          {std::string("bridge.") + pier + ".base", std::string("bridge.") + pier + ".top"}},
         {"axis", {1, 0}},
         {"law", {{"type", "elastic_spring"}, {"stiffness", 1e-3}}}});
  const nlohmann::json summary = testing::model_summary(model.dump(), path);
  std::map<std::string, double> deformation;
  for (const nlohmann::json& link : summary["links"])
    if (link.contains("peak_deformation"))
      deformation[link["id"].get<std::string>()] = link["peak_deformation"].get<double>();
  const std::map<std::string, std::string> bearings = {
      {"bridge.a0.joint.girder_end", "bridge.g0.n0.bearing_x"},
      {"bridge.joint1.left_end", "bridge.g0.n4.bearing_x"},
      {"bridge.joint1.right_end", "bridge.g1.n0.bearing_x"},
      {"bridge.a1.joint.girder_end", "bridge.g2.n4.bearing_x"}};
  double worst = 0.0;
  for (const nlohmann::json& joint : summary["joints"])
    if (const auto it = bearings.find(joint["id"].get<std::string>()); it != bearings.end()) {
      const double seat = joint["peak_seat_movement"].get<double>();
      const double bearing = deformation.at(it->second);
      std::cout << it->first << ": seat movement " << seat << " m, bearing " << bearing << " m\n";
      worst = std::max(worst, std::abs(seat - bearing) / bearing);
    }
  for (const nlohmann::json& pier : summary["piers"]) {
    const std::string id = pier["id"].get<std::string>();
    const double drift = pier["peak_drift"].get<double>();
    const double probe = deformation.at("probe." + id.substr(id.rfind('.') + 1));
    std::cout << id << ": drift " << drift << " m, probe " << probe << " m\n";
    worst = std::max(worst, std::abs(drift - probe) / probe);
  }
  std::cout << "largest relative difference " << worst << "\n";
  EXPECT_LT(worst, 1e-12);
}

// A storey whose column a floor of the other building strikes between floors has a column in
// segments, the strike's force between them: its peak shear was its lowest segment's alone, on the
// bundled pair half the shear above a strike (6.66 MN against 13.7 MN in pair.right.s6, audit
// 70). It is now the largest |V| of all its segments, as an element recorder of them gives it.
TEST(DriftMonitors, AStruckColumnsPeakShearIsItsLargestSegments) {
  const std::string path = testing::bundled_model_path("adjacent_buildings");
  nlohmann::json model = testing::bundled_model("adjacent_buildings");
  const std::vector<std::string> storeys = {"pair.right.s6", "pair.left.s5", "pair.right.s2"};
  nlohmann::json elements = nlohmann::json::array();
  for (const std::string& storey : storeys)
    for (const char* segment : {".c0", ".c1"}) elements.push_back(storey + segment);
  model["recorders"] = {{{"type", "element"}, {"elements", elements}, {"file", "columns.csv"}}};
  app::RunRequest request;
  request.model_path = path;
  request.model_text = model.dump();
  const app::RunOutcome outcome = app::run_model(request);
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const Table& columns = outcome.histories.at(0).second;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  for (const std::string& storey : storeys) {
    double lowest = 0.0, largest = 0.0;
    for (std::size_t c = 0; c < columns.columns.size(); ++c) {
      const std::string& name = columns.columns[c];
      if (name.rfind(storey + ".c", 0) != 0 || !name.ends_with(".V_i")) continue;
      for (const double v : columns.values[c]) {
        largest = std::max(largest, std::abs(v));
        if (name == storey + ".c0.V_i") lowest = std::max(lowest, std::abs(v));
      }
    }
    double reported = -1.0;
    for (const nlohmann::json& drift : summary["storeys"])
      if (drift["id"] == storey) reported = drift["peak_shear"].get<double>();
    std::cout << storey << ": peak shear " << reported << ", segments' largest " << largest
              << ", lowest segment's " << lowest << "\n";
    if (storey == "pair.right.s6") {
      EXPECT_GT(largest, 1.5 * lowest);  // the segment above the strike
    }
    EXPECT_NEAR(reported / largest, 1.0, 1e-14) << storey;
  }
}

// A pier's base shear under moving supports came from the element's end forces on u_dyn, its
// base's own motion left out: on the wave-passage bridge pier p2's peak shear was 18 % above the
// force its base's support reaction (audit 70). Released onto a stiff spring to a ground node
// that the record moves (1e13 N/m, 1e14 N m/rad), each base's reaction is that spring's force:
// the pier's peak base shear now agrees with it within the pier's own inertia and damping forces
// (1.4 % under a uniform excitation, where both were always total).
TEST(DriftMonitors, APiersBaseShearUnderMovingSupportsIsItsSupportsReaction) {
  const std::string path = testing::bundled_model_path("three_span_bridge_wave_passage");
  nlohmann::json model = testing::bundled_model("three_span_bridge_wave_passage");
  model["analysis"]["duration"] = 12.0;
  nlohmann::json expanded = nlohmann::json::parse(
      io::model_to_json(builder::expand(io::parse_model(model.dump(), path))));
  for (const char* pier : {"p1", "p2"}) {
    const std::string base = std::string("bridge.") + pier + ".base",
                      ground = std::string(pier) + "g";
    for (nlohmann::json& node : expanded["nodes"])
      if (node["id"] == base) {
        nlohmann::json moved = node;
        moved["id"] = ground;
        expanded["nodes"].push_back(moved);
        break;
      }
    for (nlohmann::json& support : expanded["supports"])
      if (support["node"] == base) support["fix"] = {"y"};
    expanded["supports"].push_back({{"node", ground}, {"fix", {"x", "y", "rz"}}});
    expanded["links"].push_back({{"id", std::string(pier) + ".rx"},
                                 {"nodes", {ground, base}},
                                 {"axis", {1, 0}},
                                 {"law", {{"type", "elastic_spring"}, {"stiffness", 1e13}}}});
    expanded["links"].push_back({{"id", std::string(pier) + ".rm"},
                                 {"nodes", {ground, base}},
                                 {"dof", "rotation"},
                                 {"law", {{"type", "elastic_spring"}, {"stiffness", 1e14}}}});
    for (nlohmann::json& excitation : expanded["excitations"])
      for (nlohmann::json& moved : excitation["supports"])
        if (moved == base) moved = ground;
  }
  const nlohmann::json summary = testing::model_summary(expanded.dump(), path);
  std::map<std::string, double> reaction;
  for (const nlohmann::json& link : summary["links"])
    reaction[link["id"].get<std::string>()] = link["peak_force"].get<double>();
  for (const char* pier : {"p1", "p2"}) {
    double shear = 0.0;
    for (const nlohmann::json& drift : summary["piers"])
      if (drift["id"] == std::string("bridge.") + pier) shear = drift["peak_shear"].get<double>();
    const double held = reaction.at(std::string(pier) + ".rx");
    std::cout << pier << ": peak base shear " << shear << " N, its support's reaction " << held
              << " N, " << 100.0 * (shear / held - 1.0) << " %\n";
    EXPECT_NEAR(shear / held, 1.0, 0.015) << pier;
  }
}

// A girder end leaves its seat by moving away from its joint, toward its own span: toward the
// joint the other girder or the backwall stops it. The unseating margin counted the girder's
// movement either way, so a seat was "unseated" by a movement into the joint (audit 70: 0.113 m
// into the joint against 0.051 m away from it). It now takes the movement away from the joint,
// the joint's opening way from its pounding link: on the bundled bridge, from the nodes'
// histories, the left ends of the joints and the right abutment's end move off their seats
// along -x, the others along +x.
TEST(JointMonitors, AGirderEndsUnseatingMovementIsAwayFromItsJoint) {
  const std::string path = testing::bundled_model_path("three_span_bridge");
  nlohmann::json model = testing::bundled_model("three_span_bridge");
  model["analysis"]["duration"] = 12.0;
  const app::LoadedModel loaded = app::load_model_text(model.dump(), path);
  // monitor: girder end, seat, the sign of the movement away from the joint
  const std::vector<std::tuple<std::string, std::string, std::string, double>> ends = {
      {"bridge.a0.joint.girder_end", "bridge.g0.n0", "bridge.a0.seat", 1.0},
      {"bridge.joint1.left_end", "bridge.g0.n4", "bridge.p1.top", -1.0},
      {"bridge.joint1.right_end", "bridge.g1.n0", "bridge.p1.top", 1.0},
      {"bridge.joint2.left_end", "bridge.g1.n4", "bridge.p2.top", -1.0},
      {"bridge.joint2.right_end", "bridge.g2.n0", "bridge.p2.top", 1.0},
      {"bridge.a1.joint.girder_end", "bridge.g2.n4", "bridge.a1.seat", -1.0}};
  std::vector<std::string> nodes;
  for (const auto& [monitor, girder, seat, sign] : ends) {
    nodes.push_back(girder);
    nodes.push_back(seat);
  }
  const testing::NodeMotion motion = testing::run_node_motion(loaded.built, nodes, {0});
  const nlohmann::json summary = testing::model_summary(model.dump(), path);
  double worst = 0.0;
  int one_sided = 0;
  for (std::size_t k = 0; k < ends.size(); ++k) {
    const auto& [monitor, girder, seat, sign] = ends[k];
    double away = 0.0, either = 0.0;
    for (const std::vector<double>& u : motion.values) {
      away = std::max(away, sign * (u[2 * k] - u[2 * k + 1]));
      either = std::max(either, std::abs(u[2 * k] - u[2 * k + 1]));
    }
    for (const nlohmann::json& joint : summary["joints"])
      if (joint["id"] == monitor) {
        const double reported = joint["peak_unseating_movement"].get<double>();
        const double margin = joint["unseating_margin"].get<double>();
        const double width = joint["seat_width"].get<double>();
        std::cout << monitor << ": away from the joint " << reported << " m (histories " << away
                  << "), either way " << either << ", margin " << margin << "\n";
        worst = std::max({worst, std::abs(reported - away), std::abs(margin - (width - away))});
        one_sided += away < either;
      }
  }
  EXPECT_LT(worst, 1e-15);
  EXPECT_GT(one_sided, 0);  // some end moved farther into its joint than away from it
}

}  // namespace
}  // namespace pound::results
