#include "links/backfill.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

Backfill::Backfill(double initial_stiffness, double ultimate_force, double ultimate_deformation,
                   double stem_stiffness)
    : stiffness_(initial_stiffness),
      ultimate_force_(ultimate_force),
      ultimate_deformation_(ultimate_deformation),
      curvature_(hyperbola_curvature(initial_stiffness, ultimate_force, ultimate_deformation)),
      stem_stiffness_(stem_stiffness) {
  if (!(initial_stiffness > 0.0 && ultimate_force > 0.0 && ultimate_deformation > 0.0 &&
        stem_stiffness >= 0.0 && std::isfinite(stem_stiffness)))
    throw std::invalid_argument("backfill needs positive K, F_ult and delta_ult, and k_s >= 0");
  if (!(curvature_ > 0.0))
    throw std::invalid_argument("backfill needs F_ult / K < delta_ult (hyperbola D > 0)");
}

LawResponse Backfill::envelope(double penetration) const {
  if (!(penetration > 0.0)) return {};
  if (penetration > ultimate_deformation_) return {.force = ultimate_force_};
  const double denominator = 1.0 + curvature_ * penetration;
  return {.force = stiffness_ * penetration / denominator,
          .stiffness = stiffness_ / (denominator * denominator)};
}

LawResponse Backfill::set_trial(const LinkKinematics& trial) {
  const double delta = trial.penetration;
  trial_permanent_ = committed_permanent_;
  if (delta <= committed_permanent_ && stem_stiffness_ > 0.0) {  // held where it was pushed
    trial_contact_ = false;
    return {.force = stem_stiffness_ * (delta - committed_permanent_),
            .stiffness = stem_stiffness_};
  }
  const double elastic = stiffness_ * (delta - committed_permanent_);
  trial_contact_ = elastic > 0.0;
  if (!trial_contact_) return {};  // the gap left by the permanent deformation: no tension
  // Inside the backbone: unloading/reloading with K. The backbone is concave with slopes <= K,
  // so the line K (delta - p) meets it only at delta_max; past it the soil deforms further.
  const LawResponse backbone = envelope(delta);
  if (elastic < backbone.force) return {.force = elastic, .stiffness = stiffness_};
  trial_permanent_ = delta - backbone.force / stiffness_;
  return backbone;
}

void Backfill::commit() {
  committed_permanent_ = trial_permanent_;
  committed_contact_ = trial_contact_;
}

void Backfill::revert() {
  trial_permanent_ = committed_permanent_;
  trial_contact_ = committed_contact_;
}

const LawEntry& Backfill::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "backfill",
      .formula =
          "compression only: `F = K·δ/(1 + D·δ)` up to δ_ult, `F_ult` beyond, "
          "`D = K/F_ult − 1/δ_ult > 0`; unloads with K, leaving a gap, never tensile; with "
          "`stem_stiffness` k_s, `F = k_s·(δ − p)` for δ < p (the wall held toward the span "
          "where it was last pushed, p the soil's permanent deformation)",
      .source =
          "abutment backfill, hyperbolic force-displacement: Shamsabadi et al. (2007, "
          "2010); Caltrans SDC",
      .parameters = {{"initial_stiffness", Range::positive, "F/L", "K_max"},
                     {"ultimate_force", Range::positive, "F", "F_ult, the passive capacity"},
                     {"ultimate_deformation", Range::positive, "L",
                      "δ_ult at which F_ult is reached, > F_ult / K_max"},
                     {"stem_stiffness", Range::positive, "F/L",
                      "k_s, the hold on the wall toward the span (δ < p); none: free that way "
                      "(girder_bridge sets K_max)"}},
      .required = {"initial_stiffness", "ultimate_force", "ultimate_deformation"},
      .traits = {.penalty = false},
      .example = {{"initial_stiffness", 2.87e7},
                  {"ultimate_force", 4.06e5},
                  {"ultimate_deformation", 0.085}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double k = *law.number("initial_stiffness");
        const double ultimate_force = *law.number("ultimate_force");
        const double ultimate_deformation = *law.number("ultimate_deformation");
        const double stem = law.number("stem_stiffness").value_or(0.0);
        if (!(hyperbola_curvature(k, ultimate_force, ultimate_deformation) > 0.0))
          throw InputError(
              where.file, where.path,
              fmt::format("backfill: ultimate_force / initial_stiffness = {} must be "
                          "below ultimate_deformation = {} (the hyperbola through "
                          "(delta_ult, F_ult) needs D = K / F_ult - 1 / delta_ult > 0)",
                          ultimate_force / k, ultimate_deformation));
        return [=](const LinkContext&) {
          return std::make_unique<Backfill>(k, ultimate_force, ultimate_deformation, stem);
        };
      }};
  return entry;
}

}  // namespace pound::links
