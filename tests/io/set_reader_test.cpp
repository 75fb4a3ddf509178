#include "io/set_reader.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "core/errors.hpp"

namespace pound::io {
namespace {

// Set files are read as if they sat in the repository's models/ folder, so relative paths reach
// the bundled model and records.
const std::string kSource = std::string(POUND_SOURCE_DIR) + "/models/set.json";
const std::string kModels = std::string(POUND_SOURCE_DIR) + "/models";

constexpr const char* kSet = R"({
  "title": "IDA",
  "models": ["three_span_bridge.json", {"id": "wave", "file": "three_span_bridge_wave_passage.json"}],
  "records": [
    {"folder": "../ground_motions", "pattern": "synthetic_soft_*.AT2", "scale": {"pga": 0.3}},
    {"file": "../ground_motions/synthetic_firm_01.AT2", "id": "firm", "scale": {"factor": 2}},
    {"file": "../ground_motions/synthetic_firm_02.AT2", "format": "columns", "column": 2,
     "time_step": 0.01, "units": "cm/s2"}
  ],
  "scales": [0.5, 1, 1.5],
  "intensity_measure": {"type": "sa", "period": 1.0},
  "limits": {"max_ductility": 1.5, "max_joint_opening": 0.1},
  "histories": false
})";

std::string edited(const std::string& json_patch) {
  return nlohmann::json::parse(kSet).patch(nlohmann::json::parse(json_patch)).dump(2);
}

