// The schema facility on a small struct of its own: reading with checks and defaults, writing
// back, unknown fields, fields of 2-D scenes and of some variants, choice tables, rules and the
// docs table.
#include "io/schema.hpp"

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"

namespace pound::io {
namespace {

using nlohmann::json;

enum class Shape { round, square };

struct Inner {
  double x = 0.0;
  int count = 3;
};

struct Part {
  std::string id;
  std::string kind;     // "plain" | "fancy"
  double length = 1.0;  // > 0, < 100
  Shape shape = Shape::round;
  bool hollow = false;  // "solid" | "hollow"
  double y = 0.0;       // 2-D only
  double depth = 0.0;   // fancy only
  std::optional<double> weight;
  std::vector<std::string> nodes;
  std::array<double, 2> offset{0.0, 0.0};
  std::vector<double> axis{1.0};
  Inner inner;
  std::vector<Inner> items;
  bool label = false;  // written always
};

const Fields<Inner>& inner_fields() {
  static const Fields<Inner> fields = {
      required("x", &Inner::x, Number<>{}, "position [L]"),
      optional("count", &Inner::count, Number<int>{at_least(1), at_most(9)}, "how many"),
  };
  return fields;
}

bool is_fancy(const Part& part) { return part.kind == "fancy"; }

const Fields<Part>& part_fields() {
  static const Fields<Part> fields = {
      unique_id(&Part::id, "parts", "the part's name"),
      required("kind", &Part::kind, names_choice({"plain", "fancy"}), "what it is"),
      optional("length", &Part::length,
               Number<>{positive, below(100.0, "must be < 100 (a short part), got {}")},
               "length [L]"),
      optional("shape", &Part::shape,
               Choice<Shape>{{{"round", Shape::round}, {"square", Shape::square}}},
               "its cross-section"),
      optional("hollow", &Part::hollow, Choice<bool>{{{"solid", false}, {"hollow", true}}},
               "solid or hollow"),
      optional("y", &Part::y, Number<>{}, "height [L]").in_plane(),
      rule<Part>([](JsonObject& object, Part& part, Context&) {
        if (part.hollow && part.length < 2.0)
          object.at("hollow").fail("a hollow part needs a length of at least 2");
      }),
      required("depth", &Part::depth, Number<>{positive}, "depth [L]").when(is_fancy, "fancy only"),
      optional("weight", &Part::weight, Number<>{non_negative}, "weight [F]"),
      optional("nodes", &Part::nodes, Names{}, "node ids"),
      optional("offset", &Part::offset, Pair<>{}, "[dx, dy] [L]"),
      optional("axis", &Part::axis, UnitVector<std::vector<double>>{}, "direction"),
      nested<Part>("more", {optional("label", &Part::label, Flag{}, "labelled").always_written()},
                   "extras"),
      optional("inner", &Part::inner, Object<Inner>{inner_fields()}, "an inner object"),
      optional("items", &Part::items, Objects<Inner>{inner_fields()}, "inner objects"),
  };
  return fields;
}

Part read_part(const std::string& text, int dimension = 1) {
  const json document = json::parse(text);
  Context context;
  context.dimension = dimension;
  Part part;
  read_into(JsonValue(document, "part.json", ""), part_fields(), part, context);
  return part;
}

json written(const Part& part, int dimension = 1) {
  Context context;
  context.dimension = dimension;
  return json::parse(write_object(part, part_fields(), context).dump());
}

std::string error_of(const std::string& text, int dimension = 1) {
  try {
    (void)read_part(text, dimension);
  } catch (const InputError& error) {
    return error.what();
  }
  return "accepted";
}

constexpr const char* kFull = R"({"id": "p", "kind": "fancy", "length": 5, "shape": "square",
  "hollow": "hollow", "y": 0.5, "depth": 2, "weight": 0, "nodes": ["a", "b"], "offset": [1, 2],
  "axis": [0.6, 0.8], "more": {"label": true}, "inner": {"x": 1.5, "count": 4},
  "items": [{"x": 1}, {"x": 2, "count": 9}]})";

TEST(Schema, ReadsEveryKindOfField) {
  const Part part = read_part(kFull, 2);
  EXPECT_EQ(part.id, "p");
  EXPECT_EQ(part.kind, "fancy");
  EXPECT_EQ(part.length, 5.0);
  EXPECT_EQ(part.shape, Shape::square);
  EXPECT_TRUE(part.hollow);
  EXPECT_EQ(part.y, 0.5);
  EXPECT_EQ(part.depth, 2.0);
  EXPECT_EQ(part.weight, 0.0);
  EXPECT_EQ(part.nodes, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(part.offset, (std::array<double, 2>{1.0, 2.0}));
  EXPECT_EQ(part.axis, (std::vector<double>{0.6, 0.8}));
  EXPECT_TRUE(part.label);
  EXPECT_EQ(part.inner.x, 1.5);
  EXPECT_EQ(part.inner.count, 4);
  ASSERT_EQ(part.items.size(), 2u);
  EXPECT_EQ(part.items[0].count, 3);
  EXPECT_EQ(part.items[1].count, 9);
}

TEST(Schema, WritesBackWhatItRead) {
  EXPECT_EQ(written(read_part(kFull, 2), 2), json::parse(kFull));
}

TEST(Schema, LeavesOutDefaultsUnlessAlwaysWritten) {
  const Part part = read_part(R"({"id": "p", "kind": "plain"})");
  EXPECT_EQ(part.length, 1.0);
  EXPECT_EQ(part.shape, Shape::round);
  EXPECT_FALSE(part.weight);
  EXPECT_EQ(part.axis, std::vector<double>{1.0});
  // "more" reads the same as a default part's, though its label is always written within it.
  EXPECT_EQ(written(part), json::parse(R"({"id": "p", "kind": "plain"})"));
}

TEST(Schema, ChecksBounds) {
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "length": 0})"),
            "part.json: /length: must be > 0, got 0");
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "length": 100})"),
            "part.json: /length: must be < 100 (a short part), got 100");
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "inner": {"x": 0, "count": 10}})"),
            "part.json: /inner/count: must be <= 9, got 10");
  EXPECT_EQ(error_of(R"({"id": "", "kind": "plain"})"),
            "part.json: /id: expected a non-empty string");
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "axis": [1, 1]})"),
            "part.json: /axis: expected exactly 1 element, got 2");
}

