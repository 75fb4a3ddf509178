// A deck mass on one bearing in 3-D under a record along the diagonal of plan (x = y): with its
// two horizontal directions coupled (a link's "shear") the bearing moves the deck as a single
// uniaxial spring along the diagonal does, and yields at F_y; as two uniaxial springs along x
// and y (what 3-D bridges had before) it yields at sqrt(2) F_y. Along x alone the coupled and the
// uncoupled bearing agree. The bearing's rest stiffness enters the modes in both directions, and
// the girder_bridge generator couples its bearings in space unless told not to.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "app/model_loading.hpp"
#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "support/input_error.hpp"
#include "support/model_summary.hpp"

namespace pound::app {
namespace {

using nlohmann::json;

const std::string kPath = std::string(POUND_SOURCE_DIR) + "/models/bearing.json";
constexpr double kMass = 1.0e6, kStiffness = 2.0e7, kYield = 3.0e5;

json bilinear() {
  return {{"type", "bilinear_spring"}, {"stiffness", kStiffness}, {"yield_force", kYield}};
}

json link(const std::string& id, std::array<double, 3> axis, json law) {
  return {{"id", id}, {"nodes", {"deck", "seat"}}, {"axis", axis}, {"law", std::move(law)}};
}

// The deck over its seat, turning held; `links` its bearing(s), excited along `direction`.
json deck(const std::vector<json>& links, std::array<double, 3> direction) {
  return {{"dimension", 3},
          {"nodes",
           {{{"id", "deck"}, {"x", 0}, {"y", 0}, {"z", 0}},
            {{"id", "seat"}, {"x", 0}, {"y", 0}, {"z", 0}}}},
          {"masses", {{{"node", "deck"}, {"mass", kMass}}}},
          {"supports",
           {{{"node", "seat"}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}},
            {{"node", "deck"}, {"fix", {"rx", "ry", "rz"}}}}},
          {"links", links},
          {"excitations",
           {{{"record", "../ground_motions/synthetic_firm_01.AT2"},
             {"units", "g"},
             {"scale", {{"pga", 0.4}}},
             {"direction", direction}}}},
          {"analysis", {{"time_step", 0.005}, {"duration", 12.0}}}};
}

json takeda_law() {
  return {{"type", "takeda"}, {"stiffness", kStiffness}, {"yield_force", kYield}};
}

json coupled_bearing() {
  json bearing = link("bearing", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}});
  bearing["shear"] = bilinear();
  return bearing;
}

const json& link_summary(const json& summary, const std::string& id) {
  for (const json& entry : summary["links"])
    if (entry["id"] == id) return entry;
  throw std::runtime_error("no link " + id);
}

double peak(const json& entry) { return entry["peak_force"].get<double>(); }

constexpr double kHalfRoot2 = 0.5 * std::numbers::sqrt2;
constexpr std::array<double, 3> kDiagonal{kHalfRoot2, kHalfRoot2, 0.0};

// The reference of a coupled bearing under the diagonal record: one uniaxial spring of `law`
// along the diagonal (across it a spring that never acts), excited along it.
json along_the_diagonal(const json& law) {
  return deck({link("along", kDiagonal, law),
               link("across", {-kHalfRoot2, kHalfRoot2, 0.0},
                    {{"type", "elastic_spring"}, {"stiffness", kStiffness}}),
               link("up", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}})},
              kDiagonal);
}

TEST(CoupledBearing, ADiagonalRecordYieldsItAsOneSpringAlongTheDiagonal) {
  const json coupled = testing::model_summary(deck({coupled_bearing()}, kDiagonal).dump(), kPath);
  const json& shear = link_summary(coupled, "bearing")["shear"];
  const json diagonal = testing::model_summary(along_the_diagonal(bilinear()).dump(), kPath);
  const json& along = link_summary(diagonal, "along");
  const double reference = along["peak_deformation"].get<double>();
  const double deformation_error =
      std::abs(shear["peak_deformation"].get<double>() - reference) / reference;
  const double energy_error = std::abs(shear["hysteretic_energy"].get<double>() -
                                       along["hysteretic_energy"].get<double>()) /
                              along["hysteretic_energy"].get<double>();
  // Two uniaxial springs along x and y: each reaches F_y.
  const json uncoupled = testing::model_summary(
      deck({link("x", {1, 0, 0}, bilinear()), link("y", {0, 1, 0}, bilinear()),
            link("up", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}})},
           kDiagonal)
          .dump(),
      kPath);
  const double uncoupled_peak =
      std::hypot(peak(link_summary(uncoupled, "x")), peak(link_summary(uncoupled, "y")));
  std::cout << fmt::format(
      "diagonal record, ductility {:.2f}: coupled against one spring along the diagonal: peak "
      "deformation {:.1e}, hysteretic energy {:.1e}; peak shear / F_y coupled {:.12f}, two "
      "uniaxial springs {:.6f}\n",
      shear["ductility"].get<double>(), deformation_error, energy_error,
      shear["peak_force"].get<double>() / kYield, uncoupled_peak / kYield);
  EXPECT_GT(shear["ductility"].get<double>(), 3.0) << "the bearing must yield well";
  EXPECT_LT(deformation_error, 1e-9);
  EXPECT_LT(energy_error, 1e-9);
  EXPECT_NEAR(shear["peak_force"].get<double>() / kYield, 1.0, 1e-12);
  EXPECT_NEAR(uncoupled_peak / kYield, std::numbers::sqrt2, 1e-9);
  EXPECT_LT(coupled["energy"]["balance_error"].get<double>(), 1e-9);
}

