// The rigid-body impact references against closed forms: a frictionless blow, a head-on deck,
// Routh's path against the simultaneous laws (two independent solutions of one contact), and
// the skewed deck over skew 0-60 degrees and mu 0-0.5: no energy gained, no rotation while both
// corners press, and the onset of rotation where one corner's impulse reaches zero, at the mu
// for which the other corner's impulse passes through the centre of mass.
#include "verification/rigid_impact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace pound::verification {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;

double kinetic(const RigidBodyInPlan& body, const PlanVelocity& v) {
  return 0.5 * body.mass * (v.x * v.x + v.y * v.y) + 0.5 * body.inertia * v.spin * v.spin;
}

TEST(RigidImpact, AFrictionlessBlowGivesTheClosedFormImpulse) {
  // Lambda = -(1 + e) g_N / W_NN, W_NN = 1/m + (rho . n)^2 / J.
  const RigidBodyInPlan body{1200.0, 3500.0};
  const PlanContact contact{{2.0, -1.5}, {-0.6, 0.8}};
  const PlanVelocity before{3.0, -1.0, 0.4};
  const double rho_n = 1.5 * -0.6 + 2.0 * 0.8;  // (z x r) . n with z x r = (1.5, 2)
  const double approach = 3.0 * -0.6 + -1.0 * 0.8 + 0.4 * rho_n;
  const double w_nn = 1.0 / body.mass + rho_n * rho_n / body.inertia;
  for (double e : {0.0, 0.6, 1.0}) {
    const double exact = -(1.0 + e) * approach / w_nn;
    const PlanImpact routh = routh_impact(body, before, contact, e, 0.0);
    const PlanImpact together = simultaneous_impact(body, before, {contact}, e, 0.0);
    const double lost = 0.5 * (1.0 - e * e) * approach * approach / w_nn;  // (1 - e^2) of it
    std::printf(
        "e = %.1f: impulses %.1e and %.1e from the closed form; energy lost %.1e from it, "
        "of the kinetic energy\n",
        e, std::abs(routh.normal_impulse[0] / exact - 1.0),
        std::abs(together.normal_impulse[0] / exact - 1.0),
        std::abs(routh.energy_lost - lost) / kinetic(body, before));
    EXPECT_NEAR(routh.normal_impulse[0], exact, 1e-13 * exact);
    EXPECT_NEAR(together.normal_impulse[0], exact, 1e-13 * exact);
    EXPECT_NEAR(routh.energy_lost, lost, 1e-12 * kinetic(body, before));
  }
}

TEST(RigidImpact, RouthsPathAndTheLawsAtTheEndAgreeOnOneContactUnlessTheSlideTurnsBack) {
  // Newton's law ends the path where g_N = -e g_N-, and a slide that stopped and stuck stays
  // stopped: then the path and the laws on the end velocities (what one implicit step imposes)
  // are one solution. A slide that turns back on the way takes friction both ways along the path,
  // one way in the end-velocity law: there the two differ (Stronge 2000, 5.3), and the path is
  // the rigid body's answer.
  const RigidBodyInPlan body{1.0, 0.05};
  int cases = 0, sticking = 0, reversed = 0;
  double worst = 0.0, reversed_apart = 0.0;
  for (double angle = 5.0; angle < 360.0; angle += 20.0)
    for (double mu : {0.0, 0.1, 0.3, 0.6, 1.2})
      for (double e : {0.0, 0.5, 1.0})
        for (double spin : {-2.0, 0.0, 3.0}) {
          const PlanContact contact{{0.4 * std::cos(angle * kDegree), 0.25}, {0.0, 1.0}};
          const PlanVelocity before{0.7 * std::sin(angle * kDegree), -1.0, spin};
          const PlanImpact routh = routh_impact(body, before, contact, e, mu);
          if (routh.normal_impulse[0] == 0.0) continue;  // not approaching
          const PlanImpact together = simultaneous_impact(body, before, {contact}, e, mu);
          const double scale = std::abs(routh.normal_impulse[0]);
          const double apart =
              std::max(std::abs(routh.normal_impulse[0] - together.normal_impulse[0]),
                       std::abs(routh.tangential_impulse[0] - together.tangential_impulse[0])) /
              scale;
          ++cases;
          sticking += routh.ends[0] == ContactEnd::sticking;
          if (routh.slide_reversed) {
            ++reversed;
            reversed_apart = std::max(reversed_apart, apart);
          } else {
            worst = std::max(worst, apart);
          }
        }
  std::printf(
      "%d impacts (%d ending stuck): impulses %.1e apart; %d with the slide turned back: "
      "up to %.2f apart\n",
      cases, sticking, worst, reversed, reversed_apart);
  EXPECT_GT(sticking, 10);
  EXPECT_GT(reversed, 0);
  EXPECT_LT(worst, 1e-12);
}

