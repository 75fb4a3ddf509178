#include "links/takeda.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {
namespace {

int sign_of(double value) { return value > 0.0 ? 1 : -1; }

// The first rule of the modified Takeda skeleton that `p` breaks, as the parameter it is about
// and what is expected (the entry's ranges have already checked each number on its own).
struct Violation {
  std::string parameter, expected;
};

std::optional<Violation> violation(const Takeda::Parameters& p) {
  if (!(p.stiffness > 0.0) || !(p.yield_force > 0.0) || !(p.cracking_force >= 0.0))
    return Violation{"stiffness",
                     "the stiffness and the yield force must be > 0, the cracking force >= 0"};
  if (!(p.hardening_ratio >= 0.0 && p.hardening_ratio < 1.0))
    return Violation{"hardening_ratio", fmt::format("the hardening ratio must be in [0, 1), got {}",
                                                    p.hardening_ratio)};
  if (!(p.unloading_exponent >= 0.0 && p.unloading_exponent < 1.0))
    return Violation{
        "unloading_exponent",
        fmt::format("the unloading exponent must be in [0, 1), got {}", p.unloading_exponent)};
  if (!(p.reloading_factor >= 0.0 && p.reloading_factor <= 1.0))
    return Violation{
        "reloading_factor",
        fmt::format("the reloading factor must be in [0, 1], got {}", p.reloading_factor)};
  if (p.cracking_force == 0.0) return std::nullopt;  // bilinear skeleton
  if (!(p.cracking_force < p.yield_force))
    return Violation{"cracking_force",
                     fmt::format("the cracking force must be below the yield force {}, got {}",
                                 p.yield_force, p.cracking_force)};
  const double elastic_yield = p.yield_force / p.stiffness;
  if (!(p.yield_deformation > elastic_yield))
    return Violation{
        "yield_deformation",
        fmt::format("the yield deformation must exceed yield_force / stiffness = {} (the cracked "
                    "branch is softer than the initial stiffness), got {}",
                    elastic_yield, p.yield_deformation)};
  const double cracked =
      (p.yield_force - p.cracking_force) / (p.yield_deformation - p.cracking_force / p.stiffness);
  const double post_yield = p.hardening_ratio * p.yield_force / p.yield_deformation;
  if (post_yield > cracked)
    return Violation{
        "hardening_ratio",
        fmt::format("the post-yield slope r F_y / d_y = {} must not exceed the cracked slope "
                    "(F_y - F_c) / (d_y - F_c / k0) = {} (a concave skeleton), got r = {}",
                    post_yield, cracked, p.hardening_ratio)};
  return std::nullopt;
}

}  // namespace

Takeda::Takeda(const Parameters& p) {
  if (const auto broken = violation(p))
    throw std::invalid_argument("takeda: " + broken->parameter + ": " + broken->expected);
  const bool trilinear = p.cracking_force > 0.0;
  k0_ = p.stiffness;
  yield_force_ = p.yield_force;
  yield_deformation_ = trilinear ? p.yield_deformation : p.yield_force / p.stiffness;
  cracking_force_ = trilinear ? p.cracking_force : p.yield_force;
  cracking_deformation_ = trilinear ? p.cracking_force / p.stiffness : yield_deformation_;
  cracked_slope_ =
      trilinear ? (yield_force_ - cracking_force_) / (yield_deformation_ - cracking_deformation_)
                : k0_;
  post_yield_slope_ = p.hardening_ratio * yield_force_ / yield_deformation_;
  alpha_ = p.unloading_exponent;
  beta_ = p.reloading_factor;
  // At rest: on the elastic line toward the positive cracking point (a reversal at its start
  // reloads toward the negative one, rule 4).
  committed_.slope = k0_;
  committed_.peak[0] = committed_.peak[1] = cracking_deformation_;
  committed_.line = {0.0, cracking_deformation_, cracking_force_};
  trial_ = committed_;
}

double Takeda::skeleton_force(double deformation) const {
  const double size = std::abs(deformation);
  double force = k0_ * size;
  if (size > yield_deformation_)
    force = yield_force_ + post_yield_slope_ * (size - yield_deformation_);
  else if (size > cracking_deformation_)
    force = cracking_force_ + cracked_slope_ * (size - cracking_deformation_);
  return std::copysign(force, deformation);
}

