// The model check's created-energy probe: links of one law spec in one context at one approach
// velocity are probed once and warned each, as a probe of their own would warn them.
#include "verification/model_check.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "io/model_reader.hpp"
#include "model/ground_motion.hpp"
#include "verification/contact_energy_probe.hpp"

namespace pound::verification {
namespace {

// Four pairs of masses closing through elastic gap springs (k = 1e4) at a step that creates
// energy at some phase of first touch (tests/verification/contact_energy_probe_test.cpp): c1 and
// c2 alike, c3 with a heavier mass, c4 like c1 but closing faster.
constexpr const char* kPairs = R"({
  "dimension": 1,
  "nodes": [{"id": "a1", "x": 0}, {"id": "b1", "x": 0}, {"id": "a2", "x": 0}, {"id": "b2", "x": 0},
            {"id": "a3", "x": 0}, {"id": "b3", "x": 0}, {"id": "a4", "x": 0}, {"id": "b4", "x": 0}],
  "masses": [{"node": "a1", "mass": 1}, {"node": "b1", "mass": 2}, {"node": "a2", "mass": 1},
             {"node": "b2", "mass": 2}, {"node": "a3", "mass": 1}, {"node": "b3", "mass": 5},
             {"node": "a4", "mass": 1}, {"node": "b4", "mass": 2}],
  "initial_velocities": [{"node": "a1", "x": 1}, {"node": "b1", "x": -0.5},
                         {"node": "a2", "x": 1}, {"node": "b2", "x": -0.5},
                         {"node": "a3", "x": 1}, {"node": "b3", "x": -0.5},
                         {"node": "a4", "x": 2}, {"node": "b4", "x": -0.5}],
  "links": [
    {"id": "c1", "nodes": ["a1", "b1"], "axis": [1], "gap": 0.00123, "law": {"type": "gap_spring", "stiffness": 1e4}},
    {"id": "c2", "nodes": ["a2", "b2"], "axis": [1], "gap": 0.00123, "law": {"type": "gap_spring", "stiffness": 1e4}},
    {"id": "c3", "nodes": ["a3", "b3"], "axis": [1], "gap": 0.00123, "law": {"type": "gap_spring", "stiffness": 1e4}},
    {"id": "c4", "nodes": ["a4", "b4"], "axis": [1], "gap": 0.00123, "law": {"type": "gap_spring", "stiffness": 1e4}}
  ],
  "analysis": {"integrator": "newmark_average_acceleration", "time_step": 0.0047, "duration": 0.1}
})";

// The warning of `link` in `warnings`, or "".
std::string warning_of(const std::vector<std::string>& warnings, const std::string& link) {
  for (const std::string& w : warnings)
    if (w.starts_with("link " + link + ": an impact")) return w;
  return "";
}

TEST(ModelCheck, ContactsOfOneSpecAndContextAreProbedOnceAndWarnedEach) {
  const builder::BuiltModel built = builder::build(io::parse_model(kPairs, "pairs.json"));
  assembly::StructuralSystem system(built.model);
  const ModelCheck check = check_model(built, built.analysis, system, false);
  // c1 and c2 share one probe; c3 (another context) and c4 (another approach velocity) have
  // theirs.
  EXPECT_EQ(check.contact_energy_probes, 3u);
  for (Index k = 0; k < 4; ++k) {
    const model::Link& link = built.model.links[static_cast<std::size_t>(k)];
    const auto own = probe_contact_energy(system.links().law(k), system.link_context(link),
                                          built.analysis, k == 3 ? 2.5 : 1.5);
    ASSERT_TRUE(own.has_value()) << link.id;
    const std::string warning = warning_of(check.warnings, link.id);
    std::printf("%s: its own probe creates %.4f %%; check: %s\n", link.id.c_str(),
                100.0 * own->created_fraction, warning.c_str());
    ASSERT_GT(own->created_fraction, 0.01) << link.id;  // each warns
    EXPECT_NE(warning.find(fmt::format("creates up to {:.2f} %", 100.0 * own->created_fraction)),
              std::string::npos)
        << warning;
  }
  EXPECT_EQ(warning_of(check.warnings, "c1").substr(8), warning_of(check.warnings, "c2").substr(8));
  EXPECT_NE(warning_of(check.warnings, "c1").substr(8), warning_of(check.warnings, "c3").substr(8));
}