// A Bouc-Wen isolator (n = 2, beta = gamma, F_y = k z_max, 5 % hardening): coupled, under the
// diagonal record, it moves the deck as the uniaxial Bouc-Wen spring along the diagonal does
// (each integrates z within ~1e-9 z_max of its ODE, tests/links/plane_bouc_wen_test.cpp; for
// n = 2 on nearly the same sub-steps).
TEST(CoupledBearing, ACoupledBoucWenIsolatorIsTheUniaxialLawAlongTheDiagonal) {
  const json smooth = {{"type", "bouc_wen"},
                       {"stiffness", kStiffness},
                       {"hardening_ratio", 0.05},
                       {"sharpness", 2.0},
                       {"beta", 1.0},
                       {"gamma", 1.0},
                       {"yield_force", kYield}};
  json bearing = coupled_bearing();
  bearing["shear"] = smooth;
  const json coupled = testing::model_summary(deck({bearing}, kDiagonal).dump(), kPath);
  const json& shear = link_summary(coupled, "bearing")["shear"];
  const json diagonal = testing::model_summary(along_the_diagonal(smooth).dump(), kPath);
  const json& along = link_summary(diagonal, "along");
  const auto relative = [](const json& a, const json& b) {
    return std::abs(a.get<double>() - b.get<double>()) / std::abs(b.get<double>());
  };
  const double deformation_error = relative(shear["peak_deformation"], along["peak_deformation"]);
  const double force_error = relative(shear["peak_force"], along["peak_force"]);
  const double energy_error = relative(shear["hysteretic_energy"], along["hysteretic_energy"]);
  std::cout << fmt::format(
      "Bouc-Wen isolator, diagonal record, ductility {:.2f}: coupled against the uniaxial law "
      "along the diagonal: peak deformation {:.1e}, peak force {:.1e}, hysteretic energy {:.1e}; "
      "energy balance {:.1e}\n",
      shear["ductility"].get<double>(), deformation_error, force_error, energy_error,
      coupled["energy"]["balance_error"].get<double>());
  EXPECT_GT(shear["ductility"].get<double>(), 3.0) << "the isolator must yield well";
  EXPECT_LT(deformation_error, 1e-9);
  EXPECT_LT(force_error, 1e-9);
  EXPECT_LT(energy_error, 1e-9);
  EXPECT_LT(coupled["energy"]["balance_error"].get<double>(), 1e-9);
}

TEST(CoupledBearing, AlongOneAxisItIsTheUniaxialBearing) {
  const json coupled =
      testing::model_summary(deck({coupled_bearing()}, {1.0, 0.0, 0.0}).dump(), kPath);
  const json uncoupled = testing::model_summary(
      deck({link("x", {1, 0, 0}, bilinear()), link("y", {0, 1, 0}, bilinear()),
            link("up", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}})},
           {1.0, 0.0, 0.0})
          .dump(),
      kPath);
  const json& shear = link_summary(coupled, "bearing")["shear"];
  const json& x = link_summary(uncoupled, "x");
  const double error =
      std::abs(shear["peak_deformation"].get<double>() - x["peak_deformation"].get<double>()) /
      x["peak_deformation"].get<double>();
  std::cout << fmt::format("record along x: coupled against uniaxial peak deformation {:.1e}\n",
                           error);
  EXPECT_LT(error, 1e-12);
  EXPECT_DOUBLE_EQ(shear["residual_deformation"].get<double>(),
                   std::abs(x["residual_deformation"].get<double>()));
}

