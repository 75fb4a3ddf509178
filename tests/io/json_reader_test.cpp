// Checked JSON reading on its own: values read as their types with the path of a bad one, unknown
// and missing fields, duplicate keys. (Edit distances and name suggestions are tested in
// model_reader_test.cpp.)
#include "io/json_reader.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace pound::io {
namespace {

// The message of the InputError `read` throws (empty if it throws none).
template <class Read>
std::string error_of(Read read) {
  try {
    read();
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(JsonReader, ValuesReadAsTheirTypeOrFailWithTheirPath) {
  const nlohmann::json doc =
      parse_json(R"({"n": 2.0, "half": 2.5, "gap": -0.01, "id": "", "on": true})", "m.json");
  JsonObject object(JsonValue(doc, "m.json", ""));
  EXPECT_EQ(object.required<int>("n"), 2);
  EXPECT_EQ(object.required<bool>("on"), true);
  EXPECT_EQ(error_of([&] { object.required<int>("half"); }),
            "m.json: /half: expected an integer, got 2.5");
  EXPECT_EQ(error_of([&] { object.required<double>("gap", non_negative); }),
            "m.json: /gap: must be >= 0, got -0.01");
  EXPECT_EQ(error_of([&] { object.required<std::string>("id", non_empty); }),
            "m.json: /id: expected a non-empty string");
  EXPECT_EQ(error_of([&] { object.required<std::string>("on"); }),
            "m.json: /on: expected a string, got a boolean");
}

TEST(JsonReader, UnknownFieldsSuggestTheClosestAndMissingOnesAreNamed) {
  const nlohmann::json doc = parse_json(R"({"gpa": 0.1, "law": {}})", "m.json");
  JsonObject object(JsonValue(doc, "m.json", "/links/0"));
  EXPECT_EQ(error_of([&] { object.required<double>("gap"); }),
            "m.json: /links/0/gpa: unknown field (did you mean 'gap'?)");
  EXPECT_EQ(error_of([&] { object.required<double>("area"); }),
            "m.json: /links/0/area: required field is missing");
  JsonObject asked(JsonValue(doc, "m.json", "/links/0"));
  asked.find("law");
  asked.find("gap");
  EXPECT_EQ(error_of([&] { asked.finish(); }),
            "m.json: /links/0/gpa: unknown field (did you mean 'gap'?)");
}

TEST(JsonReader, DuplicateKeysAndEmptyTextAreErrors) {
  EXPECT_NE(error_of([] { parse_json(R"({"a": 1, "a": 2})", "m.json"); }).find("/a"),
            std::string::npos);
  EXPECT_EQ(error_of([] { parse_json(" \n", "m.json"); }),
            "m.json: the file is empty (expected JSON)");
}

}  // namespace
}  // namespace pound::io
