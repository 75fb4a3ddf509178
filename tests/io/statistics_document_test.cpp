// batch_stats.json as a document: its keys in their order, the table of quantities that readers
// take their names and labels from, and the numbers of a group, an exceedance and a fit.
#include "io/statistics_document.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace pound::io {
namespace {

results::CaseSummary completed_case(const std::string& record, double ductility) {
  results::CaseSummary c;
  c.model = "bridge";
  c.record = record;
  c.status = results::CaseStatus::completed;
  c.intensity = 0.3;
  c.max_ductility = ductility;
  return c;
}

nlohmann::ordered_json document() {
  builder::SetSpec set;
  set.source = "sets/x.json";
  set.title = "two records";
  set.models = {{"bridge", "bridge.json"}};
  set.limits = {{"max_ductility", 1.0}};
  const std::vector<results::CaseSummary> cases = {completed_case("a", 0.5),
                                                   completed_case("b", 1.5)};
  return nlohmann::ordered_json::parse(
      to_document(results::batch_statistics(set, cases), set).dump());
}

TEST(StatisticsDocument, KeepsItsKeysInOrder) {
  const nlohmann::ordered_json doc = document();
  std::vector<std::string> keys;
  for (const auto& item : doc.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"set", "title", "cases", "completed", "failed",
                                            "input_errors", "statistics", "intensity_measure",
                                            "quantities", "groups", "fragility"}));
}

TEST(StatisticsDocument, ListsEveryQuantityWithItsMeaningLabelAndRole) {
  const nlohmann::ordered_json quantities = document()["quantities"];
  ASSERT_EQ(quantities.size(), results::batch_quantities().size());
  std::size_t k = 0;
  for (const auto& [name, entry] : quantities.items()) {
    const results::BatchQuantity& q = results::batch_quantities()[k++];
    EXPECT_EQ(name, q.name);
    EXPECT_EQ(entry["meaning"].get<std::string>(), q.meaning);
    EXPECT_EQ(entry["axis_label"].get<std::string>(), q.axis_label);
    EXPECT_EQ(entry["response"], q.response);
  }
  EXPECT_EQ(quantities["max_drift_ratio"]["axis_label"], "peak drift ratio [-]");
  EXPECT_EQ(quantities["energy_balance_error"]["response"], false);
}

TEST(StatisticsDocument, GivesTheGroupsExceedancesAndFits) {
  const nlohmann::ordered_json doc = document();
  EXPECT_EQ(doc["set"], "sets/x.json");
  EXPECT_EQ(doc["cases"], 2);
  EXPECT_EQ(doc["intensity_measure"]["type"], "pga");
  ASSERT_EQ(doc["groups"].size(), 1u);
  const auto& ductility = doc["groups"][0]["responses"]["max_ductility"];
  EXPECT_EQ(ductility["count"], 2);
  EXPECT_DOUBLE_EQ(ductility["median"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(ductility["p84"].get<double>(), 0.5 + 0.84);
  EXPECT_DOUBLE_EQ(ductility["max"].get<double>(), 1.5);
  EXPECT_EQ(doc["groups"][0]["responses"].size(), 1u);  // the only quantity the cases have
  const auto& exceedance = doc["groups"][0]["exceedance"]["max_ductility"];
  EXPECT_EQ(exceedance["exceeded"], 1);
  EXPECT_DOUBLE_EQ(exceedance["fraction"].get<double>(), 0.5);
  ASSERT_EQ(doc["fragility"].size(), 1u);
  EXPECT_EQ(doc["fragility"][0]["fitted"], false);  // one intensity: no dispersion
  EXPECT_NE(doc["fragility"][0]["reason"].get<std::string>().find("same intensity"),
            std::string::npos);
}

}  // namespace
}  // namespace pound::io
