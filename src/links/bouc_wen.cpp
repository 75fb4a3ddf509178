#include "links/bouc_wen.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

namespace {

// The sharpest knee: z's sub-steps are z_max / (64 n A) of travel.
constexpr double kMostSharpness = 50.0;

// (1 - e^-x) / x and log(1 + x) / x, both 1 at x = 0, accurate for small x.
double one_minus_exp_over(double x) { return x == 0.0 ? 1.0 : -std::expm1(-x) / x; }
double log_one_plus_over(double x) { return x == 0.0 ? 1.0 : std::log1p(x) / x; }

}  // namespace

std::optional<BoucWen::Refusal> BoucWen::refusal(const Parameters& p) {
  if (!(p.stiffness > 0.0))
    return Refusal{"stiffness", fmt::format("must be > 0, got {}", p.stiffness)};
  if (!(p.hardening_ratio >= 0.0 && p.hardening_ratio < 1.0))
    return Refusal{
        "hardening_ratio",
        fmt::format("must be in [0, 1) (1 is an elastic spring), got {}", p.hardening_ratio)};
  if (!(p.sharpness >= 1.0))
    return Refusal{"sharpness",
                   fmt::format("must be >= 1 (below 1 the tangent changes at an unbounded rate "
                               "at every z = 0), got {}",
                               p.sharpness)};
  if (p.sharpness > kMostSharpness)
    return Refusal{
        "sharpness",
        fmt::format("must be <= {:g} (the knee is then as sharp as a bilinear law's to "
                    "within a few per cent of the yield deformation, and the integration's "
                    "sub-steps shrink as 1/n: for a sharper knee use bilinear_spring), "
                    "got {}",
                    kMostSharpness, p.sharpness)};
  if (!(p.amplitude > 0.0))
    return Refusal{"amplitude", fmt::format("must be > 0, got {}", p.amplitude)};
  if (!(p.beta > 0.0))
    return Refusal{"beta", fmt::format("must be > 0 (beta = 0 dissipates nothing, beta < 0 makes "
                                       "loops that create energy), got {}",
                                       p.beta)};
  if (!(p.beta + p.gamma > 0.0))
    return Refusal{"gamma", fmt::format("beta + gamma must be > 0 (otherwise z grows without "
                                        "bound), got beta + gamma = {}",
                                        p.beta + p.gamma)};
  const double saturation = std::pow(p.amplitude / (p.beta + p.gamma), 1.0 / p.sharpness);
  if (!(std::isfinite(saturation) && saturation > 0.0))
    return Refusal{"gamma", fmt::format("z_max = (A / (beta + gamma))^(1/n) = {} is not a finite "
                                        "positive deformation",
                                        saturation)};
  return std::nullopt;
}

BoucWen::Parameters BoucWen::with_yield_force(Parameters p, double yield_force) {
  const double saturation = p.amplitude * yield_force / p.stiffness;
  const double factor = p.amplitude / std::pow(saturation, p.sharpness) / (p.beta + p.gamma);
  p.beta *= factor;
  p.gamma *= factor;
  return p;
}

BoucWen::BoucWen(const Parameters& p)
    : parameters_(p),
      stiffness_(p.stiffness),
      hardening_ratio_(p.hardening_ratio),
      sharpness_(p.sharpness),
      beta_(p.beta),
      gamma_(p.gamma),
      amplitude_(p.amplitude),
      saturation_(std::pow(p.amplitude / (p.beta + p.gamma), 1.0 / p.sharpness)),
      substeps_(saturation_, p.sharpness, p.amplitude, p.beta, p.gamma) {
  if (const std::optional<Refusal> refused = refusal(p))
    throw std::invalid_argument("bouc_wen: " + refused->parameter + " " + refused->reason);
}

double BoucWen::rate(double w, Branch branch) const {
  // |z|^n (beta s + gamma) = A (w / z_max)^n (beta s + gamma) / (beta + gamma), in the scale of
  // z_max so that no power of a small deformation underflows.
  const double power = std::pow(std::abs(w) / saturation_, sharpness_);
  if (branch == Branch::loading) return amplitude_ * (1.0 - power);
  return -amplitude_ * (1.0 + power * (beta_ - gamma_) / (beta_ + gamma_));
}

