// The plan of a batch: every model x record x scale, in that nesting order, named by its folder.
#include "builder/batch_spec.hpp"

#include <gtest/gtest.h>

namespace pound::builder {
namespace {

TEST(BatchPlan, NestsModelsRecordsAndScalesAndNamesEachCase) {
  SetSpec set;
  set.models = {{"bridge", "a.json"}, {"frame", "b.json"}};
  set.records = {{"kobe", {}}, {"elcentro", {}}, {"rinaldi", {}}};
  set.scales = {0.5, 1.5};
  const std::vector<BatchCase> cases = plan_cases(set);
  ASSERT_EQ(cases.size(), 12u);
  for (std::size_t k = 0; k < cases.size(); ++k) EXPECT_EQ(cases[k].index, k);
  EXPECT_EQ(cases[0].name, "bridge/kobe/x0.5");
  EXPECT_EQ(cases[1].name, "bridge/kobe/x1.5");
  EXPECT_EQ(cases[2].name, "bridge/elcentro/x0.5");
  EXPECT_EQ(cases[6].name, "frame/kobe/x0.5");
  EXPECT_EQ(cases[11].name, "frame/rinaldi/x1.5");
  EXPECT_EQ(cases[11].model, 1u);
  EXPECT_EQ(cases[11].record, 2u);
  EXPECT_EQ(cases[11].scale, 1.5);
}

TEST(BatchPlan, DefaultScaleIsTheRecordAsGiven) {
  SetSpec set;
  set.models = {{"m", "m.json"}};
  set.records = {{"r", {}}};
  const std::vector<BatchCase> cases = plan_cases(set);
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].name, "m/r/x1");
  EXPECT_TRUE(plan_cases(SetSpec{}).empty());
}

}  // namespace
}  // namespace pound::builder
