#include "links/kelvin_voigt.hpp"

#include <cmath>

#include "links/law_registry.hpp"
#include "links/restitution.hpp"
#include "links/restitution_calibration.hpp"

namespace pound::links {

KelvinVoigt::KelvinVoigt(double stiffness, double damping, bool clip_tension)
    : stiffness_(stiffness), damping_(damping), clip_tension_(clip_tension) {}

LawResponse KelvinVoigt::set_trial(const LinkKinematics& trial) {
  trial_contact_ = trial.penetration > 0.0;
  if (!trial_contact_) return {};
  const double force = stiffness_ * trial.penetration + damping_ * trial.penetration_rate;
  if (clip_tension_ && force < 0.0) return {};
  return {.force = force, .stiffness = stiffness_, .damping = damping_};
}

const LawEntry& KelvinVoigt::entry() {
  using Range = LawParameter::Range;
  static const LawEntry entry{
      .name = "kelvin_voigt",
      .formula =
          "`F = k·δ + c·δ̇` for δ > 0; from e: `c = 2ξ·√(k·m_eff)`, "
          "`ξ = −ln e / √(π² + ln² e)`",
      .source = "Anagnostopoulos (1988)",
      .parameters = {{"stiffness", Range::positive, "F/L", "k"},
                     {"damping", Range::non_negative, "F·T/L", "c"},
                     restitution_parameter(),
                     effective_mass_parameter()},
      .choices = {{"tension",
                   {"clip", "allow"},
                   "clip: a tensile force is set to 0; allow: the force may pull near separation"},
                  calibration_choice()},
      .required = {"stiffness"},
      .exactly_one_of = {{"damping", "restitution"}},
      .excludes = {{"damping", {"mass"}}},
      .example = {{"stiffness", 1e9}, {"restitution", 0.6}},
      .calibration = RestitutionCalibration{.unit_law =
                                                [](double ratio, const LawSpec& law) {
                                                  return std::make_unique<KelvinVoigt>(
                                                      1.0, 2.0 * ratio,
                                                      law.choice("tension", "clip") == "clip");
                                                },
                                            .published = kelvin_voigt_damping_ratio},
      .make = [](const LawSpec& law, const LawSource& where) -> LawFactory {
        const double k = *law.number("stiffness");
        const bool clip = law.choice("tension", "clip") == "clip";
        const std::optional<double> damping = law.number("damping");
        const double ratio = damping ? 0.0 : calibrated_damping(KelvinVoigt::entry(), law, where);
        return [=](const LinkContext& context) -> std::unique_ptr<LinkLaw> {
          const double c =
              damping ? *damping : 2.0 * ratio * std::sqrt(k * effective_mass(law, where, context));
          return std::make_unique<KelvinVoigt>(k, c, clip);
        };
      }};
  return entry;
}

}  // namespace pound::links