double BoucWen::slope(double z, double direction) const {
  const double sign = direction * z < 0.0 ? -1.0 : 1.0;  // sgn(d(delta) z), either at z = 0
  const double power = std::pow(std::abs(z) / saturation_, sharpness_);
  return amplitude_ * (1.0 - power * (beta_ * sign + gamma_) / (beta_ + gamma_));
}

double BoucWen::advance(double w, double& travel, Branch branch) const {
  return sharpness_ == 1.0 ? advance_exact(w, travel, branch) : advance_rk4(w, travel, branch);
}

// n = 1: loading w' = A - (beta + gamma) w tends to z_max exponentially; unloading
// w' = -A - (beta - gamma) w reaches 0 after t0 = log(1 + e w / A) / e, e = beta - gamma.
double BoucWen::advance_exact(double w, double& travel, Branch branch) const {
  if (branch == Branch::loading)
    return w - (w - saturation_) * -std::expm1(-(beta_ + gamma_) * travel);
  const double excess = beta_ - gamma_;
  const double to_zero = w / amplitude_ * log_one_plus_over(excess * w / amplitude_);
  if (travel >= to_zero) {
    travel = to_zero;
    return 0.0;
  }
  const double decay = excess * travel;
  return std::max(0.0, w * std::exp(-decay) - amplitude_ * travel * one_minus_exp_over(decay));
}

double BoucWen::rk4_step(double w, double h, Branch branch) const {
  const double k1 = rate(w, branch);
  const double k2 = rate(w + 0.5 * h * k1, branch);
  const double k3 = rate(w + 0.5 * h * k2, branch);
  const double k4 = rate(w + h * k3, branch);
  return w + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// Sub-steps from the committed state, the last one cut where the trial ends: the grid, and so
// the numbers, of a move do not depend on where the trial ends. Near z = 0 |z|^n is not smooth
// (its derivatives of order above n are unbounded there), so the sub-steps shrink in proportion
// to the travel from z = 0 (~ w / A) and RK4 keeps its accuracy on both sides of a crossing.
double BoucWen::advance_rk4(double w, double& travel, Branch branch) const {
  for (double start = 0.0; start < travel;) {
    const double h = std::min(substeps_.at(w), travel - start);
    const double next = rk4_step(w, h, branch);
    if (branch == Branch::unloading && next <= 0.0) {
      // z reaches 0 inside this sub-step: bisect its length (the step is smooth in it).
      double inside = 0.0, beyond = h;
      for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (inside + beyond);
        if (middle <= inside || middle >= beyond) break;
        (rk4_step(w, middle, branch) > 0.0 ? inside : beyond) = middle;
      }
      travel = start + beyond;
      return 0.0;
    }
    // Saturated to the last bit: the rest of the travel changes nothing.
    if (next == w) break;
    w = next;
    start += h;
  }
  return w;
}

double BoucWen::z_at(double penetration) const {
  const double move = penetration - committed_delta_;
  if (move == 0.0 || std::isnan(move)) return move == 0.0 ? committed_z_ : move;
  const double direction = move > 0.0 ? 1.0 : -1.0;
  double travel = std::abs(move);
  double w = std::abs(committed_z_);
  if (committed_z_ * direction < 0.0) {
    double unloaded = travel;
    w = advance(w, unloaded, Branch::unloading);
    if (unloaded == travel) return -direction * w;
    travel -= unloaded;  // through z = 0: the rest is loading the other way
  }
  return direction * advance(w, travel, Branch::loading);
}

LawResponse BoucWen::set_trial(const LinkKinematics& trial) {
  trial_delta_ = trial.penetration;
  trial_z_ = z_at(trial_delta_);
  const double move = trial_delta_ - committed_delta_;
  const double direction = move > 0.0 ? 1.0 : (move < 0.0 ? -1.0 : committed_direction_);
  const double elastic = hardening_ratio_ * stiffness_;
  const double hysteretic = (1.0 - hardening_ratio_) * stiffness_;
  trial_force_ = elastic * trial_delta_ + hysteretic * trial_z_;
  return {.force = trial_force_, .stiffness = elastic + hysteretic * slope(trial_z_, direction)};
}

