#include "io/model_reader.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/errors.hpp"
#include "io/json_reader.hpp"
#include "io/model_schema.hpp"
#include "links/law_registry.hpp"

namespace pound::io {
namespace {

// A valid 1-D model that uses every section with values other than the defaults; each bad case
// below changes one thing in it.
constexpr const char* kModel = R"({
  "title": "two rods",
  "dimension": 1,
  "nodes": [{"id": "a0", "x": 0.0}, {"id": "a1", "x": 1.0}, {"id": "b0", "x": 1.0}],
  "materials": [{"id": "steel", "youngs_modulus": 2.0e11, "density": 7850}],
  "elements": [{"id": "e0", "type": "truss", "nodes": ["a0", "a1"], "material": "steel",
                "area": 0.01}],
  "masses": [{"node": "b0", "mass": 2.5}],
  "supports": [{"node": "a0", "fix": ["x"]}],
  "initial_velocities": [{"node": "b0", "x": -0.1}],
  "links": [{"id": "joint", "nodes": ["a1", "b0"], "gap": 0.02, "axis": [1],
             "law": {"type": "gap_spring", "stiffness": 1.0e8}}],
  "generators": [{
    "type": "rod_pair", "id": "rods",
    "left":  {"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": 10,
              "initial_velocity": 0.1, "far_end": "free"},
    "right": {"youngs_modulus": 200, "density": 0.2, "area": 2, "length": 5, "elements": 4,
              "initial_velocity": -0.1, "far_end": "fixed"},
    "gap": 0.5,
    "law": {"type": "gap_spring", "stiffness_ratio": 1.5}
  }],
  "analysis": {"integrator": {"type": "newmark", "beta": 0.3, "gamma": 0.6},
               "time_step": 6.32456e-4, "duration": 1.0,
               "convergence": {"relative_tolerance": 1e-8, "absolute_tolerance": 1e-12,
                               "max_iterations": 30},
               "max_step_cuts": 5, "max_steps": 100000},
  "recorders": [{"type": "link", "links": ["joint", "rods.contact"], "file": "link_force.csv"},
                {"type": "node", "nodes": ["a0"]}]
})";

// kModel with a JSON patch (RFC 6902) applied.
std::string edited_model(const std::string& json_patch) {
  return nlohmann::json::parse(kModel).patch(nlohmann::json::parse(json_patch)).dump(2);
}

std::optional<InputError> error_of(const std::string& text) {
  try {
    (void)parse_model(text, "x.json");
  } catch (const InputError& error) {
    return error;
  }
  return std::nullopt;
}

TEST(ModelReader, ReadsEveryField) {
  const builder::ModelSpec spec = parse_model(kModel, "x.json");
  EXPECT_EQ(spec.source, "x.json");
  EXPECT_EQ(spec.title, "two rods");
  EXPECT_EQ(spec.dimension, 1);

  ASSERT_EQ(spec.nodes.size(), 3u);
  EXPECT_EQ(spec.nodes[1].id, "a1");
  EXPECT_EQ(spec.nodes[1].x, 1.0);
  EXPECT_EQ(spec.nodes[1].y, 0.0);

  ASSERT_EQ(spec.materials.size(), 1u);
  EXPECT_EQ(spec.materials[0].id, "steel");
  EXPECT_EQ(spec.materials[0].youngs_modulus, 2.0e11);
  EXPECT_EQ(spec.materials[0].density, 7850.0);

  ASSERT_EQ(spec.elements.size(), 1u);
  EXPECT_EQ(spec.elements[0].id, "e0");
  EXPECT_EQ(spec.elements[0].type, builder::ElementKind::truss);
  EXPECT_EQ(spec.elements[0].node_i, "a0");
  EXPECT_EQ(spec.elements[0].node_j, "a1");
  EXPECT_EQ(spec.elements[0].material, "steel");
  EXPECT_EQ(spec.elements[0].area, 0.01);

  ASSERT_EQ(spec.masses.size(), 1u);
  EXPECT_EQ(spec.masses[0].node, "b0");
  EXPECT_EQ(spec.masses[0].mass, 2.5);

  ASSERT_EQ(spec.supports.size(), 1u);
  EXPECT_EQ(spec.supports[0].node, "a0");
  EXPECT_TRUE(spec.supports[0].fixed[0]);   // x
  EXPECT_FALSE(spec.supports[0].fixed[1]);  // y

  ASSERT_EQ(spec.initial_velocities.size(), 1u);
  EXPECT_EQ(spec.initial_velocities[0].node, "b0");
  EXPECT_EQ(spec.initial_velocities[0].x, -0.1);
  EXPECT_EQ(spec.initial_velocities[0].y, 0.0);

  ASSERT_EQ(spec.links.size(), 1u);
  const builder::LinkSpec& link = spec.links[0];
  EXPECT_EQ(link.id, "joint");
  EXPECT_EQ(link.node_i, "a1");
  EXPECT_EQ(link.node_j, "b0");
  EXPECT_EQ(link.gap, 0.02);
  EXPECT_EQ(link.axis, std::vector<double>{1.0});
  EXPECT_EQ(link.law.type, "gap_spring");
  EXPECT_EQ(link.law.number("stiffness"), 1.0e8);
  EXPECT_FALSE(link.law.number("stiffness_ratio"));

  ASSERT_EQ(spec.rod_pairs.size(), 1u);
  EXPECT_EQ(spec.rod_pair_generator_index, std::vector<int>{0});
  const builder::RodPairSpec& pair = spec.rod_pairs[0];
  EXPECT_EQ(pair.id, "rods");
  EXPECT_EQ(pair.left.youngs_modulus, 100.0);
  EXPECT_EQ(pair.left.density, 0.1);
  EXPECT_EQ(pair.left.area, 1.0);
  EXPECT_EQ(pair.left.length, 10.0);
  EXPECT_EQ(pair.left.elements, 10);
  EXPECT_EQ(pair.left.initial_velocity, 0.1);
  EXPECT_FALSE(pair.left.far_end_fixed);
  EXPECT_EQ(pair.right.youngs_modulus, 200.0);
  EXPECT_EQ(pair.right.density, 0.2);
  EXPECT_EQ(pair.right.area, 2.0);
  EXPECT_EQ(pair.right.length, 5.0);
  EXPECT_EQ(pair.right.elements, 4);
  EXPECT_EQ(pair.right.initial_velocity, -0.1);
  EXPECT_TRUE(pair.right.far_end_fixed);
  EXPECT_EQ(pair.gap, 0.5);
  EXPECT_EQ(pair.law.type, "gap_spring");
  EXPECT_FALSE(pair.law.number("stiffness"));
  EXPECT_EQ(pair.law.number("stiffness_ratio"), 1.5);

  const builder::AnalysisSpec& analysis = spec.analysis;
  EXPECT_EQ(analysis.integrator.method().name, "newmark");
  EXPECT_EQ(analysis.integrator.parameter("beta"), 0.3);
  EXPECT_EQ(analysis.integrator.parameter("gamma"), 0.6);
  EXPECT_EQ(analysis.time_step, 6.32456e-4);
  EXPECT_EQ(analysis.duration, 1.0);
  EXPECT_EQ(analysis.relative_tolerance, 1e-8);
  EXPECT_EQ(analysis.absolute_tolerance, 1e-12);
  EXPECT_EQ(analysis.max_iterations, 30);
  EXPECT_EQ(analysis.max_step_cuts, 5);
  EXPECT_EQ(analysis.max_steps, 100000);

  ASSERT_EQ(spec.recorders.size(), 2u);
  EXPECT_EQ(spec.recorders[0].type, builder::RecorderKind::link);
  EXPECT_EQ(spec.recorders[0].ids, (std::vector<std::string>{"joint", "rods.contact"}));
  EXPECT_EQ(spec.recorders[0].file, "link_force.csv");
  EXPECT_EQ(spec.recorders[1].type, builder::RecorderKind::node);
  EXPECT_EQ(spec.recorders[1].ids, std::vector<std::string>{"a0"});
  EXPECT_EQ(spec.recorders[1].file, "node_1.csv");  // default: type and index
}

