#include "links/extended_penalty.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"
#include "links/law_registry.hpp"

namespace pound::links {

ExtendedPenalty::ExtendedPenalty(Numbers numbers) : numbers_(numbers) {}

ExtendedPenalty::Numbers ExtendedPenalty::automatic(const LinkContext& c, double tolerance,
                                                    double eta) {
  const double k1 = c.fixed_i ? 0.0 : c.stiffness_i, k2 = c.fixed_j ? 0.0 : c.stiffness_j;
  const double m1 = c.fixed_i ? 0.0 : c.mass_i, m2 = c.fixed_j ? 0.0 : c.mass_j;
  const double alpha0 = std::max(k1, k2) / tolerance;
  const double alpha2 = alpha0 * (m1 + m2) / (k1 + k2);
  return {alpha0, 2.0 * eta * std::sqrt(alpha0 * alpha2), alpha2};
}

LawResponse ExtendedPenalty::set_trial(const LinkKinematics& trial) {
  const double force = numbers_.alpha0 * trial.penetration +
                       numbers_.alpha1 * trial.penetration_rate +
                       numbers_.alpha2 * trial.penetration_acceleration;
  // In contact the force may hold past delta = 0 while positive (released only when it would
  // pull); out of contact it needs penetration. No condition on the rate: it would leave the
  // condensed Newton equation without a solution near a grazing contact.
  // Touched at an earlier iterate of this step, it is held as if committed: a stiff dashpot's
  // alpha1 v at touch can push the pair back past delta = 0 within the step, and the contact
  // would then be off at every iterate that applies its force and on at every one that does not
  // (no solution: Newton failed at first touch with the default eta between bare masses).
  trial_contact_ = force > 0.0 && (committed_contact_ || touched_ || trial.penetration > 0.0);
  touched_ = touched_ || trial_contact_;
  if (!trial_contact_) return {};
  return {.force = force,
          .stiffness = numbers_.alpha0,
          .damping = numbers_.alpha1,
          .mass = numbers_.alpha2};
}

const LawEntry& ExtendedPenalty::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "extended_penalty",
      .formula = "`R = α0·δ + α1·δ̇ + α2·δ̈`, released when R would turn tensile",
      .source = "Suzuki & Toi (1987)",
      .parameters = {{"alpha0", Range::positive, "F/L", "spring; default max(k1, k2) / tolerance"},
                     {"alpha1", Range::non_negative, "F·T/L",
                      "dashpot; default 2·eta·√(alpha0·alpha2)"},
                     {"alpha2", Range::non_negative, "M",
                      "mass; default alpha0·(m1 + m2)/(k1 + k2)"},
                     {"tolerance", Range::positive, "-",
                      "e*, the tolerated penetration over the adjacent elements' strain (default "
                      "1e-3)"},
                     {"eta", Range::non_negative, "-", "damping factor of alpha1 (default 1)"}},
      .traits = {.inertia = true},
      .example = {{"alpha0", 1e9}, {"alpha2", 1e4}},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double tolerance = law.number("tolerance").value_or(1e-3);
        const double eta = law.number("eta").value_or(1.0);
        const std::optional<double> alpha0 = law.number("alpha0"), alpha1 = law.number("alpha1"),
                                    alpha2 = law.number("alpha2");
        return [=](const LinkContext& context) {
          Numbers numbers{alpha0.value_or(0.0), 0.0, alpha2.value_or(0.0)};
          if (!alpha0 || !alpha2) {
            const Numbers found = automatic(context, tolerance, eta);
            if (!(found.alpha0 > 0.0) || !std::isfinite(found.alpha2))
              throw InputError(where.file, where.path,
                               "extended_penalty cannot take its numbers from the model: no "
                               "stiffness at either contact node; give 'alpha0' and 'alpha2'");
            if (!alpha0) numbers.alpha0 = found.alpha0;
            // eq. 29 with the alpha0 actually used
            if (!alpha2) numbers.alpha2 = found.alpha2 * numbers.alpha0 / found.alpha0;
          }
          numbers.alpha1 = alpha1.value_or(2.0 * eta * std::sqrt(numbers.alpha0 * numbers.alpha2));
          return std::make_unique<ExtendedPenalty>(numbers);
        };
      }};
  return entry;
}

}  // namespace pound::links
