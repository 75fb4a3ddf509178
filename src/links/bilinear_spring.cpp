#include "links/bilinear_spring.hpp"

#include <cmath>
#include <utility>

#include "links/law_registry.hpp"

namespace pound::links {

BilinearSpring::BilinearSpring(double stiffness, double yield_force, double hardening_ratio,
                               std::string name)
    : name_(std::move(name)),
      stiffness_(stiffness),
      yield_force_(yield_force),
      hardening_ratio_(hardening_ratio),
      hardening_modulus_(hardening_ratio * stiffness / (1.0 - hardening_ratio)) {}

LawResponse BilinearSpring::set_trial(const LinkKinematics& trial) {
  trial_plastic_ = committed_plastic_;
  double force = stiffness_ * (trial.penetration - committed_plastic_), slope = stiffness_;
  const double relative = force - back_force_at(committed_plastic_);
  const double excess = std::abs(relative) - yield_force_;
  if (excess > 0.0) {  // return to the yield surface, which moves with the back-force
    const double plastic_step = std::copysign(excess / (stiffness_ + hardening_modulus_), relative);
    trial_plastic_ += plastic_step;
    force -= stiffness_ * plastic_step;
    slope = hardening_ratio_ * stiffness_;
  }
  trial_force_ = force;
  return {.force = force, .stiffness = slope};
}

void BilinearSpring::commit() {
  committed_plastic_ = trial_plastic_;
  committed_force_ = trial_force_;
}

void BilinearSpring::revert() {
  trial_plastic_ = committed_plastic_;
  trial_force_ = committed_force_;
}

const LawEntry& BilinearSpring::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "bilinear_spring",
      .formula =
          "`F = k·(δ − p)`, yield at `|F − H·p| = F_y`, `H = b·k/(1 − b)`: elastic-plastic "
          "both ways, kinematic hardening, post-yield slope `b·k`",
      .source =
          "bilinear hysteretic model (OpenSees Steel01 without isotropic hardening; "
          "Caltrans SDC bilinear bearing)",
      .parameters = {{"stiffness", Range::positive, "F/L", "elastic stiffness k"},
                     {"yield_force", Range::positive, "F", "F_y"},
                     {"hardening_ratio", Range::fraction, "-",
                      "b, post-yield stiffness / k, 0 <= b < 1 (default 0)"}},
      .required = {"stiffness", "yield_force"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"stiffness", 2e7}, {"yield_force", 1e5}, {"hardening_ratio", 0.05}},
      .make = [](const LawSpec& law, const LawSource&) -> LawFactory {
        const double k = *law.number("stiffness"), yield = *law.number("yield_force");
        const double hardening = law.number("hardening_ratio").value_or(0.0);
        return [=](const LinkContext&) {
          return std::make_unique<BilinearSpring>(k, yield, hardening);
        };
      }};
  return entry;
}

}  // namespace pound::links
