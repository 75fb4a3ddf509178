// Coulomb friction: stick and slip forces, and the consistent (non-symmetric) tangent against
// finite differences in both regimes.
#include "links/coulomb_friction.hpp"

#include <gtest/gtest.h>

#include <iostream>

#include "links/gap_spring.hpp"
#include "links/kelvin_voigt.hpp"

namespace pound::links {
namespace {

CoulombFriction make() {
  return CoulombFriction(std::make_unique<KelvinVoigt>(1e6, 1e3, true), 0.4, {2e5, 500.0, 0.0});
}

// Rows: [R_n, R_t]; columns: normal delta, normal rate, slide, slide rate. Central differences.
double tangent_error(const LinkKinematics& normal, const LinkKinematics& slide) {
  CoulombFriction friction = make();
  friction.set_trial({-1e-4, 0.1, 0.0}, {0.0, 0.0, 0.0});
  friction.commit();
  const FrictionResponse at = friction.set_trial(normal, slide);
  const double analytic[2][4] = {
      {at.normal.stiffness, at.normal.damping, 0.0, 0.0},
      {at.tangential_on_normal.stiffness, at.tangential_on_normal.damping,
       at.tangential_on_slip.stiffness, at.tangential_on_slip.damping}};
  double worst = 0.0;
  for (int variable = 0; variable < 4; ++variable) {
    LinkKinematics np = normal, nm = normal, sp = slide, sm = slide;
    double* plus[4] = {&np.penetration, &np.penetration_rate, &sp.penetration,
                       &sp.penetration_rate};
    double* minus[4] = {&nm.penetration, &nm.penetration_rate, &sm.penetration,
                        &sm.penetration_rate};
    const double step = 1e-6 * std::max(std::abs(*plus[variable]), 1e-4);
    *plus[variable] += step;
    *minus[variable] -= step;
    const FrictionResponse up = friction.set_trial(np, sp), down = friction.set_trial(nm, sm);
    const double numeric[2] = {(up.normal.force - down.normal.force) / (2 * step),
                               (up.tangential_force - down.tangential_force) / (2 * step)};
    for (int row = 0; row < 2; ++row) {
      const double scale = std::abs(at.normal.force) / std::max(std::abs(*plus[variable]), 1e-4);
      worst = std::max(worst, std::abs(numeric[row] - analytic[row][variable]) / scale);
    }
  }
  return worst;
}

TEST(CoulombFriction, SticksBelowTheLimitAndSlipsAtMuTimesTheNormalForce) {
  CoulombFriction friction = make();
  friction.set_trial({-1e-4, 0.1, 0.0}, {0.0, 0.0, 0.0});
  friction.commit();
  const FrictionResponse stick = friction.set_trial({1e-4, 0.0, 0.0}, {1e-5, 0.0, 0.0});
  EXPECT_FALSE(stick.slipping);
  EXPECT_NEAR(stick.tangential_force, 2e5 * 1e-5, 1e-9);
  const FrictionResponse slip = friction.set_trial({1e-4, 0.0, 0.0}, {1e-2, -0.3, 0.0});
  EXPECT_TRUE(slip.slipping);
  // Against the velocity, not the displacement: the slide is positive but moving back.
  EXPECT_NEAR(slip.tangential_force, -0.4 * 1e6 * 1e-4, 1e-9);
  const FrictionResponse apart = friction.set_trial({-1e-4, 0.0, 0.0}, {1e-2, 0.3, 0.0});
  EXPECT_EQ(apart.tangential_force, 0.0);
}

TEST(CoulombFriction, TangentMatchesFiniteDifferencesInStickAndSlip) {
  const double stick = tangent_error({1e-4, 0.01, 0.0}, {1e-6, 0.001, 0.0});
  const double slip = tangent_error({1e-4, 0.01, 0.0}, {1e-2, 0.3, 0.0});
  std::cout << "stick tangent error " << stick << ", slip tangent error " << slip << "\n";
  EXPECT_LT(stick, 1e-6);
  EXPECT_LT(slip, 1e-6);
}

}  // namespace
}  // namespace pound::links
