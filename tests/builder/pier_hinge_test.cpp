// girder_bridge pier hinges: the hinged pier keeps the elastic pier's lateral stiffness (the
// (n + 1) / n rule), its drift monitor yields at M_y h^2 / (3 E I) and calls the ratio a
// ductility; an elastic pier's ratio is only a demand; what the generator sets may not be given.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "assembly/pushover.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "support/push_stiffness.hpp"

namespace pound::builder {
namespace {

using Json = nlohmann::json;

// The bundled three-span bridge, its record left out, with `edit` applied to its generator.
Json bridge(const std::function<void(Json&)>& edit = {}) {
  std::ifstream file(std::string(POUND_SOURCE_DIR) + "/models/three_span_bridge.json");
  Json model = Json::parse(file);
  model.erase("excitations");
  model["analysis"]["duration"] = 1.0;
  if (edit) edit(model["generators"][0]);
  return model;
}

void add_hinges(Json& generator) {
  generator.erase("pier_yield_displacement");
  generator["pier_hinge"] = {{"yield_moment", 4.0e6},
                             {"law", {{"type", "bilinear_spring"}, {"hardening_ratio", 0.02}}}};
}

BuiltModel built(const Json& model) { return build(io::parse_model(model.dump(), "bridge.json")); }

// The lateral stiffness at a pier top, from one small elastic push.
double pier_top_stiffness(const BuiltModel& model) {
  return testing::push_stiffness(model, "bridge.p1.top", 0);
}

TEST(PierHinge, KeepsTheElasticPiersLateralStiffness) {
  const double elastic = pier_top_stiffness(built(bridge()));
  const double hinged = pier_top_stiffness(built(bridge(add_hinges)));
  const double error = std::abs(hinged / elastic - 1);
  std::cout << "pier-top stiffness: elastic " << elastic << ", hinged " << hinged
            << ", relative difference " << error << "\n";
  EXPECT_LT(error, 1e-9);
}

TEST(PierHinge, TheDriftMonitorYieldsWhereTheHingeDoes) {
  const BuiltModel hinged = built(bridge(add_hinges));
  const double ei = 3.0e10 * 0.8, h = 8.0;
  ASSERT_EQ(hinged.drift_monitors.size(), 2u);
  for (const DriftMonitor& monitor : hinged.drift_monitors) {
    EXPECT_TRUE(monitor.yields);
    EXPECT_NEAR(*monitor.yield_drift, 4.0e6 * h * h / (3 * ei), 1e-15);
  }
  const BuiltModel elastic = built(bridge());
  EXPECT_FALSE(elastic.drift_monitors[0].yields);  // pier_yield_drift: a demand, not a ductility
  EXPECT_EQ(*elastic.drift_monitors[0].yield_drift, 0.04);
  // The hinge links exist and act on rotations, with the generator's numbers.
  const auto& link = hinged.model.links[hinged.link_index.at("bridge.p1.hinge")];
  EXPECT_TRUE(link.rotational);
  EXPECT_NEAR(*link.make_law({})->yield_deformation(), 4.0e6 / (11 * 3 * ei / h), 1e-18);
}

// A trilinear Takeda hinge (cracking at 1.5 MN m, yield at the given rotation theta_y = 4.848e-4,
// past M_y / k_h = 5.05e-6 on its cracked branch): the pier yields when the hinge does, at
// theta_y h + n / (n + 1) M_y h^2 / (3 E I) = 3.879 + 3.232 = 7.111 mm, not at M_y h^2 / (3 E I)
// = 3.556 mm (which doubled its ductility). A push of the pier top in 2,000 increments to 10 mm
// finds where the hinge reaches theta_y, interpolated between increments.
TEST(PierHinge, ATrilinearHingesPierYieldsWhereItsHingeReachesItsYieldRotation) {
  constexpr double theta_y = 4.848e-4, m_y = 4.0e6, ei = 3.0e10 * 0.8, h = 8.0, n = 10.0;
  const BuiltModel model = built(bridge([&](Json& generator) {
    add_hinges(generator);
    generator["pier_hinge"]["law"] = {{"type", "takeda"},
                                      {"cracking_force", 1.5e6},
                                      {"yield_deformation", theta_y},
                                      {"hardening_ratio", 0.03}};
  }));
  const double expected = theta_y * h + n / (n + 1) * m_y * h * h / (3 * ei);
  const double monitor = *model.drift_monitors[0].yield_drift;
  assembly::StructuralSystem system(model.model);
  const Index rotation = system.dofs().own_equation(model.node_index.at("bridge.p1.hinge"), 2);
  const Index top = system.dofs().own_equation(model.node_index.at("bridge.p1.top"), 0);
  double previous_rotation = 0.0, previous_top = 0.0, found = NAN;
  const auto observe = [&](const assembly::PushoverPoint&, const Vector& u) {
    const double turn = std::abs(u[rotation]);
    if (std::isnan(found) && turn >= theta_y)
      found = previous_top +
              (u[top] - previous_top) * (theta_y - previous_rotation) / (turn - previous_rotation);
    previous_rotation = turn;
    previous_top = u[top];
  };
  assembly::PushoverControl control{.equation = top, .target = 0.01, .increments = 2000};
  control.pattern = Vector::Zero(system.size());
  control.pattern[top] = 1.0;
  const assembly::PushoverResult pushed =
      assembly::pushover(system, Vector::Zero(system.size()), control, observe);
  ASSERT_TRUE(pushed.stopped.empty()) << pushed.stopped;
  std::cout << "trilinear hinge: pier yields at " << found << " m pushed, monitor " << monitor
            << " m, formula " << expected << " m\n";
  EXPECT_NEAR(monitor, expected, 1e-15);
  EXPECT_NEAR(found, monitor, 1e-4 * monitor);
}

TEST(PierHinge, AYieldCurvatureGivesTheYieldMoment) {
  const BuiltModel model = built(bridge([](Json& generator) {
    add_hinges(generator);
    generator["pier_hinge"].erase("yield_moment");
    generator["pier_hinge"]["yield_curvature"] = 2.0e-4;
    generator["pier_hinge"]["plastic_hinge_length"] = 0.8;
  }));
  // M_y = E I phi_y = 4.8e6 N m.
  EXPECT_NEAR(*model.drift_monitors[0].yield_drift, 4.8e6 * 64 / (3 * 2.4e10), 1e-15);
}

// The post-yield slope of a pier alone (its bearings a 1 N/m spring: the girders do not resist),
// pushed at its top well past yield: the law's hardening ratio r is the pier's, r 3 E I / h^3
// (the hinge's own is r / (1 + n (1 - r)) in series with the stiffened pier; given to the hinge
// as it was, r = 0.03 made the pier's 0.254, 8.5 times as stiff).
double pier_post_yield_slope(const Json& law) {
  const BuiltModel model = built(bridge([&](Json& generator) {
    add_hinges(generator);
    generator["pier_hinge"]["law"] = law;
    generator["bearing"] = {{"type", "elastic_spring"}, {"stiffness", 1.0}};
  }));
  // To 8 times the pier's yield displacement, 3.56 mm.
  const auto result = testing::push(model, "bridge.p1.top", 0, 0.03, 30);
  const auto& last = result.curve.back();
  const auto& before = result.curve[result.curve.size() - 2];
  return (last.load_factor - before.load_factor) / (last.displacement - before.displacement);
}

TEST(PierHinge, TheLawsHardeningRatioIsThePiers) {
  const double elastic = 3.0 * 3.0e10 * 0.8 / (8.0 * 8.0 * 8.0);  // 3 E I / h^3
  for (const Json& law : {Json{{"type", "bilinear_spring"}, {"hardening_ratio", 0.03}},
                          Json{{"type", "takeda"}, {"hardening_ratio", 0.03}},
                          Json{{"type", "clough"}, {"hardening_ratio", 0.1}}}) {
    const double ratio = law["hardening_ratio"].get<double>();
    const double slope = pier_post_yield_slope(law);
    const double error = std::abs(slope / (ratio * elastic) - 1.0);
    std::cout << law["type"] << ": post-yield slope " << slope
              << " N/m against r 3EI/h^3 = " << ratio * elastic << ", relative error " << error
              << "\n";
    EXPECT_LT(error, 1e-6) << law;  // the bearings' 2 N/m of 4.2e6 N/m: 5e-7
  }
}

void expect_refused(const Json& model, const std::string& path, const std::string& words) {
  try {
    built(model);
    FAIL() << "accepted; expected an error at " << path;
  } catch (const InputError& error) {
    std::cout << error.what() << "\n";
    EXPECT_NE(std::string(error.what()).find("bridge.json: " + path), std::string::npos);
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos);
  }
}

TEST(PierHinge, BadHingesAreRefusedAtTheirPath) {
  expect_refused(bridge([](Json& g) {
                   add_hinges(g);
                   g["pier_hinge"]["law"]["stiffness"] = 1e9;
                 }),
                 "/generators/0/pier_hinge/law/stiffness", "set by the generator");
  expect_refused(bridge([](Json& g) {
                   add_hinges(g);
                   g["pier_hinge"]["yield_curvature"] = 1e-4;
                 }),
                 "/generators/0/pier_hinge", "either 'yield_moment' or 'yield_curvature'");
  expect_refused(bridge([](Json& g) {
                   add_hinges(g);
                   g["pier_yield_drift"] = 0.04;
                 }),
                 "/generators/0/pier_yield_drift", "not with 'pier_hinge'");
  Json one_d = Json::parse(R"({"nodes": [{"id": "a", "x": 0}], "masses": [{"node": "a", "mass": 1}],
    "gravity": {}, "analysis": {"time_step": 0.1, "duration": 1}})");
  try {
    build(io::parse_model(one_d.dump(), "bridge.json"));
    FAIL() << "gravity accepted in 1-D";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("/gravity"), std::string::npos) << error.what();
  }
}

