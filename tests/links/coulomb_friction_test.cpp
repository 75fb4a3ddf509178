// Coulomb friction: stick and slip forces, and the consistent (non-symmetric) tangent against
// finite differences in both regimes, with one tangent (plane scenes) and two (3-D: the limit is
// a circle, slip is against the slide velocity, and its direction's turn enters the tangent); a
// slip turning back, or starting out of a stick, passes the limit continuously in the slide.
#include "links/coulomb_friction.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
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
      {at.tangential_on_normal[0].stiffness, at.tangential_on_normal[0].damping,
       at.tangential_on_slip[0][0].stiffness, at.tangential_on_slip[0][0].damping}};
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
                               (up.tangential_force[0] - down.tangential_force[0]) / (2 * step)};
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
  EXPECT_NEAR(stick.tangential_force[0], 2e5 * 1e-5, 1e-9);
  const FrictionResponse slip = friction.set_trial({1e-4, 0.0, 0.0}, {1e-2, -0.3, 0.0});
  EXPECT_TRUE(slip.slipping);
  // Against the velocity, not the displacement: the slide is positive but moving back.
  EXPECT_NEAR(slip.tangential_force[0], -0.4 * 1e6 * 1e-4, 1e-9);
  const FrictionResponse apart = friction.set_trial({-1e-4, 0.0, 0.0}, {1e-2, 0.3, 0.0});
  EXPECT_EQ(apart.tangential_force[0], 0.0);
}

// A block slipping forwards (R_n = 100 N, limit 40 N, k_t = 2e5 N/m) whose velocity turns within a
// step: the force follows the stick force k_t (s - s_0) down from +40 N to -40 N over
// 2 mu R_n / k_t = 0.4 mm of slide, continuous at every slide. A slip force against the velocity
// would jump by 2 mu R_n = 80 N where the stick force passes the limit, a jump at which Newton's
// iteration cycles (a friction pendulum's runs failed so).
TEST(CoulombFriction, ASlipTurningBackPassesThroughTheStickBranch) {
  CoulombFriction friction(std::make_unique<KelvinVoigt>(1e6, 0.0, true), 0.4, {2e5, 0.0, 0.0});
  friction.set_trial({-1e-4, 0.1, 0.0}, {0.0, 0.0, 0.0});
  friction.commit();
  EXPECT_TRUE(friction.set_trial({1e-4, 0.0, 0.0}, {1e-3, 0.1, 0.0}).slipping);
  friction.commit();  // slipping forwards at +40 N, its anchor at 1e-3 - 40 / 2e5 = 0.8 mm
  double worst_jump = 0.0, previous = 0.0;
  const double step = 1e-6;
  for (int i = 0; i <= 700; ++i) {
    const double slide = 1.1e-3 - step * i;  // from beyond the last slip back past the reversal
    const FrictionResponse r = friction.set_trial({1e-4, 0.0, 0.0}, {slide, -0.1, 0.0});
    const double expected = std::clamp(2e5 * (slide - 0.8e-3), -40.0, 40.0);
    EXPECT_NEAR(r.tangential_force[0], expected, 1e-9) << "slide " << slide;
    if (i > 0) worst_jump = std::max(worst_jump, std::abs(r.tangential_force[0] - previous));
    previous = r.tangential_force[0];
  }
  std::cout << "largest force change over a 1e-6 m slide through the turn: " << worst_jump
            << " N (stick slope: 0.2 N)\n";
  EXPECT_LE(worst_jump, 2e5 * step * (1 + 1e-9));
}

TEST(CoulombFriction, TangentMatchesFiniteDifferencesInStickAndSlip) {
  const double stick = tangent_error({1e-4, 0.01, 0.0}, {1e-6, 0.001, 0.0});
  const double slip = tangent_error({1e-4, 0.01, 0.0}, {1e-2, 0.3, 0.0});
  std::cout << "stick tangent error " << stick << ", slip tangent error " << slip << "\n";
  EXPECT_LT(stick, 1e-6);
  EXPECT_LT(slip, 1e-6);
}

// Two tangents. The 3 x 7 tangent [R_n, R_t1, R_t2] / d(delta, delta_dot, s1, s2, s1_dot,
// s2_dot, s1_ddot) by central differences, each column relative to the largest force over the
// variable's scale; `columns` leaves out the rate columns where slip at rest turns into slip
// along the velocity (the direction's two branches meet there with different derivatives).
using PlaneTrial = std::array<double, 7>;

