#include "links/hertz_damp.hpp"

#include <cmath>

#include "links/law_registry.hpp"
#include "links/restitution.hpp"
#include "links/restitution_calibration.hpp"

namespace pound::links {

HertzDamp::HertzDamp(double stiffness, double damping_ratio)
    : stiffness_(stiffness), damping_ratio_(damping_ratio) {}

LawResponse HertzDamp::set_trial(const LinkKinematics& trial) {
  trial_ = trial;
  if (!(trial.penetration > 0.0)) return {};
  const double root = std::sqrt(trial.penetration);
  const double elastic = stiffness_ * trial.penetration * root;  // k_h delta^1.5
  const double elastic_slope = 1.5 * stiffness_ * root;
  const OnsetVelocity v0 = onset_.at(trial);
  if (!(v0.velocity > 0.0)) return {.force = elastic, .stiffness = elastic_slope};
  const double factor = 1.0 + damping_ratio_ * trial.penetration_rate / v0.velocity;
  if (factor <= 0.0) return {};
  // d(factor)/d(v0) = -xi_bar delta_dot / v0^2, and v0 depends on the trial in the onset step.
  const double d_factor_d_v0 =
      -damping_ratio_ * trial.penetration_rate / (v0.velocity * v0.velocity);
  return {.force = elastic * factor,
          .stiffness = elastic_slope * factor + elastic * d_factor_d_v0 * v0.d_penetration,
          .damping = elastic * (damping_ratio_ / v0.velocity + d_factor_d_v0 * v0.d_rate)};
}

const LawEntry& HertzDamp::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "hertz_damp",
      .formula = "`F = k_h·δ^1.5·(1 + ξ̄·δ̇/v0)`, never tensile; from e: `ξ̄ = 8(1−e)/(5e)`",
      .source = "Muthukumar & DesRoches (2006); ξ̄ from e after Ye, Li & Zhu (2009)",
      .parameters = {{"stiffness", Range::positive, "F/L^1.5", "k_h"},
                     {"damping_ratio", Range::non_negative, "-", "ξ̄"},
                     restitution_parameter()},
      .choices = {calibration_choice()},
      .required = {"stiffness"},
      .exactly_one_of = {{"damping_ratio", "restitution"}},
      .traits = {.stiff_at_first_touch = false, .uses_approach_velocity = true},
      .example = {{"stiffness", 4e10}, {"restitution", 0.6}},
      .calibration = RestitutionCalibration{.unit_law =
                                                [](double ratio, const LawSpec&) {
                                                  return std::make_unique<HertzDamp>(1.0, ratio);
                                                },
                                            .published = hertz_damp_ratio_ye},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double k = *law.number("stiffness");
        const double ratio = law.number("damping_ratio").value_or(0.0);
        const double damping = law.number("damping_ratio")
                                   ? ratio
                                   : calibrated_damping(HertzDamp::entry(), law, where);
        return [k, damping](const LinkContext&) { return std::make_unique<HertzDamp>(k, damping); };
      }};
  return entry;
}

}  // namespace pound::links
