// The Bouc-Wen spring: consistent tangents against central finite differences on every branch,
// z along a history of reversals against an independent fine RK4 solution of the Bouc-Wen ODE
// (whatever step the caller takes), its bounds, and its admissible parameters through the model
// reader.
#include "links/bouc_wen.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "io/model_reader.hpp"
#include "support/bouc_wen_shapes.hpp"

namespace pound::links {
namespace {

using Shape = testing::BoucWenShape;
constexpr double kZmax = testing::kBoucWenZmax;
constexpr auto shapes = testing::bouc_wen_shapes;

LinkKinematics at(double penetration) { return {penetration, 0.0, 0.0}; }

// The law after committing `history`, then tried at `trial`: |dF/d(delta) - central
// difference| * reach / |F|, and the other two tangents must be exactly 0 (rate independent).
double tangent_error(const BoucWen::Parameters& parameters, const std::vector<double>& history,
                     double trial) {
  BoucWen law(parameters);
  for (double delta : history) {
    law.set_trial(at(delta));
    law.commit();
  }
  const LawResponse response = law.set_trial(at(trial));
  EXPECT_EQ(response.damping, 0.0);
  EXPECT_EQ(response.mass, 0.0);
  const double reach = std::max(std::abs(trial), 1e-3);
  const double step = 1e-6 * reach;
  const double numeric =
      (law.set_trial(at(trial + step)).force - law.set_trial(at(trial - step)).force) / (2 * step);
  return std::abs(numeric - response.stiffness) * reach / std::abs(response.force);
}

TEST(BoucWen, TangentsMatchFiniteDifferencesOnEveryBranch) {
  const double z = kZmax;
  struct Path {
    std::string label;
    std::vector<double> history;
    double trial;
  };
  const std::vector<Path> paths = {
      {"first loading, elastic part", {}, 0.3 * z},
      {"first loading through the knee", {}, 1.2 * z},
      {"loading far past the knee", {}, -6.0 * z},
      {"loading in committed steps", {0.5 * z, 1.0 * z, 1.5 * z}, 2.0 * z},
      {"unloading after loading", {3.0 * z}, 2.5 * z},
      {"reversal through z = 0 in the trial", {3.0 * z}, -0.5 * z},
      {"reversal to the other knee", {3.0 * z}, -2.0 * z},
      {"reloading after a full cycle", {3.0 * z, -3.0 * z}, -1.0 * z},
      {"inner loop", {3.0 * z, 1.0 * z, 2.0 * z}, 1.2 * z},
  };
  for (const Shape& s : shapes())
    for (const Path& p : paths) {
      const double error = tangent_error(s.parameters, p.history, p.trial);
      std::cout << s.label << ", " << p.label << ": tangent error " << error << "\n";
      EXPECT_LT(error, 1e-6) << s.label << ", " << p.label;
    }
}

// An independent solution of dz/d(delta) = A - |z|^n (beta sgn(d(delta) z) + gamma) from `from`
// to `to`: classic RK4 in delta with `steps` equal steps, the sign re-evaluated at every stage
// (the fine step makes the crossing of z = 0 harmless).
double reference_z(const BoucWen::Parameters& p, double z, double from, double to, int steps) {
  const double h = (to - from) / steps;
  const auto rate = [&](double value) {
    const double sign = h * value < 0.0 ? -1.0 : 1.0;
    return p.amplitude - std::pow(std::abs(value), p.sharpness) * (p.beta * sign + p.gamma);
  };
  for (int i = 0; i < steps; ++i) {
    const double k1 = rate(z), k2 = rate(z + 0.5 * h * k1), k3 = rate(z + 0.5 * h * k2);
    const double k4 = rate(z + h * k3);
    z += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return z;
}

// The reversal points of a history: growing and shrinking loops, inner loops, a long excursion.
std::vector<double> reversals(double z_max) {
  const std::vector<double> shares = {0.0, 3.0, -2.0, 2.5, -0.5, 1.0, 0.2, -4.0, 6.0, -0.3};
  std::vector<double> points;
  for (double share : shares) points.push_back(share * z_max);
  return points;
}

// Each segment between reversals cut into kCheckpoints equal parts; the law's steps end on them.
constexpr int kCheckpoints = 1000;

// The reference z at every checkpoint of the history, with `per_segment` RK4 steps a segment.
std::vector<double> reference_history(const BoucWen::Parameters& p,
                                      const std::vector<double>& points, int per_segment) {
  std::vector<double> z = {0.0};
  for (std::size_t segment = 1; segment < points.size(); ++segment) {
    const double from = points[segment - 1], to = points[segment];
    for (int i = 1; i <= kCheckpoints; ++i)
      z.push_back(reference_z(p, z.back(), from + (to - from) * (i - 1) / kCheckpoints,
                              from + (to - from) * i / kCheckpoints, per_segment / kCheckpoints));
  }
  return z;
}

// Max |z_law - z_reference| / z_max over every step end of the history, each segment taken in
// `steps` equal committed steps (steps divides kCheckpoints).
double history_error(const BoucWen::Parameters& p, const std::vector<double>& points,
                     const std::vector<double>& reference, int steps) {
  BoucWen law(p);
  const int stride = kCheckpoints / steps;
  double worst = 0.0;
  for (std::size_t segment = 1; segment < points.size(); ++segment) {
    const double from = points[segment - 1], to = points[segment];
    for (int i = 1; i <= steps; ++i) {
      law.set_trial(at(from + (to - from) * i / steps));
      law.commit();
      const double z =
          reference[(segment - 1) * kCheckpoints + static_cast<std::size_t>(i * stride)];
      worst = std::max(worst, std::abs(law.hysteretic_deformation() - z) / law.saturation());
    }
  }
  return worst;
}

TEST(BoucWen, FollowsTheExactSolutionOfItsOdeWhateverTheStep) {
  constexpr int kReferenceSteps = 100000;  // per segment, each 0.3 to 10 z_max long
  for (const Shape& s : shapes()) {
    const std::vector<double> points = reversals(BoucWen(s.parameters).saturation());
    const std::vector<double> reference = reference_history(s.parameters, points, kReferenceSteps);
    // The reference's own error: its change from half its steps (RK4: 16 times that error).
    const std::vector<double> half = reference_history(s.parameters, points, kReferenceSteps / 2);
    double change = 0.0;
    for (std::size_t i = 0; i < reference.size(); ++i)
      change =
          std::max(change, std::abs(reference[i] - half[i]) / BoucWen(s.parameters).saturation());
    for (int steps : {1, 5, 40, 1000}) {
      const double error = history_error(s.parameters, points, reference, steps);
      std::cout << s.label << ", " << steps
                << " steps per segment: max |z - z_ode| / z_max = " << error
                << " (reference: " << change << " from half its steps)\n";
      EXPECT_LT(error, 1e-6) << s.label << ", " << steps << " steps";
    }
    EXPECT_LT(change, 1e-8) << s.label;
  }
}

// Loading far past the knee: z tends to z_max and the force to a k delta + (1 - a) k z_max;
// yield_deformation is where the initial tangent k (a + (1 - a) A) meets that line.
TEST(BoucWen, SaturatesAtItsBoundAndYieldsWhereTheTangentsMeet) {
  for (const Shape& s : shapes()) {
    const BoucWen::Parameters& p = s.parameters;
    const double z_max = std::pow(p.amplitude / (p.beta + p.gamma), 1.0 / p.sharpness);
    BoucWen law(p);
    EXPECT_NEAR(law.saturation(), z_max, 1e-15 * z_max) << s.label;
    const double initial = law.set_trial(at(0.0)).stiffness;
    EXPECT_NEAR(initial, p.stiffness * (p.hardening_ratio + (1 - p.hardening_ratio) * p.amplitude),
                1e-12 * p.stiffness)
        << s.label;
    const double far = 200.0 * z_max;
    const double force = law.set_trial(at(far)).force;
    const double line = p.hardening_ratio * p.stiffness * far;
    EXPECT_NEAR(force - line, (1 - p.hardening_ratio) * p.stiffness * z_max,
                1e-9 * p.stiffness * z_max)
        << s.label;
    const double post = p.hardening_ratio * p.stiffness;
    const double crossing = (1 - p.hardening_ratio) * p.stiffness * z_max / (initial - post);
    EXPECT_NEAR(*law.yield_deformation(), crossing, 1e-12 * crossing) << s.label;
  }
}

// Random walks of committed steps never leave |z| <= z_max, and a revert forgets the trial.
TEST(BoucWen, StaysInsideItsBoundsAndRevertsItsTrial) {
  for (const Shape& s : shapes()) {
    BoucWen law(s.parameters);
    const double z_max = law.saturation();
    double delta = 0.0, worst = 0.0;
    unsigned seed = 12345;
    for (int i = 0; i < 1000; ++i) {
      seed = seed * 1103515245u + 12345u;
      const double step = (static_cast<double>(seed >> 8) / (1u << 24) - 0.5) * 2.0 * z_max;
      delta = std::clamp(delta + step, -8.0 * z_max, 8.0 * z_max);
      law.set_trial(at(delta));
      law.commit();
      worst = std::max(worst, std::abs(law.hysteretic_deformation()) / z_max - 1.0);
    }
    EXPECT_LE(worst, 1e-12) << s.label;
    const double committed = law.hysteretic_deformation();
    const double force = law.set_trial(at(delta)).force;
    law.set_trial(at(delta + 3.0 * z_max));
    law.revert();
    EXPECT_EQ(law.set_trial(at(delta)).force, force) << s.label;
    EXPECT_EQ(law.hysteretic_deformation(), committed) << s.label;
  }
}

TEST(BoucWen, RefusesParametersWithoutBoundedHysteresis) {
  const BoucWen::Parameters good = testing::bouc_wen_shape(2.0, 0.5, 0.5, 0.05);
  EXPECT_NO_THROW(BoucWen{good});
  auto refused = [&](auto change) {
    BoucWen::Parameters p = good;
    change(p);
    const std::optional<BoucWen::Refusal> refusal = BoucWen::refusal(p);
    EXPECT_THROW(BoucWen{p}, std::invalid_argument);
    return refusal ? refusal->parameter : std::string("(accepted)");
  };
  EXPECT_EQ(refused([](auto& p) { p.beta = 0.0; }), "beta");
  EXPECT_EQ(refused([](auto& p) { p.beta = -p.gamma / 2; }), "beta");
  EXPECT_EQ(refused([](auto& p) { p.gamma = -p.beta; }), "gamma");
  EXPECT_EQ(refused([](auto& p) { p.sharpness = 0.5; }), "sharpness");
  EXPECT_EQ(refused([](auto& p) { p.sharpness = 51.0; }), "sharpness");
  EXPECT_EQ(refused([](auto& p) { p.amplitude = 0.0; }), "amplitude");
  EXPECT_EQ(refused([](auto& p) { p.hardening_ratio = 1.0; }), "hardening_ratio");
  EXPECT_EQ(refused([](auto& p) { p.stiffness = 0.0; }), "stiffness");
}

// A girder on a Bouc-Wen bearing, read and built from a model file.
builder::BuiltModel built(const std::string& law) {
  const std::string text = fmt::format(R"({{
    "nodes": [{{"id": "girder", "x": 0.0}}, {{"id": "abutment", "x": 1.0}}],
    "masses": [{{"node": "girder", "mass": 1e5}}],
    "supports": [{{"node": "abutment", "fix": ["x"]}}],
    "links": [{{"id": "bearing", "nodes": ["girder", "abutment"], "gap": 0, "law": {}}}],
    "analysis": {{"time_step": 0.01, "duration": 1}}
  }})",
                                       law);
  return builder::build(io::parse_model(text, "m.json"));
}

