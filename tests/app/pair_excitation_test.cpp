// Issue 18 item 3: the two horizontal components of a station acting together on a 3-D scene
// ("pair" of an excitation), turned by an angle and scaled as one to a RotD50 target. The records
// are made here (two columns of decaying sines), so no shared files are needed.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::read_text;

// Two different components, 0.01 s apart, 8 s long, in g.
void write_pair(const fs::path& file, std::size_t samples = 800) {
  std::ofstream out(file);
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = 0.01 * static_cast<double>(i), decay = std::exp(-0.4 * t);
    out << fmt::format("{:.17g} {:.17g}\n", 0.3 * decay * std::sin(2 * M_PI * 1.3 * t),
                       0.2 * decay * std::sin(2 * M_PI * 0.7 * t + 0.5));
  }
}

// The first component of write_pair as a PEER .AT2 file (NGA-West2 header, five values a row).
void write_at2(const fs::path& file, std::size_t samples = 800) {
  std::ofstream out(file);
  out << "PEER NGA STRONG MOTION DATABASE RECORD\nsynthetic, made by the test\n"
         "ACCELERATION TIME SERIES IN UNITS OF G\n"
      << fmt::format("NPTS= {}, DT= .0100 SEC\n", samples);
  for (std::size_t i = 0; i < samples; ++i) {
    const double t = 0.01 * static_cast<double>(i);
    out << fmt::format("{:15.7E}", 0.3 * std::exp(-0.4 * t) * std::sin(2 * M_PI * 1.3 * t))
        << (i % 5 == 4 ? "\n" : "");
  }
}

// A column 5 m tall with a mass on top; `symmetric`: the same bending stiffness about both axes.
json column(double angle, bool symmetric = true) {
  return {{"dimension", 3},
          {"nodes",
           {{{"id", "base"}, {"x", 0.0}, {"y", 0.0}, {"z", 0.0}},
            {{"id", "top"}, {"x", 0.0}, {"y", 0.0}, {"z", 5.0}}}},
          {"materials",
           {{{"id", "c"}, {"youngs_modulus", 3e10}, {"density", 0.0}, {"poisson_ratio", 0.2}}}},
          {"elements",
           {{{"id", "col"},
             {"type", "beam"},
             {"nodes", {"base", "top"}},
             {"material", "c"},
             {"area", 0.4},
             {"inertia_y", 0.01},
             {"inertia_z", symmetric ? 0.01 : 0.03},
             {"torsion", 0.02},
             {"orientation", {1.0, 0.0, 0.0}}}}},
          {"masses", {{{"node", "top"}, {"mass", 1e5}, {"rotary_inertia", {1e4, 1e4, 2e4}}}}},
          {"supports", {{{"node", "base"}, {"fix", {"x", "y", "z", "rx", "ry", "rz"}}}}},
          {"damping", {{"modes", {1, 2}}, {"ratio", 0.05}}},
          {"excitations",
           {{{"record", "pair.txt"},
             {"format", "columns"},
             {"time_step", 0.01},
             {"units", "g"},
             {"pair", {{"column", 2}, {"angle", angle}}}}}},
          {"analysis", {{"time_step", 0.01}}},
          {"recorders", {{{"type", "node"}, {"nodes", {"top"}}, {"file", "top.csv"}}}}};
}

class PairExcitation : public testing::PoundProcess {
 protected:
  void SetUp() override {
    PoundProcess::SetUp();
    write_pair(path("pair.txt"));
  }
  testing::Outcome run(const json& model, const std::string& name) {
    std::ofstream(path(name + ".json")) << model.dump(1);
    return pound({"run", path(name + ".json").string(), "--quiet", "--out", path(name).string()});
  }
  // The top's (u_x, u_y) at every step.
  std::vector<std::array<double, 2>> top_motion(const std::string& name) {
    std::istringstream csv(read_text(path(name) / "top.csv"));
    std::string line;
    std::getline(csv, line);
    std::vector<std::string> header;
    for (std::istringstream cells(line); std::getline(cells, line, ',');) header.push_back(line);
    const auto column = [&](const std::string& key) {
      return std::find(header.begin(), header.end(), key) - header.begin();
    };
    const auto x = column("top.u_x [m]"), y = column("top.u_y [m]");
    std::vector<std::array<double, 2>> motion;
    while (std::getline(csv, line)) {
      std::vector<double> row;
      for (std::istringstream cells(line); std::getline(cells, line, ',');)
        row.push_back(std::stod(line));
      motion.push_back({row[static_cast<std::size_t>(x)], row[static_cast<std::size_t>(y)]});
    }
    return motion;
  }
};

