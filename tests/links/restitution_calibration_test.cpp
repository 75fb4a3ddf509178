// Calibration from a coefficient of restitution, run on the law objects themselves.
#include "links/restitution_calibration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "core/errors.hpp"
#include "links/gap_spring.hpp"
#include "links/restitution.hpp"

namespace pound::links {
namespace {

// Each calibratable law, with every variant of its choices calibrated exactly: the knob found
// for e gives e back (the bisection stops within 1e-9 of e, or when the knob is known to 1e-12).
TEST(RestitutionCalibration, TheKnobFoundForEReachesE) {
  for (const LawEntry* entry : law_registry()) {
    if (!entry->calibration) continue;
    for (const std::string tension : {"clip", "allow"}) {
      LawSpec law{entry->name, {}, {{"calibration", "exact"}}};
      // Kelvin-Voigt both clipped and allowing tension; the others have no such choice.
      if (entry->name == "kelvin_voigt") {
        law.choices["tension"] = tension;
      } else if (tension == "allow") {
        continue;
      }
      for (double e : {0.3, 0.6, 0.9}) {
        const double knob = damping_for_restitution(*entry, law, e);
        const double reached = impact_restitution(*entry->calibration->unit_law(knob, law));
        std::cout << entry->name << " (" << law.choice("tension", "-") << ") e = " << e << ": knob "
                  << knob << ", reached " << reached << ", error " << reached - e << "\n";
        EXPECT_NEAR(reached, e, 1e-8) << entry->name;
      }
    }
  }
}

// Kelvin-Voigt with tension allowed has a closed form (Anagnostopoulos): xi = -ln e /
// sqrt(pi^2 + ln^2 e). The law's own impact, integrated by RK4 at h = 1e-4 (error ~h^4 per unit
// time), with the dashpot's jumps at contact and release resolved, finds it to the bisection's
// stop at 1e-9 in e (measured: 2e-9 relative in xi).
TEST(RestitutionCalibration, KelvinVoigtAllowingTensionMatchesItsClosedForm) {
  const LawEntry& entry = *find_law("kelvin_voigt");
  const LawSpec law{"kelvin_voigt", {}, {{"tension", "allow"}, {"calibration", "exact"}}};
  for (double e : {0.2, 0.5, 0.8}) {
    const double exact = kelvin_voigt_damping_ratio(e);
    const double found = damping_for_restitution(entry, law, e);
    std::cout << "e = " << e << ": xi " << found << " against " << exact << ", relative error "
              << found / exact - 1.0 << "\n";
    EXPECT_NEAR(found / exact, 1.0, 1e-6);
  }
}

// An undamped law rebounds at the speed it came in.
TEST(RestitutionCalibration, AnElasticLawRestitutesOne) {
  GapSpring spring(1.0);
  const double e = impact_restitution(spring);
  std::cout << "gap spring: e - 1 = " << e - 1.0 << "\n";
  EXPECT_NEAR(e, 1.0, 1e-12);
}

TEST(RestitutionCalibration, PublishedTakesTheSourcesFormulaAndErrorsNameTheRestitution) {
  const LawEntry& entry = *find_law("hertz_damp");
  const LawSpec published{"hertz_damp", {{"restitution", 0.5}}, {{"calibration", "published"}}};
  EXPECT_DOUBLE_EQ(calibrated_damping(entry, published, {"m.json", "/links/3/law"}),
                   hertz_damp_ratio_ye(0.5));
  EXPECT_EQ(damping_for_restitution(entry, published, 1.0), 0.0);
}

}  // namespace
}  // namespace pound::links