// A lead-rubber bearing under two components at right angles (0.4 g and 0.3 g, turned 37
// degrees from x): the explicit central difference and Newmark give the same shear history's
// peaks to their O(dt^2) difference (dt = 1 ms, ductility about 45).
TEST(CoupledBearing, CentralDifferenceAndNewmarkAgreeUnderTwoComponents) {
  json bearing = coupled_bearing();
  bearing["shear"] = {{"type", "lead_rubber"},
                      {"characteristic_strength", 2.7e5},
                      {"post_yield_stiffness", 2e6},
                      {"elastic_stiffness", 2e7}};
  json model = deck({bearing}, {0.8, 0.6, 0.0});
  model["excitations"].push_back({{"record", "../ground_motions/synthetic_soft_01.AT2"},
                                  {"units", "g"},
                                  {"scale", {{"pga", 0.3}}},
                                  {"direction", {-0.6, 0.8, 0.0}}});
  model["analysis"]["time_step"] = 0.001;
  const auto shear = [&](const std::string& integrator) {
    model["analysis"]["integrator"] = integrator;
    return link_summary(testing::model_summary(model.dump(), kPath), "bearing")["shear"];
  };
  const json implicit = shear("newmark_average_acceleration");
  const json explicit_ = shear("central_difference");
  double worst = 0.0;
  for (const std::string key : {"peak_force", "peak_deformation", "hysteretic_energy"})
    worst =
        std::max(worst, std::abs(explicit_[key].get<double>() / implicit[key].get<double>() - 1));
  std::cout << fmt::format(
      "two components, ductility {:.1f}: central difference against Newmark {:.1e}\n",
      implicit["ductility"].get<double>(), worst);
  EXPECT_GT(implicit["ductility"].get<double>(), 10.0);
  EXPECT_LT(worst, 1e-5);
}

// An elastic shear holds the deck in x and y alike: two modes at k / m, one at k_v / m.
TEST(CoupledBearing, ItsRestStiffnessHoldsTheDeckInBothDirections) {
  json bearing = coupled_bearing();
  bearing["shear"] = {{"type", "elastic_spring"}, {"stiffness", kStiffness}};
  const LoadedModel loaded = load_model_text(deck({bearing}, kDiagonal).dump(), kPath);
  const assembly::StructuralSystem system(loaded.built.model);
  const assembly::Modes modes = assembly::modal_analysis(system);
  ASSERT_EQ(modes.omega_squared.size(), 3);
  const double expected = kStiffness / kMass;
  const double error = std::max(std::abs(modes.omega_squared[0] / expected - 1.0),
                                std::abs(modes.omega_squared[1] / expected - 1.0));
  std::cout << fmt::format("deck on an elastic coupled bearing: omega^2 against k / m {:.1e}\n",
                           error);
  EXPECT_LT(error, 1e-14);
  EXPECT_NEAR(modes.omega_squared[2] / (1e10 / kMass), 1.0, 1e-14);
}

// A bearing whose plan axes are turned by 30 degrees ("tangent": t_1 = (cos 30, sin 30, 0)) and
// whose two directions differ (shear_2 twice as stiff and 1.5 times as strong): under a record
// along t_1 it is the uniaxial spring of `shear` along t_1, under one along t_2 = axis x t_1 the
// uniaxial spring of `shear_2` along t_2.
TEST(CoupledBearing, ATurnedEllipticBearingActsAlongItsOwnTangents) {
  const double angle = std::numbers::pi / 6.0;
  const std::array<double, 3> t1{std::cos(angle), std::sin(angle), 0.0};
  const std::array<double, 3> t2{-std::sin(angle), std::cos(angle), 0.0};
  const json second = {
      {"type", "bilinear_spring"}, {"stiffness", 2.0 * kStiffness}, {"yield_force", 1.5 * kYield}};
  json bearing = coupled_bearing();
  bearing["shear_2"] = second;
  bearing["tangent"] = t1;
  double worst = 0.0;
  for (const int along_tangent : {1, 2}) {
    const std::array<double, 3>& direction = along_tangent == 1 ? t1 : t2;
    const json law = along_tangent == 1 ? bilinear() : second;
    const json coupled = testing::model_summary(deck({bearing}, direction).dump(), kPath);
    const json& shear = link_summary(coupled, "bearing")["shear"];
    const std::array<double, 3> normal{-direction[1], direction[0], 0.0};
    const json uniaxial = testing::model_summary(
        deck({link("along", direction, law), link("across", normal, bilinear()),
              link("up", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}})},
             direction)
            .dump(),
        kPath);
    const json& along = link_summary(uniaxial, "along");
    const double error = std::abs(
        shear["peak_deformation"].get<double>() / along["peak_deformation"].get<double>() - 1.0);
    std::cout << fmt::format(
        "bearing turned 30 deg, elliptic, record along t_{}: coupled against the uniaxial spring "
        "{:.1e} (ductility {:.2f})\n",
        along_tangent, error, shear["ductility"].get<double>());
    EXPECT_GT(shear["ductility"].get<double>(), 2.0);
    worst = std::max(worst, error);
  }
  EXPECT_LT(worst, 1e-9);
  json alone = link("spring", {0, 0, 1}, bilinear());
  alone["tangent"] = t1;
  testing::expect_input_error([&] { load_model_text(deck({alone}, t1).dump(), kPath); },
                              "/links/0/tangent", "has neither");
  bearing["tangent"] = {0.0, 0.0, 1.0};
  testing::expect_input_error([&] { load_model_text(deck({bearing}, t1).dump(), kPath); },
                              "/links/0/tangent", "along the link's axis");
}