// A column that bends alike about both axes responds to the pair turned by a as it does to the
// pair unturned, turned by a: u(a) = R(a) u(0) at every step.
TEST_F(PairExcitation, TurningThePairTurnsTheResponseOfASymmetricColumn) {
  ASSERT_EQ(run(column(0.0), "unturned").exit_code, 0);
  const double angle = 37.0;
  ASSERT_EQ(run(column(angle), "turned").exit_code, 0);
  const auto unturned = top_motion("unturned"), turned = top_motion("turned");
  ASSERT_EQ(turned.size(), unturned.size());
  const double c = std::cos(angle * M_PI / 180.0), s = std::sin(angle * M_PI / 180.0);
  double worst = 0.0, peak = 0.0;
  for (std::size_t i = 0; i < turned.size(); ++i) {
    const double x = c * unturned[i][0] - s * unturned[i][1];
    const double y = s * unturned[i][0] + c * unturned[i][1];
    worst = std::max({worst, std::abs(turned[i][0] - x), std::abs(turned[i][1] - y)});
    peak = std::max({peak, std::abs(x), std::abs(y)});
  }
  std::printf("  turned by %.0f deg: largest difference %.2e of a peak %.4g m\n", angle, worst,
              peak);
  EXPECT_LT(worst, 1e-12 * peak);
  EXPECT_GT(peak, 1e-3);
}

// Drift monitors of a 3-D scene measure along x or y ("direction"): a column's drifts are its
// top's peak displacements along each (its base is fixed).
TEST_F(PairExcitation, DriftMonitorsMeasureAlongTheirDirection) {
  json model = column(37.0, false);
  model["monitors"]["drifts"] = {
      {{"id", "along_x"}, {"bottom", "base"}, {"top", "top"}, {"height", 5.0}},
      {{"id", "along_y"}, {"bottom", "base"}, {"top", "top"}, {"height", 5.0}, {"direction", "y"}}};
  ASSERT_EQ(run(model, "drifts").exit_code, 0);
  const json storeys = json::parse(read_text(path("drifts") / "summary.json"))["storeys"];
  double peak_x = 0.0, peak_y = 0.0;
  for (const auto& [x, y] : top_motion("drifts")) {
    peak_x = std::max(peak_x, std::abs(x));
    peak_y = std::max(peak_y, std::abs(y));
  }
  std::printf("  drifts %.6g (x) and %.6g (y) m\n", peak_x, peak_y);
  EXPECT_EQ(storeys[0]["peak_drift"].get<double>(), peak_x);
  EXPECT_EQ(storeys[1]["peak_drift"].get<double>(), peak_y);
  EXPECT_GT(std::abs(peak_x - peak_y), 0.01 * peak_x);  // stiffer about one axis
  model["dimension"] = 3;
  model["monitors"]["drifts"][0]["direction"] = "z";
  const testing::Outcome bad = run(model, "bad");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_TRUE(testing::contains(bad.err, "/monitors/drifts/0/direction")) << bad.err;
}

// A pair scaled to an Sa target has that RotD50 at the period (pound spectrum computes it apart),
// and its components keep their ratio: one factor for both.
TEST_F(PairExcitation, TargetScalesThePairToItsRotD50) {
  json model = column(20.0, false);
  model["excitations"][0]["scale"] = {{"sa", 0.4}, {"period", 0.6}};
  ASSERT_EQ(run(model, "scaled").exit_code, 0);
  const json excitation = json::parse(read_text(path("scaled") / "summary.json"))["excitations"][0];
  const double factor = excitation["factor"].get<double>();
  const testing::Outcome spectrum =
      pound({"spectrum", path("pair.txt").string(), "--format", "columns", "--dt", "0.01",
             "--pair-column", "2", "--periods", "0.6", "--scale", fmt::format("{:.17g}", factor),
             "--json"});
  ASSERT_EQ(spectrum.exit_code, 0) << spectrum.err;
  const double rot_d50 = json::parse(spectrum.out)["rotd50_g"][0].get<double>();
  std::printf("  RotD50 after scaling %.15g g (target 0.4), factor %.6g\n", rot_d50, factor);
  EXPECT_NEAR(rot_d50, 0.4, 1e-12);
  EXPECT_EQ(excitation["pair"]["angle_deg"], 20.0);
  // One factor for both: each component's applied peak is the factor times its peak in the file.
  std::istringstream file(read_text(path("pair.txt")));
  double peak_first = 0.0, peak_second = 0.0;
  for (double first, second; file >> first >> second;) {
    peak_first = std::max(peak_first, std::abs(first));
    peak_second = std::max(peak_second, std::abs(second));
  }
  EXPECT_NEAR(excitation["pga_g"].get<double>(), factor * peak_first, 1e-12 * peak_first);
  EXPECT_NEAR(excitation["pair"]["pga_g"].get<double>(), factor * peak_second, 1e-12 * peak_second);
}