double Takeda::skeleton_slope(double deformation) const {
  const double size = std::abs(deformation);
  if (size > yield_deformation_) return post_yield_slope_;
  return size > cracking_deformation_ ? cracked_slope_ : k0_;
}

LawResponse Takeda::set_trial(const LinkKinematics& trial) {
  trial_ = committed_;
  // Each move ends at the goal or at a branch point; a path meets at most a few of them, so a
  // bound on the moves only guards against a broken invariant.
  for (int move = 0; trial_.deformation != trial.penetration && move < 64; ++move)
    advance(trial_, trial.penetration);
  return {.force = trial_.force, .stiffness = trial_.slope};
}

void Takeda::advance(State& state, double goal) const {
  const int direction = goal > state.deformation ? 1 : -1;
  switch (state.branch) {
    case Branch::skeleton:
      along_skeleton(state, goal, direction);
      break;
    case Branch::reloading:
      along_line(state, goal, direction);
      break;
    case Branch::unloading:
      along_unloading(state, goal, direction);
      break;
  }
  // Off the skeleton the path stays inside the peaks (rules 2-4), so this raises a peak only
  // along the skeleton or on arriving at a yield-point target.
  double& peak = state.peak[index(sign_of(state.deformation))];
  peak = std::max(peak, std::abs(state.deformation));
}

// Rule 1, or a reversal on the skeleton (rule 2).
void Takeda::along_skeleton(State& state, double goal, int direction) const {
  if (direction != sign_of(state.deformation)) return start_unloading(state);
  state.deformation = goal;
  state.force = skeleton_force(goal);
  state.slope = skeleton_slope(goal);
}

// A reloading line toward its target, then the skeleton (rule 4); reversed, rule 2.
void Takeda::along_line(State& state, double goal, int direction) const {
  const Line& line = state.line;
  const int side = sign_of(line.target);
  if (direction != side) {
    if (state.deformation != line.start) return start_unloading(state);
    state.line = reloading_line(state, line.start, direction);
    return;
  }
  state.slope = line.slope();
  if ((goal - line.target) * side <= 0.0) {
    state.deformation = goal;
    state.force = line.slope() * (goal - line.start);
    return;
  }
  state.deformation = line.target;
  state.force = line.target_force;
  state.branch = Branch::skeleton;
}

// Rule 2 away from the departure point, rule 3 back toward it, rule 4 past zero force.
void Takeda::along_unloading(State& state, double goal, int direction) const {
  const int side = sign_of(state.departure_force);
  const double slope = state.unloading_slope;
  state.slope = slope;
  const double end = direction == side
                         ? state.departure
                         : state.departure - state.departure_force / slope;  // zero force
  if ((goal - end) * direction <= 0.0) {
    state.deformation = goal;
    state.force = state.departure_force + slope * (goal - state.departure);
    return;
  }
  state.deformation = end;
  if (direction == side) {
    state.force = state.departure_force;
    state.branch = state.departed_skeleton ? Branch::skeleton : Branch::reloading;
    return;
  }
  state.force = 0.0;
  state.line = reloading_line(state, end, direction);
  state.branch = Branch::reloading;
}

std::optional<double> Takeda::stored_energy(double force, double /*deformation*/) const {
  if (force == 0.0) return 0.0;
  State state = committed_;
  if (state.branch != Branch::unloading) start_unloading(state);
  return force * force / (2.0 * state.unloading_slope);
}

void Takeda::start_unloading(State& state) const {
  const int side = sign_of(state.force);
  double slope = unloading_stiffness(state, side);
  state.departed_skeleton = state.branch == Branch::skeleton;
  // From the skeleton the secant (at most k0) keeps zero force on T's side of the origin; from a
  // reloading line its own slope keeps it past the line's start, and a secant to the origin
  // there would grow without bound near d = 0 (OpenSees' Hysteretic unloads at k0 there).
  if (state.departed_skeleton && state.deformation * side > 0.0)
    slope = std::max(slope, state.force / state.deformation);
  if (!state.departed_skeleton) slope = std::max(slope, state.line.slope());
  state.departure = state.deformation;
  state.departure_force = state.force;
  state.unloading_slope = slope;
  state.branch = Branch::unloading;
}

