// Calibration from a coefficient of restitution, run on the law objects themselves.
#include "links/restitution_calibration.hpp"

#include <gtest/gtest.h>

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <iostream>
#include <limits>

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

// The knob found for e, checked by an independent integration of the unit impact x'' = -F(x, x'):
// Boost.Odeint's adaptive Dormand-Prince at 1e-15, with dense output to locate the release (the
// same to 1e-12 at 1e-13). Jankowski's damping grows as x^(1/4) from first touch: with the
// calibration's RK4 steps growing from 1e-12 by doubling it was 2e-8 off, by 10 % it is 1e-10
// off; at a fixed 1e-3 its knob was 3e-5 off, at 1e-4 (the step before) 2e-6.
double restitution_by_dopri5(LinkLaw& law) {
  namespace odeint = boost::numeric::odeint;
  using Phase = std::array<double, 2>;
  law.set_trial({-std::numeric_limits<double>::min(), 1.0, 0.0});
  law.commit();
  const auto motion = [&law](const Phase& x, Phase& dxdt, double) {
    dxdt[0] = x[1];
    dxdt[1] = -law.set_trial({x[0], x[1], 0.0}).force;
  };
  auto stepper = odeint::make_dense_output(1e-15, 1e-15, odeint::runge_kutta_dopri5<Phase>());
  stepper.initialize(Phase{0.0, 1.0}, 0.0, 1e-12);
  while (stepper.current_time() < 100.0) {
    stepper.do_step(motion);
    const Phase now = stepper.current_state();
    if (now[0] <= 0.0 && stepper.current_time() > 1e-3) {
      // The release, by bisection of the dense output over the last step.
      double before = stepper.previous_time(), after = stepper.current_time();
      Phase at{};
      for (int k = 0; k < 100 && after - before > 1e-15; ++k) {
        const double middle = 0.5 * (before + after);
        stepper.calc_state(middle, at);
        (at[0] > 0.0 ? before : after) = middle;
      }
      stepper.calc_state(after, at);
      return -at[1];
    }
    law.set_trial({now[0], now[1], 0.0});
    law.commit();
  }
  return NAN;
}

TEST(RestitutionCalibration, AnAdaptiveIntegrationOfTheImpactGivesEBack) {
  for (const std::string name : {"hertz_damp", "jankowski"}) {
    const LawEntry& entry = *find_law(name);
    const LawSpec law{name, {}, {{"calibration", "exact"}}};
    for (double e : {0.3, 0.6, 0.9}) {
      const double knob = damping_for_restitution(entry, law, e);
      const double reached = restitution_by_dopri5(*entry.calibration->unit_law(knob, law));
      std::cout << name << " e = " << e << ": knob " << knob << ", Dormand-Prince gives " << reached
                << ", error " << reached - e << "\n";
      EXPECT_NEAR(reached, e, 1e-9) << name;
    }
  }
}

}  // namespace
}  // namespace pound::links
