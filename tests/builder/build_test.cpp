#include "builder/build.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <string>

#include "assembly/modal_analysis.hpp"
#include "assembly/structural_system.hpp"
#include "assembly/truss.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "links/extended_penalty.hpp"
#include "links/gap_spring.hpp"
#include "support/elements.hpp"

namespace pound::builder {
namespace {

// A valid 1-D model in which every kind of reference occurs once; the error cases change one
// thing in it (RFC 6902 patch). Nodes b and c are at the same place.
constexpr const char* kModel = R"({
  "nodes": [{"id": "a", "x": 0.0}, {"id": "b", "x": 1.0}, {"id": "c", "x": 1.0}],
  "materials": [{"id": "steel", "youngs_modulus": 100, "density": 1}],
  "elements": [{"id": "e0", "type": "truss", "nodes": ["a", "b"], "material": "steel",
                "area": 1}],
  "masses": [{"node": "c", "mass": 1}],
  "supports": [{"node": "a", "fix": ["x"]}],
  "initial_velocities": [{"node": "c", "x": -0.1}],
  "links": [{"id": "joint", "nodes": ["b", "c"], "axis": [1],
             "law": {"type": "gap_spring", "stiffness": 10}}],
  "analysis": {"time_step": 0.01, "duration": 1},
  "recorders": [{"type": "link", "links": ["joint"], "file": "joint.csv"},
                {"type": "node", "nodes": ["c"], "file": "c.csv"}]
})";

// A model that is one rod pair and nothing else.
constexpr const char* kRodPair = R"({
  "generators": [{
    "type": "rod_pair", "id": "rods",
    "left":  {"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": 10,
              "initial_velocity": 0.1},
    "right": {"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": 10,
              "initial_velocity": -0.1},
    "law": {"type": "gap_spring", "stiffness_ratio": 1.0}
  }],
  "analysis": {"time_step": 0.01, "duration": 1}
})";

std::string patched(const char* model, const std::string& json_patch) {
  return nlohmann::json::parse(model).patch(nlohmann::json::parse(json_patch)).dump();
}

ModelSpec spec_of(const std::string& text) { return io::parse_model(text, "m.json"); }

