// Issue 16 items 2 and 4: what a run writes beside every-step histories, checked against the
// every-step history of the same run. Floor spectra equal the spectrum of the recorded absolute
// acceleration computed directly as a record; envelopes are the history's extremes and their
// times; an output interval keeps exactly the history's rows at its multiples; a node records
// only the directions it moves in. The bundled pair of buildings pounding under its record.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "app/model_run.hpp"
#include "model/ground_motion.hpp"

namespace pound::app {
namespace {

namespace fs = std::filesystem;

// The bundled buildings (10 s of the record) with `recorders`, `separation` apart (0.5 m: they
// never meet, so the run is linear, with no cut steps); the run's tables by file name.
std::map<std::string, Table> run_buildings(const nlohmann::json& recorders,
                                           double separation = 0.03) {
  const fs::path source = fs::path(POUND_SOURCE_DIR) / "models";
  nlohmann::json model = nlohmann::json::parse(std::ifstream(source / "adjacent_buildings.json"));
  model["excitations"][0]["record"] =
      (source / model["excitations"][0]["record"].get<std::string>()).string();
  model["analysis"]["duration"] = 10.0;
  model["generators"][0]["separation"] = separation;
  model["recorders"] = recorders;
  const fs::path folder = fs::temp_directory_path() / fmt::format("pound_recorders_{}", ::getpid());
  fs::create_directories(folder);
  std::ofstream(folder / "model.json") << model.dump();
  RunRequest request;
  request.model_path = (folder / "model.json").string();
  const RunOutcome outcome = run_model(request);
  fs::remove_all(folder);
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  std::map<std::string, Table> tables;
  for (const auto& [file, table] : outcome.histories) tables[file] = table;
  return tables;
}

const std::vector<double>& column(const Table& table, const std::string& name) {
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    if (table.columns[c] == name) return table.values[c];
  ADD_FAILURE() << "no column " << name;
  static const std::vector<double> none;
  return none;
}

const nlohmann::json kRoofs = {"pair.left.f5", "pair.right.f8"};

const std::vector<double> kPeriods = {0.0, 0.1, 0.3, 0.6, 1.0, 2.0};

nlohmann::json roofs_and_spectra() {
  return {
      {{"type", "node"}, {"nodes", kRoofs}, {"accelerations", "absolute"}, {"file", "roofs.csv"}},
      {{"type", "spectrum"},
       {"nodes", kRoofs},
       {"damping", {0.02, 0.05}},
       {"periods", kPeriods},
       {"file", "spectra.csv"}}};
}

// Apart, so that every step is the nominal one and the history is a record of 0.002 s.
TEST(RecorderOutput, FloorSpectraAreTheSpectraOfTheRecordedAbsoluteAccelerations) {
  const std::vector<double>& periods = kPeriods;
  auto tables = run_buildings(roofs_and_spectra(), 0.5);
  const Table& history = tables.at("roofs.csv");
  const Table& spectra = tables.at("spectra.csv");
  EXPECT_EQ(spectra.values[0], periods);
  double worst = 0.0;
  for (const std::string roof : {"pair.left.f5", "pair.right.f8"}) {
    model::GroundMotion floor{roof, 0.002, column(history, roof + ".a_abs_x")};
    ASSERT_EQ(floor.acceleration.size(), 5001u);
    for (const double damping : {0.02, 0.05}) {
      const std::string name = fmt::format("{}.sa_x_{:g}%", roof, 100.0 * damping);
      const std::vector<double>& sa = column(spectra, name);
      for (std::size_t p = 0; p < periods.size(); ++p) {
        const double direct = model::spectral_acceleration(floor, periods[p], damping);
        worst = std::max(worst, std::abs(sa.at(p) - direct) / direct);
      }
    }
  }
  std::printf("floor spectra against the recorded a_abs: largest relative difference %.2e\n",
              worst);
  EXPECT_LT(worst, 1e-12);
}

// Pounding, with cut steps: period 0 is the peak floor acceleration of every step, and the
// spectra are those of the linearly interpolated history, peaks taken at its samples
// (model::ResponseOscillator, tested against spectra of records with steps of any length).
TEST(RecorderOutput, FloorSpectraOfAPoundingRunFollowEveryStep) {
  auto tables = run_buildings(roofs_and_spectra());
  const Table& history = tables.at("roofs.csv");
  const Table& spectra = tables.at("spectra.csv");
  EXPECT_GT(history.values[0].size(), 5001u) << "no cut steps: the case tests nothing more";
  for (const std::string roof : {"pair.left.f5", "pair.right.f8"}) {
    const std::vector<double>& times = history.values[0];
    const std::vector<double>& floor = column(history, roof + ".a_abs_x");
    double peak = 0.0;
    for (double a : floor) peak = std::max(peak, std::abs(a));
    EXPECT_EQ(column(spectra, roof + ".sa_x_5%").at(0), peak);
    for (std::size_t p = 1; p < kPeriods.size(); ++p) {
      model::ResponseOscillator oscillator(kPeriods[p], 0.05);
      for (std::size_t r = 1; r < times.size(); ++r)
        oscillator.advance(floor[r - 1], floor[r], times[r] - times[r - 1]);
      EXPECT_EQ(column(spectra, roof + ".sa_x_5%").at(p), oscillator.pseudo_acceleration());
    }
  }
}

TEST(RecorderOutput, AnEnvelopeIsTheHistorysExtremesAndTheirFirstTimes) {
  auto tables = run_buildings(
      {{{"type", "node"}, {"nodes", kRoofs}, {"file", "roofs.csv"}},
       {{"type", "node"}, {"nodes", kRoofs}, {"envelope", true}, {"file", "roofs_envelope.csv"}},
       {{"type", "link"}, {"file", "links.csv"}},
       {{"type", "link"}, {"envelope", true}, {"file", "links_envelope.npy"}}});
  for (const auto& [history_file, envelope_file] :
       {std::pair{"roofs.csv", "roofs_envelope.csv"}, {"links.csv", "links_envelope.npy"}}) {
    const Table& history = tables.at(history_file);
    const Table& envelope = tables.at(envelope_file);
    ASSERT_EQ(envelope.labels.size() + 1, history.columns.size());
    for (std::size_t q = 0; q < envelope.labels.size(); ++q) {
      ASSERT_EQ(envelope.labels[q], history.columns[q + 1]);
      const std::vector<double>& values = history.values[q + 1];
      const auto max = std::max_element(values.begin(), values.end());
      const auto min = std::min_element(values.begin(), values.end());
      const double time_of_max = history.values[0][static_cast<std::size_t>(max - values.begin())];
      const double time_of_min = history.values[0][static_cast<std::size_t>(min - values.begin())];
      EXPECT_EQ(envelope.values[0][q], *max) << envelope.labels[q];
      EXPECT_EQ(envelope.values[1][q], time_of_max) << envelope.labels[q];
      EXPECT_EQ(envelope.values[2][q], *min) << envelope.labels[q];
      EXPECT_EQ(envelope.values[3][q], time_of_min) << envelope.labels[q];
      EXPECT_EQ(envelope.values[4][q], std::max(std::abs(*max), std::abs(*min)));
    }
  }
}

TEST(RecorderOutput, AnIntervalKeepsTheHistorysRowsAtItsMultiplesAndRecordsOnlyFreeDirections) {
  auto tables = run_buildings(
      {{{"type", "node"}, {"nodes", kRoofs}, {"file", "every.csv"}},
       {{"type", "node"}, {"nodes", kRoofs}, {"interval", 0.05}, {"file", "interval.csv"}},
       {{"type", "node"}, {"nodes", kRoofs}, {"every", 7}, {"file", "seventh.csv"}}});
  const Table& every = tables.at("every.csv");
  // The floors of shear buildings move only along x: no y or rotation columns.
  EXPECT_EQ(every.columns.size(), 1u + 2u * 4u);
  for (const std::string& name : every.columns)
    EXPECT_TRUE(name == "time" || name.ends_with("_x")) << name;
  // The rows each keeps, picked from the every-step history (cut steps included): every
  // seventh state; the first state at or after each multiple of 0.05 s.
  const std::vector<double>& times = every.values[0];
  std::vector<std::size_t> seventh, interval;
  for (std::size_t r = 0; r < times.size(); r += 7) seventh.push_back(r);
  for (int m = 0; m * 0.05 <= times.back() + 1e-12; ++m) {
    const auto at =
        std::find_if(times.begin(), times.end(), [&](double t) { return t >= m * 0.05 - 1e-12; });
    const auto row = static_cast<std::size_t>(at - times.begin());
    if (interval.empty() || interval.back() != row) interval.push_back(row);
  }
  EXPECT_GT(times.size(), 5001u) << "no cut steps: the case tests nothing more";
  EXPECT_EQ(interval.size(), 201u);
  for (const auto& [file, rows] :
       {std::pair{"interval.csv", interval}, std::pair{"seventh.csv", seventh}}) {
    const Table& thin = tables.at(file);
    EXPECT_EQ(thin.columns, every.columns);
    ASSERT_EQ(thin.values[0].size(), rows.size()) << file;
    for (std::size_t c = 0; c < every.columns.size(); ++c)
      for (std::size_t r = 0; r < rows.size(); ++r)
        ASSERT_EQ(thin.values[c][r], every.values[c][rows[r]])
            << file << " " << every.columns[c] << " row " << r;
  }
}

}  // namespace
}  // namespace pound::app