// Pairs that mean nothing are refused with their path, and nothing is written.
TEST_F(PairExcitation, MeaninglessPairsAreRefused) {
  struct Case {
    const char* name;
    std::function<void(json&)> change;
    const char* where;
    const char* phrase;
  };
  write_pair(path("short.txt"), 500);
  write_at2(path("one.AT2"));
  const Case cases[] = {
      {"direction",
       [](json& m) {
         m["excitations"][0]["direction"] = {1.0, 0.0, 0.0};
       },
       "/excitations/0/direction", "turn it with 'pair.angle'"},
      {"nothing", [](json& m) { m["excitations"][0]["pair"] = json::object(); },
       "/excitations/0/pair", "give the second component's 'record'"},
      {"other_grid",
       [](json& m) {
         m["excitations"][0]["pair"] = {{"record", "short.txt"}, {"column", 2}};
       },
       "/excitations/0/pair", "must have as many samples"},
      {"missing", [](json& m) { m["excitations"][0]["pair"]["record"] = "nowhere.txt"; },
       "/excitations/0/pair/record", "nowhere.txt"},
      // An .AT2 file has one component: a column of it would read that component again.
      {"at2_pair_column",
       [](json& m) {
         m["excitations"][0] = {{"record", "one.AT2"}, {"pair", {{"column", 2}}}};
       },
       "/excitations/0/pair/column", "a PEER .AT2 file holds one component"},
      {"at2_column",
       [](json& m) {
         m["excitations"][0] = {
             {"record", "one.AT2"}, {"column", 2}, {"pair", {{"record", "one.AT2"}}}};
       },
       "/excitations/0/column", "a PEER .AT2 file holds one component"},
      {"angle", [](json& m) { m["excitations"][0]["pair"]["angle"] = 400; },
       "/excitations/0/pair/angle", "must be < 360"},
      {"plane",
       [](json& m) {
         m = {{"dimension", 2},
              {"nodes", {{{"id", "a"}, {"x", 0.0}, {"y", 0.0}}}},
              {"masses", {{{"node", "a"}, {"mass", 1.0}}}},
              {"excitations", {{{"record", "pair.txt"}, {"pair", {{"column", 2}}}}}},
              {"analysis", {{"time_step", 0.01}}}};
       },
       "/excitations/0/pair", "only allowed when dimension is 3"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    json model = column(0.0);
    c.change(model);
    const testing::Outcome outcome = run(model, c.name);
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_TRUE(testing::contains(outcome.err, std::string(c.where) + ":")) << outcome.err;
    EXPECT_TRUE(testing::contains(outcome.err, c.phrase)) << outcome.err;
    EXPECT_FALSE(fs::exists(path(c.name)));
  }
  // The first component's column is not the second's when that is its own .AT2 file.
  json model = column(0.0);
  model["excitations"][0] = {{"record", "pair.txt"},
                             {"time_step", 0.01},
                             {"column", 2},
                             {"pair", {{"record", "one.AT2"}}}};
  const testing::Outcome paired = run(model, "columns_and_at2");
  EXPECT_EQ(paired.exit_code, 0) << paired.err;
}

// A batch set takes pairs (3-D models only: a 1-D model's cases fail with the reason) and
// reports the pair's intensity measure: here the geometric mean of the components' Sa, which
// `pound spectrum` computes apart, of a pair scaled to RotD50 0.4 g, at each IDA scale.
TEST_F(PairExcitation, BatchSetsRunPairsAndReportTheirIntensityMeasure) {
  std::ofstream(path("column.json")) << column(0.0).dump(1);
  const json set = {
      {"models", {path("column.json").string(), POUND_SOURCE_DIR "/models/two_sdof_girders.json"}},
      {"records",
       {{{"file", "pair.txt"},
         {"format", "columns"},
         {"time_step", 0.01},
         {"pair", {{"column", 2}, {"angle", 10.0}}},
         {"scale", {{"sa", 0.4}, {"period", 0.6}}}}}},
      {"scales", {1, 2}},
      {"intensity_measure", {{"type", "sa"}, {"period", 0.6}, {"pair", "geometric_mean"}}}};
  std::ofstream(path("set.json")) << set.dump(1);
  const testing::Outcome batch =
      pound({"batch", path("set.json").string(), "--out", path("batch").string()});
  EXPECT_EQ(batch.exit_code, 3) << batch.err;  // the 1-D model's cases fail
  std::istringstream rows(read_text(path("batch") / "batch_summary.csv"));
  std::string line;
  std::getline(rows, line);
  std::vector<std::string> header;
  for (std::istringstream cells(line); std::getline(cells, line, ',');) header.push_back(line);
  const auto at = [&](const std::string& key) {
    return static_cast<std::size_t>(std::find(header.begin(), header.end(), key) - header.begin());
  };
  std::map<std::string, std::vector<std::string>> cases;
  while (std::getline(rows, line)) {
    std::vector<std::string> cells;
    for (std::istringstream in(line); std::getline(in, line, ',');) cells.push_back(line);
    cases[cells[0]] = cells;
  }
  const testing::Outcome spectrum =
      pound({"spectrum", path("pair.txt").string(), "--format", "columns", "--dt", "0.01",
             "--pair-column", "2", "--periods", "0.6", "--json"});
  const json measures = json::parse(spectrum.out);
  const double geometric_mean =
      measures["geometric_mean_g"][0].get<double>() * 0.4 / measures["rotd50_g"][0].get<double>();
  for (const double scale : {1.0, 2.0}) {
    const auto& row = cases.at(fmt::format("column/pair/x{:g}", scale));
    EXPECT_EQ(row[at("status")], "completed");
    const double intensity = std::stod(row[at("intensity")]);
    std::printf("  x%g: geometric mean Sa %.15g g (pound spectrum %.15g g)\n", scale, intensity,
                scale * geometric_mean);
    EXPECT_NEAR(intensity, scale * geometric_mean, 1e-12 * geometric_mean);
  }
  EXPECT_EQ(cases.at("two_sdof_girders/pair/x1")[at("status")], "input_error");
  EXPECT_TRUE(
      testing::contains(read_text(path("batch") / "batch_summary.csv"), "needs a 3-D scene"));
}

}  // namespace
// A case whose record entry cannot be applied (a pair column of a one-component .AT2 file) fails
// alone, its reason naming the set file and the record's entry, not the model's
// "/excitations/0", which the case's record replaced.
TEST_F(PairExcitation, ABatchCasesRecordErrorNamesTheSetsEntry) {
  std::ofstream(path("column.json")) << column(0.0).dump(1);
  write_at2(path("first.AT2"));
  const json set = {{"models", {path("column.json").string()}},
                    {"records", {{{"file", "first.AT2"}, {"pair", {{"column", 2}}}}}},
                    {"histories", false}};
  std::ofstream(path("set.json")) << set.dump(1);
  EXPECT_EQ(
      pound({"batch", path("set.json").string(), "--out", path("batch").string(), "-q"}).exit_code,
      3);
  const std::string rows = read_text(path("batch") / "batch_summary.csv");
  std::cout << rows;
  EXPECT_TRUE(testing::contains(rows, path("set.json").string() +
                                          ": /records/0/pair/column: a "
                                          "PEER .AT2 file holds one component"))
      << rows;
  EXPECT_FALSE(testing::contains(rows, "/excitations/0")) << rows;
}

