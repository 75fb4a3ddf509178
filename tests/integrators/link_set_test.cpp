// LinkSet on a hand-made set of two links over 4 DOFs, every number computed by hand:
//   link 0, Kelvin-Voigt (k = 100, c = 5), row 0 = u0 - u1, gap 0.1;
//   link 1, a gap spring (k = 200) with Coulomb friction (mu = 0.5, k_t = 50, c_t = 2, m_t = 3),
//           normal row 1 = u2, tangential row 2 = u1 + 2 u3.
#include "integrators/link_set.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "links/coulomb_friction.hpp"
#include "links/gap_spring.hpp"
#include "links/hard_contact.hpp"
#include "links/kelvin_voigt.hpp"
#include "support/vectors.hpp"

namespace pound::integrators {
namespace {

using testing::entries;

LinkSet two_links() {
  std::vector<LinkSet::Link> links(2);
  links[0].normal_row = {{0, 1.0}, {1, -1.0}};
  links[0].gap = 0.1;
  links[0].law = std::make_unique<links::KelvinVoigt>(100.0, 5.0, true);
  links[1].normal_row = {{2, 1.0}};
  links[1].tangential_rows = {{{1, 1.0}, {3, 2.0}}};
  links[1].friction = std::make_unique<links::CoulombFriction>(
      std::make_unique<links::GapSpring>(200.0), 0.5,
      links::StickPenalty{.stiffness = 50.0, .damping = 2.0, .mass = 3.0});
  return LinkSet(4, std::move(links));
}

// Forces and total tangent of one trial with rate factor 10 and acceleration factor 100.
struct Trial {
  Vector force;
  Matrix tangent;
};

Trial trial(LinkSet& links, const Vector& delta, const Vector& rate, const Vector& acceleration) {
  Trial t;
  links.set_trial(delta, rate, acceleration, 10.0, 100.0, t.force, t.tangent);
  return t;
}

TEST(LinkSet, RowsFollowTheLinksWithTheTangentialRowAfterItsNormalOne) {
  const LinkSet links = two_links();
  EXPECT_EQ(links.count(), 2);
  EXPECT_EQ(links.size(), 3);
  EXPECT_EQ(links.row(0), 0);
  EXPECT_EQ(links.row(1), 1);
  EXPECT_FALSE(links.has_friction(0));
  EXPECT_TRUE(links.has_friction(1));
  EXPECT_EQ(links.friction(0), nullptr);
  ASSERT_NE(links.friction(1), nullptr);
  EXPECT_EQ(links.friction(1)->coefficient(), 0.5);
  EXPECT_EQ(links.law(0).name(), "kelvin_voigt");
  EXPECT_EQ(links.law(1).name(), "gap_spring");  // the normal law inside the friction
  const Matrix expected{{1, -1, 0, 0}, {0, 0, 1, 0}, {0, 1, 0, 2}};
  EXPECT_EQ(Matrix(links.connectivity()), expected);
  EXPECT_EQ(links.gaps(), entries({0.1, 0.0, 0.0}));
}

TEST(LinkSet, PenetrationsAreBuMinusTheGapsAndRatesAreBx) {
  const LinkSet links = two_links();
  Vector delta, rate;
  links.penetration(entries({0.3, 0.15, 0.02, 0.01}), delta);
  EXPECT_NEAR(delta[0], 0.3 - 0.15 - 0.1, 1e-15);
  EXPECT_NEAR(delta[1], 0.02, 1e-15);
  EXPECT_NEAR(delta[2], 0.15 + 2 * 0.01, 1e-15);
  links.project(entries({1.0, -2.0, 0.5, 3.0}), rate);
  EXPECT_EQ(rate, entries({3.0, 0.5, 4.0}));
}

// A step's three products in one pass are the three separate ones to the bit, signed zeros
// included (Eigen's sparse product sums from +0).
TEST(LinkSet, PenetrationsAndRateInOnePassAreTheSeparatePassesToTheBit) {
  const LinkSet links = two_links();
  const std::array<Vector, 4> vectors = {
      entries({0.3, 0.15, 0.02, 0.01}), entries({1.0 / 3.0, -2.0 / 7.0, 1e-17, 5.5}),
      entries({-0.0, 0.0, -0.0, -0.0}), entries({0.1, 0.1, 0.0, -0.05})};
  for (const Vector& u_1 : vectors)
    for (const Vector& u_2 : vectors)
      for (const Vector& v : vectors) {
        Vector delta_1, delta_2, rate, expected_1, expected_2, expected_rate;
        links.penetrations_and_rate(u_1, u_2, v, delta_1, delta_2, rate);
        links.penetration(u_1, expected_1);
        links.penetration(u_2, expected_2);
        links.project(v, expected_rate);
        for (Index r = 0; r < links.size(); ++r) {
          EXPECT_EQ(delta_1[r], expected_1[r]);
          EXPECT_EQ(delta_2[r], expected_2[r]);
          EXPECT_EQ(rate[r], expected_rate[r]);
          EXPECT_EQ(std::signbit(rate[r]), std::signbit(expected_rate[r]));
          EXPECT_EQ(std::signbit(delta_1[r]), std::signbit(expected_1[r]));
        }
      }
}

// The predictor's two products in one pass are the separate ones to the bit, signed zeros
// included.
TEST(LinkSet, PenetrationAndRateInOnePassAreTheSeparatePassesToTheBit) {
  const LinkSet links = two_links();
  const std::array<Vector, 3> vectors = {entries({0.3, 0.15, 0.02, 0.01}),
                                         entries({1.0 / 3.0, -2.0 / 7.0, 1e-17, 5.5}),
                                         entries({-0.0, 0.0, -0.0, -0.0})};
  for (const Vector& u : vectors)
    for (const Vector& v : vectors) {
      Vector delta, rate, expected_delta, expected_rate;
      links.penetration_and_rate(u, v, delta, rate);
      links.penetration(u, expected_delta);
      links.project(v, expected_rate);
      for (Index r = 0; r < links.size(); ++r) {
        EXPECT_EQ(delta[r], expected_delta[r]);
        EXPECT_EQ(rate[r], expected_rate[r]);
        EXPECT_EQ(std::signbit(rate[r]), std::signbit(expected_rate[r]));
      }
    }
}

// nodal -= B^T F over the rows with a force: the rows of F = 0 leave every entry as it was, -0
// included.
TEST(LinkSet, SubtractTransposeTakesBTransposeFFromTheNodalVector) {
  const LinkSet links = two_links();
  Vector nodal = entries({1.0, -0.0, 2.0, 0.5});
  links.subtract_transpose(entries({7.0, 0.0, 2.0}), nodal);
  EXPECT_EQ(nodal, entries({1.0 - 7.0, -0.0 + 7.0 - 2.0, 2.0, 0.5 - 4.0}));
  Vector untouched = entries({1.0, -0.0, 2.0, 0.5});
  links.subtract_transpose(entries({0.0, 0.0, 0.0}), untouched);
  EXPECT_TRUE(std::signbit(untouched[1]));
  EXPECT_EQ(untouched, entries({1.0, -0.0, 2.0, 0.5}));
}

TEST(LinkSet, ForcesEnterTheEquationsAsBTransposeF) {
  const LinkSet links = two_links();
  const Vector nodal = links.connectivity().transpose() * entries({7.0, 4.0, 2.0});
  EXPECT_EQ(nodal, entries({7.0, -7.0 + 2.0, 4.0, 2.0 * 2.0}));
}

TEST(LinkSet, NodalNormIsTheNormOfBTransposeS) {
  const LinkSet links = two_links();
  for (const Vector& s :
       {entries({7.0, 4.0, 2.0}), entries({-1.5, 0.0, 3.25}), entries({0, 0, 0})}) {
    const Vector direct = links.connectivity().transpose() * s;
    EXPECT_NEAR(links.nodal_norm(s), direct.norm(), 1e-14 * (1.0 + direct.norm()));
  }
  EXPECT_NEAR(links.nodal_norm(entries({7.0, 4.0, 2.0})), std::sqrt(49.0 + 25.0 + 16.0 + 16.0),
              1e-13);
}

TEST(LinkSet, SlippingFrictionGivesMuRnAndCouplesTheTangentialRowToTheNormalOne) {
  LinkSet links = two_links();
  // Link 0: F = 100 0.05 + 5 0.4 = 7, tangent k + c 10 = 150. Link 1: R_n = 200 0.02 = 4; the
  // stick force 50 0.17 + 2 0.02 = 8.54 exceeds mu R_n = 2, so it slips along +s:
  // R_t = 2, dR_t/d(delta) = mu dR_n/d(delta) = 100, dR_t/ds = 0.
  const Trial t = trial(links, entries({0.05, 0.02, 0.17}), entries({0.4, 0.0, 0.02}),
                        entries({0.0, 0.0, 0.0}));
  EXPECT_NEAR(t.force[0], 7.0, 1e-13);
  EXPECT_NEAR(t.force[1], 4.0, 1e-13);
  EXPECT_NEAR(t.force[2], 2.0, 1e-13);
  const Matrix expected{{150, 0, 0}, {0, 200, 0}, {0, 100, 0}};
  EXPECT_TRUE(t.tangent.isApprox(expected, 1e-14)) << t.tangent;
}

TEST(LinkSet, StickingFrictionGivesTheStickPenaltyAndItsTotalTangent) {
  LinkSet links = two_links();
  // Stick force 50 0.01 + 3 0.1 = 0.8 <= mu R_n = 2. Total tangent of the tangential row:
  // k_t + c_t 10 + m_t 100 = 370, not coupled to the normal row.
  const Trial t = trial(links, entries({-0.01, 0.02, 0.01}), entries({0.0, 0.0, 0.0}),
                        entries({0.0, 0.0, 0.1}));
  EXPECT_EQ(t.force[0], 0.0);  // link 0 open
  EXPECT_NEAR(t.force[2], 0.8, 1e-14);
  const Matrix expected{{0, 0, 0}, {0, 200, 0}, {0, 0, 370}};
  EXPECT_TRUE(t.tangent.isApprox(expected, 1e-14)) << t.tangent;
  // The mass tangent alone, for an explicit step: only m_t.
  Vector force;
  Matrix mass;
  links.set_trial_mass(entries({-0.01, 0.02, 0.01}), entries({0.0, 0.0, 0.0}),
                       entries({0.0, 0.0, 0.1}), force, mass);
  EXPECT_EQ(force, t.force);
  EXPECT_EQ(mass, (Matrix{{0, 0, 0}, {0, 0, 0}, {0, 0, 3}}));
}

// A tangent already of its size is written block by block, not cleared: one trial after another
// into the same matrix (slip, then stick, then open) gives what a fresh matrix gets each time,
// and a block's entries that a law leaves at zero (stick uncouples s from delta) are written.
TEST(LinkSet, ATangentKeptAtItsSizeEqualsAFreshOne) {
  LinkSet links = two_links();
  const Vector rest = entries({0.0, 0.0, 0.0});
  const std::vector<std::array<Vector, 3>> trials = {
      {entries({0.05, 0.02, 0.17}), entries({0.4, 0.0, 0.02}), rest},  // slips
      {entries({-0.01, 0.02, 0.01}), rest, entries({0.0, 0.0, 0.1})},  // sticks, link 0 open
      {entries({-0.01, -0.02, 0.0}), rest, rest}};                     // both open
  Vector force;
  Matrix kept;
  for (const auto& [delta, rate, acceleration] : trials) {
    links.set_trial(delta, rate, acceleration, 10.0, 100.0, force, kept);
    const Trial fresh = trial(links, delta, rate, acceleration);
    EXPECT_EQ(kept, fresh.tangent);
    EXPECT_EQ(force, fresh.force);
  }
  EXPECT_EQ(kept, Matrix::Zero(3, 3));
}

TEST(LinkSet, CommitKeepsTheSlipAnchorAndRevertForgetsATrial) {
  LinkSet links = two_links();
  const Vector none = entries({0.0, 0.0, 0.0});
  // The slip of the test above, committed: the anchor moves to 0.17 - (2 - 2 0.02)/50 = 0.1308,
  // where the stick force equals the slip force.
  trial(links, entries({0.05, 0.02, 0.17}), entries({0.4, 0.0, 0.02}), none);
  links.commit();
  const double anchor = 0.17 - (2.0 - 2.0 * 0.02) / 50.0;
  EXPECT_NEAR(trial(links, entries({0.05, 0.02, anchor + 0.01}), none, none).force[2], 0.5, 1e-12);
  // A trial far away (a slip moving the trial anchor), reverted and committed: the anchor holds.
  trial(links, entries({0.05, 0.02, 0.9}), entries({0.0, 0.0, 1.0}), none);
  links.revert();
  links.commit();
  EXPECT_NEAR(trial(links, entries({0.05, 0.02, anchor + 0.01}), none, none).force[2], 0.5, 1e-12);
}

TEST(LinkSet, AnchoringFrictionAtRestSetsTheStickForce) {
  LinkSet links = two_links();
  const Vector none = entries({0.0, 0.0, 0.0});
  trial(links, entries({0.05, 0.02, 0.17}), none, none);  // slips (8.5 > 2); committed at s = 0.17
  links.commit();
  // The tangential force asked for is the one of the friction link's tangential row (row 2).
  links.anchor_friction_at_rest(entries({123.0, 456.0, 1.0}));
  EXPECT_NEAR(trial(links, entries({0.05, 0.02, 0.17}), none, none).force[2], 1.0, 1e-12);
}

// A link in a contact plane has three rows (normal, t1, t2) whose 3 x 3 tangent block is filled;
// a friction law's tangents must match its rows, and hard friction stays in a plane.
TEST(LinkSet, FrictionInAContactPlaneHasARowPerTangent) {
  const auto plane_link = [](int tangents, std::unique_ptr<links::LinkLaw> normal) {
    std::vector<LinkSet::Link> links(1);
    links[0].normal_row = {{2, 1.0}};
    links[0].tangential_rows = {{{0, 1.0}}, {{1, 1.0}}};
    links[0].friction = std::make_unique<links::CoulombFriction>(
        std::move(normal), 0.5, links::StickPenalty{.stiffness = 50.0}, std::nullopt, tangents);
    return LinkSet(3, std::move(links));
  };
  LinkSet links = plane_link(2, std::make_unique<links::GapSpring>(200.0));
  EXPECT_EQ(links.size(), 3);
  EXPECT_EQ(links.rows(0), 3);
  Vector force;
  Matrix tangent;
  // Pressed by 200 * 0.01 = 2 (limit 1), sliding along (3, 4) / 5: slips, the turn couples t1, t2.
  links.set_trial(Vector{{0.01, -0.02, 0.01}}, Vector{{0.0, 0.3, 0.4}}, Vector::Zero(3), 1.0, 0.0,
                  force, tangent);
  EXPECT_NEAR(force[1], 0.6, 1e-15);
  EXPECT_NEAR(force[2], 0.8, 1e-15);
  EXPECT_NEAR(tangent(1, 2), -1.0 * 0.6 * 0.8 / 0.5, 1e-15);
  EXPECT_NEAR(tangent(2, 1), tangent(1, 2), 1e-15);
  EXPECT_NEAR(tangent(1, 0), 0.5 * 0.6 * 200.0, 1e-12);
  EXPECT_THROW(plane_link(1, std::make_unique<links::GapSpring>(200.0)), std::invalid_argument);
  // On a hard contact both tangents are constraint rows of one contact plane.
  LinkSet hard = plane_link(2, std::make_unique<links::HardContact>(0.0));
  const LinkSet::HardRows rows = hard.hard_rows();
  EXPECT_NE(rows.contacts[0], nullptr);
  EXPECT_EQ(rows.frictions[1], rows.frictions[2]);
  EXPECT_NE(rows.frictions[1], nullptr);
  EXPECT_EQ(rows.tangent, (std::vector<int>{0, 0, 1}));
  EXPECT_EQ(rows.pair, (std::vector<char>{0, 1, 1}));
}

// A contact plane's tangent whose DOFs are all held (z fixed under a plane scene written in 3-D)
// has no slide to constrain: its row is no hard row, and the other is a plane scene's friction.
TEST(LinkSet, AHardContactPlaneTangentThatCannotMoveIsNoConstraint) {
  std::vector<LinkSet::Link> links(1);
  links[0].normal_row = {{1, 1.0}};
  links[0].tangential_rows = {{{0, 1.0}}, {}};
  links[0].friction = std::make_unique<links::CoulombFriction>(
      std::make_unique<links::HardContact>(0.0), 0.5, links::StickPenalty{}, std::nullopt, 2);
  LinkSet set(2, std::move(links));
  const LinkSet::HardRows rows = set.hard_rows();
  EXPECT_NE(rows.frictions[1], nullptr);
  EXPECT_EQ(rows.frictions[2], nullptr);
  EXPECT_EQ(rows.pair, (std::vector<char>{0, 0, 0}));
}

TEST(LinkSet, ScalarLinksHaveOneRowEach) {
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(std::make_unique<links::GapSpring>(10.0));
  laws.push_back(std::make_unique<links::GapSpring>(20.0));
  LinkSet links(3, {{{0, 1.0}, {2, -1.0}}, {{1, -1.0}}}, {0.5, 0.25}, std::move(laws));
  EXPECT_EQ(links.count(), 2);
  EXPECT_EQ(links.size(), 2);
  EXPECT_EQ(links.row(1), 1);
  Vector delta;
  links.penetration(entries({1.0, -1.0, 0.25}), delta);
  EXPECT_EQ(delta, entries({1.0 - 0.25 - 0.5, 1.0 - 0.25}));
  const Trial t = trial(links, delta, entries({0.0, 0.0}), entries({0.0, 0.0}));
  EXPECT_EQ(t.force, entries({2.5, 15.0}));
  EXPECT_EQ(t.tangent, (Matrix{{10, 0}, {0, 20}}));
}

}  // namespace
}  // namespace pound::integrators