// The example bearing's law object with `changed` numbers.
std::string law_text(const std::map<std::string, double>& changed = {}) {
  std::map<std::string, double> numbers = {{"stiffness", 2e7},
                                           {"hardening_ratio", 0.05},
                                           {"sharpness", 2.0},
                                           {"beta", 2e4},
                                           {"gamma", 2e4}};
  for (const auto& [name, value] : changed) numbers[name] = value;
  std::string text = R"({"type": "bouc_wen")";
  for (const auto& [name, value] : numbers) text += fmt::format(R"(, "{}": {})", name, value);
  return text + "}";
}

TEST(BoucWen, BuildsFromAModelFile) {
  const auto law = built(law_text()).model.links.at(0).make_law(LinkContext{});
  ASSERT_NE(dynamic_cast<BoucWen*>(law.get()), nullptr);
  EXPECT_EQ(law->name(), "bouc_wen");
  EXPECT_NEAR(*law->yield_deformation(), std::sqrt(1.0 / 4e4), 1e-15);
}

// The reader's ranges (beta > 0, gamma >= 0, amplitude > 0, hardening_ratio < 1) and the law's
// own conditions (1 <= sharpness <= 50) both name the parameter's path.
TEST(BoucWen, BadParametersAreInputErrorsAtTheirPath) {
  struct Bad {
    std::string parameter;
    double value;
    std::string part;
  };
  for (const Bad& bad :
       {Bad{"sharpness", 0.5, "must be >= 1"}, Bad{"sharpness", 2e12, "<= 50"},
        Bad{"beta", 0.0, "must be > 0"}, Bad{"gamma", -1e4, "must be >= 0"},
        Bad{"amplitude", 0.0, "must be > 0"}, Bad{"hardening_ratio", 1.0, "must be < 1"}}) {
    std::optional<InputError> error;
    try {
      (void)built(law_text({{bad.parameter, bad.value}}));
    } catch (const InputError& caught) {
      error = caught;
    }
    ASSERT_TRUE(error.has_value()) << bad.parameter;
    std::cout << error->where() << ": " << error->reason() << "\n";
    EXPECT_EQ(error->file(), "m.json");
    EXPECT_EQ(error->where(), "/links/0/law/" + bad.parameter) << error->what();
    EXPECT_NE(error->reason().find(bad.part), std::string::npos) << error->what();
  }
}

}  // namespace
}  // namespace pound::links
