// Recorders and link summaries on states made by hand: which columns, which values, in which
// order, and the pounding summary's counts, peaks and integrals against hand computations.
#include "results/recorders.hpp"

#include <gtest/gtest.h>

#include "support/vectors.hpp"

namespace pound::results {
namespace {

using testing::entries;

// Link rows: 0 a frictionless link "joint"; 1 and 2 the normal and tangential rows of "pad".
integrators::State link_state(double time, const Vector& force, const Vector& penetration) {
  integrators::State state;
  state.time = time;
  state.link_force = force;
  state.link_penetration = penetration;
  return state;
}

TEST(LinkRecorder, WritesForceAndPenetrationAndForAFrictionLinkItsTangentialRow) {
  LinkRecorder recorder("links.csv", {{0, false}, {1, true}}, {"joint", "pad"});
  EXPECT_EQ(recorder.file(), "links.csv");
  const std::vector<std::string> columns = {"time",      "joint.force",     "joint.penetration",
                                            "pad.force", "pad.penetration", "pad.tangential_force",
                                            "pad.slide"};
  EXPECT_EQ(recorder.table().columns, columns);
  recorder.record(link_state(0.0, entries({0, 0, 0}), entries({-0.1, -0.2, 0})));
  recorder.record(link_state(0.5, entries({7, 4, -2}), entries({0.05, 0.02, 0.17})));
  const auto& values = recorder.table().values;
  ASSERT_EQ(values.size(), columns.size());
  EXPECT_EQ(values[0], (std::vector<double>{0.0, 0.5}));
  EXPECT_EQ(values[1], (std::vector<double>{0.0, 7.0}));
  EXPECT_EQ(values[2], (std::vector<double>{-0.1, 0.05}));
  EXPECT_EQ(values[3], (std::vector<double>{0.0, 4.0}));
  EXPECT_EQ(values[4], (std::vector<double>{-0.2, 0.02}));
  EXPECT_EQ(values[5], (std::vector<double>{0.0, -2.0}));
  EXPECT_EQ(values[6], (std::vector<double>{0.0, 0.17}));
}

// A ground accelerating at 10 t along x and 100 t along y, with node 7's y support moving too.
GroundAcceleration test_ground() {
  return {[](double time, Vector& frame) {
            frame = entries({10.0 * time, 10.0 * time});
          },
          [](Index node, int direction, double time) {
            return direction == 0 ? 10.0 * time : (node == 7 ? 100.0 : 0.0) * time;
          }};
}

TEST(NodeRecorder, WritesDisplacementVelocityAccelerationPerDirectionAndZeroWhereFixed) {
  // Node "top" (7): x is equation 1, y fixed; node "tip" (3): x equation 0 only.
  GroundAcceleration ground = test_ground();
  NodeRecorder recorder("nodes.csv", {{1, -1}, {0}}, {7, 3}, {"top", "tip"},
                        builder::AccelerationFrame::both, ground);
  const std::vector<std::string> columns = {"time",        "top.u_x", "top.v_x", "top.a_rel_x",
                                            "top.a_abs_x", "top.u_y", "top.v_y", "top.a_rel_y",
                                            "top.a_abs_y", "tip.u_x", "tip.v_x", "tip.a_rel_x",
                                            "tip.a_abs_x"};
  EXPECT_EQ(recorder.table().columns, columns);
  integrators::State state;
  state.time = 0.25;
  state.displacement = entries({1.0, 2.0});
  state.velocity = entries({3.0, 4.0});
  state.acceleration = entries({5.0, 6.0});
  recorder.record(state);
  std::vector<double> row;
  for (const auto& column : recorder.table().values) row.push_back(column.at(0));
  // Absolute: relative + the frame's 2.5 where free; the support's own 25 where fixed.
  EXPECT_EQ(row, (std::vector<double>{0.25, 2.0, 4.0, 6.0, 8.5, 0.0, 0.0, 0.0, 25.0, 1.0, 3.0, 5.0,
                                      7.5}));
}

TEST(NodeRecorder, WritesOnlyTheAccelerationsAskedFor) {
  for (const auto frame :
       {builder::AccelerationFrame::relative, builder::AccelerationFrame::absolute}) {
    GroundAcceleration ground = test_ground();
    NodeRecorder recorder("nodes.csv", {{0}}, {3}, {"tip"}, frame, ground);
    const bool relative = frame == builder::AccelerationFrame::relative;
    EXPECT_EQ(recorder.table().columns,
              (std::vector<std::string>{"time", "tip.u_x", "tip.v_x",
                                        relative ? "tip.a_rel_x" : "tip.a_abs_x"}));
  }
}

TEST(LinkSummaries, CountEngagementsAndIntegrateImpulseAndWorkByTrapezoids) {
  // Row 1 of two: open, contact (F = 2, delta = 0.01), contact (F = 4, delta = 0.03), open,
  // contact again (F = 1, delta = 0.005), at times 0, 0.1, 0.2, 0.3, 0.4.
  LinkSummaries summaries({1});
  const double times[] = {0.0, 0.1, 0.2, 0.3, 0.4};
  const double forces[] = {0.0, 2.0, 4.0, 0.0, 1.0};
  const double penetrations[] = {-0.02, 0.01, 0.03, -0.01, 0.005};
  for (int k = 0; k < 5; ++k)
    summaries.record(
        link_state(times[k], entries({99.0, forces[k]}), entries({-99.0, penetrations[k]})));
  const LinkSummary& s = summaries.summaries().at(0);
  EXPECT_EQ(s.impacts, 2);
  EXPECT_EQ(s.peak_force, 4.0);
  EXPECT_EQ(s.peak_tension, 0.0);
  EXPECT_EQ(s.peak_penetration, 0.03);
  EXPECT_EQ(s.peak_opening, 0.02);
  // Impulse: 0.1/2 (0 + 2 + 2 + 4 + 4 + 0 + 0 + 1) = 0.65.
  EXPECT_NEAR(s.impulse, 0.65, 1e-15);
  // Work: 1/2 sum (F_k + F_k+1)(delta_k+1 - delta_k)
  //     = (2 0.03 + 6 0.02 + 4 (-0.04) + 1 0.015) / 2 = 0.0175.
  EXPECT_NEAR(s.work, 0.0175, 1e-15);
  EXPECT_EQ(s.first_contact, 0.1);
  EXPECT_EQ(s.last_contact, 0.4);
}

TEST(LinkSummaries, ARestrainerReportsTensionAndAContactAtTheStartIsAnImpact) {
  LinkSummaries summaries({0});
  summaries.record(link_state(0.0, entries({-3.0}), entries({-0.2})));
  summaries.record(link_state(1.0, entries({-5.0}), entries({-0.3})));
  const LinkSummary& s = summaries.summaries().at(0);
  EXPECT_EQ(s.impacts, 1);
  EXPECT_EQ(s.peak_force, 0.0);
  EXPECT_EQ(s.peak_tension, 5.0);
  EXPECT_EQ(s.peak_opening, 0.3);
  EXPECT_NEAR(s.impulse, -4.0, 1e-15);
  EXPECT_NEAR(s.work, -4.0 * -0.1, 1e-15);
  EXPECT_EQ(s.first_contact, 0.0);
}

TEST(LinkSummaries, ALinkNeverInContactHasNoContactTimes) {
  LinkSummaries summaries({0});
  summaries.record(link_state(0.0, entries({0.0}), entries({-0.2})));
  summaries.record(link_state(1.0, entries({0.0}), entries({-0.1})));
  const LinkSummary& s = summaries.summaries().at(0);
  EXPECT_EQ(s.impacts, 0);
  EXPECT_EQ(s.first_contact, -1.0);
  EXPECT_EQ(s.last_contact, -1.0);
  EXPECT_EQ(s.impulse, 0.0);
}

}  // namespace
}  // namespace pound::results