TEST(RigidImpact, AStraightDeckHitsHeadOnWithoutTurning) {
  const SkewedDeck deck{30.0, 12.0, 0.0, 4.0e5, 0.5};
  for (double mu : {0.0, 0.3}) {
    const PlanImpact impact = skewed_deck_impact(deck, 0.6, mu);
    std::printf("mu %.1f: v_x %.15g, v_y %.3g, spin %.3g\n", mu, impact.after.x, impact.after.y,
                impact.after.spin);
    EXPECT_NEAR(impact.after.x, -0.3, 1e-15);
    EXPECT_NEAR(impact.after.y, 0.0, 1e-15);
    EXPECT_NEAR(impact.after.spin, 0.0, 1e-16);
    EXPECT_NEAR(impact.normal_impulse[0], impact.normal_impulse[1],
                1e-9 * impact.normal_impulse[0]);
  }
}

// The mu at which the impulse of one corner alone, slipping (s the sign of its slide velocity
// along t = z x n), passes through the centre of mass: (r x (n - mu s t))_z = 0.
double onset_friction(const PlanContact& corner, int slide) {
  const PlaneVector t{-corner.normal.y, corner.normal.x};
  const double r_cross_n = corner.point.x * corner.normal.y - corner.point.y * corner.normal.x;
  const double r_cross_t = corner.point.x * t.y - corner.point.y * t.x;
  return r_cross_n / (slide * r_cross_t);
}

TEST(RigidImpact, ASkewedDeckTurnsOnlyWhenACornerLiftsAndNeverGainsEnergy) {
  int turned = 0, pressed = 0;
  double worst_gain = 0.0, worst_spin_pressed = 0.0;
  for (double skew = 0.0; skew <= 60.0; skew += 5.0)
    for (double mu = 0.0; mu <= 0.5 + 1e-12; mu += 0.05)
      for (double e : {0.0, 0.6, 1.0}) {
        const SkewedDeck deck{30.0, 12.0, skew * kDegree, 4.0e5, 0.5};
        const PlanImpact impact = skewed_deck_impact(deck, e, mu);
        const double energy = kinetic(deck.body(), {deck.speed, 0.0, 0.0});
        worst_gain = std::max(worst_gain, -impact.energy_lost / energy);
        const bool both = impact.normal_impulse[0] > 1e-9 * deck.mass * deck.speed &&
                          impact.normal_impulse[1] > 1e-9 * deck.mass * deck.speed;
        if (both) {
          ++pressed;
          worst_spin_pressed =
              std::max(worst_spin_pressed, std::abs(impact.after.spin) * deck.length / deck.speed);
        } else {
          ++turned;
        }
      }
  std::printf(
      "%d impacts with both corners pressing (largest spin x L / V %.1e), %d with one "
      "lifting; largest energy gain %.1e of the approach\n",
      pressed, worst_spin_pressed, turned, worst_gain);
  EXPECT_GT(pressed, 0);
  EXPECT_GT(turned, 0);
  EXPECT_LT(worst_spin_pressed, 1e-12);
  EXPECT_LE(worst_gain, 1e-12);
}

TEST(RigidImpact, ASkewedDeckStopsTurningWhereTheObtuseCornersImpulseMeetsTheCentre) {
  // Past the skew at which the foot of the perpendicular from the centre of mass leaves the end
  // (sin 2 skew > 2 W / L, 26.6 degrees here) the normal impulses alone turn the deck about its
  // obtuse corner, lifting the acute one; friction along the wall turns it back, and from the mu
  // at which the obtuse corner's impulse passes through the centre both corners press and the
  // deck leaves without turning. That mu, found by bisection, against its closed form (sliding:
  // below tan(skew) / (1 + e), where the slide would stop).
  const double e = 0.6;
  for (double skew : {30.0, 45.0, 60.0}) {
    const SkewedDeck deck{30.0, 12.0, skew * kDegree, 4.0e5, 0.5};
    const PlanContact obtuse = deck.corners()[1];
    const double slide_velocity = deck.speed * -obtuse.normal.y;  // v . t, t = z x n
    const double exact = onset_friction(obtuse, slide_velocity < 0.0 ? -1 : 1);
    const auto acute_lifts = [&](double mu) {
      return skewed_deck_impact(deck, e, mu).normal_impulse[0] <= 1e-12 * deck.mass * deck.speed;
    };
    double below = 0.0, above = std::tan(skew * kDegree) / (1.0 + e);
    ASSERT_TRUE(acute_lifts(below)) << skew;
    ASSERT_FALSE(acute_lifts(above)) << skew;
    for (int k = 0; k < 60; ++k) {
      const double middle = 0.5 * (below + above);
      (acute_lifts(middle) ? below : above) = middle;
    }
    const double spin_below = skewed_deck_impact(deck, e, 0.5 * below).after.spin;
    std::printf(
        "skew %2.0f deg: both corners press from mu %.12f, closed form %.12f (%.1e); at "
        "half of it the deck turns at %.3g rad/s\n",
        skew, above, exact, std::abs(above / exact - 1.0), spin_below);
    EXPECT_NEAR(above, exact, 1e-9 * exact);
    EXPECT_GT(std::abs(spin_below), 1e-3);
  }
}

}  // namespace
}  // namespace pound::verification