FrictionResponse in_plane(CoulombFriction& friction, const PlaneTrial& x) {
  const std::array<LinkKinematics, 2> slide{LinkKinematics{x[2], x[4], x[6]},
                                            LinkKinematics{x[3], x[5], 0.0}};
  return friction.set_trial({x[0], x[1], 0.0}, slide);
}

CoulombFriction in_plane_law() {
  return CoulombFriction(std::make_unique<KelvinVoigt>(1e6, 1e3, true), 0.4, {2e5, 500.0, 30.0},
                         std::nullopt, 2);
}

// `before`: committed states the trial starts from (after the contact's first touch).
double plane_tangent_error(const PlaneTrial& at, bool expect_slip, int columns,
                           std::initializer_list<PlaneTrial> before = {}) {
  CoulombFriction friction = in_plane_law();
  in_plane(friction, {-1e-4, 0.1, 0, 0, 0, 0, 0});
  friction.commit();
  for (const PlaneTrial& state : before) {
    in_plane(friction, state);
    friction.commit();
  }
  const FrictionResponse r = in_plane(friction, at);
  EXPECT_EQ(r.slipping, expect_slip);
  const auto analytic = [&](int row, int v) {
    const auto kind = [&](const LawResponse& l, int order) {
      return order == 0 ? l.stiffness : order == 1 ? l.damping : l.mass;
    };
    const std::size_t a = static_cast<std::size_t>(row - 1);
    if (v < 2) return kind(row == 0 ? r.normal : r.tangential_on_normal[a], v);
    if (row == 0) return 0.0;
    const int order = v < 4 ? 0 : v < 6 ? 1 : 2;
    const std::size_t b = static_cast<std::size_t>(v < 6 ? (v - 2) % 2 : 0);
    return kind(r.tangential_on_slip[a][b], order);
  };
  const auto forces = [](const FrictionResponse& f) {
    return std::array<double, 3>{f.normal.force, f.tangential_force[0], f.tangential_force[1]};
  };
  double worst = 0.0;
  for (int v = 0; v < columns; ++v) {
    const double h = 1e-7 * std::max(std::abs(at[static_cast<std::size_t>(v)]), 1e-3);
    PlaneTrial up = at, down = at;
    up[static_cast<std::size_t>(v)] += h;
    down[static_cast<std::size_t>(v)] -= h;
    const auto p = forces(in_plane(friction, up)), m = forces(in_plane(friction, down));
    const double scale =
        std::abs(r.normal.force) / std::max(std::abs(at[static_cast<std::size_t>(v)]), 1e-3);
    for (int row = 0; row < 3; ++row)
      worst = std::max(
          worst,
          std::abs((p[static_cast<std::size_t>(row)] - m[static_cast<std::size_t>(row)]) / (2 * h) -
                   analytic(row, v)) /
              scale);
  }
  return worst;
}

TEST(CoulombFriction, InAContactPlaneTheLimitIsACircleAndSlipOpposesTheVelocity) {
  CoulombFriction friction = in_plane_law();
  in_plane(friction, {-1e-4, 0.1, 0, 0, 0, 0, 0});
  friction.commit();
  // R_n = 1e6 * 1e-4 = 100 N, limit 40 N. A stick force of (30, 30) N is 42 N: it slips,
  // though each component is below the limit.
  const FrictionResponse box = in_plane(friction, {1e-4, 0, 1.5e-4, 1.5e-4, 0, 0, 0});
  EXPECT_TRUE(box.slipping);
  EXPECT_NEAR(std::hypot(box.tangential_force[0], box.tangential_force[1]), 40.0, 1e-9);
  EXPECT_NEAR(box.tangential_force[0], box.tangential_force[1], 1e-12);
  const FrictionResponse held = in_plane(friction, {1e-4, 0, 1.0e-4, 1.0e-4, 0, 0, 0});
  EXPECT_FALSE(held.slipping);
  EXPECT_NEAR(held.tangential_force[0], 20.0, 1e-9);
  // Sliding along (3, -4) / 5: the force is 40 N along the velocity, whatever the slide.
  const FrictionResponse slide = in_plane(friction, {1e-4, 0, 1e-2, 0.0, 0.3, -0.4, 0});
  EXPECT_TRUE(slide.slipping);
  EXPECT_NEAR(slide.tangential_force[0], 0.4 * 100.0 * 0.6, 1e-9);
  EXPECT_NEAR(slide.tangential_force[1], -0.4 * 100.0 * 0.8, 1e-9);
}