// "damping": the hinges get a1 k_h (initial) with the model's a1, the dashpot that makes the
// hinge's damping stiffness-proportional like the pier's; without it none.
TEST(PierHinge, HingeDampingTakesTheModelsStiffnessCoefficient) {
  const double ei = 3.0e10 * 0.8, h = 8.0, hinge_stiffness = 11 * 3 * ei / h;
  for (const char* kind : {"initial", "committed"}) {
    const BuiltModel model = built(bridge([kind](Json& generator) {
      add_hinges(generator);
      generator["pier_hinge"]["damping"] = kind;
    }));
    const double a1 = model.model.damping->stiffness_coefficient;
    ASSERT_GT(a1, 0.0);
    const auto& link = model.model.links[model.link_index.at("bridge.p2.hinge")];
    const double damping = link.make_law({})->set_trial({0.0, 1e-3, 0.0}).damping;
    EXPECT_NEAR(damping, a1 * hinge_stiffness, 1e-12 * a1 * hinge_stiffness) << kind;
  }
  const BuiltModel undamped = built(bridge(add_hinges));
  const auto& link = undamped.model.links[undamped.link_index.at("bridge.p2.hinge")];
  EXPECT_EQ(link.make_law({})->set_trial({0.0, 1e-3, 0.0}).damping, 0.0);
}