// The check's warnings for a model whose one record "pulse.txt" is a half sine of 0.3 g over a
// second.
std::vector<std::string> warnings_under_pulse(const std::string& text) {
  std::vector<double> pulse;
  for (int k = 0; k <= 100; ++k) pulse.push_back(0.3 * std::sin(M_PI * k / 100.0));
  const builder::BuiltModel built = builder::build(
      io::parse_model(text, "model.json"),
      {model::GroundMotion{.name = "pulse", .time_step = 0.01, .acceleration = pulse}});
  assembly::StructuralSystem system(built.model);
  return check_model(built, built.analysis, system, false).warnings;
}

// A girder on two friction bearings seated under its weight from a static start strikes nothing
// unless it lifts off: no impact warnings for the bearings, which an unloaded start (no static
// state) still gets.
TEST(ModelCheck, BearingsSeatedUnderTheWeightAreNotWarnedOfImpacts) {
  const auto bearing_warnings = [](bool static_start) {
    const std::string text = fmt::format(R"({{
      "dimension": 2,
      "generators": [{{
        "type": "girder_bridge", "id": "b", "spans": [20],
        "girder": {{"youngs_modulus": 3e10, "area": 4, "inertia": 2.5, "density": 2500,
                    "elements": 4}},
        "pier": {{"youngs_modulus": 3e10, "area": 3, "inertia": 0.8, "density": 2500}},
        "pier_height": 8, "bearing_vertical_stiffness": 1e10,
        "bearing_friction": {{"coefficient": 0.05, "radius": 2, "stick_stiffness": 1e10}},
        "abutment": {{"gap": 0.5, "law": {{"type": "hertz_damp", "stiffness": 1e10,
                                           "restitution": 0.6}}}}}}],
      "loads": [{{"node": "b.g0.n0", "y": -245250}}, {{"node": "b.g0.n1", "y": -490500}},
                {{"node": "b.g0.n2", "y": -490500}}, {{"node": "b.g0.n3", "y": -490500}},
                {{"node": "b.g0.n4", "y": -245250}}],
      "excitations": [{{"record": "pulse.txt", "units": "g"}}],
      "analysis": {{"time_step": 1e-3, "initial_state": "{}"}}}})",
                                         static_start ? "static" : "unloaded");
    int count = 0;
    for (const std::string& w : warnings_under_pulse(text))
      if (w.find("bearing") != std::string::npos && w.find("impact") != std::string::npos) ++count;
    return count;
  };
  const int seated = bearing_warnings(true), from_rest = bearing_warnings(false);
  std::printf("bearing impact warnings: static start %d, from rest %d\n", seated, from_rest);
  EXPECT_EQ(seated, 0);
  EXPECT_GT(from_rest, 0);
  // A block on a flat slider held by a horizontal spring: pressed by a vertical load it is seated;
  // pushed only sideways nothing presses it, and it is warned as any contact.
  const auto block_warnings = [](const char* load) {
    const std::string text = fmt::format(R"({{
      "dimension": 2,
      "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "seat", "x": 0, "y": 0}}],
      "masses": [{{"node": "block", "mass": 1e5}}],
      "supports": [{{"node": "seat", "fix": ["x", "y"]}}],
      "loads": [{{"node": "block", {}}}],
      "links": [{{"id": "bearing", "nodes": ["block", "seat"], "axis": [0, -1],
                  "law": {{"type": "gap_spring", "stiffness": 1e11}},
                  "friction": {{"coefficient": 0.06, "stick_stiffness": 1e10}}}},
                {{"id": "spring", "nodes": ["block", "seat"], "axis": [1, 0],
                  "law": {{"type": "elastic_spring", "stiffness": 1e6}}}}],
      "excitations": [{{"record": "pulse.txt", "units": "g", "direction": [1, 0]}}],
      "analysis": {{"time_step": 1e-3, "initial_state": "static"}}}})",
                                         load);
    return static_cast<int>(!warning_of(warnings_under_pulse(text), "bearing").empty());
  };
  EXPECT_EQ(block_warnings(R"("y": -9.81e5)"), 0);
  EXPECT_EQ(block_warnings(R"("x": 1000)"), 1);
}