void BoucWen::commit() {
  if (trial_delta_ != committed_delta_)
    committed_direction_ = trial_delta_ > committed_delta_ ? 1.0 : -1.0;
  committed_delta_ = trial_delta_;
  committed_z_ = trial_z_;
  committed_force_ = trial_force_;
}

void BoucWen::revert() {
  trial_delta_ = committed_delta_;
  trial_z_ = committed_z_;
  trial_force_ = committed_force_;
}

const LawEntry& BoucWen::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "bouc_wen",
      .formula =
          "`F = a·k·δ + (1 − a)·k·z`, `dz/dδ = A − |z|^n·(β·sgn(dδ·z) + γ)`, z from 0: smooth "
          "hysteresis, `|z| → z_max = (A/(β + γ))^(1/n)`, integrated in δ (rate independent)",
      .source =
          "Bouc (1967); Wen (1976), J. Eng. Mech. Div. 102(EM2); OpenSees BoucWen without "
          "degradation",
      .parameters =
          {{"stiffness", Range::positive, "F/L", "k (OpenSees ko): initial stiffness when A = 1"},
           {"hardening_ratio", Range::fraction, "-",
            "a (OpenSees alpha): post-yield / initial stiffness, 0 <= a < 1 (default 0)"},
           {"sharpness", Range::positive, "-",
            "n (OpenSees n), 1 to 50: sharpness of the knee, 1 smooth, 10 or more nearly bilinear"},
           {"beta", Range::positive, "1/L^n",
            "β (OpenSees beta) > 0: unloading is stiffer than loading by 2·β·|z|^n (the loop's "
            "width)"},
           {"gamma", Range::non_negative, "1/L^n",
            "γ (OpenSees gamma): loading slope `dz/dδ = A − (β + γ)·|z|^n`, unloading "
            "`A + (β − γ)·|z|^n` (γ = β: unloading at the initial slope)"},
           {"amplitude", Range::positive, "-", "A (OpenSees Ao): dz/dδ at z = 0 (default 1)"},
           {"yield_force", Range::positive, "F",
            "F_y: the equivalent bilinear yield force k·z_max/A; with it β and γ give only the "
            "loop's shape, both scaled by one factor so that z_max = A·F_y/k (a generator sets "
            "it for pier hinges)"}},
      .required = {"stiffness", "sharpness", "beta", "gamma"},
      .traits = {.role = LinkRole::spring, .penalty = false},
      // z_max = 5 mm: beta + gamma = 1 / z_max^2 for n = 2.
      .example = {{"stiffness", 2e7},
                  {"hardening_ratio", 0.05},
                  {"sharpness", 2.0},
                  {"beta", 2e4},
                  {"gamma", 2e4}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        Parameters parameters{.stiffness = *law.number("stiffness"),
                              .hardening_ratio = law.number("hardening_ratio").value_or(0.0),
                              .sharpness = *law.number("sharpness"),
                              .beta = *law.number("beta"),
                              .gamma = *law.number("gamma"),
                              .amplitude = law.number("amplitude").value_or(1.0)};
        const std::optional<double> yield_force = law.number("yield_force");
        if (yield_force && !refusal(parameters)) {
          parameters = with_yield_force(parameters, *yield_force);
          if (const std::optional<Refusal> refused = refusal(parameters))
            throw InputError(where.file, where.path + "/yield_force",
                             fmt::format("bouc_wen: yield_force {} makes {} {}", *yield_force,
                                         refused->parameter, refused->reason));
        }
        if (const std::optional<Refusal> refused = refusal(parameters))
          throw InputError(where.file, where.path + "/" + refused->parameter,
                           "bouc_wen: " + refused->parameter + " " + refused->reason);
        return [=](const LinkContext&) { return std::make_unique<BoucWen>(parameters); };
      }};
  return entry;
}

}  // namespace pound::links
