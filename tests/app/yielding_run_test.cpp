// The yielding building pair example as `pound run` reports it: each yielding storey's link gives
// its plastic drift (peak - yield) and what it dissipated, the energy balance names the part of
// the links' energy that is hysteretic (their sum), and the balance still closes to rounding.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/model_run.hpp"

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

}  // namespace
}  // namespace pound::app
