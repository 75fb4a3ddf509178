// The yielding building pair example as `pound run` reports it: each yielding storey's link gives
// its plastic drift (peak - yield) and what it dissipated, the energy balance names the part of
// the links' energy that is hysteretic (their sum), and the balance still closes to rounding.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>

#include "app/model_run.hpp"
#include "support/collapsing_column.hpp"

namespace pound::app {
namespace {

TEST(YieldingRun, SummaryGivesPlasticDemandsAndTheHystereticPartOfTheBalance) {
  RunRequest request;
  request.model_path = std::string(POUND_SOURCE_DIR) + "/models/adjacent_buildings_yielding.json";
  request.histories = false;
  const RunOutcome outcome = run_model(request);
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  double hysteretic = 0.0;
  int storeys = 0;
  for (const nlohmann::json& link : summary["links"]) {
    if (!link.contains("yield_deformation")) continue;
    ++storeys;
    const double plastic =
        link["peak_deformation"].get<double>() - link["yield_deformation"].get<double>();
    EXPECT_DOUBLE_EQ(link["peak_plastic_deformation"].get<double>(), std::max(0.0, plastic));
    EXPECT_GT(link["hysteretic_energy"].get<double>(), 0.0) << link["id"];
    hysteretic += link["hysteretic_energy"].get<double>();
  }
  EXPECT_EQ(storeys, 12);  // 4 + 8 Takeda storeys, each yields at 0.3 g
  const nlohmann::json& energy = summary["energy"];
  std::cout << "links " << energy["links"] << ", of which hysteretic " << energy["links_hysteretic"]
            << "; balance error " << energy["worst_balance_error"] << "\n";
  EXPECT_NEAR(energy["links_hysteretic"].get<double>(), hysteretic, 1e-9 * hysteretic);
  EXPECT_LT(energy["links_hysteretic"].get<double>(), energy["links"].get<double>());
  EXPECT_LT(energy["worst_balance_error"].get<double>(), 1e-9);
}

// A bundled model edited by `edit`, its record named from the models' folder, run with its
// histories off.
RunOutcome run_edited(const std::string& name, const std::string& record,
                      const std::function<void(nlohmann::json&)>& edit) {
  const std::string models = std::string(POUND_SOURCE_DIR) + "/models/";
  nlohmann::json model = nlohmann::json::parse(std::ifstream(models + name));
  edit(model);
  model["excitations"][0]["record"] = models + "../ground_motions/" + record;
  const std::filesystem::path file =
      std::filesystem::temp_directory_path() / fmt::format("pound_edited_{}_{}", ::getpid(), name);
  std::ofstream(file) << model.dump();
  RunRequest request;
  request.model_path = file.string();
  request.histories = false;
  RunOutcome outcome = run_model(request);
  std::filesystem::remove(file);
  return outcome;
}

// The hinged bridge with its hinges given by a yield curvature and a plastic-hinge length: each
// pier's curvature ductility is 1 + theta_p / (phi_y L_p) of its hinge's plastic rotation.
TEST(YieldingRun, HingedPiersReportTheirCurvatureDuctility) {
  const double phi_y = 4.0e6 / (3.0e10 * 0.8), hinge_length = 0.8;  // M_y = E I phi_y as before
  const RunOutcome outcome =
      run_edited("three_span_bridge_takeda.json", "synthetic_firm_01.AT2", [&](nlohmann::json& m) {
        nlohmann::json& hinge = m["generators"][0]["pier_hinge"];
        hinge.erase("yield_moment");
        hinge["yield_curvature"] = phi_y;
        hinge["plastic_hinge_length"] = hinge_length;
      });
  ASSERT_TRUE(outcome.failure.empty()) << outcome.failure;
  const nlohmann::json summary = nlohmann::json::parse(outcome.summary.dump());
  std::map<std::string, double> plastic;
  for (const nlohmann::json& link : summary["links"])
    if (link.contains("peak_plastic_deformation"))
      plastic[link["id"].get<std::string>()] = link["peak_plastic_deformation"].get<double>();
  int piers = 0;
  for (const nlohmann::json& drift : summary["piers"]) {
    const std::string id = drift["id"].get<std::string>();
    const double expected = 1.0 + plastic.at(id + ".hinge") / (phi_y * hinge_length);
    std::cout << id << ": curvature ductility " << drift["curvature_ductility"]
              << ", displacement ductility " << drift["ductility"] << "\n";
    EXPECT_NEAR(drift["curvature_ductility"].get<double>(), expected, 1e-12 * expected);
    EXPECT_GT(expected, 1.0);
    ++piers;
  }
  EXPECT_EQ(piers, 2);
  EXPECT_NE(outcome.report.find("curvature ductility"), std::string::npos) << outcome.report;
}

// A column that collapses under P-Delta once its hinge yields (support/collapsing_column.hpp):
// the drift (thousands of percent) is told as a collapse, not left as a drift with a hint of a
// soft stiffness; the same column elastic under the same shaking is not.
TEST(YieldingRun, APDeltaRunawayIsToldAsACollapse) {
  const auto column_run = [](double yield_moment) {
    const std::string text = testing::collapsing_column(yield_moment);
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / fmt::format("pound_collapse_{}.json", ::getpid());
    std::ofstream(file) << text;
    RunRequest request;
    request.model_path = file.string();
    request.histories = false;
    const RunOutcome outcome = run_model(request);
    std::filesystem::remove(file);
    return outcome;
  };
  const auto collapse_warnings = [](const RunOutcome& outcome) {
    int found = 0;
    for (const std::string& w : outcome.warnings)
      if (w.find("read it as a collapse") != std::string::npos) {
        std::cout << w << "\n";
        ++found;
      }
    return found;
  };
  const RunOutcome yielding = column_run(4.0e6);
  ASSERT_TRUE(yielding.failure.empty()) << yielding.failure;
  EXPECT_EQ(collapse_warnings(yielding), 1);
  const RunOutcome elastic = column_run(4.0e9);
  ASSERT_TRUE(elastic.failure.empty()) << elastic.failure;
  EXPECT_EQ(collapse_warnings(elastic), 0);
}

// The yielding pair with `storey_damping` set on both buildings.
nlohmann::json run_with_storey_damping(const std::string& damping) {
  const RunOutcome outcome = run_edited(
      "adjacent_buildings_yielding.json", "synthetic_soft_01.AT2", [&](nlohmann::json& model) {
        for (const char* side : {"left", "right"})
          model["generators"][0][side]["storey_damping"] = damping;
      });
  EXPECT_TRUE(outcome.failure.empty()) << outcome.failure;
  return nlohmann::json::parse(outcome.summary.dump());
}

// Storey damping in the storey links (a1 k_0 or a1 k_t): its work is reported per storey apart
// from the hysteretic energy, the balance closes, and committed-tangent damping dissipates less
// than initial-stiffness damping, whose a1 k_0 stays on after a storey yields (every Takeda
// tangent is at most k_0; Charney 2008).
TEST(YieldingRun, StoreyDampingIsReportedApartFromHysteresis) {
  std::map<std::string, double> totals;
  for (const std::string kind : {"initial", "committed"}) {
    const nlohmann::json summary = run_with_storey_damping(kind);
    int storeys = 0;
    for (const nlohmann::json& link : summary["links"]) {
      if (!link.contains("yield_deformation")) continue;
      ++storeys;
      EXPECT_GT(link["damping_energy"].get<double>(), 0.0) << link["id"];
      EXPECT_GE(link["hysteretic_energy"].get<double>(), 0.0) << link["id"];
      EXPECT_LT(link["hysteretic_energy"].get<double>() + link["damping_energy"].get<double>(),
                link["work"].get<double>() * (1 + 1e-12))
          << link["id"];
      totals[kind] += link["damping_energy"].get<double>();
    }
    EXPECT_EQ(storeys, 12);
    EXPECT_EQ(summary["links"].size(), 12u + 4u) << "the storeys and the 4 pounding links, no more";
    EXPECT_LT(summary["energy"]["worst_balance_error"].get<double>(), 1e-9) << kind;
  }
  std::cout << "storey damping energy: initial stiffness " << totals["initial"]
            << ", committed tangent " << totals["committed"] << " (ratio "
            << totals["committed"] / totals["initial"] << ")\n";
  EXPECT_LT(totals["committed"], totals["initial"]);
}

}  // namespace
}  // namespace pound::app
