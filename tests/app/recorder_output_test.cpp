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
#include <numbers>
#include <string>

#include "app/model_run.hpp"
#include "model/ground_motion.hpp"
#include "support/tables.hpp"

namespace pound::app {
namespace {

namespace fs = std::filesystem;

// The bundled buildings, their record named from anywhere.
nlohmann::json bundled_buildings() {
  const fs::path source = fs::path(POUND_SOURCE_DIR) / "models";
  nlohmann::json model = nlohmann::json::parse(std::ifstream(source / "adjacent_buildings.json"));
  model["excitations"][0]["record"] =
      (source / model["excitations"][0]["record"].get<std::string>()).string();
  return model;
}

// The bundled buildings (10 s of the record) with `recorders`, `separation` apart (0.5 m: they
// never meet, so the run is linear, with no cut steps). Newton is held to 3 iterations a step so
// that pounding steps that need more are cut (9 of them): the recorders must follow cut steps.
RunOutcome run_buildings_model(const nlohmann::json& recorders, double separation) {
  nlohmann::json model = bundled_buildings();
  model["analysis"]["duration"] = 10.0;
  model["analysis"]["convergence"] = {{"max_iterations", 3}};
  model["generators"][0]["separation"] = separation;
  model["recorders"] = recorders;
  const fs::path folder = fs::temp_directory_path() / fmt::format("pound_recorders_{}", ::getpid());
  fs::create_directories(folder);
  std::ofstream(folder / "model.json") << model.dump();
  RunRequest request;
  request.model_path = (folder / "model.json").string();
  const RunOutcome outcome = run_model(request);
  fs::remove_all(folder);
  return outcome;
}

// The same run's tables by file name.
std::map<std::string, Table> run_buildings(const nlohmann::json& recorders,
                                           double separation = 0.03) {
  const RunOutcome outcome = run_buildings_model(recorders, separation);
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  std::map<std::string, Table> tables;
  for (const auto& [file, table] : outcome.histories) tables[file] = table;
  return tables;
}

using testing::column;

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
        // Over the run's samples: the floor goes on moving after the run, so a floor spectrum
        // takes no free vibration after its last sample as a record's spectrum does.
        double direct = model::spectral_acceleration(floor, periods[p], damping);
        if (periods[p] > 0.0) {
          double largest = 0.0;
          for (const double u : model::sdof_response(floor, periods[p], damping).displacement)
            largest = std::max(largest, std::abs(u));
          const double omega = 2.0 * std::numbers::pi / periods[p];
          direct = omega * omega * largest;
        }
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
    const std::vector<std::string>& labels = envelope.text_columns.at(0).values;
    ASSERT_EQ(labels.size() + 1, history.columns.size());
    for (std::size_t q = 0; q < labels.size(); ++q) {
      ASSERT_EQ(labels[q], history.columns[q + 1]);
      const std::vector<double>& values = history.values[q + 1];
      const auto max = std::max_element(values.begin(), values.end());
      const auto min = std::min_element(values.begin(), values.end());
      const double time_of_max = history.values[0][static_cast<std::size_t>(max - values.begin())];
      const double time_of_min = history.values[0][static_cast<std::size_t>(min - values.begin())];
      EXPECT_EQ(envelope.values[0][q], *max) << labels[q];
      EXPECT_EQ(envelope.values[1][q], time_of_max) << labels[q];
      EXPECT_EQ(envelope.values[2][q], *min) << labels[q];
      EXPECT_EQ(envelope.values[3][q], time_of_min) << labels[q];
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

// Issue 16 item 3: member forces. A cantilever column (L = 4, two beams) under a constant tip
// load P along x, starting from static equilibrium with no excitation, so that it stays there:
// statics gives every end force (tension positive along the element's axis, which runs from
// base to tip; V and M as the nodes act on each element).
TEST(RecorderOutput, ElementEndForcesOfACantileverAreTheStaticOnes) {
  constexpr double P = 2.5e4, L = 4.0;
  const fs::path folder = fs::temp_directory_path() / fmt::format("pound_members_{}", ::getpid());
  fs::create_directories(folder);
  std::ofstream(folder / "model.json") << R"({
    "dimension": 2,
    "nodes": [{"id": "base", "x": 0, "y": 0}, {"id": "mid", "x": 0, "y": 2},
              {"id": "tip", "x": 0, "y": 4}, {"id": "anchor", "x": 0, "y": 8}],
    "materials": [{"id": "steel", "youngs_modulus": 2e11, "density": 7850}],
    "elements": [{"id": "e1", "type": "beam", "nodes": ["base", "mid"], "material": "steel",
                  "area": 0.01, "inertia": 1e-4},
                 {"id": "e2", "type": "beam", "nodes": ["mid", "tip"], "material": "steel",
                  "area": 0.01, "inertia": 1e-4},
                 {"id": "tie", "type": "truss", "nodes": ["anchor", "tip"], "material": "steel",
                  "area": 1e-4}],
    "supports": [{"node": "base", "fix": ["x", "y", "rz"]}, {"node": "anchor", "fix": ["x", "y"]}],
    "loads": [{"node": "tip", "x": 25000}],
    "monitors": {"drifts": [{"id": "tie", "bottom": "anchor", "top": "tip", "height": 4,
                             "base_element": "tie"},
                            {"id": "column", "kind": "pier", "bottom": "base", "top": "tip",
                             "height": 4, "base_element": "e1"}]},
    "analysis": {"time_step": 0.001, "duration": 0.01, "initial_state": "static"},
    "recorders": [{"type": "element", "elements": ["e1", "e2"], "file": "members.csv"},
                  {"type": "element", "elements": ["e1"], "envelope": true,
                   "file": "base.csv"}]
  })";
  RunRequest request;
  request.model_path = (folder / "model.json").string();
  const RunOutcome outcome = run_model(request);
  fs::remove_all(folder);
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const Table& members = outcome.histories.at(0).second;
  EXPECT_EQ(members.columns, (std::vector<std::string>{
                                 "time", "e1.N_i", "e1.V_i", "e1.M_i", "e1.N_j", "e1.V_j", "e1.M_j",
                                 "e2.N_i", "e2.V_i", "e2.M_i", "e2.N_j", "e2.V_j", "e2.M_j"}));
  // Magnitudes: no axial force; shear P in both; moment P L at the base, P L / 2 at mid-height,
  // none at the tip.
  const double expected[] = {0, P, P * L, 0, P, P * L / 2, 0, P, P * L / 2, 0, P, 0};
  double worst = 0.0;
  for (std::size_t c = 1; c < members.columns.size(); ++c)
    for (double value : members.values[c])
      worst = std::max(worst, std::abs(std::abs(value) - expected[c - 1]) / (P * L));
  std::printf("cantilever end forces against statics: largest error %.2e of P L\n", worst);
  EXPECT_LT(worst, 1e-9);
  // End i and end j of an element balance: V_i = -V_j, and M_i + M_j + V_j l = 0.
  EXPECT_NEAR(members.values[2][0], -members.values[5][0], 1e-9 * P);
  EXPECT_NEAR(members.values[3][0] + members.values[6][0] + members.values[5][0] * 2.0, 0.0,
              1e-9 * P * L);
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  EXPECT_NEAR(summary["piers"][0]["peak_shear"].get<double>(), P, 1e-9 * P);
  EXPECT_NEAR(summary["piers"][0]["peak_base_moment"].get<double>(), P * L, 1e-9 * P * L);
  // A vertical tie at the tip carries no load here, and a truss has no shear: none reported.
  EXPECT_FALSE(summary["storeys"][0].contains("peak_shear"));
  const Table& base = outcome.histories.at(1).second;
  EXPECT_EQ(base.text_columns.at(0).values.at(1), "e1.V_i");
  EXPECT_NEAR(base.values[4][1], P, 1e-9 * P);  // abs_max
}

// A shear-building storey's shear is its stiffness times its drift at every step (its floors
// hold the mass, its column none): apart, with no pounding, the peaks match exactly.
TEST(RecorderOutput, StoreyShearOfTheBuildingsIsStiffnessTimesDrift) {
  const nlohmann::json model = bundled_buildings();
  const RunOutcome outcome = run_buildings_model(model["recorders"], 0.5);
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  double worst = 0.0;
  std::size_t checked = 0;
  for (const nlohmann::json& storey : summary["storeys"]) {
    const std::string id = storey["id"];
    const bool left = id.starts_with("pair.left.");
    const std::size_t s = std::stoul(id.substr(id.rfind(".s") + 2)) - 1;
    const double stiffness =
        model["generators"][0][left ? "left" : "right"]["storeys"][s]["stiffness"].get<double>();
    const double expected = stiffness * storey["peak_drift"].get<double>();
    worst = std::max(worst, std::abs(storey["peak_shear"].get<double>() - expected) / expected);
    EXPECT_FALSE(storey.contains("peak_base_moment"));
    ++checked;
  }
  EXPECT_EQ(checked, 13u);
  std::printf("storey shear against k x drift over %zu storeys: largest error %.2e\n", checked,
              worst);
  EXPECT_LT(worst, 1e-9);
}

}  // namespace
}  // namespace pound::app