double Takeda::unloading_stiffness(const State& state, int side) const {
  const double peak = state.peak[index(side)];
  if (peak > yield_deformation_)
    return yield_force_ / yield_deformation_ * std::pow(yield_deformation_ / peak, alpha_);
  if (peak > cracking_deformation_)
    return (skeleton_force(peak) + cracking_force_) / (peak + cracking_deformation_);
  return k0_;
}

Takeda::Line Takeda::reloading_line(const State& state, double start, int side) const {
  const double peak = state.peak[index(side)];
  const bool yielded = peak > yield_deformation_;
  const bool other_yielded = state.peak[index(-side)] > yield_deformation_;
  double target = peak;
  if (yielded) {
    const double shifted = peak - beta_ * (peak - yield_deformation_);
    if (start * side < shifted) target = shifted;
  } else if (other_yielded) {
    target = yield_deformation_;
  }
  return {start, side * target, skeleton_force(side * target)};
}

const LawEntry& Takeda::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "takeda",
      .formula =
          "trilinear skeleton `k0` to `(F_c, F_c/k0)`, to `(F_y, δ_y)`, then `r·F_y/δ_y` "
          "(bilinear without `cracking_force`); unloading `k_y·(δ_y/δ_p)^α` after yield "
          "(`k_y = F_y/δ_y`, δ_p the peak on the side it unloads from, each side its own), "
          "toward the opposite cracking point before yield; "
          "past zero force reloading toward the opposite peak moved back `β·(δ_p − δ_y)` (the "
          "yield point if that side has not yielded), then the skeleton; inner loops return "
          "along the unloading line",
      .source =
          "modified Takeda: Takeda, Sozen & Nielsen (1970), J. Struct. Div. ASCE 96(ST12); "
          "unloading exponent of Otani (1974, 1981); reloading factor β of Ruaumoko (Carr)",
      .parameters =
          {{"stiffness", Range::positive, "F/L", "k0, the initial (uncracked) stiffness"},
           {"cracking_force", Range::positive, "F",
            "F_c < F_y, the force at cracking (at δ_c = F_c/k0); leave out for a bilinear "
            "skeleton"},
           {"yield_force", Range::positive, "F", "F_y"},
           {"yield_deformation", Range::positive, "L",
            "δ_y > F_y/k0, the deformation at yield (with cracking_force; F_y/k0 without)"},
           {"hardening_ratio", Range::fraction, "-",
            "r, post-yield slope / (F_y/δ_y), no steeper than the cracked branch (default 0)"},
           {"unloading_exponent", Range::fraction, "-",
            "α, 0 <= α < 1: unloading stiffness `k_y·(δ_y/δ_p)^α` after yield (default 0.4, "
            "Takeda et al. 1970)"},
           {"reloading_factor", Range::non_negative, "-",
            "β, 0 <= β <= 1: reloading aims β times the peak's plastic part back toward the "
            "yield point (default 0: at the previous peak)"}},
      .required = {"stiffness", "yield_force"},
      .needs = {{"cracking_force", {"yield_deformation"}},
                {"yield_deformation", {"cracking_force"}}},
      .traits = {.role = LinkRole::spring, .penalty = false},
      .example = {{"stiffness", 1e8},
                  {"cracking_force", 2e5},
                  {"yield_force", 6e5},
                  {"yield_deformation", 0.015},
                  {"hardening_ratio", 0.02},
                  {"unloading_exponent", 0.4}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const Parameters parameters{
            .stiffness = *law.number("stiffness"),
            .cracking_force = law.number("cracking_force").value_or(0.0),
            .yield_force = *law.number("yield_force"),
            .yield_deformation = law.number("yield_deformation").value_or(0.0),
            .hardening_ratio = law.number("hardening_ratio").value_or(0.0),
            .unloading_exponent = law.number("unloading_exponent").value_or(0.4),
            .reloading_factor = law.number("reloading_factor").value_or(0.0)};
        if (const auto broken = violation(parameters))
          throw InputError(where.file, where.path + "/" + broken->parameter,
                           "takeda: " + broken->expected);
        return [=](const LinkContext&) { return std::make_unique<Takeda>(parameters); };
      }};
  return entry;
}

}  // namespace pound::links
