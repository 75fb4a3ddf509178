#include "links/viscous_damper.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

ViscousDamper::ViscousDamper(double coefficient, double exponent, double linear_velocity)
    : coefficient_(coefficient), exponent_(exponent), linear_velocity_(linear_velocity) {}

LawResponse ViscousDamper::set_trial(const LinkKinematics& trial) {
  const double rate = trial.penetration_rate, speed = std::abs(rate);
  trial_loaded_ = rate != 0.0;
  // At rest too when linear (alpha = 1, no v_l): pow(0, 0) = 1.
  if (speed <= linear_velocity_) {
    const double damping = coefficient_ * std::pow(linear_velocity_, exponent_ - 1.0);
    return {.force = damping * rate, .damping = damping};
  }
  const double force = coefficient_ * std::pow(speed, exponent_);
  return {.force = std::copysign(force, rate), .damping = exponent_ * force / speed};
}

const LawEntry& ViscousDamper::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "viscous_damper",
      .formula = "`F = c·|δ̇|^α·sign(δ̇)`, linear `c·v_l^(α−1)·δ̇` below `|δ̇| = v_l`",
      .source =
          "fluid viscous damper (Constantinou & Symans 1993; OpenSees ViscousDamper "
          "without its spring)",
      .parameters = {{"coefficient", Range::positive, "F·(T/L)^α", "c"},
                     {"exponent", Range::unit, "-", "α (default 1: linear)"},
                     {"linear_velocity", Range::positive, "L/T",
                      "v_l, below which the force is linear (needed when α < 1)"}},
      .required = {"coefficient"},
      .traits = {.role = LinkRole::spring, .stiff_at_first_touch = false, .penalty = false},
      .example = {{"coefficient", 2e6}, {"exponent", 0.35}, {"linear_velocity", 1e-2}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double c = *law.number("coefficient");
        const double alpha = law.number("exponent").value_or(1.0);
        if (alpha < 1.0 && !law.number("linear_velocity"))
          throw InputError(where.file, where.path,
                           "an exponent below 1 needs 'linear_velocity', the speed below which "
                           "the force is linear (the tangent is infinite at rest)");
        const double linear_velocity = law.number("linear_velocity").value_or(0.0);
        return [=](const LinkContext&) {
          return std::make_unique<ViscousDamper>(c, alpha, linear_velocity);
        };
      }};
  return entry;
}

}  // namespace pound::links