TEST(ModelReader, ReadsPlaneFields) {
  const builder::ModelSpec spec = parse_model(R"({
    "dimension": 2,
    "nodes": [{"id": "a", "x": 0, "y": 1.5}, {"id": "b", "x": 0.6, "y": 2.3}],
    "supports": [{"node": "a", "fix": ["y", "x"]}, {"node": "b", "fix": ["y"]}],
    "initial_velocities": [{"node": "b", "y": -0.5}],
    "links": [{"id": "l", "nodes": ["a", "b"], "axis": [0.6, 0.8],
               "law": {"type": "gap_spring", "stiffness": 10}}],
    "analysis": {"time_step": 0.01, "duration": 1}
  })",
                                              "plane.json");
  EXPECT_EQ(spec.dimension, 2);
  EXPECT_EQ(spec.nodes[1].y, 2.3);
  EXPECT_TRUE(spec.supports[0].fixed[0]);
  EXPECT_TRUE(spec.supports[0].fixed[1]);
  EXPECT_FALSE(spec.supports[1].fixed[0]);
  EXPECT_TRUE(spec.supports[1].fixed[1]);
  EXPECT_EQ(spec.initial_velocities[0].x, 0.0);
  EXPECT_EQ(spec.initial_velocities[0].y, -0.5);
  EXPECT_EQ(spec.links[0].axis, (std::vector<double>{0.6, 0.8}));
  EXPECT_EQ(spec.links[0].gap, 0.0);
}

TEST(ModelReader, AppliesDefaults) {
  const builder::ModelSpec spec =
      parse_model(R"({"analysis": {"time_step": 0.01, "duration": 2}})", "x.json");
  const builder::ModelSpec defaults;
  EXPECT_EQ(spec.title, "");
  EXPECT_EQ(spec.dimension, 1);
  EXPECT_TRUE(spec.nodes.empty());
  EXPECT_TRUE(spec.links.empty());
  EXPECT_TRUE(spec.rod_pairs.empty());
  EXPECT_TRUE(spec.recorders.empty());
  EXPECT_EQ(spec.analysis.integrator.parameter("beta"), 0.25);
  EXPECT_EQ(spec.analysis.integrator.parameter("gamma"), 0.5);
  EXPECT_EQ(spec.analysis.relative_tolerance, defaults.analysis.relative_tolerance);
  EXPECT_EQ(spec.analysis.absolute_tolerance, 0.0);
  EXPECT_EQ(spec.analysis.max_iterations, 25);
  EXPECT_EQ(spec.analysis.max_step_cuts, 10);
  EXPECT_EQ(spec.analysis.max_steps, 0);

  const builder::ModelSpec rods = parse_model(edited_model(R"([
    {"op": "remove", "path": "/generators/0/gap"},
    {"op": "remove", "path": "/generators/0/left/far_end"},
    {"op": "remove", "path": "/generators/0/left/initial_velocity"},
    {"op": "remove", "path": "/links/0/gap"},
    {"op": "remove", "path": "/links/0/axis"},
    {"op": "remove", "path": "/recorders/0/links"},
    {"op": "remove", "path": "/recorders/0/file"}])"),
                                              "x.json");
  EXPECT_EQ(rods.rod_pairs[0].gap, 0.0);
  EXPECT_FALSE(rods.rod_pairs[0].left.far_end_fixed);
  EXPECT_EQ(rods.rod_pairs[0].left.initial_velocity, 0.0);
  EXPECT_EQ(rods.links[0].gap, 0.0);
  EXPECT_FALSE(rods.links[0].axis);
  EXPECT_TRUE(rods.recorders[0].ids.empty());  // every link
  EXPECT_EQ(rods.recorders[0].file, "link_0.csv");
}