// Stiffness-proportional damping of the shear ("rayleigh", a1 = 0.01 s): the coupled bearing under
// the diagonal record with its damping on the initial stiffness or on the committed tangent
// still moves as one uniaxial spring along the diagonal with the same damping (the spring across
// it, damped too, never moves), its damping work and hysteretic energy apart as that spring's.
TEST(CoupledBearing, ItsRayleighDampingIsTheUniaxialSpringsAlongTheDiagonal) {
  for (const char* stiffness : {"initial", "committed"}) {
    const json rayleigh = {{"stiffness", stiffness}, {"stiffness_coefficient", 0.01}};
    json bearing = coupled_bearing();
    bearing["rayleigh"] = rayleigh;
    const json coupled = testing::model_summary(deck({bearing}, kDiagonal).dump(), kPath);
    const json& shear = link_summary(coupled, "bearing")["shear"];
    json along_link = link("along", kDiagonal, bilinear());
    along_link["rayleigh"] = rayleigh;
    json across_link = link("across", {-kHalfRoot2, kHalfRoot2, 0.0},
                            {{"type", "elastic_spring"}, {"stiffness", kStiffness}});
    across_link["rayleigh"] = rayleigh;
    json up = link("up", {0, 0, 1}, {{"type", "elastic_spring"}, {"stiffness", 1e10}});
    up["rayleigh"] = rayleigh;
    const json diagonal =
        testing::model_summary(deck({along_link, across_link, up}, kDiagonal).dump(), kPath);
    const json& along = link_summary(diagonal, "along");
    double worst = 0.0;
    for (const auto& [mine, theirs] : {std::pair{"peak_deformation", "peak_deformation"},
                                       {"hysteretic_energy", "hysteretic_energy"},
                                       {"damping_energy", "damping_energy"}})
      worst =
          std::max(worst, std::abs(shear[mine].get<double>() / along[theirs].get<double>() - 1.0));
    std::cout << fmt::format(
        "diagonal record, {} stiffness damping: coupled against the damped spring along the "
        "diagonal: peak deformation, hysteretic and damping energy to {:.1e} (damping energy "
        "{:.4g}, hysteretic {:.4g}); energy balance {:.1e}\n",
        stiffness, worst, shear["damping_energy"].get<double>(),
        shear["hysteretic_energy"].get<double>(), coupled["energy"]["balance_error"].get<double>());
    EXPECT_GT(shear["ductility"].get<double>(), 3.0);
    EXPECT_LT(worst, 1e-9);
    EXPECT_LT(coupled["energy"]["balance_error"].get<double>(), 1e-9);
  }
}

TEST(CoupledBearing, BadShearsAreRefusedAtTheirPath) {
  const auto refused = [&](json bearing, const std::string& where, const std::string& phrase,
                           int dimension = 3) {
    json model = deck({bearing}, kDiagonal);
    model["dimension"] = dimension;
    testing::expect_input_error([&] { load_model_text(model.dump(), kPath); }, where, phrase);
  };
  json friction = coupled_bearing();
  friction["friction"] = {{"coefficient", 0.1}};
  refused(friction, "/links/0/friction", "not both");
  json takeda = coupled_bearing();
  takeda["shear"] = takeda_law();
  refused(takeda, "/links/0/shear/type", "takeda cannot");
  json hard = coupled_bearing();
  hard["law"] = {{"type", "hard_contact"}, {"restitution", 0.5}};
  refused(hard, "/links/0/law", "force law");
}

