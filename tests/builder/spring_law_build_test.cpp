// The structural spring laws from a model file: each builds into its law object on a link, and
// bad parameters are input errors naming the law's path in the file.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "links/backfill.hpp"
#include "links/bilinear_spring.hpp"
#include "links/elastic_spring.hpp"

namespace pound::builder {
namespace {

// A girder on a bearing next to an abutment: one link whose law is `law` (a JSON object).
std::string model_with(const std::string& law, double gap = 0.0) {
  return fmt::format(R"({{
    "nodes": [{{"id": "girder", "x": 0.0}}, {{"id": "abutment", "x": 1.0}}],
    "masses": [{{"node": "girder", "mass": 1e5}}],
    "supports": [{{"node": "abutment", "fix": ["x"]}}],
    "links": [{{"id": "spring", "nodes": ["girder", "abutment"], "gap": {}, "law": {}}}],
    "analysis": {{"time_step": 0.01, "duration": 1}}
  }})",
                     gap, law);
}

BuiltModel built(const std::string& law, double gap = 0.0) {
  return build(io::parse_model(model_with(law, gap), "m.json"));
}

// The law object the model's only link makes.
std::unique_ptr<links::LinkLaw> law_of(const BuiltModel& model) {
  EXPECT_EQ(model.model.links.size(), 1u);
  return model.model.links.at(0).make_law(links::LinkContext{});
}

// Reading or building the model must fail at `where` with a reason containing `part`.
void expect_error(const std::string& law, const std::string& where, const std::string& part) {
  std::optional<InputError> error;
  try {
    (void)built(law);
  } catch (const InputError& caught) {
    error = caught;
  }
  ASSERT_TRUE(error.has_value()) << "no error for " << law;
  EXPECT_EQ(error->file(), "m.json");
  EXPECT_EQ(error->where(), where) << error->what();
  EXPECT_NE(error->reason().find(part), std::string::npos) << error->what();
}

TEST(SpringLawBuild, ElasticSpringBuilds) {
  const auto law = law_of(built(R"({"type": "elastic_spring", "stiffness": 2e7})"));
  const auto& spring = dynamic_cast<const links::ElasticSpring&>(*law);
  EXPECT_EQ(spring.stiffness(), 2e7);
  EXPECT_DOUBLE_EQ(law->set_trial({.penetration = -0.01}).force, -2e5);  // pulls too
}

TEST(SpringLawBuild, BilinearSpringBuilds) {
  const auto law = law_of(built(R"({"type": "bilinear_spring", "stiffness": 2e7,
                                    "yield_force": 1e5, "hardening_ratio": 0.05})"));
  ASSERT_NE(dynamic_cast<links::BilinearSpring*>(law.get()), nullptr);
  const links::LawResponse yielded = law->set_trial({.penetration = -0.01});
  EXPECT_DOUBLE_EQ(yielded.force, -(0.05 * 2e7 * 0.01 + 0.95 * 1e5));
  EXPECT_DOUBLE_EQ(yielded.stiffness, 0.05 * 2e7);
}

TEST(SpringLawBuild, BilinearSpringHardeningDefaultsToZero) {
  const auto law =
      law_of(built(R"({"type": "bilinear_spring", "stiffness": 2e7, "yield_force": 1e5})"));
  EXPECT_DOUBLE_EQ(law->set_trial({.penetration = 0.02}).force, 1e5);
}

TEST(SpringLawBuild, BackfillBuildsBehindAnExpansionJoint) {
  const BuiltModel model = built(R"({"type": "backfill", "initial_stiffness": 2.87e7,
                                     "ultimate_force": 4.06e5, "ultimate_deformation": 0.085})",
                                 0.05);
  EXPECT_EQ(model.model.links.at(0).gap, 0.05);
  const auto law = law_of(model);
  const auto& soil = dynamic_cast<const links::Backfill&>(*law);
  EXPECT_NEAR(soil.envelope(0.085).force, 4.06e5, 1e-6);
  EXPECT_EQ(law->set_trial({.penetration = -0.01}).force, 0.0);
}

TEST(SpringLawBuild, ElasticSpringWithoutStiffness) {
  expect_error(R"({"type": "elastic_spring"})", "/links/0/law/stiffness", "missing");
}

TEST(SpringLawBuild, ElasticSpringWithZeroStiffness) {
  expect_error(R"({"type": "elastic_spring", "stiffness": 0})", "/links/0/law/stiffness",
               "must be > 0");
}

TEST(SpringLawBuild, BilinearSpringWithoutYieldForce) {
  expect_error(R"({"type": "bilinear_spring", "stiffness": 2e7})", "/links/0/law/yield_force",
               "missing");
}

TEST(SpringLawBuild, BilinearSpringWithHardeningRatioOne) {
  expect_error(R"({"type": "bilinear_spring", "stiffness": 2e7, "yield_force": 1e5,
                   "hardening_ratio": 1.0})",
               "/links/0/law/hardening_ratio", "must be < 1");
}

TEST(SpringLawBuild, BackfillWithoutUltimateDeformation) {
  expect_error(R"({"type": "backfill", "initial_stiffness": 2.87e7, "ultimate_force": 4.06e5})",
               "/links/0/law/ultimate_deformation", "missing");
}

TEST(SpringLawBuild, BackfillReachingItsUltimateForceElastically) {
  // F_ult / K = 0.1 >= delta_ult = 0.08: no hyperbola through (delta_ult, F_ult) softens.
  expect_error(R"({"type": "backfill", "initial_stiffness": 1e6, "ultimate_force": 1e5,
                   "ultimate_deformation": 0.08})",
               "/links/0/law",
               "backfill: ultimate_force / initial_stiffness = 0.1 must be below "
               "ultimate_deformation = 0.08");
}

}  // namespace
}  // namespace pound::builder