std::optional<InputError> build_error(const ModelSpec& spec) {
  try {
    (void)build(spec);
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

// Building `spec` must fail at `where` (in m.json) with a reason containing `part`.
void expect_error(const ModelSpec& spec, const std::string& where, const std::string& part) {
  const std::optional<InputError> error = build_error(spec);
  ASSERT_TRUE(error.has_value()) << "no error, expected one at " << where;
  EXPECT_EQ(error->file(), "m.json");
  EXPECT_EQ(error->where(), where) << error->what();
  EXPECT_NE(error->reason().find(part), std::string::npos) << error->what();
}

// The same for kModel with `json_patch` applied.
void expect_error(const std::string& json_patch, const std::string& where,
                  const std::string& part) {
  expect_error(spec_of(patched(kModel, json_patch)), where, part);
}

double law_stiffness(const model::Link& link) {
  const auto law = link.make_law(links::LinkContext{});
  return dynamic_cast<const links::GapSpring&>(*law).stiffness();
}

TEST(Build, UnchangedModelBuilds) {
  const BuiltModel built = build(spec_of(kModel));
  EXPECT_EQ(built.model.nodes.size(), 3u);
  EXPECT_EQ(testing::element_count<assembly::Truss>(built.model), 1u);
  ASSERT_EQ(built.model.links.size(), 1u);
  EXPECT_EQ(built.model.links[0].node_i, built.node_index.at("b"));
  EXPECT_EQ(built.model.links[0].node_j, built.node_index.at("c"));
  EXPECT_EQ(built.recorders.size(), 2u);
  EXPECT_FALSE(built.sole_rod_pair.has_value());
}

TEST(Build, ErrorMessageNamesFileAndPath) {
  const auto error =
      build_error(spec_of(patched(kModel, R"([{"op": "replace", "path": "/elements/0/nodes/1",
                                   "value": "zz"}])")));
  ASSERT_TRUE(error.has_value());
  EXPECT_STREQ(error->what(), "m.json: /elements/0/nodes/1: node 'zz' does not exist");
}

// A JSON patch of kModel that the builder must refuse, at `where` with `part` in the reason.
struct BadPatch {
  std::string name;
  std::string json_patch;
  std::string where;
  std::string part;
};

void PrintTo(const BadPatch& bad, std::ostream* out) { *out << bad.name; }

std::string case_name(const ::testing::TestParamInfo<BadPatch>& info) { return info.param.name; }

class Rejects : public ::testing::TestWithParam<BadPatch> {};

TEST_P(Rejects, Patch) { expect_error(GetParam().json_patch, GetParam().where, GetParam().part); }

INSTANTIATE_TEST_SUITE_P(
    Build, Rejects,
    ::testing::Values(
        BadPatch{"element_node_missing",
                 R"([{"op": "replace", "path": "/elements/0/nodes/1", "value": "zz"}])",
                 "/elements/0/nodes/1", "node 'zz' does not exist"},
        BadPatch{"element_material_missing",
                 R"([{"op": "replace", "path": "/elements/0/material", "value": "wood"}])",
                 "/elements/0/material", "material 'wood' does not exist"},
        BadPatch{"zero_length_element",
                 R"([{"op": "replace", "path": "/elements/0/nodes/0", "value": "c"}])",
                 "/elements/0/nodes", "zero length"},
        BadPatch{"infinitely_long_element",
                 R"([{"op": "replace", "path": "/nodes/0/x", "value": -1e308},
                   {"op": "replace", "path": "/nodes/1/x", "value": 1e308}])",
                 "/elements/0/nodes",
                 "element 'e0' is infinitely long (nodes 'a' and 'b' are inf apart)"},
        BadPatch{"link_between_coincident_nodes_needs_an_axis",
                 R"([{"op": "remove", "path": "/links/0/axis"}])", "/links/0", "\"axis\""},
        BadPatch{"recorder_naming_a_missing_link",
                 R"([{"op": "replace", "path": "/recorders/0/links/0", "value": "nope"}])",
                 "/recorders/0/links/0", "link 'nope' does not exist"},
        BadPatch{"recorder_naming_a_missing_node",
                 R"([{"op": "replace", "path": "/recorders/1/nodes/0", "value": "nope"}])",
                 "/recorders/1/nodes/0", "node 'nope' does not exist"},
        BadPatch{"mass_on_a_missing_node",
                 R"([{"op": "replace", "path": "/masses/0/node", "value": "nope"}])",
                 "/masses/0/node", "node 'nope' does not exist"},
        BadPatch{"support_on_a_missing_node",
                 R"([{"op": "replace", "path": "/supports/0/node", "value": "nope"}])",
                 "/supports/0/node", "node 'nope' does not exist"},
        BadPatch{"initial_velocity_on_a_missing_node",
                 R"([{"op": "replace", "path": "/initial_velocities/0/node", "value": "nope"}])",
                 "/initial_velocities/0/node", "node 'nope' does not exist"}),
    case_name);

// duration / time_step steps overflowed the step count: the run "completed" with no step taken.
TEST(Build, UncountablyManySteps) {
  expect_error(R"([{"op": "replace", "path": "/analysis/time_step", "value": 1e-300}])",
               "/analysis/time_step",
               "1e-300 over a duration of 1 is 1e+300 steps, more than the 1e+15");
  expect_error(R"([{"op": "replace", "path": "/analysis/duration", "value": 1e300}])",
               "/analysis/time_step", "is 1e+302 steps");
  EXPECT_FALSE(build_error(spec_of(
      patched(kModel, R"([{"op": "replace", "path": "/analysis/time_step", "value": 1e-14}])"))));
}

// Stiffness-proportional damping past critical at the first mode (a1 w1 / 2 > 1) is refused at
// its path: at a1 = 1e15 s the bundled bridge was refused for "nothing holds it" (the girders'
// mass lost to round-off beside a1 K) and at 1e10 s it ran with no motion left to study. Just
// below critical builds.
TEST(Build, StiffnessDampingPastCriticalAtTheFirstModeIsRefused) {
  const BuiltModel undamped = build(spec_of(kModel));
  const double period =
      assembly::natural_periods(assembly::StructuralSystem(undamped.model), 1).at(0);
  const double critical = period / std::numbers::pi;  // a1 w1 / 2 = 1
  const auto with_a1 = [](double a1) {
    return spec_of(patched(kModel, fmt::format(R"([{{"op": "add", "path": "/damping", "value":
        {{"mass_coefficient": 0.1, "stiffness_coefficient": {:.17g}}}}}])",
                                               a1)));
  };
  const BuiltModel below = build(with_a1(0.99 * critical));
  EXPECT_DOUBLE_EQ(below.model.damping->stiffness_coefficient, 0.99 * critical);
  expect_error(
      with_a1(1.01 * critical), "/damping/stiffness_coefficient",
      fmt::format("gives the first mode (period {:.3g} s) a damping ratio of 1.01 ", period));
  expect_error(with_a1(1e15), "/damping/stiffness_coefficient", "above critical (1)");
  expect_error(with_a1(1e308), "/damping/stiffness_coefficient",
               "a damping ratio of over 1e308 (too large to represent)");
  std::printf("first period %.6g s, critical a1 %.6g s\n", period, critical);
}