// A friction coefficient above 1 (a block that a sideways force of more than its weight does not
// move) warns, named with its link; 0.6 (concrete on concrete) and exactly 1 do not.
TEST(ModelCheck, AFrictionCoefficientAboveOneWarns) {
  const auto friction_warnings = [](double coefficient) {
    const std::string text = fmt::format(R"({{
      "dimension": 2,
      "nodes": [{{"id": "block", "x": 0, "y": 0}}, {{"id": "seat", "x": 0, "y": 0}}],
      "masses": [{{"node": "block", "mass": 1e5}}],
      "supports": [{{"node": "seat", "fix": ["x", "y"]}}],
      "loads": [{{"node": "block", "y": -9.81e5}}],
      "links": [{{"id": "bearing", "nodes": ["block", "seat"], "axis": [0, -1],
                  "law": {{"type": "gap_spring", "stiffness": 1e11}},
                  "friction": {{"coefficient": {}, "stick_stiffness": 1e10}}}},
                {{"id": "spring", "nodes": ["block", "seat"], "axis": [1, 0],
                  "law": {{"type": "elastic_spring", "stiffness": 1e6}}}}],
      "excitations": [{{"record": "pulse.txt", "units": "g", "direction": [1, 0]}}],
      "analysis": {{"time_step": 1e-3, "initial_state": "static"}}}})",
                                         coefficient);
    std::vector<std::string> found;
    for (const std::string& w : warnings_under_pulse(text))
      if (w.find("friction coefficient") != std::string::npos) found.push_back(w);
    std::printf("mu = %g: %s\n", coefficient, found.empty() ? "no warning" : found[0].c_str());
    return found;
  };
  EXPECT_TRUE(friction_warnings(0.6).empty());
  EXPECT_TRUE(friction_warnings(1.0).empty());
  const std::vector<std::string> five = friction_warnings(5.0);
  ASSERT_EQ(five.size(), 1U);
  EXPECT_TRUE(five[0].starts_with("link 'bearing': friction coefficient mu = 5 is above 1"))
      << five[0];
}

// A mass on a spring in millimetres, shaken by a half-sine pulse of 0.4 g given in model units
// (mm/s2) that peaks at 0.5 s, scaled by `scale` (JSON, or none), analysed for `duration` at
// `time_step`: the check's warnings that contain `about`.
std::vector<std::string> pulse_warnings(const std::string& scale,
                                        const std::string& about = "beyond any earthquake",
                                        double duration = 1.0, double time_step = 0.01) {
  constexpr double kGravityMm = 9806.65;
  std::vector<double> pulse;
  for (int k = 0; k <= 100; ++k) pulse.push_back(0.4 * kGravityMm * std::sin(M_PI * k / 100.0));
  const std::string text =
      fmt::format(R"({{
    "dimension": 1, "units": {{"length": "mm", "time": "s", "mass": "t"}},
    "nodes": [{{"id": "ground", "x": 0}}, {{"id": "top", "x": 0}}],
    "supports": [{{"node": "ground", "fix": ["x"]}}],
    "masses": [{{"node": "top", "mass": 1}}],
    "links": [{{"id": "spring", "nodes": ["ground", "top"], "axis": [1],
               "law": {{"type": "elastic_spring", "stiffness": 400}}}}],
    "excitations": [{{"record": "pulse.txt", "units": "model"{}}}],
    "analysis": {{"time_step": {}, "duration": {}}}}})",
                  scale.empty() ? "" : ", \"scale\": " + scale, time_step, duration);
  const builder::BuiltModel built = builder::build(
      io::parse_model(text, "pulse.json"),
      {model::GroundMotion{.name = "pulse", .time_step = 0.01, .acceleration = pulse}});
  assembly::StructuralSystem system(built.model);
  std::vector<std::string> peaks;
  for (const std::string& w : check_model(built, built.analysis, system, false).warnings)
    if (w.find(about) != std::string::npos) peaks.push_back(w);
  std::printf("scale %s: %zu warning(s) %s\n", scale.empty() ? "none" : scale.c_str(), peaks.size(),
              peaks.empty() ? "" : peaks[0].c_str());
  return peaks;
}

