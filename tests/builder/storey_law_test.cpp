// adjacent_buildings yielding storeys: a storey law is the storey's exact shear-drift relation
// (an elastic_spring law with its dashpot reproduces the elastic building), the leaning column
// gives each storey its P-Delta -P/h from the weight above, and what cannot be modelled (a floor
// of the other building hitting a yielding storey mid-height) or would be set twice is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "assembly/pushover.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"

namespace pound::builder {
namespace {

using Json = nlohmann::json;

constexpr double kG = 9.80665;

// A pair of equal-floor buildings (3 and 2 storeys of 3 m) far apart, no record.
Json pair_model() {
  return Json::parse(R"({
    "dimension": 2, "units": {"length": "m", "time": "s"},
    "generators": [{"type": "adjacent_buildings", "id": "pair", "separation": 1.0,
      "left": {"damping_ratio": 0.05, "storeys": [
        {"height": 3, "mass": 3e5, "stiffness": 4e8}, {"height": 3, "mass": 3e5, "stiffness": 3e8},
        {"height": 3, "mass": 2e5, "stiffness": 2e8}]},
      "right": {"damping_ratio": 0.05, "storeys": [
        {"height": 3, "mass": 2e5, "stiffness": 3e8}, {"height": 3, "mass": 2e5, "stiffness": 2e8}]},
      "law": {"type": "jankowski", "stiffness": 2.75e9, "restitution": 0.65}}],
    "analysis": {"time_step": 0.002, "duration": 4}})");
}

Json& storeys(Json& model, const char* side) { return model["generators"][0][side]["storeys"]; }

BuiltModel built(const Json& model, std::vector<model::GroundMotion> motions = {}) {
  return build(io::parse_model(model.dump(), "pair.json"), std::move(motions));
}

// The floors' x displacement histories under a half-sine ground pulse.
std::vector<double> floor_histories(const Json& model) {
  std::vector<double> pulse;
  for (int k = 0; k <= 500; ++k) pulse.push_back(3.0 * std::sin(3.14159265358979 * k / 500.0));
  Json with_record = model;
  with_record["excitations"] = Json::parse(R"([{"record": "pulse.txt", "units": "model"}])");
  const BuiltModel made =
      built(with_record,
            {model::GroundMotion{.name = "pulse", .time_step = 0.002, .acceleration = pulse}});
  assembly::StructuralSystem system(made.model);
  auto integrator = make_integrator(made.analysis);
  integrators::TransientAnalysis analysis(system, *integrator,
                                          make_transient_settings(made.analysis));
  std::vector<Index> floors;
  for (const char* id :
       {"pair.left.f1", "pair.left.f2", "pair.left.f3", "pair.right.f1", "pair.right.f2"})
    floors.push_back(system.dofs().own_equation(made.node_index.at(id), 0));
  std::vector<double> history;
  integrators::State state;
  analysis.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    for (Index row : floors) history.push_back(s.displacement[row]);
  });
  return history;
}

// max_k |a_k - b_k|
double largest_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) largest = std::max(largest, std::abs(a[k] - b[k]));
  return largest;
}

void set_storey_damping(Json& model, const char* kind) {
  for (const char* side : {"left", "right"}) model["generators"][0][side]["storey_damping"] = kind;
}

TEST(StoreyLaw, ElasticStoreyLinksReproduceTheElasticBuilding) {
  Json elastic = pair_model(), linked = pair_model();
  for (const char* side : {"left", "right"})
    for (Json& storey : storeys(linked, side)) storey["law"] = {{"type", "elastic_spring"}};
  const std::vector<double> columns = floor_histories(elastic), links = floor_histories(linked);
  ASSERT_EQ(columns.size(), links.size());
  double peak = 0.0;
  for (double u : columns) peak = std::max(peak, std::abs(u));
  const double difference = largest_difference(columns, links);
  std::cout << "storey links against storey columns (with their a1 k dashpots): max difference "
            << difference / peak << " of the peak floor displacement " << peak << "\n";
  EXPECT_GT(peak, 1e-3);
  // Both solve the same linear equations; only the order of the sums differs (and Newton's
  // tolerance 1e-10 on the link rows).
  EXPECT_LT(difference / peak, 1e-8);
  // Without its dashpots the building loses its stiffness-proportional damping.
  set_storey_damping(linked, "none");
  const double change = largest_difference(columns, floor_histories(linked));
  std::cout << "storey_damping none changes the response by " << change / peak << "\n";
  EXPECT_GT(change / peak, 1e-3);
  // An elastic law's committed tangent is its stiffness: a1 k in the link is the dashpot again.
  set_storey_damping(linked, "committed");
  const double committed_difference = largest_difference(columns, floor_histories(linked));
  std::cout << "storey_damping committed (elastic storeys) against the columns: "
            << committed_difference / peak << "\n";
  EXPECT_LT(committed_difference / peak, 1e-8);
}