TEST(ModelReader, ReadsIntegratorPresets) {
  const auto with_integrator = [](const std::string& integrator) {
    return parse_model(R"({"analysis": {"time_step": 0.01, "duration": 2, "integrator": )" +
                           integrator + "}}",
                       "x.json")
        .analysis.integrator;
  };
  const builder::IntegratorSpec linear = with_integrator(R"("newmark_linear_acceleration")");
  EXPECT_EQ(linear.method().name, "newmark");
  EXPECT_EQ(linear.parameter("beta"), 1.0 / 6.0);
  EXPECT_EQ(linear.parameter("gamma"), 0.5);
  const builder::IntegratorSpec average = with_integrator(R"("newmark_average_acceleration")");
  EXPECT_EQ(average.parameter("beta"), 0.25);
  EXPECT_EQ(average.parameter("gamma"), 0.5);
  const builder::IntegratorSpec plain = with_integrator(R"({"type": "newmark"})");
  EXPECT_EQ(plain.parameter("beta"), 0.25);
  EXPECT_EQ(plain.parameter("gamma"), 0.5);
}

TEST(ModelReader, AcceptsIntegralFloatsAndNearlyUnitAxes) {
  const builder::ModelSpec spec = parse_model(edited_model(R"([
    {"op": "replace", "path": "/generators/0/left/elements", "value": 10.0},
    {"op": "replace", "path": "/links/0/axis", "value": [-1.0000000001]}])"),
                                              "x.json");
  EXPECT_EQ(spec.rod_pairs[0].left.elements, 10);
  EXPECT_EQ(spec.links[0].axis, std::vector<double>{-1.0000000001});
}

TEST(ModelReader, MessageNamesFilePathAndExpectation) {
  const std::optional<InputError> error =
      error_of(edited_model(R"([{"op": "replace", "path": "/links/0/gap", "value": -0.01}])"));
  ASSERT_TRUE(error);
  EXPECT_STREQ(error->what(), "x.json: /links/0/gap: must be >= 0, got -0.01");
}

TEST(ModelReader, ReadsAdaptiveStepping) {
  const builder::ModelSpec on = parse_model(
      edited_model(R"([{"op": "add", "path": "/analysis/adaptive", "value": true}])"), "x.json");
  ASSERT_TRUE(on.analysis.adaptive);
  EXPECT_EQ(on.analysis.adaptive->tolerance, 1e-5);
  const builder::ModelSpec off = parse_model(
      edited_model(R"([{"op": "add", "path": "/analysis/adaptive", "value": false}])"), "x.json");
  EXPECT_FALSE(off.analysis.adaptive);
  const builder::ModelSpec set =
      parse_model(edited_model(R"([{"op": "add", "path": "/analysis/adaptive",
                        "value": {"tolerance": 1e-3, "min_time_step": 1e-6, "max_time_step": 0.01}}])"),
                  "x.json");
  ASSERT_TRUE(set.analysis.adaptive);
  EXPECT_EQ(set.analysis.adaptive->tolerance, 1e-3);
  EXPECT_EQ(set.analysis.adaptive->min_time_step, 1e-6);
  EXPECT_EQ(set.analysis.adaptive->max_time_step, 0.01);
  for (
      const auto& [patch, message] : std::vector<std::pair<std::string, std::string>>{
          {R"([{"op": "add", "path": "/analysis/adaptive", "value": {"tolerence": 1e-3}}])",
           "x.json: /analysis/adaptive/tolerence: unknown field (did you mean 'tolerance'?)"},
          {R"([{"op": "add", "path": "/analysis/adaptive", "value": {"tolerance": -1}}])",
           "x.json: /analysis/adaptive/tolerance: must be > 0, got -1"},
          {R"([{"op": "add", "path": "/analysis/adaptive", "value": {"min_time_step": 1, "max_time_step": 0.1}}])",
           "x.json: /analysis/adaptive/min_time_step: must be <= max_time_step"},
          {R"([{"op": "add", "path": "/analysis/adaptive", "value": true},
               {"op": "replace", "path": "/analysis/integrator", "value": "central_difference"}])",
           "x.json: /analysis/adaptive: adaptive stepping is for the implicit integrators"}}) {
    const std::optional<InputError> error = error_of(edited_model(patch));
    ASSERT_TRUE(error) << patch;
    EXPECT_EQ(std::string(error->what()).rfind(message, 0), 0u) << error->what();
  }
}

TEST(ModelReader, SuggestsOnlyCloseNames) {
  const std::optional<InputError> error =
      error_of(edited_model(R"([{"op": "add", "path": "/nodes/0/colour", "value": "red"}])"));
  ASSERT_TRUE(error);
  EXPECT_EQ(error->where(), "/nodes/0/colour");
  EXPECT_EQ(error->reason(), "unknown field");
}

TEST(ModelReader, ReadsAFile) {
  const std::filesystem::path path =
      std::filesystem::path(testing::TempDir()) / "pound_model_reader_test.json";
  std::ofstream(path) << kModel;
  const builder::ModelSpec spec = read_model_file(path.string());
  EXPECT_EQ(spec.source, path.string());
  EXPECT_EQ(spec.nodes.size(), 3u);
  std::filesystem::remove(path);
}

// Reading `path` must fail naming the path, for `reason`.
void expect_unreadable(const std::string& path, const std::string& reason) {
  try {
    (void)read_model_file(path);
    ADD_FAILURE() << "read " << path;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.reason(), reason);
  }
}

TEST(ModelReader, RejectsMissingFile) {
  expect_unreadable(
      (std::filesystem::path(testing::TempDir()) / "pound_no_such_model.json").string(),
      "no such file");
}

TEST(ModelReader, RejectsFolder) {
  expect_unreadable(testing::TempDir(), "is a folder, not a file");
}

TEST(JsonReader, SuggestsTheClosestName) {
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("abc", ""), 3u);
  EXPECT_EQ(edit_distance("gpa", "gap"), 1u);
  EXPECT_EQ(closest_name("matrial", {"id", "material", "area"}), "material");
  EXPECT_EQ(closest_name("Youngs_Modulus", {"youngs_modulus"}), "youngs_modulus");
  EXPECT_FALSE(closest_name("foo", {"fix", "node"}));
  EXPECT_FALSE(closest_name("z", {"x", "y"}));
  EXPECT_EQ(closest_name("gpa", {"id", "gap"}), "gap");
}