// A contact stuck at rest on its spring (R_n = 100 N, limit 40 N, k_t = 2e5 N/m) whose slide
// grows along (0.6, 0.8) past the circle while it rocks at 1e-7 m/s, 0.7 degrees off that line
// (as a friction pendulum at rest does): the slip goes along the stick force, continuous where it
// crosses the circle. Along the velocity F_c jumped by 40 N x 0.0122 rad = 0.49 N there, and
// Newton's iteration cycled between the two sides.
TEST(CoulombFriction, InAContactPlaneASlipOutOfAStickGoesAlongTheStickForce) {
  CoulombFriction friction = in_plane_law();
  in_plane(friction, {-1e-4, 0.1, 0, 0, 0, 0, 0});
  friction.commit();
  EXPECT_FALSE(in_plane(friction, {1e-4, 0, 0.6e-4, 0.8e-4, 0, 0, 0}).slipping);
  friction.commit();  // stuck, anchored at s = 0
  const double angle = std::atan2(0.8, 0.6) + 0.0122, speed = 1e-7, step = 1e-7;
  double worst_jump = 0.0, worst_off_line = 0.0;
  std::array<double, 2> previous{};
  int slipping = 0;
  for (int i = 0; i <= 800; ++i) {
    const double radius = 1.6e-4 + step * i;  // stick force 32 N to 48 N
    const FrictionResponse r = in_plane(
        friction,
        {1e-4, 0, 0.6 * radius, 0.8 * radius, speed * std::cos(angle), speed * std::sin(angle), 0});
    slipping += r.slipping;
    const auto& f = r.tangential_force;
    worst_off_line = std::max(worst_off_line, std::abs(0.8 * f[0] - 0.6 * f[1]));
    if (i > 0)
      worst_jump = std::max(worst_jump, std::hypot(f[0] - previous[0], f[1] - previous[1]));
    previous = f;
  }
  std::cout << "out of a stick: largest force change over a 1e-7 m slide " << worst_jump
            << " N (stick slope 0.02 N), largest force off the slide's line " << worst_off_line
            << " N\n";
  EXPECT_GT(slipping, 300);
  EXPECT_LE(worst_jump, 2e5 * step * (1 + 1e-6));
  // The dashpot's c_t s_dot (5e-5 N) is all that turns the force off the line.
  EXPECT_LT(worst_off_line, 1e-6);
  EXPECT_NEAR(std::hypot(previous[0], previous[1]), 40.0, 1e-9);
}

TEST(CoulombFriction, InAContactPlaneTheTangentMatchesFiniteDifferences) {
  const double stick = plane_tangent_error({1e-4, 0.01, 1e-6, -2e-6, 1e-3, 2e-3, 0.5}, false, 7);
  const double slip = plane_tangent_error({1e-4, 0.01, 1e-2, -3e-3, 0.3, -0.4, 2.0}, true, 7);
  // At rest and slipping: the direction is the stick force's (rate columns left out).
  const double rest = plane_tangent_error({1e-4, 0.0, 2e-4, -1.5e-4, 0.0, 0.0, 0.0}, true, 4);
  // Slipping along +t1, then turning back (velocity (-0.1, 0.2)) with the stick force still
  // forwards: along the stick force, every column.
  const double turning = plane_tangent_error({1e-4, 0.01, 1.5e-3, 1e-4, -0.1, 0.2, 0.0}, true, 7,
                                             {{1e-4, 0.0, 1e-3, 0.0, 0.1, 0.0, 0.0}});
  // Stuck at rest, then past the circle while rocking at 1e-7 m/s 0.7 degrees off the stick
  // force (a pendulum at rest): along the stick force, every column.
  const double rocking = plane_tangent_error(
      {1e-4, 0.0, 1.5e-4, 2e-4, 0.6e-7 - 0.8e-7 * 0.0122, 0.8e-7 + 0.6e-7 * 0.0122, 0.0}, true, 7,
      {{1e-4, 0.0, 0.6e-4, 0.8e-4, 0.0, 0.0, 0.0}});
  std::cout << "in-plane tangent errors: stick " << stick << ", slip " << slip << ", slip at rest "
            << rest << ", turning back " << turning << ", out of a stick rocking " << rocking
            << "\n";
  EXPECT_LT(turning, 1e-6);
  EXPECT_LT(rocking, 1e-6);
  EXPECT_LT(stick, 1e-6);
  EXPECT_LT(slip, 1e-6);
  EXPECT_LT(rest, 1e-6);
}

}  // namespace
}  // namespace pound::links