// The left building's pushover at its top under gravity with chord P-Delta: storey 1 bilinear
// (V_y, r), storeys 2 and 3 elastic columns. Each storey's shear is the pushing load lambda, so
// lambda = F_1(d_1) - P_1 d_1 / h and lambda = (k_s - P_s / h) d_s for s = 2, 3 exactly, with P_s
// the weight above storey s.
TEST(StoreyLaw, PushoverGivesTheStoreyLawLessTheWeightAboveOverTheHeight) {
  Json model = pair_model();
  const double yield_force = 1.5e6, ratio = 0.05, k1 = 4e8, h = 3.0;
  storeys(model, "left")[0]["law"] = {
      {"type", "bilinear_spring"}, {"yield_force", yield_force}, {"hardening_ratio", ratio}};
  model["gravity"] = {{"p_delta", "chord"}};
  const BuiltModel made = built(model);
  assembly::StructuralSystem system(made.model);
  const auto x = [&](const char* id) {
    return system.dofs().own_equation(made.node_index.at(id), 0);
  };
  assembly::PushoverControl control{.equation = x("pair.left.f3"), .target = 0.1, .increments = 50};
  control.pattern = Vector::Zero(system.size());
  control.pattern[control.equation] = 1.0;
  const double weights[3] = {8e5 * kG, 5e5 * kG, 2e5 * kG}, stiffness[3] = {k1, 3e8, 2e8};
  double worst = 0.0, largest_drift = 0.0;
  const auto check = [&](const assembly::PushoverPoint& point, const Vector& u) {
    const double drifts[3] = {u[x("pair.left.f1")], u[x("pair.left.f2")] - u[x("pair.left.f1")],
                              u[x("pair.left.f3")] - u[x("pair.left.f2")]};
    const double d_y = yield_force / k1;
    const double link =
        drifts[0] <= d_y ? k1 * drifts[0] : yield_force + ratio * k1 * (drifts[0] - d_y);
    worst = std::max(worst, std::abs(link - weights[0] / h * drifts[0] - point.load_factor));
    for (int s = 1; s < 3; ++s)
      worst = std::max(worst,
                       std::abs((stiffness[s] - weights[s] / h) * drifts[s] - point.load_factor));
    largest_drift = std::max(largest_drift, drifts[0]);
  };
  const assembly::PushoverResult result =
      assembly::pushover(system, Vector::Zero(system.size()), control, check);
  EXPECT_TRUE(result.stopped.empty()) << result.stopped;
  std::cout << "storey shears against F(d) - P d / h: worst " << worst / yield_force
            << " of V_y; storey 1 drift reached " << largest_drift / (yield_force / k1)
            << " x yield\n";
  EXPECT_GT(largest_drift, 10 * yield_force / k1);  // well into the post-yield branch
  EXPECT_LT(worst / yield_force, 1e-9);
  // The storey's drift monitor yields where its law does.
  EXPECT_TRUE(made.drift_monitors[0].yields);
  EXPECT_NEAR(*made.drift_monitors[0].yield_drift, yield_force / k1, 1e-18);
}

TEST(StoreyLaw, GravityBeyondAStoreysBucklingLoadIsRefused) {
  Json model = pair_model();
  model["gravity"] = {{"p_delta", "chord"}, {"acceleration", 2e3}};  // P_1 / h > k_1
  const BuiltModel made = built(model);
  try {
    assembly::StructuralSystem system(made.model);
    FAIL() << "a storey past its buckling load was accepted";
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("/gravity/p_delta"), std::string::npos);
  }
}

void expect_refused(const Json& model, const std::string& path, const std::string& words) {
  try {
    built(model);
    FAIL() << "accepted; expected an error at " << path;
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("pair.json: " + path), std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(StoreyLaw, WhatCannotBeModelledIsRefusedAtItsPath) {
  Json given_stiffness = pair_model();
  storeys(given_stiffness, "left")[1]["law"] = {
      {"type", "bilinear_spring"}, {"stiffness", 1e8}, {"yield_force", 1e6}};
  expect_refused(given_stiffness, "/generators/0/left/storeys/1/law/stiffness",
                 "the storey's own `stiffness`");
  Json contact_law = pair_model();
  storeys(contact_law, "right")[0]["law"] = {{"type", "viscous_damper"}, {"coefficient", 1e6}};
  expect_refused(contact_law, "/generators/0/right/storeys/0/law", "cannot be a storey's");
  Json cut = pair_model();
  storeys(cut, "right")[0]["height"] = 4.5;  // the left floors at 3 and 6 m... 3 m cuts it
  storeys(cut, "right")[0]["law"] = {{"type", "bilinear_spring"}, {"yield_force", 1e6}};
  expect_refused(cut, "/generators/0/right/storeys/0/law", "between its floors");
  Json beam_force = Json::parse(R"({"dimension": 2,
    "nodes": [{"id": "a", "x": 0, "y": 0}, {"id": "b", "x": 0, "y": 3}],
    "materials": [{"id": "m", "youngs_modulus": 1, "density": 0}],
    "elements": [{"id": "e", "type": "beam", "nodes": ["a", "b"], "material": "m", "area": 1,
                  "inertia": 1, "axial_force": -1e5}],
    "analysis": {"time_step": 0.1, "duration": 1}})");
  expect_refused(beam_force, "/elements/0/axial_force",
                 "unknown field");  // as any truss-only field
}

}  // namespace
}  // namespace pound::builder