// Issue 16 item 8: a yield drift is a displacement; its new name says so, its old one still reads.
TEST(ModelReader, YieldDisplacementIsAlsoReadUnderItsOlderName) {
  for (const char* name : {"yield_displacement", "yield_drift"}) {
    const std::string monitors = fmt::format(
        R"({{"drifts": [{{"id": "s", "bottom": "a0", "top": "a1", "height": 3, "{}": 0.02}}]}})",
        name);
    const builder::ModelSpec spec =
        parse_model(nlohmann::json::parse(kModel)
                        .patch(nlohmann::json::parse(
                            R"([{"op": "add", "path": "/monitors", "value": )" + monitors + "}]"))
                        .dump(),
                    "x.json");
    ASSERT_EQ(spec.drift_monitors.size(), 1u);
    EXPECT_EQ(spec.drift_monitors[0].yield_drift, 0.02) << name;
  }
}

// A bad input, the JSON path (or line and column) its error must name, and a phrase of the
// message. `input` is the whole text for text cases and a JSON patch of kModel for edit cases.
struct BadCase {
  std::string name;
  std::string input;
  std::string where;
  std::string phrase;
};

void PrintTo(const BadCase& bad, std::ostream* out) { *out << bad.name; }

void expect_rejected(const std::string& text, const BadCase& bad) {
  const std::optional<InputError> error = error_of(text);
  ASSERT_TRUE(error) << "accepted:\n" << text;
  EXPECT_EQ(error->file(), "x.json");
  EXPECT_EQ(error->where(), bad.where) << error->what();
  EXPECT_NE(error->reason().find(bad.phrase), std::string::npos)
      << "message: " << error->what() << "\nexpected phrase: " << bad.phrase;
}

std::string case_name(const testing::TestParamInfo<BadCase>& info) { return info.param.name; }

// One-operation JSON patches; `value` is JSON text.
std::string patch(const std::string& operation, const std::string& path, const std::string& value) {
  return R"([{"op": ")" + operation + R"(", "path": ")" + path + R"(", "value": )" + value + "}]";
}
std::string replaced(const std::string& path, const std::string& value) {
  return patch("replace", path, value);
}
std::string added(const std::string& path, const std::string& value) {
  return patch("add", path, value);
}
// Two additions in one patch.
std::string added(const std::string& path, const std::string& value, const std::string& second_path,
                  const std::string& second_value) {
  const std::string first = added(path, value), second = added(second_path, second_value);
  return first.substr(0, first.size() - 1) + ", " + second.substr(1);
}
std::string removed(const std::string& path) {
  return R"([{"op": "remove", "path": ")" + path + R"("}])";
}
std::string moved(const std::string& from, const std::string& path) {
  return R"([{"op": "move", "from": ")" + from + R"(", "path": ")" + path + R"("}])";
}

class BadText : public testing::TestWithParam<BadCase> {};