TEST(PierHinge, LinkRayleighDampingIsRefusedWhereItMeansNothing) {
  Json contact = bridge();
  contact["links"] =
      Json::parse(R"([{"id": "extra", "nodes": ["bridge.a0.ground", "bridge.g0.n0"], "axis": [1, 0],
    "law": {"type": "kelvin_voigt", "stiffness": 1e9, "restitution": 0.6},
    "rayleigh": {"stiffness": "committed"}}])");
  expect_refused(contact, "/links/0/rayleigh", "for structural springs and hinges");
  Json undamped = bridge();
  undamped.erase("damping");
  undamped["links"] =
      Json::parse(R"([{"id": "extra", "nodes": ["bridge.a0.ground", "bridge.g0.n0"], "axis": [1, 0],
    "law": {"type": "elastic_spring", "stiffness": 1e6}, "rayleigh": {"stiffness": "initial"}}])");
  expect_refused(undamped, "/links/0/rayleigh/stiffness_coefficient", "give the link its own");
  undamped["links"][0]["rayleigh"]["stiffness_coefficient"] = 0.002;
  const BuiltModel made = built(undamped);
  EXPECT_DOUBLE_EQ(made.model.links[made.link_index.at("extra")]
                       .make_law({})
                       ->set_trial({0.0, 1.0, 0.0})
                       .damping,
                   0.002 * 1e6);
}

}  // namespace
}  // namespace pound::builder
