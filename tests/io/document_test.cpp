// Documents as JSON: keys in the order they were set, numbers in full, non-finite numbers as
// null, nested objects and lists.
#include "io/document.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>

namespace pound::io {
namespace {

TEST(Document, KeepsTheOrderKeysWereSetIn) {
  Document doc;
  doc.set("zeta", 1L).set("alpha", 2L).set("mid", 3L);
  EXPECT_EQ(doc.dump(-1), R"({"zeta":1,"alpha":2,"mid":3})");
  doc.set("alpha", 5L);  // set again: the value changes, the place stays
  EXPECT_EQ(doc.dump(-1), R"({"zeta":1,"alpha":5,"mid":3})");
}

TEST(Document, NumbersReadBackExactlyAndNonFiniteOnesAreNull) {
  const double third = 1.0 / 3.0, tiny = 5e-324;
  Document doc;
  doc.set("third", third)
      .set("tiny", tiny)
      .set("nan", std::nan(""))
      .set("infinity", std::numeric_limits<double>::infinity())
      .set("list", std::vector<double>{0.1, -std::numeric_limits<double>::infinity()});
  const nlohmann::json back = nlohmann::json::parse(doc.dump());
  EXPECT_EQ(back["third"].get<double>(), third);
  EXPECT_EQ(back["tiny"].get<double>(), tiny);
  EXPECT_TRUE(back["nan"].is_null());
  EXPECT_TRUE(back["infinity"].is_null());
  EXPECT_EQ(back["list"][0].get<double>(), 0.1);
  EXPECT_TRUE(back["list"][1].is_null());
}

TEST(Document, NestsObjectsAndListsOfObjects) {
  Document child;
  child.set("name", "a").set("ok", true);
  Document doc;
  doc.set("child", child).set("items", std::vector<Document>{child, Document().set("n", 2)});
  EXPECT_EQ(doc.dump(-1),
            R"({"child":{"name":"a","ok":true},"items":[{"name":"a","ok":true},{"n":2}]})");
  Document copy = doc;  // a copy is independent
  copy.set("extra", 1L);
  EXPECT_EQ(doc.dump(-1).find("extra"), std::string::npos);
}

}  // namespace
}  // namespace pound::io
