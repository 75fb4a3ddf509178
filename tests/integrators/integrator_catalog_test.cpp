// The integrator catalog: names, presets, parameters, and that every entry makes an integrator
// that integrates.
#include "integrators/integrator_catalog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <set>

#include "integrators/transient_analysis.hpp"
#include "support/oscillator.hpp"

namespace pound::integrators {
namespace {

TEST(IntegratorCatalog, NamesAndPresetsAreUniqueAndFindable) {
  std::set<std::string> names, presets;
  for (const IntegratorEntry* entry : integrator_catalog()) {
    EXPECT_TRUE(names.insert(entry->name).second) << entry->name;
    EXPECT_EQ(find_integrator(entry->name), entry);
    EXPECT_FALSE(entry->description.empty());
    EXPECT_FALSE(entry->presets.empty()) << entry->name;
    for (const IntegratorPreset& preset : entry->presets) {
      EXPECT_TRUE(presets.insert(preset.name).second) << preset.name;
      EXPECT_EQ(&IntegratorChoice::preset(preset.name).method(), entry);
      for (const auto& [name, value] : preset.parameters) {
        ASSERT_NE(entry->parameter(name), nullptr) << preset.name << ": " << name;
        EXPECT_TRUE(entry->parameter(name)->admits(value)) << preset.name << ": " << name;
      }
    }
    for (const IntegratorParameter& parameter : entry->parameters)
      EXPECT_TRUE(parameter.admits(parameter.fallback)) << entry->name << ": " << parameter.name;
  }
  // The presets model files have used since the start stay (more may come).
  const std::vector<std::string> all_presets = preset_names();
  for (const char* kept : {"newmark_average_acceleration", "newmark_linear_acceleration", "hht",
                           "generalized_alpha", "central_difference"})
    EXPECT_NE(std::find(all_presets.begin(), all_presets.end(), kept), all_presets.end()) << kept;
  EXPECT_THROW(IntegratorChoice::preset("euler"), std::invalid_argument);
}

TEST(IntegratorCatalog, ChoicesTakeDefaultsAndNameTheirPreset) {
  const IntegratorChoice average;
  EXPECT_EQ(average.label(), "newmark_average_acceleration");
  EXPECT_EQ(average.parameter("beta"), 0.25);
  IntegratorChoice linear = IntegratorChoice::preset("newmark_linear_acceleration");
  EXPECT_EQ(linear.parameter("beta"), 1.0 / 6.0);
  EXPECT_EQ(linear.make()->name(), "newmark_linear_acceleration");
  linear.set("beta", 0.3);
  EXPECT_EQ(linear.label(), "newmark");
  EXPECT_TRUE(IntegratorChoice::preset("central_difference").is_explicit());
  EXPECT_FALSE(IntegratorChoice::preset("hht").is_explicit());
  std::vector<std::string> studied;
  for (const IntegratorChoice& choice : IntegratorChoice::studied())
    studied.push_back(choice.label());
  // Every method is studied once, under its preset's name when its study parameters are one.
  EXPECT_EQ(studied.size(), integrator_catalog().size());
  EXPECT_EQ(std::vector<std::string>(studied.begin(), studied.begin() + 4),
            (std::vector<std::string>{"newmark_average_acceleration", "hht", "generalized_alpha",
                                      "central_difference"}));
  EXPECT_EQ(IntegratorChoice::studied()[2].parameter("rho_infinity"), 0.5);
}

// Every method as the catalog makes it: one period of a free oscillator at 100 steps per period
// ends within 1 % of where it started (the methods are second order: (w dt)^2 / 12 ~ 3e-4 phase).
TEST(IntegratorCatalog, EveryMethodIntegratesAnOscillator) {
  for (const IntegratorChoice& choice : IntegratorChoice::studied()) {
    testing::Oscillator oscillator(1.0, 0.0, 4.0 * std::numbers::pi * std::numbers::pi);
    const auto integrator = choice.make();
    TransientAnalysis analysis(oscillator, *integrator, {.time_step = 0.01, .end_time = 1.0});
    State state;
    state.displacement = Vector::Constant(1, 1.0);
    state.velocity = Vector::Zero(1);
    analysis.run(state);
    std::cout << choice.label() << ": u(T) - u(0) = " << state.displacement[0] - 1.0 << "\n";
    EXPECT_NEAR(state.displacement[0], 1.0, 0.01) << choice.label();
  }
}

}  // namespace
}  // namespace pound::integrators