// A record scaled past 5 g (about any earthquake's peak) warns, named with its excitation; the
// peak is taken in g whatever the model's units (0.4 g in mm/s2 is 3,923, not 400 g).
TEST(ModelCheck, ARecordScaledPastAnyEarthquakesPeakWarns) {
  EXPECT_TRUE(pulse_warnings("").empty());
  EXPECT_TRUE(pulse_warnings(R"({"pga": 4.9})").empty());
  EXPECT_TRUE(pulse_warnings(R"({"factor": 12})").empty());                     // 4.8 g
  const std::vector<std::string> strong = pulse_warnings(R"({"factor": 13})");  // 5.2 g
  ASSERT_EQ(strong.size(), 1u);
  EXPECT_TRUE(strong[0].starts_with("/excitations/0: record 'pulse' peaks at 5.2 g")) << strong[0];
  EXPECT_NE(strong[0].find("\"units\""), std::string::npos);
  ASSERT_EQ(pulse_warnings(R"({"pga": 100})").size(), 1u);
}

// An analysis stopped before the record's largest acceleration warns; one that reaches it does
// not.
TEST(ModelCheck, AnAnalysisThatStopsBeforeTheRecordsPeakWarns) {
  EXPECT_TRUE(pulse_warnings("", "before record", 1.0).empty());
  EXPECT_TRUE(pulse_warnings("", "before record", 0.5).empty());
  const std::vector<std::string> short_run = pulse_warnings("", "before record", 0.3);
  ASSERT_EQ(short_run.size(), 1u);
  EXPECT_EQ(short_run[0],
            "the analysis stops at 0.3 s, before record 'pulse' reaches its largest acceleration "
            "(at 0.5 s): its strongest shaking is not analysed (is /analysis/duration what you "
            "meant?)");
}

// A record along a direction in which every DOF with mass is held loads nothing: every response
// is 0, which would pass for a result. A 2-D mass held vertically, shaken vertically, warns;
// shaken horizontally, not.
TEST(ModelCheck, ARecordThatLoadsNothingWarns) {
  const auto warnings = [](const std::string& direction) {
    const std::string text = fmt::format(R"({{
      "dimension": 2,
      "nodes": [{{"id": "ground", "x": 0, "y": 0}}, {{"id": "top", "x": 1, "y": 0}}],
      "supports": [{{"node": "ground", "fix": ["x", "y"]}}, {{"node": "top", "fix": ["y"]}}],
      "masses": [{{"node": "top", "mass": 1}}],
      "links": [{{"id": "spring", "nodes": ["ground", "top"], "axis": [1, 0],
                 "law": {{"type": "elastic_spring", "stiffness": 400}}}}],
      "excitations": [{{"record": "pulse.txt", "direction": {}}}],
      "analysis": {{"time_step": 0.01, "duration": 1}}}})",
                                         direction);
    const builder::BuiltModel built = builder::build(
        io::parse_model(text, "vertical.json"),
        {model::GroundMotion{.name = "pulse", .time_step = 0.01, .acceleration = {0.0, 0.1, 0.0}}});
    assembly::StructuralSystem system(built.model);
    std::vector<std::string> found;
    for (const std::string& w : check_model(built, built.analysis, system, false).warnings)
      if (w.find("loads nothing") != std::string::npos) found.push_back(w);
    return found;
  };
  EXPECT_TRUE(warnings("[1, 0]").empty());
  const std::vector<std::string> vertical = warnings("[0, 1]");
  ASSERT_EQ(vertical.size(), 1u);
  EXPECT_EQ(vertical[0],
            "/excitations/0: record 'pulse' acts along [0, 1], in which every DOF with mass is "
            "held: it loads nothing and every response to it is 0 (is its \"direction\" what you "
            "meant?)");
}

// A pair of horizontal components is one entry of the file and two excitations of the model: a
// vertical record after it, loading nothing where the floor is held in z, is /excitations/1 (it
// was named /excitations/2).
TEST(ModelCheck, ARecordAfterAPairIsNamedByItsEntry) {
  const std::string text = R"({
    "dimension": 3,
    "nodes": [{"id": "ground", "x": 0, "y": 0, "z": 0}, {"id": "top", "x": 0, "y": 0, "z": 0}],
    "supports": [{"node": "ground", "fix": ["x", "y", "z"]}, {"node": "top", "fix": ["z"]}],
    "masses": [{"node": "top", "mass": 1}],
    "links": [{"id": "x", "nodes": ["ground", "top"], "axis": [1, 0, 0],
               "law": {"type": "elastic_spring", "stiffness": 400}},
              {"id": "y", "nodes": ["ground", "top"], "axis": [0, 1, 0],
               "law": {"type": "elastic_spring", "stiffness": 400}}],
    "excitations": [{"record": "pulse.txt", "pair": {"record": "pulse.txt"}},
                    {"record": "pulse.txt", "direction": [0, 0, 1]}],
    "analysis": {"time_step": 0.01, "duration": 1}})";
  const model::GroundMotion pulse{
      .name = "pulse", .time_step = 0.01, .acceleration = {0.0, 0.1, 0.0}};
  const builder::BuiltModel built =
      builder::build(io::parse_model(text, "pair.json"), {pulse, pulse}, {pulse, std::nullopt});
  assembly::StructuralSystem system(built.model);
  std::vector<std::string> found;
  for (const std::string& w : check_model(built, built.analysis, system, false).warnings)
    if (w.find("loads nothing") != std::string::npos) found.push_back(w);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_TRUE(found[0].starts_with("/excitations/1: record 'pulse' acts along [0, 0, 1]"))
      << found[0];
}

