#include "links/restrainer.hpp"

#include <cmath>
#include <limits>

#include "links/law_registry.hpp"

namespace pound::links {

Restrainer::Restrainer(std::string name, double stiffness, double slack, double yield_force,
                       double hardening_ratio)
    : name_(std::move(name)),
      stiffness_(stiffness),
      slack_(slack),
      yield_force_(yield_force),
      hardening_(hardening_ratio * stiffness / (1.0 - hardening_ratio)) {}

LawResponse Restrainer::set_trial(const LinkKinematics& trial) {
  const double elongation = -trial.penetration - slack_ - committed_plastic_;
  trial_plastic_ = committed_plastic_;
  trial_taut_ = elongation > 0.0;
  if (!trial_taut_) return {};
  double tension = stiffness_ * elongation, slope = stiffness_;
  const double excess = tension - (yield_force_ + hardening_ * committed_plastic_);
  if (excess > 0.0) {  // return to the yield line
    const double plastic_step = excess / (stiffness_ + hardening_);
    trial_plastic_ += plastic_step;
    tension -= stiffness_ * plastic_step;
    slope = stiffness_ * hardening_ / (stiffness_ + hardening_);
  }
  // dF/d(delta) = d(-T)/d(delta) = dT/d(opening).
  return {.force = -tension, .stiffness = slope};
}

std::optional<double> Restrainer::yield_deformation() const {
  if (!std::isfinite(yield_force_)) return std::nullopt;
  return yield_force_ / stiffness_;
}

void Restrainer::commit() {
  committed_plastic_ = trial_plastic_;
  committed_taut_ = trial_taut_;
}

void Restrainer::revert() {
  trial_plastic_ = committed_plastic_;
  trial_taut_ = committed_taut_;
}

namespace {

// A restrainer and a hook are one class: the hook never yields.
LawFactory make_restrainer(const LawSpec& law) {
  const double k = *law.number("stiffness"), slack = law.number("slack").value_or(0.0);
  const double yield = law.number("yield_force").value_or(std::numeric_limits<double>::infinity());
  const double hardening = law.number("hardening_ratio").value_or(0.0);
  return [=](const LinkContext&) {
    return std::make_unique<Restrainer>(law.type, k, slack, yield, hardening);
  };
}

}  // namespace

const LawEntry& Restrainer::restrainer_entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "restrainer",
      .formula =
          "tension `T = k·(o − slack − p)` when positive, yield at `T_y + H·p`, "
          "`H = b·k/(1 − b)`; `F = −T`, `o = −δ` the opening",
      .source = "cable restrainers (Caltrans SDC; FHWA)",
      .parameters = {{"stiffness", Range::positive, "F/L", "k"},
                     {"slack", Range::non_negative, "L", "(default 0)"},
                     {"yield_force", Range::positive, "F", "T_y (default: elastic)"},
                     {"hardening_ratio", Range::fraction, "-",
                      "b, post-yield stiffness / k (default 0)"}},
      .required = {"stiffness"},
      .needs = {{"hardening_ratio", {"yield_force"}}},
      .traits = {.role = LinkRole::tension, .penalty = false},
      .example = {{"stiffness", 5e7}, {"slack", 0.02}, {"yield_force", 1e6}},
      .make = [](const LawSpec& law, const LawSource&) { return make_restrainer(law); }};
  return entry;
}

const LawEntry& Restrainer::hook_entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "hook",
      .formula = "tension `T = k·(o − slack)` when positive; `F = −T`",
      .source = "tension gap (OpenSees ElasticPPGap used as a hook)",
      .parameters = {{"stiffness", Range::positive, "F/L", "k"},
                     {"slack", Range::non_negative, "L", "(default 0)"}},
      .required = {"stiffness"},
      .traits = {.role = LinkRole::tension, .penalty = false},
      .example = {{"stiffness", 5e7}, {"slack", 0.02}},
      .make = [](const LawSpec& law, const LawSource&) { return make_restrainer(law); }};
  return entry;
}

}  // namespace pound::links