TEST(Build, LinkJoiningANodeToItself) {
  // The reader already refuses ["b", "b"] (a repeated name); the builder checks it again for
  // specs made in code.
  ModelSpec spec = spec_of(kModel);
  spec.links[0].node_j = spec.links[0].node_i;
  expect_error(spec, "/links/0/nodes", "cannot join a node to itself");
}

TEST(Build, UserNodeWithAGeneratedId) {
  const std::string text = patched(kRodPair, R"([{"op": "add", "path": "/nodes",
                                                  "value": [{"id": "rods.left.0", "x": 5}]}])");
  expect_error(spec_of(text), "/generators/0",
               "duplicate node id 'rods.left.0' (also at /nodes/0)");
}

// Generated entries are blamed on the generator that made them, not on the first one.
TEST(Build, ClashWithTheSecondGeneratorNamesIt) {
  const std::string text = patched(kRodPair, R"([
      {"op": "copy", "from": "/generators/0", "path": "/generators/1"},
      {"op": "replace", "path": "/generators/1/id", "value": "more"},
      {"op": "add", "path": "/nodes", "value": [{"id": "more.left.0", "x": 5}]}])");
  expect_error(spec_of(text), "/generators/1",
               "duplicate node id 'more.left.0' (also at /nodes/0)");
}

TEST(Build, RodPairNeedsA1dScene) {
  expect_error(spec_of(patched(kRodPair, R"([{"op": "add", "path": "/dimension", "value": 2}])")),
               "/generators/0", "1-D");
}

TEST(Build, RodPairExpandsIntoNodesElementsAndOneLink) {
  const BuiltModel built = build(spec_of(kRodPair));
  const model::Model& model = built.model;
  const int n = 10;
  EXPECT_EQ(model.nodes.size(), static_cast<std::size_t>(2 * (n + 1)));
  EXPECT_EQ(testing::element_count<assembly::Truss>(model), static_cast<std::size_t>(2 * n));
  EXPECT_TRUE(model.supports.empty());
  ASSERT_EQ(model.links.size(), 1u);
  const model::Link& link = model.links[0];
  EXPECT_EQ(link.id, "rods.contact");
  EXPECT_EQ(link.axis, (model::Coordinates{1.0, 0.0}));
  EXPECT_EQ(link.node_i, built.node_index.at("rods.left.10"));
  EXPECT_EQ(link.node_j, built.node_index.at("rods.right.0"));
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(built.node_index.at("rods.left.0"))].position[0],
            -10.0);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(link.node_i)].position[0], 0.0);
  EXPECT_EQ(model.nodes[static_cast<std::size_t>(link.node_j)].position[0], 0.0);
  EXPECT_DOUBLE_EQ(
      model.nodes[static_cast<std::size_t>(built.node_index.at("rods.right.10"))].position[0],
      10.0);
  ASSERT_EQ(model.initial_velocity.size(), model.nodes.size());
  EXPECT_EQ(model.initial_velocity[static_cast<std::size_t>(link.node_i)][0], 0.1);
  EXPECT_EQ(model.initial_velocity[static_cast<std::size_t>(link.node_j)][0], -0.1);
  ASSERT_TRUE(built.sole_rod_pair.has_value());
  EXPECT_EQ(built.sole_rod_pair->id, "rods");
}