TEST(Schema, RejectsUnknownFieldsSuggestingTheClosest) {
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "lenght": 3})"),
            "part.json: /lenght: unknown field (did you mean 'length'?)");
  EXPECT_EQ(error_of(R"({"id": "p", "knid": "plain"})"),
            "part.json: /knid: unknown field (did you mean 'kind'?)");
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "inner": {"x": 1, "cuont": 2}})"),
            "part.json: /inner/cuont: unknown field (did you mean 'count'?)");
}

TEST(Schema, PlaneFieldsOnlyInTwoDimensions) {
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "y": 0})"),
            "part.json: /y: only allowed when dimension is 2");
  EXPECT_EQ(read_part(R"({"id": "p", "kind": "plain", "y": 3})", 2).y, 3.0);
  EXPECT_FALSE(written(read_part(R"({"id": "p", "kind": "plain"})", 1), 1).contains("y"));
  EXPECT_EQ(written(read_part(R"({"id": "p", "kind": "plain", "y": 3})", 2), 2)["y"], 3.0);
}

TEST(Schema, VariantFieldsAreUnknownToTheOthers) {
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "depth": 2})"),
            "part.json: /depth: unknown field here: it applies only where the docs say (fancy "
            "only)");
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "fancy"})"),
            "part.json: /depth: required field is missing");
  EXPECT_EQ(read_part(R"({"id": "p", "kind": "fancy", "depth": 2})").depth, 2.0);
  Part plain = read_part(R"({"id": "p", "kind": "plain"})");
  plain.depth = 7.0;  // not a field of a plain part: not written
  EXPECT_FALSE(written(plain).contains("depth"));
}

TEST(Schema, ChoiceTablesMapNamesToValues) {
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "plain", "shape": "sqaure"})"),
            "part.json: /shape: expected one of 'round', 'square', got 'sqaure' (did you mean "
            "'square'?)");
  Part part = read_part(R"({"id": "p", "kind": "plain", "length": 3, "hollow": "hollow"})");
  EXPECT_TRUE(part.hollow);
  part.shape = Shape::square;
  part.hollow = false;
  const json text = written(part);
  EXPECT_EQ(text["shape"], "square");
  EXPECT_FALSE(text.contains("hollow"));  // the default
}

TEST(Schema, RulesRunWhereTheyStand) {
  // The rule sees length and hollow, and runs before depth is asked for.
  EXPECT_EQ(error_of(R"({"id": "p", "kind": "fancy", "hollow": "hollow"})"),
            "part.json: /hollow: a hollow part needs a length of at least 2");
}

TEST(Schema, IdsAreUniqueWithinTheirScope) {
  const json document =
      json::parse(R"([{"id": "a", "kind": "plain"}, {"id": "a", "kind": "plain"}])");
  Context context;
  const std::vector<JsonValue> items = JsonValue(document, "parts.json", "").elements();
  Part first, second;
  read_into(items[0], part_fields(), first, context);
  try {
    read_into(items[1], part_fields(), second, context);
    FAIL() << "a repeated id was accepted";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "parts.json: /1/id: duplicate id 'a' (first at /0/id)");
  }
}

TEST(Schema, DocsTableListsEveryField) {
  const std::string table = field_table(part_fields());
  EXPECT_EQ(table.find("| field | type | default | meaning |\n| --- | --- | --- | --- |\n"), 0u)
      << table;
  for (const char* row : {
           "| `id` | string, unique | required | the part's name |",
           "| `length` | number > 0, < 100 | `1` | length [L] |",
           "| `shape` | `\"round\"` or `\"square\"` | `\"round\"` | its cross-section |",
           "| `y` | number | `0` | height [L] (2-D only) |",
           "| `depth` | number > 0 | required | depth [L] (fancy only) |",
           "| `weight` | number ≥ 0 | – | weight [F] |",
           "| `more.label` | true or false | `false` | labelled |",
           "| `inner.count` | integer ≥ 1, ≤ 9 | `3` | how many |",
           "| `items` | array of objects | – | inner objects |",
       })
    EXPECT_NE(table.find(row), std::string::npos) << "no row\n" << row << "\nin\n" << table;
}

}  // namespace
}  // namespace pound::io