std::string error_of(const std::string& text) {
  try {
    (void)parse_set(text, kSource);
  } catch (const InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(SetReader, ReadsModelsRecordsScalesAndLimits) {
  const builder::SetSpec set = parse_set(kSet, kSource);
  EXPECT_EQ(set.title, "IDA");
  ASSERT_EQ(set.models.size(), 2u);
  EXPECT_EQ(set.models[0].id, "three_span_bridge");
  EXPECT_EQ(set.models[0].path, kModels + "/three_span_bridge.json");
  EXPECT_EQ(set.models[1].id, "wave");
  // The folder's matches in name order, then the single files; a column other than the first
  // names the id.
  ASSERT_EQ(set.records.size(), 4u);
  EXPECT_EQ(set.records[0].id, "synthetic_soft_01");
  EXPECT_EQ(set.records[1].id, "synthetic_soft_02");
  EXPECT_EQ(set.records[0].excitation.record,
            std::string(POUND_SOURCE_DIR) + "/ground_motions/synthetic_soft_01.AT2");
  EXPECT_EQ(set.records[0].excitation.target_pga, 0.3);
  EXPECT_EQ(set.records[2].id, "firm");
  EXPECT_EQ(set.records[2].excitation.scale_factor, 2.0);
  EXPECT_EQ(set.records[3].id, "synthetic_firm_02_col2");
  EXPECT_EQ(set.records[3].excitation.units, "cm/s2");
  EXPECT_EQ(set.records[3].excitation.time_step, 0.01);
  EXPECT_EQ(set.scales, (std::vector<double>{0.5, 1.0, 1.5}));
  EXPECT_EQ(set.intensity.type, builder::IntensityKind::sa);
  EXPECT_EQ(set.intensity.period, 1.0);
  EXPECT_EQ(set.intensity.damping, 0.05);
  EXPECT_EQ(set.intensity.pair, builder::PairMeasure::rot_d50);  // for pairs, by default
  ASSERT_EQ(set.limits.size(), 2u);
  EXPECT_FALSE(set.histories);

  const std::vector<builder::BatchCase> cases = builder::plan_cases(set);
  ASSERT_EQ(cases.size(), 2u * 4u * 3u);
  EXPECT_EQ(cases[0].name, "three_span_bridge/synthetic_soft_01/x0.5");
  EXPECT_EQ(cases[4].name, "three_span_bridge/synthetic_soft_02/x1");
  EXPECT_EQ(cases.back().name, "wave/synthetic_firm_02_col2/x1.5");
  for (std::size_t k = 0; k < cases.size(); ++k) EXPECT_EQ(cases[k].index, k);
}

struct BadSet {
  const char* name;
  const char* patch;
  const char* message;
};

class SetReaderRefuses : public ::testing::TestWithParam<BadSet> {};

TEST_P(SetReaderRefuses, NamingThePathAndWhatWasExpected) {
  const std::string message = error_of(edited(GetParam().patch));
  EXPECT_NE(message.find(GetParam().message), std::string::npos) << message;
  EXPECT_EQ(message.rfind(kSource, 0), 0u) << message;  // starts with the file name
}

INSTANTIATE_TEST_SUITE_P(
    Cases, SetReaderRefuses,
    ::testing::Values(
        BadSet{"NoModels", R"([{"op": "replace", "path": "/models", "value": []}])",
               "/models: expected at least 1"},
        BadSet{"MissingModelFile",
               R"([{"op": "replace", "path": "/models/0", "value": "nowhere.json"}])",
               "/models/0: model file '"},
        BadSet{"DuplicateModelId",
               R"([{"op": "replace", "path": "/models/1/id", "value": "three_span_bridge"}])",
               "duplicate model id 'three_span_bridge'"},
        BadSet{"UnsafeId", R"([{"op": "replace", "path": "/models/1/id", "value": "a/b"}])",
               "/models/1/id: id 'a/b' names a folder"},
        BadSet{"PartialId", R"([{"op": "replace", "path": "/models/1/id", "value": ".partial"}])",
               "/models/1/id: id '.partial' is a hidden folder name"},
        BadSet{"SummaryId",
               R"([{"op": "replace", "path": "/models/1/id", "value": "batch_summary.csv"}])",
               "/models/1/id: id 'batch_summary.csv' is the name of a file of the batch folder"},
        BadSet{"PlanRecordId",
               R"([{"op": "replace", "path": "/records/1/id", "value": "batch_plan.json"}])",
               "/records/1/id: id 'batch_plan.json' is the name"},
        BadSet{"NulInRecordPath",
               R"([{"op": "replace", "path": "/records/1/file", "value": "a\u0000b"}])",
               "/records/1/file: a NUL character"},
        BadSet{"RecordIsADevice",
               R"([{"op": "replace", "path": "/records/1/file", "value": "/dev/zero"}])",
               "/records/1/file: record '/dev/zero': not a regular file (a character device)"},
        BadSet{
            "MissingRecord",
            R"([{"op": "replace", "path": "/records/1/file", "value": "../ground_motions/none.AT2"}])",
            "/records/1/file: record '"},
        BadSet{"FileAndFolder",
               R"([{"op": "add", "path": "/records/1/folder", "value": "../ground_motions"}])",
               "/records/1: give either 'file'"},
        BadSet{"NoMatch", R"([{"op": "replace", "path": "/records/0/pattern", "value": "*.none"}])",
               "/records/0/pattern: no file in"},
        BadSet{"DuplicateRecordId",
               R"([{"op": "replace", "path": "/records/1/id", "value": "synthetic_soft_01"}])",
               "duplicate record id 'synthetic_soft_01'"},
        BadSet{"RecordTypo", R"([{"op": "add", "path": "/records/1/unit", "value": "g"}])",
               "/records/1/unit: unknown field (did you mean 'units'?)"},
        BadSet{"BadUnits", R"([{"op": "add", "path": "/records/1/units", "value": "gal"}])",
               "/records/1/units"},
        BadSet{"TwoScales", R"([{"op": "add", "path": "/records/1/scale/pga", "value": 0.3}])",
               "give exactly one of 'factor', 'pga'"},
        BadSet{"PairFileOfAFolder",
               R"([{"op": "add", "path": "/records/0/pair",
                    "value": {"record": "../ground_motions/synthetic_firm_01.AT2"}}])",
               "/records/0/pair/record: a pair's second file belongs to one record"},
        BadSet{"PairWithNothing", R"([{"op": "add", "path": "/records/1/pair", "value": {}}])",
               "/records/1/pair: give the second component's 'record'"},
        BadSet{"MissingPairFile",
               R"([{"op": "add", "path": "/records/1/pair", "value": {"record": "nowhere.AT2"}}])",
               "/records/1/pair/record: record"},
        BadSet{"UnknownPairMeasure",
               R"([{"op": "add", "path": "/intensity_measure/pair", "value": "mean"}])",
               "/intensity_measure/pair: expected one of 'rotd50', 'geometric_mean'"},
        BadSet{"NegativeScale", R"([{"op": "replace", "path": "/scales/1", "value": -1}])",
               "/scales/1: must be > 0"},
        BadSet{"RepeatedScale", R"([{"op": "replace", "path": "/scales/1", "value": 0.5}])",
               "/scales/1: scale 0.5 is given twice"},
        BadSet{"LimitTypo", R"([{"op": "add", "path": "/limits/max_ductilty", "value": 2}])",
               "/limits/max_ductilty: unknown quantity (did you mean 'max_ductility'?); a limit "
               "is on one of: impacts, max_pounding_force,"},
        // A quantity's name cut short: the names it begins (audit 71: none was suggested).
        BadSet{"LimitCutShort", R"([{"op": "add", "path": "/limits/max_drift", "value": 0.01}])",
               "/limits/max_drift: unknown quantity (did you mean 'max_drift_ratio'?)"},
        BadSet{"NegativeLimit", R"([{"op": "add", "path": "/limits/impacts", "value": -1}])",
               "/limits/impacts: must be >= 0"},
        BadSet{"SaWithoutPeriod", R"([{"op": "remove", "path": "/intensity_measure/period"}])",
               "/intensity_measure"},
        // Sa of an oscillator at or past critical damping: the batch stopped at its first case
        // with exit 3 ("an unexpected failure"), a lock file left behind.
        BadSet{"AbsurdMeasurePeriod",
               R"([{"op": "replace", "path": "/intensity_measure/period", "value": 1e6}])",
               "/intensity_measure/period: must be <= 1000 (pound spectrum's range), got 1000000"},
        BadSet{"AbsurdScalePeriod",
               R"([{"op": "replace", "path": "/records/0/scale",
                    "value": {"sa": 0.5, "period": 1e6}}])",
               "/records/0/scale/period: must be <= 1000 (pound spectrum's range), got 1000000"},
        BadSet{"CriticalMeasureDamping",
               R"([{"op": "add", "path": "/intensity_measure/damping", "value": 1}])",
               "/intensity_measure/damping: must be below 1 (an underdamped oscillator), got 1"},
        BadSet{"CriticalScaleDamping",
               R"([{"op": "replace", "path": "/records/0/scale",
                    "value": {"sa": 0.5, "period": 1, "damping": 1.5}}])",
               "/records/0/scale/damping: must be below 1 (an underdamped oscillator), got 1.5"},
        BadSet{"HistoriesNotBool", R"([{"op": "replace", "path": "/histories", "value": "no"}])",
               "/histories: expected true or false"}),
    [](const ::testing::TestParamInfo<BadSet>& param_info) { return param_info.param.name; });

TEST(SetReader, MalformedJsonNamesTheLine) {
  const std::string message = error_of("{\n  \"models\": [\n}");
  EXPECT_NE(message.find("line 3"), std::string::npos) << message;
}

}  // namespace
}  // namespace pound::io