// A batch row's pga_g of a pair is the larger component's: the pair with its weaker component
// first (0.182 g, then 0.278 g) reads 0.278 g, not the first's 0.182 g.
TEST_F(PairExcitation, ABatchRowsPgaOfAPairIsTheLargerComponents) {
  std::ofstream(path("column.json")) << column(0.0).dump(1);
  const json set = {{"models", {path("column.json").string()}},
                    {"records",
                     {{{"file", "pair.txt"},
                       {"format", "columns"},
                       {"column", 2},
                       {"time_step", 0.01},
                       {"pair", {{"column", 1}}}}}},
                    {"histories", false}};
  std::ofstream(path("set.json")) << set.dump(1);
  ASSERT_EQ(
      pound({"batch", path("set.json").string(), "--out", path("batch").string(), "-q"}).exit_code,
      0);
  const json spectrum =
      json::parse(pound({"spectrum", path("pair.txt").string(), "--format", "columns", "--dt",
                         "0.01", "--pair-column", "2", "--periods", "0.6", "--json"})
                      .out);
  const std::string rows = read_text(path("batch") / "batch_summary.csv");
  const std::string header = rows.substr(0, rows.find('\n'));
  const std::string row = rows.substr(rows.find('\n') + 1);
  std::vector<std::string> names, cells;
  for (std::istringstream in(header); std::getline(in, names.emplace_back(), ',');) {
  }
  for (std::istringstream in(row); std::getline(in, cells.emplace_back(), ',');) {
  }
  const auto column_of = std::find(names.begin(), names.end(), "pga_g") - names.begin();
  const double pga = std::stod(cells.at(static_cast<std::size_t>(column_of)));
  const double larger =
      std::max(spectrum["pga1_g"].get<double>(), spectrum["pga2_g"].get<double>());
  std::printf("pair pga_g %.9g g, components %.9g and %.9g g\n", pga,
              spectrum["pga2_g"].get<double>(), spectrum["pga1_g"].get<double>());
  EXPECT_NEAR(pga, larger, 1e-9 * larger);
}

}  // namespace pound