TEST(Build, StiffnessRatioIsTakenFromTheSofterAdjacentElement) {
  // Left: E A / h = 100 * 1 / (10 / 10) = 100; right: 200 * 2 / (5 / 4) = 320.
  const std::string unequal = patched(kRodPair, R"([
    {"op": "replace", "path": "/generators/0/right",
     "value": {"youngs_modulus": 200, "density": 0.2, "area": 2, "length": 5, "elements": 4}},
    {"op": "replace", "path": "/generators/0/law/stiffness_ratio", "value": 1.5}])");
  const BuiltModel built = build(spec_of(unequal));
  EXPECT_EQ(built.model.nodes.size(), 11u + 5u);
  EXPECT_EQ(testing::element_count<assembly::Truss>(built.model), 10u + 4u);
  ASSERT_EQ(built.model.links.size(), 1u);
  EXPECT_DOUBLE_EQ(law_stiffness(built.model.links[0]), 1.5 * 100.0);

  // The same with the rods swapped: the softer one is now on the right.
  ModelSpec swapped = spec_of(unequal);
  std::swap(swapped.rod_pairs[0].left, swapped.rod_pairs[0].right);
  EXPECT_DOUBLE_EQ(law_stiffness(build(swapped).model.links[0]), 1.5 * 100.0);
}

TEST(Build, FixedFarEndBecomesASupportOnTheRightRod) {
  const BuiltModel built =
      build(spec_of(patched(kRodPair, R"([{"op": "add", "path": "/generators/0/right/far_end",
                              "value": "fixed"}])")));
  ASSERT_EQ(built.model.supports.size(), 1u);
  EXPECT_EQ(built.model.supports[0].node, built.node_index.at("rods.right.10"));
  EXPECT_TRUE(built.model.supports[0].fixed[0]);
  EXPECT_FALSE(built.model.supports[0].fixed[1]);
}

TEST(Build, DiagonalLinkAxisComesFromCoordinates) {
  const BuiltModel built = build(spec_of(R"({
    "dimension": 2,
    "nodes": [{"id": "p", "x": 1, "y": 1}, {"id": "q", "x": 4, "y": 5}],
    "masses": [{"node": "p", "mass": 1}, {"node": "q", "mass": 1}],
    "links": [{"id": "l", "nodes": ["p", "q"], "law": {"type": "gap_spring", "stiffness": 1}}],
    "analysis": {"time_step": 0.01, "duration": 1}
  })"));
  ASSERT_EQ(built.model.links.size(), 1u);
  EXPECT_DOUBLE_EQ(built.model.links[0].axis[0], 0.6);
  EXPECT_DOUBLE_EQ(built.model.links[0].axis[1], 0.8);
}

TEST(Build, LinkAxisIn1dPointsFromITowardsJ) {
  const BuiltModel built = build(spec_of(R"({
    "nodes": [{"id": "p", "x": 3}, {"id": "q", "x": 1}],
    "masses": [{"node": "p", "mass": 1}, {"node": "q", "mass": 1}],
    "links": [{"id": "l", "nodes": ["p", "q"], "law": {"type": "gap_spring", "stiffness": 1}}],
    "analysis": {"time_step": 0.01, "duration": 1}
  })"));
  ASSERT_EQ(built.model.links.size(), 1u);
  EXPECT_EQ(built.model.links[0].axis, (model::Coordinates{-1.0, 0.0}));
}

TEST(Build, WithoutRecordersEveryLinkIsRecordedToLinksCsv) {
  const BuiltModel built = build(spec_of(patched(kModel, R"([
    {"op": "remove", "path": "/recorders"},
    {"op": "add", "path": "/links/-",
     "value": {"id": "second", "nodes": ["a", "c"], "law": {"type": "gap_spring",
                                                            "stiffness": 1}}}])")));
  ASSERT_EQ(built.recorders.size(), 1u);
  EXPECT_EQ(built.recorders[0].kind, RecorderKind::link);
  EXPECT_EQ(built.recorders[0].file, "links.csv");
  EXPECT_EQ(built.recorders[0].items, (std::vector<Index>{0, 1}));
}

TEST(Build, EmptyRecordersRecordNothing) {
  const BuiltModel built =
      build(spec_of(patched(kModel, R"([{"op": "replace", "path": "/recorders", "value": []}])")));
  EXPECT_TRUE(built.recorders.empty());
}

}  // namespace
}  // namespace pound::builder

namespace pound::builder {
namespace {

TEST(BuildLaws, FrictionNeedsATwoOrThreeDimensionalScene) {
  expect_error(R"([{"op": "add", "path": "/links/0/friction", "value": {"coefficient": 0.3}}])",
               "/links/0/friction", "a 2-D or 3-D scene");
}

TEST(BuildLaws, RestrainerTakesSlackNotGap) {
  expect_error(R"([{"op": "replace", "path": "/links/0/law",
                    "value": {"type": "restrainer", "stiffness": 1e7, "slack": 0.01}},
                   {"op": "add", "path": "/links/0/gap", "value": 0.02}])",
               "/links/0/gap", "slack");
}