TEST_P(BadText, IsRejected) { expect_rejected(GetParam().input, GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    ModelReader, BadText,
    testing::Values(BadCase{"syntax_error", "{\n  \"analysis\": {\n    \"x\" 1}}",
                            "line 3, column 9",
                            "syntax error: unexpected number literal; expected ':'"},
                    BadCase{"trailing_comma", R"({"analysis": {},})", "line 1, column 17",
                            "syntax error: unexpected '}'"},
                    BadCase{"bad_literal", "{\"title\":\n tru}", "line 2, column 5",
                            "syntax error: invalid literal"},
                    BadCase{"garbage_after_object", "{\"title\": \"x\"}\n x", "line 2, column 2",
                            "syntax error: invalid literal; expected end of input"},
                    BadCase{"unterminated", "{\"title\": \"x\"\n", "line 2, column 1",
                            "syntax error: unexpected end of input"},
                    BadCase{"number_overflow", R"({"dimension": 1e400})", "line 1, column 19",
                            "number out of range: 1e400"},
                    BadCase{"repeated_key", R"({"analysis": {"time_step": 1, "time_step": 2}})",
                            "/analysis/time_step", "field given twice"},
                    BadCase{"repeated_key_in_array",
                            R"({"nodes": [{"id": "a"}, {"id": "b", "id": "c"}]})", "/nodes/1/id",
                            "field given twice"},
                    BadCase{"utf16_text", std::string("\xFF\xFE{\0}\0", 6), "",
                            "UTF-16 text; save it as UTF-8"},
                    BadCase{"binary", std::string("\177ELF\2\1\1\0\0", 9), "line 1, column 8",
                            "a NUL byte: binary data or UTF-16 text"},
                    BadCase{"empty_text", "", "", "empty"},  // where "": the whole file
                    BadCase{"blank_text", " \n\t\r\n", "", "empty"},
                    BadCase{"top_level_array", "[]", "", "expected an object, got an array"},
                    BadCase{"top_level_number", "3", "", "expected an object, got a number"}),
    case_name);

class BadEdit : public testing::TestWithParam<BadCase> {};

TEST_P(BadEdit, IsRejected) { expect_rejected(edited_model(GetParam().input), GetParam()); }

INSTANTIATE_TEST_SUITE_P(
    ModelReader, BadEdit,
    testing::Values(
        // Types.
        BadCase{"gap_is_string", replaced("/links/0/gap", R"("0.1")"), "/links/0/gap",
                "expected a number, got a string"},
        BadCase{"nodes_is_object", replaced("/nodes", "{}"), "/nodes",
                "expected an array, got an object"},
        BadCase{"node_is_string", replaced("/nodes/1", R"("a1")"), "/nodes/1",
                "expected an object, got a string"},
        BadCase{"id_is_number", replaced("/nodes/0/id", "7"), "/nodes/0/id",
                "expected a string, got a number"},
        BadCase{"id_is_empty", replaced("/nodes/0/id", R"("")"), "/nodes/0/id",
                "expected a non-empty string"},
        BadCase{"title_is_number", replaced("/title", "5"), "/title", "expected a string"},
        BadCase{"analysis_is_array", replaced("/analysis", "[]"), "/analysis",
                "expected an object, got an array"},
        BadCase{"integrator_is_number", replaced("/analysis/integrator", "0.25"),
                "/analysis/integrator", "expected an object or a preset name string"},
        BadCase{"x_is_null", replaced("/nodes/0/x", "null"), "/nodes/0/x",
                "expected a number, got null"},
        // Required fields.
        BadCase{"missing_analysis", removed("/analysis"), "/analysis", "required field is missing"},
        BadCase{"missing_time_step", removed("/analysis/time_step"), "/analysis/time_step",
                "required field is missing"},
        BadCase{"missing_duration", removed("/analysis/duration"), "/analysis",
                "needs 'duration' (it may be left out only with 'excitations')"},
        BadCase{"missing_material", removed("/elements/0/material"), "/elements/0/material",
                "required field is missing"},
        BadCase{"missing_node_x", removed("/nodes/0/x"), "/nodes/0/x", "required field is missing"},
        BadCase{"missing_link_law", removed("/links/0/law"), "/links/0/law",
                "required field is missing"},
        BadCase{"missing_rod", removed("/generators/0/left"), "/generators/0/left",
                "required field is missing"},
        BadCase{"missing_recorder_nodes", removed("/recorders/1/nodes"), "/recorders/1/nodes",
                "required field is missing"},
        // Unknown fields.
        BadCase{"misspelt_required_field", moved("/elements/0/material", "/elements/0/matrial"),
                "/elements/0/matrial", "unknown field (did you mean 'material'?)"},
        BadCase{"misspelt_analysis", moved("/analysis", "/analysys"), "/analysys",
                "unknown field (did you mean 'analysis'?)"},
        BadCase{"unknown_top_level_field", added("/colour", R"("red")"), "/colour",
                "unknown field"},
        BadCase{"misspelt_optional_field", added("/links/0/gpa", "0.1"), "/links/0/gpa",
                "unknown field (did you mean 'gap'?)"},
        BadCase{"unknown_law_field", added("/links/0/law/damping", "0.1"), "/links/0/law/damping",
                "unknown field"},
        BadCase{"unknown_rod_field", added("/generators/0/left/colour", "1"),
                "/generators/0/left/colour", "unknown field"},
        BadCase{"misspelt_generator_field", added("/generators/0/gaps", "0.1"),
                "/generators/0/gaps", "unknown field (did you mean 'gap'?)"},
        BadCase{"misspelt_convergence_field", added("/analysis/convergence/max_iteration", "5"),
                "/analysis/convergence/max_iteration",
                "unknown field (did you mean 'max_iterations'?)"},
        BadCase{"unknown_integrator_field", added("/analysis/integrator/alpha", "0.1"),
                "/analysis/integrator/alpha", "unknown field"},
        BadCase{"yield_displacement_under_both_names",
                added("/monitors", R"({"drifts": [{"id": "s", "bottom": "a0", "top": "a1",
                                         "height": 3, "yield_drift": 0.02,
                                         "yield_displacement": 0.02}]})"),
                "/monitors/drifts/0/yield_drift",
                "'yield_drift' is the older name of 'yield_displacement': give one of them"},
        BadCase{"unknown_recorder_field", added("/recorders/0/every_step", "2"),
                "/recorders/0/every_step", "unknown field"},
        BadCase{"zero_output_interval", added("/recorders/0/interval", "0"),
                "/recorders/0/interval", "must be > 0"},
        BadCase{"negative_output_interval", added("/recorders/1/interval", "-0.01"),
                "/recorders/1/interval", "must be > 0"},
        BadCase{"zero_every", added("/recorders/0/every", "0"), "/recorders/0/every",
                "must be >= 1"},
        BadCase{"every_and_interval",
                added("/recorders/0/every", "2", "/recorders/0/interval", "0.01"),
                "/recorders/0/interval", "give \"every\" or \"interval\", not both"},
        BadCase{"thinned_envelope",
                added("/recorders/1/envelope", "true", "/recorders/1/every", "3"),
                "/recorders/1/every", "an envelope takes every step"},
        BadCase{"spectrum_damping_of_one",
                replaced("/recorders/1", R"({"type": "spectrum", "nodes": ["girder_1"],
                                             "damping": [0.05, 1.0]})"),
                "/recorders/1/damping/1", "a damping ratio must be in (0, 1), got 1"},
        BadCase{"spectrum_damping_zero",
                replaced("/recorders/1", R"({"type": "spectrum", "nodes": ["girder_1"],
                                             "damping": [0]})"),
                "/recorders/1/damping/0", "must be > 0"},
        BadCase{"negative_spectrum_period",
                replaced("/recorders/1", R"({"type": "spectrum", "nodes": ["girder_1"],
                                             "periods": [0.1, -1]})"),
                "/recorders/1/periods/1", ">= 0"},
        BadCase{"damping_on_a_node_recorder", added("/recorders/1/damping", "[0.05]"),
                "/recorders/1/damping", "unknown field"},
        BadCase{"envelope_of_a_spectrum",
                replaced("/recorders/1", R"({"type": "spectrum", "nodes": ["girder_1"],
                                             "envelope": true})"),
                "/recorders/1/envelope", "unknown field"},
        BadCase{"links_in_node_recorder", added("/recorders/1/links", R"(["joint"])"),
                "/recorders/1/links", "unknown field"},
        // Ranges.
        BadCase{"negative_gap", replaced("/links/0/gap", "-0.01"), "/links/0/gap",
                "must be >= 0, got -0.01"},
        BadCase{"negative_generator_gap", replaced("/generators/0/gap", "-1"), "/generators/0/gap",
                "must be >= 0, got -1"},
        BadCase{"zero_youngs_modulus", replaced("/materials/0/youngs_modulus", "0"),
                "/materials/0/youngs_modulus", "must be > 0, got 0"},
        BadCase{"negative_youngs_modulus", replaced("/materials/0/youngs_modulus", "-2e11"),
                "/materials/0/youngs_modulus", "must be > 0"},
        BadCase{"negative_density", replaced("/materials/0/density", "-1"), "/materials/0/density",
                "must be >= 0, got -1"},
        BadCase{"zero_area", replaced("/elements/0/area", "0"), "/elements/0/area",
                "must be > 0, got 0"},
        BadCase{"negative_area", replaced("/elements/0/area", "-0.01"), "/elements/0/area",
                "must be > 0, got -0.01"},
        BadCase{"zero_mass", replaced("/masses/0/mass", "0"), "/masses/0/mass", "must be > 0"},
        BadCase{"negative_rod_length", replaced("/generators/0/left/length", "-10"),
                "/generators/0/left/length", "must be > 0, got -10"},
        BadCase{"zero_rod_density", replaced("/generators/0/right/density", "0"),
                "/generators/0/right/density", "must be > 0, got 0"},
        BadCase{"zero_rod_area", replaced("/generators/0/right/area", "0"),
                "/generators/0/right/area", "must be > 0, got 0"},
        BadCase{"zero_elements", replaced("/generators/0/right/elements", "0"),
                "/generators/0/right/elements", "must be >= 1, got 0"},
        BadCase{"fractional_elements", replaced("/generators/0/right/elements", "2.5"),
                "/generators/0/right/elements", "expected an integer, got 2.5"},
        BadCase{"too_many_elements", replaced("/generators/0/right/elements", "2000000000"),
                "/generators/0/right/elements", "must be <= 100000000, got 2000000000"},
        BadCase{"huge_elements", replaced("/generators/0/right/elements", "1e12"),
                "/generators/0/right/elements",
                "expected an integer from -2147483648 to 2147483647, got 1000000000000"},
        BadCase{"huge_integer_elements",
                replaced("/generators/0/right/elements", "99999999999999999999"),
                "/generators/0/right/elements", "expected an integer from"},
        BadCase{"elements_is_string", replaced("/generators/0/right/elements", R"("10")"),
                "/generators/0/right/elements", "expected an integer, got a string"},
        BadCase{"negative_stiffness", replaced("/links/0/law/stiffness", "-1e8"),
                "/links/0/law/stiffness", "must be > 0"},
        BadCase{"zero_stiffness_ratio", replaced("/generators/0/law/stiffness_ratio", "0"),
                "/generators/0/law/stiffness_ratio", "must be > 0, got 0"},
        BadCase{"negative_time_step", replaced("/analysis/time_step", "-1e-3"),
                "/analysis/time_step", "must be > 0, got -0.001"},
        BadCase{"zero_duration", replaced("/analysis/duration", "0"), "/analysis/duration",
                "must be > 0, got 0"},
        BadCase{"zero_beta", replaced("/analysis/integrator/beta", "0"),
                "/analysis/integrator/beta", "must be > 0, got 0"},
        BadCase{"small_gamma", replaced("/analysis/integrator/gamma", "0.4"),
                "/analysis/integrator/gamma", "must be >= 0.5, got 0.4"},
        BadCase{"zero_max_iterations", replaced("/analysis/convergence/max_iterations", "0"),
                "/analysis/convergence/max_iterations", "must be >= 1, got 0"},
        BadCase{"zero_relative_tolerance",
                replaced("/analysis/convergence/relative_tolerance", "0"),
                "/analysis/convergence/relative_tolerance", "must be > 0, got 0"},
        BadCase{"negative_absolute_tolerance",
                replaced("/analysis/convergence/absolute_tolerance", "-1"),
                "/analysis/convergence/absolute_tolerance", "must be >= 0, got -1"},
        BadCase{"negative_max_step_cuts", replaced("/analysis/max_step_cuts", "-1"),
                "/analysis/max_step_cuts", "must be >= 0, got -1"},
        BadCase{"negative_max_steps", replaced("/analysis/max_steps", "-5"), "/analysis/max_steps",
                "must be >= 0, got -5"},
        BadCase{"huge_max_steps", replaced("/analysis/max_steps", "1e19"), "/analysis/max_steps",
                "expected an integer from -9223372036854775808 to 9223372036854775807"},
        // Enumerations and dimensions.
        BadCase{"dimension_4", replaced("/dimension", "4"), "/dimension",
                "must be 1, 2 or 3, got 4"},
        BadCase{"fractional_dimension", replaced("/dimension", "1.5"), "/dimension",
                "expected an integer, got 1.5"},
        BadCase{"node_y_in_1d", added("/nodes/0/y", "0"), "/nodes/0/y",
                "only allowed when dimension is 2 or 3"},
        BadCase{"node_z_in_1d", added("/nodes/0/z", "0"), "/nodes/0/z",
                "only allowed when dimension is 3"},
        BadCase{"fix_y_in_1d", replaced("/supports/0/fix", R"(["x", "y"])"), "/supports/0/fix/1",
                "only allowed when dimension is 2 or 3"},
        BadCase{"velocity_y_in_1d", added("/initial_velocities/0/y", "0.1"),
                "/initial_velocities/0/y", "only allowed when dimension is 2 or 3"},
        BadCase{"fix_z_in_1d", replaced("/supports/0/fix", R"(["z"])"), "/supports/0/fix/0",
                "only allowed when dimension is 3"},
        BadCase{"bad_fix_direction", replaced("/supports/0/fix", R"(["w"])"), "/supports/0/fix/0",
                "expected one of 'x', 'y', 'z', 'rx', 'ry', 'rz', got 'w'"},
        BadCase{"upper_case_direction", replaced("/supports/0/fix", R"(["X"])"),
                "/supports/0/fix/0", "got 'X' (did you mean 'x'?)"},
        BadCase{"empty_fix", replaced("/supports/0/fix", "[]"), "/supports/0/fix",
                "expected at least 1 element, got 0"},
        BadCase{"repeated_fix", replaced("/supports/0/fix", R"(["x", "x"])"), "/supports/0/fix/1",
                "duplicate direction 'x' (first at /supports/0/fix/0)"},
        BadCase{"axis_too_long", replaced("/links/0/axis", "[1, 0]"), "/links/0/axis",
                "expected exactly 1 element, got 2"},
        BadCase{"axis_not_unit", replaced("/links/0/axis", "[0.5]"), "/links/0/axis",
                "must be a unit vector (length 1 within 1e-09), got length 0.5"},
        BadCase{"axis_nearly_unit", replaced("/links/0/axis", "[1.000001]"), "/links/0/axis",
                "must be a unit vector"},
        BadCase{"axis_component_string", replaced("/links/0/axis", R"(["1"])"), "/links/0/axis/0",
                "expected a number, got a string"},
        BadCase{"beam_in_1d_scene", replaced("/elements/0/type", R"("beam")"), "/elements/0/type",
                "a beam needs a 2-D or 3-D scene"},
        BadCase{"unknown_element_type", replaced("/elements/0/type", R"("bar")"),
                "/elements/0/type", "expected one of 'truss', 'beam', 'quad', got 'bar'"},
        BadCase{"bad_far_end", replaced("/generators/0/left/far_end", R"("hinged")"),
                "/generators/0/left/far_end", "expected one of 'free', 'fixed', got 'hinged'"},
        BadCase{"unknown_generator_type", replaced("/generators/0/type", R"("rod_par")"),
                "/generators/0/type", "got 'rod_par' (did you mean 'rod_pair'?)"},
        BadCase{"missing_generator_type", removed("/generators/0/type"), "/generators/0/type",
                "required field is missing"},
        BadCase{"unknown_integrator_preset", replaced("/analysis/integrator", R"("newmark")"),
                "/analysis/integrator",
                "expected one of 'newmark_average_acceleration', 'newmark_linear_acceleration'"},
        BadCase{"unknown_integrator_type", replaced("/analysis/integrator/type", R"("wilson")"),
                "/analysis/integrator/type",
                "expected one of 'newmark', 'hht', 'generalized_alpha', 'central_difference'"},
        BadCase{"auto_step_for_an_implicit_integrator",
                replaced("/analysis/time_step", R"("auto")"), "/analysis/time_step",
                "implicit integrators need a number"},
        BadCase{"hht_with_newmark_beta", replaced("/analysis/integrator/type", R"("hht")"),
                "/analysis/integrator/beta", "unknown field"},
        BadCase{"hht_alpha_positive",
                replaced("/analysis/integrator", R"({"type": "hht", "alpha": 0.1})"),
                "/analysis/integrator/alpha", "must be <= 0"},
        BadCase{"rho_infinity_above_one",
                replaced("/analysis/integrator",
                         R"({"type": "generalized_alpha", "rho_infinity": 1.5})"),
                "/analysis/integrator/rho_infinity", "must be <= 1"},
        // Contact laws.
        // The law catalog: every law's parameters, ranges and combinations.
        BadCase{"kelvin_voigt_without_damping",
                replaced("/links/0/law", R"({"type": "kelvin_voigt", "stiffness": 1e8})"),
                "/links/0/law", "kelvin_voigt needs 'damping' or 'restitution'"},
        BadCase{"kelvin_voigt_damping_and_restitution",
                replaced("/links/0/law", R"({"type": "kelvin_voigt", "stiffness": 1e8,
                                             "damping": 10, "restitution": 0.5})"),
                "/links/0/law", "give either 'damping' or 'restitution', not both"},
        BadCase{"restitution_above_one",
                replaced("/links/0/law", R"({"type": "hertz_damp", "stiffness": 1e8,
                                             "restitution": 1.2})"),
                "/links/0/law/restitution", "must be <= 1"},
        BadCase{"restitution_zero",
                replaced("/links/0/law", R"({"type": "jankowski", "stiffness": 1e8,
                                             "restitution": 0})"),
                "/links/0/law/restitution", "must be > 0"},
        BadCase{"bad_tension_choice",
                replaced("/links/0/law", R"({"type": "kelvin_voigt", "stiffness": 1e8,
                                             "restitution": 0.5, "tension": "clipped"})"),
                "/links/0/law/tension", "expected one of 'clip', 'allow', got 'clipped'"},
        BadCase{"bad_calibration_choice",
                replaced("/links/0/law", R"({"type": "hertz_damp", "stiffness": 1e8,
                                             "restitution": 0.5, "calibration": "ye"})"),
                "/links/0/law/calibration", "expected one of 'exact', 'published'"},
        BadCase{"bilinear_k1_without_k2",
                replaced("/links/0/law", R"({"type": "bilinear_impact", "k1": 1e8,
                                             "yield_penetration": 0.001})"),
                "/links/0/law", "'k1' needs 'k2'"},
        BadCase{"bilinear_k1_with_stiffness",
                replaced("/links/0/law", R"({"type": "bilinear_impact", "k1": 1e8, "k2": 1e7,
                                             "yield_penetration": 0.001, "stiffness": 1e9})"),
                "/links/0/law/stiffness", "not allowed together with 'k1'"},
        BadCase{"yield_fraction_one",
                replaced("/links/0/law", R"({"type": "bilinear_impact", "stiffness": 1e9,
                                             "restitution": 0.6, "yield_fraction": 1})"),
                "/links/0/law/yield_fraction", "must be < 1"},
        BadCase{"extended_penalty_misspelt",
                replaced("/links/0/law", R"({"type": "extended_penalty", "alhpa0": 1e9})"),
                "/links/0/law/alhpa0", "unknown field (did you mean 'alpha0'?)"},
        BadCase{"hardening_without_yield",
                replaced("/links/0/law", R"({"type": "restrainer", "stiffness": 1e7,
                                             "hardening_ratio": 0.05})"),
                "/links/0/law", "'hardening_ratio' needs 'yield_force'"},
        BadCase{"negative_slack",
                replaced("/links/0/law", R"({"type": "hook", "stiffness": 1e7, "slack": -0.01})"),
                "/links/0/law/slack", "must be >= 0"},
        // Friction and loads.
        BadCase{"friction_without_coefficient", added("/links/0/friction", R"({})"),
                "/links/0/friction/coefficient", "required field is missing"},
        BadCase{"negative_friction", added("/links/0/friction", R"({"coefficient": -0.2})"),
                "/links/0/friction/coefficient", "must be >= 0"},
        BadCase{"friction_misspelt",
                added("/links/0/friction", R"({"coefficient": 0.2, "stik_stiffness": 1})"),
                "/links/0/friction/stik_stiffness", "did you mean 'stick_stiffness'?"},
        BadCase{"load_y_in_1d", added("/loads", R"([{"node": "b0", "y": -9.81}])"), "/loads/0/y",
                "only allowed when dimension is 2 or 3"},
        BadCase{"load_is_string", added("/loads", R"([{"node": "b0", "x": "heavy"}])"),
                "/loads/0/x", "expected a number"},
        BadCase{"unknown_law", replaced("/links/0/law/type", R"("gap_sprng")"), "/links/0/law/type",
                "got 'gap_sprng' (did you mean 'gap_spring'?)"},
        BadCase{"law_without_stiffness", removed("/links/0/law/stiffness"), "/links/0/law",
                "needs 'stiffness'"},
        BadCase{"misspelt_stiffness", moved("/links/0/law/stiffness", "/links/0/law/stifness"),
                "/links/0/law/stifness", "unknown field (did you mean 'stiffness'?)"},
        BadCase{"stiffness_ratio_in_link", added("/links/0/law/stiffness_ratio", "1"),
                "/links/0/law/stiffness_ratio", "only allowed inside a rod_pair generator"},
        BadCase{"stiffness_and_ratio", added("/generators/0/law/stiffness", "1e8"),
                "/generators/0/law", "give either 'stiffness' or 'stiffness_ratio', not both"},
        BadCase{"generator_law_without_stiffness", removed("/generators/0/law/stiffness_ratio"),
                "/generators/0/law", "needs 'stiffness' or 'stiffness_ratio'"},
        // Node pairs and duplicate ids.
        BadCase{"element_with_three_nodes", replaced("/elements/0/nodes", R"(["a0", "a1", "b0"])"),
                "/elements/0/nodes", "expected exactly 2 elements, got 3"},
        BadCase{"element_nodes_is_string", replaced("/elements/0/nodes", R"("a0")"),
                "/elements/0/nodes", "expected an array, got a string"},
        BadCase{"link_joins_a_node_to_itself", replaced("/links/0/nodes", R"(["a1", "a1"])"),
                "/links/0/nodes/1", "duplicate node 'a1' (first at /links/0/nodes/0)"},
        BadCase{"duplicate_node_id", replaced("/nodes/2/id", R"("a0")"), "/nodes/2/id",
                "duplicate id 'a0' (first at /nodes/0/id)"},
        BadCase{"duplicate_material_id",
                added("/materials/-", R"({"id": "steel", "youngs_modulus": 1, "density": 1})"),
                "/materials/1/id", "duplicate id 'steel' (first at /materials/0/id)"},
        BadCase{"duplicate_element_id",
                added("/elements/-",
                      R"({"id": "e0", "type": "truss", "nodes": ["a1", "b0"], "material": "steel",
                        "area": 1})"),
                "/elements/1/id", "duplicate id 'e0' (first at /elements/0/id)"},
        BadCase{"duplicate_link_id",
                added("/links/-",
                      R"({"id": "joint", "nodes": ["a0", "b0"],
                        "law": {"type": "gap_spring", "stiffness": 1}})"),
                "/links/1/id", "duplicate id 'joint' (first at /links/0/id)"},
        // Recorders.
        BadCase{"recorder_file_in_parent", replaced("/recorders/0/file", R"("../out.csv")"),
                "/recorders/0/file", "must be a plain file name ending in .csv"},
        BadCase{"recorder_file_in_folder", replaced("/recorders/0/file", R"("out\\f.csv")"),
                "/recorders/0/file", "must be a plain file name ending in .csv"},
        BadCase{"recorder_file_not_csv", replaced("/recorders/0/file", R"("out.txt")"),
                "/recorders/0/file", "must be a plain file name ending in .csv"},
        BadCase{"duplicate_recorder_file", added("/recorders/1/file", R"("link_force.csv")"),
                "/recorders/1/file",
                "duplicate file name 'link_force.csv' (first at /recorders/0/file)"},
        BadCase{"file_clashes_with_default", replaced("/recorders/0/file", R"("node_1.csv")"),
                "/recorders/1", "duplicate file name 'node_1.csv' (first at /recorders/0/file)"},
        BadCase{"unknown_recorder_type", replaced("/recorders/0/type", R"("elemnt")"),
                "/recorders/0/type",
                "expected one of 'link', 'node', 'element', 'spectrum', got 'elemnt'"},
        BadCase{"empty_link_list", replaced("/recorders/0/links", "[]"), "/recorders/0/links",
                "expected at least 1 element, got 0"},
        BadCase{"recorder_node_is_number", replaced("/recorders/1/nodes/0", "1"),
                "/recorders/1/nodes/0", "expected a string, got a number"}),
    case_name);

// Each law's example (what docs/laws.md shows) is a law object the reader accepts as it is.
TEST(ModelReader, EveryLawsExampleReads) {
  for (const links::LawEntry* law : links::law_registry()) {
    nlohmann::json object{{"type", law->name}};
    for (const auto& [name, value] : law->example) object[name] = value;
    const builder::LawSpec read =
        read_law_in(JsonValue(object, "x.json", "/links/0/law"), LawPlace::link);
    EXPECT_EQ(read.parameters, law->example) << law->name;
  }
}

}  // namespace
}  // namespace pound::io