// girder_bridge in space: one `.bearing` per girder end, coupled, unless "none" is asked for;
// "circular" with a law that has no coupled form is refused.
TEST(CoupledBearing, TheBridgeGeneratorCouplesItsBearingsInSpace) {
  std::ifstream file(std::string(POUND_SOURCE_DIR) + "/models/skewed_bridge_3d.json");
  std::stringstream text;
  text << file.rdbuf();
  json model = json::parse(text.str());
  const auto bearings = [&](const json& bridge) {
    const LoadedModel loaded = load_model_text(bridge.dump(), kPath);
    int coupled = 0, x = 0;
    for (const model::Link& l : loaded.built.model.links) {
      coupled += l.shear.has_value();
      x += l.id.ends_with(".bearing_x");
    }
    return std::pair{coupled, x};
  };
  const auto [coupled, x] = bearings(model);
  EXPECT_GT(coupled, 0);
  EXPECT_EQ(x, 0);
  json smooth = model;  // a Bouc-Wen isolator couples too
  smooth["generators"][0]["bearing"] = {{"type", "bouc_wen"}, {"stiffness", 2e7},
                                        {"sharpness", 2.0},   {"beta", 1.0},
                                        {"gamma", 1.0},       {"yield_force", 3e5}};
  EXPECT_EQ(bearings(smooth), (std::pair{coupled, 0}));
  model["generators"][0]["bearing_interaction"] = "none";
  const auto [none_coupled, none_x] = bearings(model);
  EXPECT_EQ(none_coupled, 0);
  EXPECT_EQ(none_x, coupled);
  model["generators"][0]["bearing_interaction"] = "circular";
  model["generators"][0]["bearing"] = takeda_law();
  testing::expect_input_error([&] { load_model_text(model.dump(), kPath); },
                              "/generators/0/bearing_interaction", "no coupled form");
}

}  // namespace
}  // namespace pound::app

namespace pound::app {
namespace {

// A bearing a static initial state pushes past yield (a deck's dead load on a sloped seat, a
// thermal push) holds F^2 / 2k of elastic energy before the run does any work on it: its
// hysteretic energy is what the run dissipated, 0 where the run only holds it there or moves it
// elastically about it (it read -F^2 / 2k: -562.5 J for the audit's bearing at 1.5 F_y).
TEST(CoupledBearing, AStaticStatesYieldIsNotTheRunsHystereticEnergy) {
  const double angle = std::numbers::pi / 6.0;
  json hardening = bilinear();
  hardening["hardening_ratio"] = 0.05;  // held past yield
  json bearing = coupled_bearing();
  bearing["shear"] = hardening;
  for (const bool shaken : {false, true}) {
    // At rest it is pushed past yield; shaken, to half of it (a record at the yield surface
    // yields it further at once).
    const double push = shaken ? 0.5 * kYield : 1.5 * kYield, extra = shaken ? 0.0 : 1.2 * kYield;
    json model = deck({bearing, link("x", {1, 0, 0}, hardening)}, {1, 0, 0});
    model["loads"] = {
        {{"node", "deck"}, {"x", push * std::cos(angle) + extra}, {"y", push * std::sin(angle)}}};
    model["analysis"] = {{"time_step", 0.005}, {"duration", 2.0}, {"initial_state", "static"}};
    if (shaken)  // small enough to stay elastic about the pushed state
      model["excitations"][0]["scale"] = {{"pga", 0.002}};
    else
      model.erase("excitations");
    const json summary = testing::model_summary(model.dump(), kPath);
    const double coupled = link_summary(summary, "bearing")["shear"]["hysteretic_energy"];
    const double uniaxial = link_summary(summary, "x")["hysteretic_energy"];
    const double held = kYield * kYield / (2.0 * kStiffness);  // the order of what it holds
    std::cout << fmt::format(
        "static push {}: hysteretic energy of the coupled bearing {:.2e}, of the "
        "uniaxial link {:.2e} of F_y^2/2k\n",
        shaken ? "to half the yield, then a record that keeps it elastic"
               : "past yield, then at rest",
        coupled / held, uniaxial / held);
    EXPECT_LT(std::abs(coupled), 1e-9 * held);
    EXPECT_LT(std::abs(uniaxial), 1e-9 * held);
  }
}

}  // namespace
}  // namespace pound::app