// What only the assembled model can tell: the masses and stiffnesses a law's automatic numbers
// need. The error still names the law in the file.
std::optional<InputError> assembly_error(const std::string& json_patch) {
  const BuiltModel built = build(spec_of(patched(kModel, json_patch)));
  try {
    assembly::StructuralSystem system(built.model);
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

TEST(BuildLaws, RestitutionWithoutAnyMassAtTheLinkIsAnError) {
  // Both ends fixed: no effective mass for the Kelvin-Voigt damping from e.
  const auto error = assembly_error(R"([
      {"op": "replace", "path": "/links/0/law",
       "value": {"type": "kelvin_voigt", "stiffness": 1e7, "restitution": 0.5}},
      {"op": "add", "path": "/supports/-", "value": {"node": "b", "fix": ["x"]}},
      {"op": "add", "path": "/supports/-", "value": {"node": "c", "fix": ["x"]}}])");
  ASSERT_TRUE(error.has_value());
  EXPECT_EQ(error->file(), "m.json");
  EXPECT_EQ(error->where(), "/links/0/law/mass") << error->what();
  EXPECT_NE(error->reason().find("give 'mass'"), std::string::npos) << error->what();
}

TEST(BuildLaws, ExtendedPenaltyBuildsItsNumbersFromTheModel) {
  const BuiltModel built = build(spec_of(patched(
      kModel,
      R"([{"op": "replace", "path": "/links/0/law", "value": {"type": "extended_penalty"}}])")));
  assembly::StructuralSystem system(built.model);
  const auto& law = dynamic_cast<const links::ExtendedPenalty&>(system.links().law(0));
  const links::LinkContext context = system.link_context(built.model.links[0]);
  const auto expected = links::ExtendedPenalty::automatic(context, 1e-3, 1.0);
  EXPECT_DOUBLE_EQ(law.numbers().alpha0, expected.alpha0);
  EXPECT_DOUBLE_EQ(law.numbers().alpha1, expected.alpha1);
  EXPECT_DOUBLE_EQ(law.numbers().alpha2, expected.alpha2);
  EXPECT_GT(expected.alpha0, 0.0);
}

}  // namespace
}  // namespace pound::builder

namespace pound::builder {
namespace {

// Multi-support excitation names supports; anything else is refused with its path.
TEST(BuildExcitations, MovingSupportsMustBeSupports) {
  const std::string base = R"({
    "nodes": [{"id": "g", "x": 0}, {"id": "m", "x": 1}],
    "materials": [{"id": "k", "youngs_modulus": 100, "density": 1}],
    "elements": [{"id": "e", "type": "truss", "nodes": ["g", "m"], "material": "k", "area": 1}],
    "supports": [{"node": "g", "fix": ["x"]}],
    "excitations": [{"record": "r.AT2", "supports": ["SUPPORT"]}],
    "analysis": {"time_step": 0.01}})";
  model::GroundMotion motion{"r", 0.01, {0.0, 1.0, 0.0}};
  auto error_for = [&](const std::string& support) -> std::optional<InputError> {
    std::string text = base;
    text.replace(text.find("SUPPORT"), 7, support);
    try {
      (void)build(io::parse_model(text, "m.json"), {motion});
    } catch (const InputError& error) {
      return error;
    }
    return std::nullopt;
  };
  EXPECT_FALSE(error_for("g").has_value());
  const auto missing = error_for("nowhere");
  ASSERT_TRUE(missing.has_value());
  EXPECT_EQ(missing->where(), "/excitations/0/supports/0");
  EXPECT_NE(missing->reason().find("does not exist"), std::string::npos);
  const auto free_node = error_for("m");
  ASSERT_TRUE(free_node.has_value());
  EXPECT_EQ(free_node->where(), "/excitations/0/supports/0");
  EXPECT_NE(free_node->reason().find("not a support"), std::string::npos) << free_node->what();
}

TEST(BuildExcitations, AWavePassageNeedsTheSupportsItReaches) {
  try {
    (void)io::parse_model(R"({"nodes": [{"id": "g", "x": 0}],
      "excitations": [{"record": "r.AT2", "wave_passage": {"apparent_velocity": 300}}],
      "analysis": {"time_step": 0.01}})",
                          "m.json");
    FAIL() << "accepted";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "/excitations/0/wave_passage");
    EXPECT_NE(error.reason().find("needs the 'supports'"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pound::builder
