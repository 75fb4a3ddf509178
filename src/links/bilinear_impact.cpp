#include "links/bilinear_impact.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

BilinearImpact::BilinearImpact(Calibration calibration) : calibration_(calibration) {}
BilinearImpact::BilinearImpact(Loop loop) : committed_loop_(loop), trial_loop_(loop) {}

BilinearImpact::Calibrated BilinearImpact::calibrate(const Calibration& c, double velocity) {
  const double e2 = c.restitution * c.restitution, a = c.yield_fraction;
  const double energy = 0.5 * c.effective_mass * velocity * velocity;
  const double peak = std::pow(2.0 * energy * (1.0 + e2) / (2.0 * c.hertz_stiffness), 0.4);
  const double dissipated = (1.0 - e2) * energy;
  const double k_eff = c.hertz_stiffness * std::sqrt(peak);
  // d/dv0: peak ~ v0^0.8, k_eff ~ v0^0.4, dissipated ~ v0^2, dissipated / peak^2 ~ v0^0.4.
  const double excess = dissipated / (peak * peak);
  Calibrated out;
  out.loop = {k_eff + excess / a, k_eff - excess / (1.0 - a), a * peak};
  const double d_k_eff = 0.4 * k_eff / velocity, d_excess = 0.4 * excess / velocity;
  out.d_velocity = {d_k_eff + d_excess / a, d_k_eff - d_excess / (1.0 - a),
                    0.8 * a * peak / velocity};
  return out;
}

LawResponse BilinearImpact::set_trial(const LinkKinematics& trial) {
  trial_ = trial;
  trial_force_ = 0.0;
  if (!(trial.penetration > 0.0)) return {};
  // Loop and history: the committed ones while in contact; at a new impact, calibrated from v0
  // and starting from zero force at delta = 0.
  Loop loop = committed_loop_, d_loop{0.0, 0.0, 0.0};
  double start_force = committed_force_, start_penetration = onset_.committed().penetration;
  OnsetVelocity v0{};
  if (!onset_.in_contact()) {
    start_force = 0.0;
    start_penetration = 0.0;
    if (calibration_) {
      v0 = onset_.at(trial);
      if (!(v0.velocity > 0.0)) v0 = {1e-12, 0.0, 0.0};  // at rest: calibrate for a tiny impact
      const Calibrated c = calibrate(*calibration_, v0.velocity);
      loop = c.loop;
      d_loop = c.d_velocity;
    }
  }
  trial_loop_ = loop;
  const double delta = trial.penetration;
  // Elastic move with K1 from the start, bounded by the two lines.
  double force = start_force + loop.k1 * (delta - start_penetration);
  double slope = loop.k1, d_force_d_v0 = d_loop.k1 * (delta - start_penetration);
  const double upper =
      loop.k1 * loop.yield_penetration + loop.k2 * (delta - loop.yield_penetration);
  const double lower = loop.k2 * delta;
  if (force > upper) {
    force = upper;
    slope = loop.k2;
    d_force_d_v0 = d_loop.k1 * loop.yield_penetration + loop.k1 * d_loop.yield_penetration +
                   d_loop.k2 * (delta - loop.yield_penetration) -
                   loop.k2 * d_loop.yield_penetration;
  } else if (force < lower) {
    force = lower;
    slope = loop.k2;
    d_force_d_v0 = d_loop.k2 * delta;
  }
  trial_force_ = std::max(force, 0.0);
  return {.force = trial_force_,
          .stiffness = slope + d_force_d_v0 * v0.d_penetration,
          .damping = d_force_d_v0 * v0.d_rate};
}

void BilinearImpact::commit() {
  onset_.commit(trial_, trial_.penetration > 0.0);
  committed_force_ = trial_force_;
  committed_loop_ = trial_loop_;
}

void BilinearImpact::revert() {
  trial_ = onset_.committed();
  trial_force_ = committed_force_;
  trial_loop_ = committed_loop_;
}

const LawEntry& BilinearImpact::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "bilinear_impact",
      .formula =
          "hysteretic loop between `F = K1·δy + K2·(δ − δy)` and `F = K2·δ`, slope K1 "
          "inside; from e: calibrated at every impact so that the two-mass restitution is e",
      .source = "Muthukumar (2003); OpenSees ImpactMaterial",
      .parameters = {{"stiffness", Range::positive, "F/L^1.5",
                      "k_h of the Hertz law it approximates"},
                     restitution_parameter(),
                     {"yield_fraction", Range::fraction, "-", "a = δy/δm (default 0.1)"},
                     effective_mass_parameter(),
                     {"k1", Range::positive, "F/L", "K1"},
                     {"k2", Range::positive, "F/L", "K2"},
                     {"yield_penetration", Range::positive, "L", "δy"}},
      .exactly_one_of = {{"restitution", "k1"}},
      .needs = {{"restitution", {"stiffness"}}, {"k1", {"k2", "yield_penetration"}}},
      .excludes = {{"k1", {"stiffness", "yield_fraction", "mass"}}},
      .traits = {.stiff_at_first_touch = false, .uses_approach_velocity = true},
      .example = {{"stiffness", 4e10}, {"restitution", 0.6}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        if (law.number("k1")) {
          const Loop loop{*law.number("k1"), *law.number("k2"), *law.number("yield_penetration")};
          return [loop](const LinkContext&) { return std::make_unique<BilinearImpact>(loop); };
        }
        const double k = *law.number("stiffness"), e = *law.number("restitution");
        const double fraction = law.number("yield_fraction").value_or(0.1);
        if ((1.0 - e * e) / (1.0 + e * e) >= 1.0 - fraction)
          throw InputError(where.file, where.path + "/restitution",
                           fmt::format("e = {} cannot be reached with yield_fraction {}: the loop "
                                       "would need K2 <= 0 (raise e or lower yield_fraction)",
                                       e, fraction));
        return [=](const LinkContext& context) {
          return std::make_unique<BilinearImpact>(
              Calibration{k, e, effective_mass(law, where, context), fraction});
        };
      }};
  return entry;
}

}  // namespace pound::links