// More than a billion steps (a time step or duration mistyped by powers of ten) warns with the run
// time that means; a billion does not.
TEST(ModelCheck, AnAnalysisOfMoreThanABillionStepsWarns) {
  EXPECT_TRUE(pulse_warnings("", "steps (a duration", 1.0, 1e-9).empty());
  const std::vector<std::string> long_run = pulse_warnings("", "steps (a duration", 1.5, 1e-9);
  ASSERT_EQ(long_run.size(), 1u);
  EXPECT_TRUE(
      long_run[0].starts_with("the analysis takes 1.5e+09 steps (a duration of 1.5 over a "
                              "time step of 1e-09): at a microsecond a step, a plane "
                              "bridge of 60 DOFs, that is about 25 minutes"))
      << long_run[0];
  const std::vector<std::string> years = pulse_warnings("", "steps (a duration", 1e7, 1e-6);
  ASSERT_EQ(years.size(), 1u);
  EXPECT_NE(years[0].find("1e+13 steps"), std::string::npos) << years[0];
  EXPECT_NE(years[0].find("about 116 days"), std::string::npos) << years[0];
}

// Two bare masses closing through a stiff extended penalty under central difference: "auto" takes
// 0.8 of the stable step, which the contact itself sets, so the impact spans about three steps
// (its kinetic energy came out 2.8 % above the initial one, unwarned). The "auto" step is checked
// as the step it takes; a given step of T_contact / 40 is not warned.
TEST(ModelCheck, AnAutoStepIsCheckedAgainstTheContactsDuration) {
  const auto contact_warnings = [](const std::string& step) {
    const std::string text = fmt::format(R"({{
      "dimension": 1,
      "nodes": [{{"id": "a", "x": 0}}, {{"id": "b", "x": 1}}],
      "masses": [{{"node": "a", "mass": 1e4}}, {{"node": "b", "mass": 1e4}}],
      "initial_velocities": [{{"node": "a", "x": 2}}],
      "links": [{{"id": "c", "nodes": ["a", "b"], "axis": [1], "gap": 0.01,
                 "law": {{"type": "extended_penalty", "alpha0": 1e10, "alpha2": 1e3}}}}],
      "analysis": {{"integrator": "central_difference", "time_step": {}, "duration": 0.1}}
    }})",
                                         step);
    const builder::BuiltModel built = builder::build(io::parse_model(text, "pair.json"));
    assembly::StructuralSystem system(built.model);
    builder::AnalysisSpec analysis = built.analysis;
    builder::settle_time_step(analysis, built.model, system, "pair.json");
    std::vector<std::string> found;
    for (const std::string& w : check_model(built, analysis, system, false).warnings)
      if (w.starts_with("link c:")) found.push_back(w);
    return std::pair{analysis.time_step, found};
  };
  // T_contact = pi sqrt((m_eff + alpha2) / alpha0) = pi sqrt(6000 / 1e10) = 2.4335 ms.
  const double duration = M_PI * std::sqrt(6000.0 / 1e10);
  const auto [auto_step, warned] = contact_warnings("\"auto\"");
  std::printf("auto step %.4g = contact duration / %.2f\n", auto_step, duration / auto_step);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_NE(warned[0].find("the \"auto\" time step"), std::string::npos) << warned[0];
  EXPECT_NE(warned[0].find(fmt::format("at most {:.4g}", duration / 20.0)), std::string::npos)
      << warned[0];
  EXPECT_TRUE(contact_warnings(fmt::format("{}", duration / 40.0)).second.empty());
}

}  // namespace
}  // namespace pound::verification
