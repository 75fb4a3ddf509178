#include "builder/law_catalog.hpp"

namespace pound::builder {
namespace {
using Range = LawParameter::Range;

std::vector<LawType> make_catalog() {
  const LawParameter restitution{"restitution", Range::restitution,
                                 "target coefficient of restitution e, 0 < e <= 1"};
  const LawChoice calibration{
      "calibration",
      {"exact", "published"},
      "how 'restitution' becomes damping: exact (the two-mass impact reaches e) or published (the "
      "source's formula, approximate)"};
  const LawParameter mass{"mass", Range::positive,
                          "effective mass m1 m2 / (m1 + m2) [M]; default: from the model's lumped "
                          "masses at the two nodes"};
  return {
      {.type = "gap_spring",
       .formula = "F = k delta for delta > 0",
       .source = "Kawashima (1980); the linear spring / penalty of Maison & Kasai",
       .parameters = {{"stiffness", Range::positive, "k [F/L]"},
                      {"stiffness_ratio", Range::positive,
                       "k over E A / h of the softer adjacent element (rod_pair only)"}},
       .exactly_one_of = {{"stiffness", "stiffness_ratio"}},
       .generator_only = {"stiffness_ratio"}},
      {.type = "kelvin_voigt",
       .formula = "F = k delta + c delta_dot for delta > 0; c = 2 xi sqrt(k m_eff), "
                  "xi = -ln e / sqrt(pi^2 + ln^2 e)",
       .source = "Anagnostopoulos (1988)",
       .parameters = {{"stiffness", Range::positive, "k [F/L]"},
                      {"damping", Range::non_negative, "c [F T/L]"},
                      restitution,
                      mass},
       .choices = {{"tension",
                    {"clip", "allow"},
                    "clip: a tensile force is set to 0; allow: the force may pull near separation"},
                   calibration},
       .required = {"stiffness"},
       .exactly_one_of = {{"damping", "restitution"}},
       .excludes = {{"damping", {"mass"}}}},
      {.type = "hertz",
       .formula = "F = k_h delta^1.5 for delta > 0",
       .source = "Hertz (1882); Davis (1992)",
       .parameters = {{"stiffness", Range::positive, "k_h [F/L^1.5]"}},
       .required = {"stiffness"}},
      {.type = "hertz_damp",
       .formula = "F = k_h delta^1.5 (1 + xi_bar delta_dot / v0); xi_bar = 8 (1 - e) / (5 e)",
       .source = "Muthukumar & DesRoches (2006); damping from e after Ye, Li & Zhu (2009)",
       .parameters = {{"stiffness", Range::positive, "k_h [F/L^1.5]"},
                      {"damping_ratio", Range::non_negative, "xi_bar [-]"},
                      restitution},
       .choices = {calibration},
       .required = {"stiffness"},
       .exactly_one_of = {{"damping_ratio", "restitution"}}},
      {.type = "jankowski",
       .formula = "F = beta delta^1.5 + c delta_dot approaching, beta delta^1.5 separating; "
                  "c = 2 xi sqrt(beta sqrt(delta) m_eff)",
       .source = "Jankowski (2005)",
       .parameters = {{"stiffness", Range::positive, "beta [F/L^1.5]"},
                      {"damping_ratio", Range::non_negative, "xi [-]"},
                      restitution,
                      mass},
       .choices = {calibration},
       .required = {"stiffness"},
       .exactly_one_of = {{"damping_ratio", "restitution"}}},
      {.type = "bilinear_impact",
       .formula = "hysteretic loop between F = K1 dy + K2 (delta - dy) and F = K2 delta, slope K1 "
                  "inside; from e: calibrated at every impact so the two-mass restitution is e",
       .source = "Muthukumar (2003); OpenSees ImpactMaterial",
       .parameters = {{"stiffness", Range::positive,
                       "k_h of the Hertz law it approximates [F/L^1.5]"},
                      restitution,
                      {"yield_fraction", Range::fraction, "a = delta_y / delta_m (default 0.1)"},
                      mass,
                      {"k1", Range::positive, "K1 [F/L]"},
                      {"k2", Range::positive, "K2 [F/L]"},
                      {"yield_penetration", Range::positive, "delta_y [L]"}},
       .exactly_one_of = {{"restitution", "k1"}},
       .needs = {{"restitution", {"stiffness"}}, {"k1", {"k2", "yield_penetration"}}},
       .excludes = {{"k1", {"stiffness", "yield_fraction", "mass"}}}},
      {.type = "extended_penalty",
       .formula = "R = alpha0 delta + alpha1 delta_dot + alpha2 delta_ddot; released when R "
                  "would turn tensile",
       .source = "Suzuki & Toi (1987)",
       .parameters = {{"alpha0", Range::positive, "spring [F/L]; default max(k1, k2) / tolerance"},
                      {"alpha1", Range::non_negative,
                       "dashpot [F T/L]; default 2 eta sqrt(alpha0 alpha2)"},
                      {"alpha2", Range::non_negative,
                       "mass [M]; default alpha0 (m1 + m2) / (k1 + k2)"},
                      {"tolerance", Range::positive,
                       "e*, the tolerated penetration over the adjacent elements' strain "
                       "(default 1e-3)"},
                      {"eta", Range::non_negative, "damping factor of alpha1 (default 1)"}}},
      {.type = "restrainer",
       .formula = "tension T = k (opening - slack - p) when positive, yield at T_y + H p; F = -T",
       .source = "cable restrainers (Caltrans SDC; FHWA)",
       .parameters = {{"stiffness", Range::positive, "k [F/L]"},
                      {"slack", Range::non_negative, "[L] (default 0)"},
                      {"yield_force", Range::positive, "T_y [F] (default: elastic)"},
                      {"hardening_ratio", Range::fraction, "post-yield stiffness / k (default 0)"}},
       .required = {"stiffness"},
       .needs = {{"hardening_ratio", {"yield_force"}}}},
      {.type = "hook",
       .formula = "tension T = k (opening - slack) when positive; F = -T",
       .source = "tension gap (OpenSees ElasticPPGap used as a hook)",
       .parameters = {{"stiffness", Range::positive, "k [F/L]"},
                      {"slack", Range::non_negative, "[L] (default 0)"}},
       .required = {"stiffness"}},
      // Structural springs: links with gap 0 whose laws act in both directions.
      {.type = "elastic_spring",
       .formula = "F = k delta in compression and tension",
       .source = "linear bearing / abutment spring (Caltrans SDC; OpenSees Elastic material)",
       .parameters = {{"stiffness", Range::positive, "k [F/L]"}},
       .required = {"stiffness"}},
      {.type = "bilinear_spring",
       .formula = "F = k (delta - p), |F - H p| <= F_y, H = b k / (1 - b): elastic-plastic in "
                  "both directions with kinematic hardening, post-yield slope b k",
       .source = "bilinear hysteretic model (OpenSees Steel01 without isotropic hardening; "
                 "Caltrans SDC bilinear bearing)",
       .parameters = {{"stiffness", Range::positive, "elastic stiffness k [F/L]"},
                      {"yield_force", Range::positive, "F_y [F]"},
                      {"hardening_ratio", Range::fraction,
                       "b, post-yield stiffness / k, 0 <= b < 1 (default 0)"}},
       .required = {"stiffness", "yield_force"}},
      {.type = "backfill",
       .formula = "compression only: F = K delta / (1 + D delta) up to delta_ult, F_ult beyond, "
                  "D = K / F_ult - 1 / delta_ult > 0; unloading with K leaves a gap of the "
                  "permanent deformation, never tensile",
       .source = "abutment backfill, hyperbolic force-displacement: Shamsabadi et al. (2007, "
                 "2010); Caltrans SDC",
       .parameters = {{"initial_stiffness", Range::positive, "K_max [F/L]"},
                      {"ultimate_force", Range::positive, "F_ult, the passive capacity [F]"},
                      {"ultimate_deformation", Range::positive,
                       "delta_ult at which F_ult is reached [L], > F_ult / K_max"}},
       .required = {"initial_stiffness", "ultimate_force", "ultimate_deformation"}},
  };
}

}  // namespace

const std::vector<LawType>& law_catalog() {
  static const std::vector<LawType> catalog = make_catalog();
  return catalog;
}

const LawType* find_law_type(const std::string& type) {
  for (const LawType& law : law_catalog())
    if (law.type == type) return &law;
  return nullptr;
}

std::vector<std::string> law_type_names() {
  std::vector<std::string> names;
  for (const LawType& law : law_catalog()) names.push_back(law.type);
  return names;
}

}  // namespace pound::builder
