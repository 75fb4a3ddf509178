// Recorders and link summaries on states made by hand: which columns, which values, in which
// order, and the pounding summary's counts, peaks and integrals against hand computations.
#include "results/recorders.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <random>
#include <utility>
#include <vector>

#include "assembly/beam.hpp"
#include "assembly/beam_3d.hpp"
#include "support/dof_readings.hpp"
#include "support/vectors.hpp"

namespace pound::results {
namespace {

using testing::dof;
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
  HistoryRecorder recorder(
      "links.csv", std::make_unique<LinkQuantities>(std::vector<LinkRows>{{0, 0}, {1, 1}},
                                                    std::vector<std::string>{"joint", "pad"}));
  EXPECT_EQ(recorder.file(), "links.csv");
  const std::vector<std::string> columns = {"time",      "joint.force",     "joint.penetration",
                                            "pad.force", "pad.penetration", "pad.tangential_force",
                                            "pad.slide"};
  EXPECT_EQ(recorder.table().columns, columns);
  recorder.record(link_state(0.0, entries({0, 0, 0}), entries({-0.1, -0.2, 0})));
  recorder.record(link_state(0.5, entries({7, 4, -2}), entries({0.05, 0.02, 0.17})));
  const auto& values = recorder.history().values;
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
  return {2,
          [](double time, std::vector<double>& scales) { scales = {10.0 * time}; },
          {entries({1.0, 1.0})},
          [](Index node, int direction, double time) {
            return direction == 0 ? 10.0 * time : (node == 7 ? 100.0 : 0.0) * time;
          }};
}

TEST(NodeRecorder, WritesDisplacementVelocityAccelerationPerDirectionAndZeroWhereFixed) {
  // Node "top" (7): x is equation 1, y fixed; node "tip" (3): x equation 0 only.
  GroundAcceleration ground = test_ground();
  HistoryRecorder recorder(
      "nodes.csv",
      std::make_unique<NodeQuantities>(
          std::vector<std::vector<DofReading>>{{dof(1), dof(-1)}, {dof(0)}},
          std::vector<std::vector<int>>{{0, 1}, {0}}, 2, std::vector<Index>{7, 3},
          std::vector<std::string>{"top", "tip"}, builder::AccelerationFrame::both, ground));
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
  for (const auto& column : recorder.history().values) row.push_back(column.at(0));
  // Absolute: relative + the frame's 2.5 where free; the support's own 25 where fixed.
  EXPECT_EQ(row, (std::vector<double>{0.25, 2.0, 4.0, 6.0, 8.5, 0.0, 0.0, 0.0, 25.0, 1.0, 3.0, 5.0,
                                      7.5}));
}

TEST(NodeRecorder, WritesOnlyTheAccelerationsAskedFor) {
  for (const auto frame :
       {builder::AccelerationFrame::relative, builder::AccelerationFrame::absolute}) {
    GroundAcceleration ground = test_ground();
    HistoryRecorder recorder(
        "nodes.csv",
        std::make_unique<NodeQuantities>(
            std::vector<std::vector<DofReading>>{{dof(0)}}, std::vector<std::vector<int>>{{0}}, 2,
            std::vector<Index>{3}, std::vector<std::string>{"tip"}, frame, ground));
    const bool relative = frame == builder::AccelerationFrame::relative;
    EXPECT_EQ(recorder.table().columns,
              (std::vector<std::string>{"time", "tip.u_x", "tip.v_x",
                                        relative ? "tip.a_rel_x" : "tip.a_abs_x"}));
  }
}

// One link "gap" whose force is 10 t: the rows kept say which steps a sampling took.
std::vector<double> kept_times(builder::OutputSampling sampling, double dt, int steps) {
  HistoryRecorder recorder("gap.csv",
                           std::make_unique<LinkQuantities>(std::vector<LinkRows>{{0, 0}},
                                                            std::vector<std::string>{"gap"}),
                           sampling);
  for (int k = 0; k <= steps; ++k) {
    const double time = k * dt;
    recorder.record(link_state(time, entries({10.0 * time}), entries({0.0})));
  }
  const Table& table = recorder.history();
  EXPECT_EQ(table.values[0].size(), table.values[1].size());
  for (std::size_t r = 0; r < table.values[0].size(); ++r)
    EXPECT_EQ(table.values[1][r], 10.0 * table.values[0][r]);  // rows stay whole
  return table.values[0];
}

// A 3-D column with rigid offsets on a skewed axis whose DOFs a rigid floor gives as two or
// three equations (u_x = u_m - y theta, ...), and a plane beam with one DOF fixed.
std::vector<std::shared_ptr<const model::Element>> test_elements() {
  assembly::Beam3d::Section section;
  section.youngs_modulus = 3.0e10;
  section.shear_modulus = 1.25e10;
  section.area = 0.36;
  section.inertia_y = 0.0108;
  section.inertia_z = 0.0075;
  section.torsion = 0.012;
  const assembly::Point3 bottom(0.4, -0.2, 0.0), top(0.9, 0.3, 3.5);
  assembly::Beam::Section beam_section;
  beam_section.youngs_modulus = 2.0e11;
  beam_section.area = 0.02;
  beam_section.inertia = 3.0e-4;
  return {
      std::make_shared<assembly::Beam3d>(
          "column",
          std::array<assembly::Beam3d::End, 2>{
              {{0, bottom, {0.0, 0.0, 0.2}}, {1, top, {0.1, 0.0, -0.3}}}},
          assembly::Point3(1.0, 0.2, 0.0), section, false, std::nullopt),
      std::make_shared<assembly::Beam>(
          "girder", std::array<model::ElementNode, 2>{{{2, {0.0, 0.0, 0.0}}, {3, {6.0, 0.8, 0.0}}}},
          beam_section, false, std::nullopt)};
}

// Each element DOF over equations 0-19: one to three terms, or none (fixed).
std::vector<std::vector<DofReading>> test_readings(std::mt19937& random) {
  std::uniform_int_distribution<Index> equation(0, 19), terms(0, 3);
  std::uniform_real_distribution<double> coefficient(-4.0, 4.0);
  std::vector<std::vector<DofReading>> readings(2);
  for (std::size_t k = 0; k < readings.size(); ++k)
    for (int j = 0; j < (k == 0 ? 12 : 6); ++j) {
      DofReading& reading = readings[k].emplace_back();
      const Index count = j == 2 && k == 1 ? 0 : std::max<Index>(1, terms(random));
      for (Index t = 0; t < count; ++t) reading.push_back({equation(random), coefficient(random)});
    }
  return readings;
}

TEST(ElementQuantities, EndForcesAreTheElementsOwnWithinRoundOffAndOnlyThoseAskedFor) {
  // Each end force is read as one sum over the equations, its row of the element's end force map
  // times the readings. Against the same quantity in long double from the element's map and
  // each DOF's reading, and against the element's own end_forces(u_e): within a few units of
  // round-off of the sum of the terms' magnitudes (the scale any ordering of the sum is exact
  // to), over displacements with a large rigid part (cancellation).
  std::mt19937 random(20261129);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto elements = test_elements();
  double worst_map = 0.0, worst_element = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const auto readings = test_readings(random);
    const ElementQuantities all(elements, readings);
    ASSERT_EQ(all.names().size(), 18u);
    EXPECT_EQ(all.names()[0], "column.N_i");
    EXPECT_EQ(all.names()[12], "girder.N_i");
    integrators::State state;
    state.displacement = Vector(20);
    const double rigid = trial % 2 == 0 ? 1.0 : 1.0e4;
    for (Index e = 0; e < 20; ++e) state.displacement[e] = rigid + 1e-3 * unit(random);
    std::vector<double> values(18);
    all.take(state, values.data());
    std::size_t place = 0;
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const Matrix map = model::end_force_map(*elements[k]);
      Vector element_u(map.cols());
      for (Index j = 0; j < map.cols(); ++j)
        element_u[j] =
            model::value_of(readings[k][static_cast<std::size_t>(j)], state.displacement);
      const Vector own = elements[k]->end_forces(element_u);
      for (Index s = 0; s < map.rows(); ++s, ++place) {
        long double exact = 0.0L, scale = 0.0L;
        for (Index j = 0; j < map.cols(); ++j)
          for (const model::DofTerm& term : readings[k][static_cast<std::size_t>(j)]) {
            const long double product = static_cast<long double>(map(s, j)) * term.coefficient *
                                        state.displacement[term.equation];
            exact += product;
            scale += std::abs(product);
          }
        const double margin = static_cast<double>(scale) + 1e-300;
        worst_map =
            std::max(worst_map, std::abs(values[place] - static_cast<double>(exact)) / margin);
        worst_element = std::max(worst_element, std::abs(values[place] - own[s]) / margin);
      }
    }
    // Only the end forces asked for, in the order asked: the same sums, so the same bits.
    const ElementQuantities some(elements, readings, {{7, 1}, {}});
    ASSERT_EQ(some.names(), (std::vector<std::string>{"column.Vy_j", "column.Vy_i"}));
    std::vector<double> chosen(2);
    some.take(state, chosen.data());
    EXPECT_EQ(chosen[0], values[7]);
    EXPECT_EQ(chosen[1], values[1]);
  }
  std::cout << "end forces against long double: " << worst_map
            << " of the terms' magnitudes; against the element's own: " << worst_element << '\n';
  EXPECT_LT(worst_map, 1e-15);
  EXPECT_LT(worst_element, 1e-14);
}

TEST(ElementQuantities, AnUnloadedElementsEndForcesArePositiveZeros) {
  // As the element's own products summed from 0: no -0 in a history or an envelope.
  std::mt19937 random(7);
  const ElementQuantities quantities(test_elements(), test_readings(random));
  integrators::State state;
  state.displacement = Vector::Zero(20);
  std::vector<double> values(18, 1.0);
  quantities.take(state, values.data());
  for (const double value : values) EXPECT_TRUE(value == 0.0 && !std::signbit(value));
}

TEST(HistoryRecorder, KeepsEveryKthStepCountingTheStartAsStepZero) {
  EXPECT_EQ(kept_times({3, 0.0}, 0.5, 7), (std::vector<double>{0.0, 1.5, 3.0}));
  EXPECT_EQ(kept_times({1, 0.0}, 0.5, 3), (std::vector<double>{0.0, 0.5, 1.0, 1.5}));
}

TEST(HistoryRecorder, KeepsTheFirstStepAtOrAfterEachMultipleOfTheInterval) {
  // Steps of 0.003 (times rounded as k dt): an interval of 10 steps keeps every tenth exactly,
  // though k * 0.003 misses 0.03 multiples in the last bits.
  const std::vector<double> tenth = kept_times({1, 0.03}, 0.003, 100);
  ASSERT_EQ(tenth.size(), 11u);
  for (std::size_t k = 0; k < tenth.size(); ++k)
    EXPECT_EQ(tenth[k], 10.0 * static_cast<double>(k) * 0.003);
  // An interval that is no multiple of the step: the first step past each multiple.
  EXPECT_EQ(kept_times({1, 0.25}, 0.1, 10),
            (std::vector<double>{0.0, 0.30000000000000004, 0.5, 0.8, 1.0}));
}

TEST(HistoryRecorder, HoldsWhatItsSamplingKeepsForTheMemoryCheck) {
  auto recorder = [](builder::OutputSampling sampling) {
    return HistoryRecorder("gap.csv",
                           std::make_unique<LinkQuantities>(std::vector<LinkRows>{{0, 0}},
                                                            std::vector<std::string>{"gap"}),
                           sampling);
  };
  EXPECT_EQ(recorder({}).held_values(1001, 10.0), 3.0 * 1001);
  EXPECT_EQ(recorder({10, 0.0}).held_values(1001, 10.0), 3.0 * 101);
  EXPECT_EQ(recorder({1, 0.5}).held_values(1001, 10.0), 3.0 * 21);
}

TEST(EnvelopeRecorder, GivesMaxMinTheirFirstTimesAndTheLargestMagnitudePerQuantity) {
  EnvelopeRecorder recorder(
      "envelope.csv", std::make_unique<LinkQuantities>(std::vector<LinkRows>{{0, 0}, {1, 1}},
                                                       std::vector<std::string>{"joint", "pad"}));
  const double forces[][3] = {{0, 1, -1}, {5, 2, 3}, {5, -7, 0}, {-2, 2, 1}};
  for (int k = 0; k < 4; ++k)
    recorder.record(link_state(0.1 * k, entries({forces[k][0], forces[k][1], forces[k][2]}),
                               entries({-0.1 * k, 0.0, 0.01 * k})));
  const Table table = recorder.table();
  ASSERT_EQ(table.text_columns.size(), 2u);
  EXPECT_EQ(table.text_columns[0].name, "quantity");
  EXPECT_EQ(table.text_columns[0].values,
            (std::vector<std::string>{"joint.force", "joint.penetration", "pad.force",
                                      "pad.penetration", "pad.tangential_force", "pad.slide"}));
  EXPECT_EQ(table.text_columns[1].name, "unit");
  EXPECT_EQ(table.columns,
            (std::vector<std::string>{"max", "time_of_max", "min", "time_of_min", "abs_max"}));
  auto row = [&](std::size_t r) {
    std::vector<double> values;
    for (const auto& column : table.values) values.push_back(column.at(r));
    return values;
  };
  EXPECT_EQ(row(0), (std::vector<double>{5.0, 0.1, -2.0, 0.30000000000000004, 5.0}));  // first 5
  EXPECT_EQ(row(2), (std::vector<double>{2.0, 0.1, -7.0, 0.2, 7.0}));
  EXPECT_EQ(row(4), (std::vector<double>{3.0, 0.1, -1.0, 0.0, 3.0}));
  EXPECT_EQ(recorder.held_values(1e9, 1e3), 0.0);
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

// An engagement whose work ends negative gave the structure that much (an open contact holds
// nothing); one still going counts when its work so far is negative.
TEST(LinkSummaries, CreatedEnergyIsTheNegativeWorkOfEachEngagement) {
  LinkSummaries summaries({0});
  const double forces[] = {0.0, 2.0, 4.0, 0.0, 0.0, 1.0};
  const double penetrations[] = {-0.001, 0.01, 0.005, -0.05, -0.05, -0.06};
  for (int k = 0; k < 6; ++k)
    summaries.record(link_state(0.1 * k, entries({forces[k]}), entries({penetrations[k]})));
  const LinkSummary& s = summaries.summaries().at(0);
  // First engagement: (2 0.011 + 6 (-0.005) + 4 (-0.055)) / 2 = -0.114; the second, going on:
  // 1 (-0.01) / 2 = -0.005.
  EXPECT_NEAR(s.finished_created_energy, 0.114, 1e-15);
  EXPECT_NEAR(s.engagement_work, -0.005, 1e-15);
  EXPECT_NEAR(s.created_energy(), 0.119, 1e-15);
  EXPECT_NEAR(s.work, -0.119, 1e-15);
}

// A contact engaged at the start (preloaded) held energy the run did not give it: giving it back
// creates nothing; the engagements after it count again.
TEST(LinkSummaries, AnEngagementUnderWayAtTheStartIsNotCounted) {
  LinkSummaries summaries({0});
  const double forces[] = {4.0, 2.0, 0.0, 0.0, 2.0, 0.0};
  const double penetrations[] = {0.02, 0.01, -0.01, -0.02, 0.01, -0.03};
  for (int k = 0; k < 6; ++k)
    summaries.record(link_state(0.1 * k, entries({forces[k]}), entries({penetrations[k]})));
  const LinkSummary& s = summaries.summaries().at(0);
  // Preloaded: (6 (-0.01) + 2 (-0.02)) / 2 = -0.05, not counted; then (2 0.03 + 2 (-0.04)) / 2
  // = -0.01, counted.
  EXPECT_NEAR(s.work, -0.06, 1e-15);
  EXPECT_NEAR(s.created_energy(), 0.01, 1e-15);
  EXPECT_EQ(s.impacts, 2);
}

// A positive engagement creates nothing (the first test's history: +0.01, then +0.0075).
TEST(LinkSummaries, AnEngagementThatTookEnergyCreatedNone) {
  LinkSummaries summaries({0});
  const double forces[] = {0.0, 2.0, 4.0, 0.0, 1.0};
  const double penetrations[] = {-0.02, 0.01, 0.03, -0.01, 0.005};
  for (int k = 0; k < 5; ++k)
    summaries.record(link_state(0.1 * k, entries({forces[k]}), entries({penetrations[k]})));
  EXPECT_EQ(summaries.summaries().at(0).created_energy(), 0.0);
  EXPECT_NEAR(summaries.summaries().at(0).engagement_work, 0.0075, 1e-15);
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

// The summaries keep their running quantities by column (one array per quantity over the links);
// each link must still get what following it alone by the definitions gives: five links on
// seven rows, engagements starting and ending at random, one link's force a step
// force (rectangle rule), one in contact at the start, over 2,000 steps.
// Rows apart (gathered) or one after the other (copied).
void expect_each_link_followed_alone(const std::vector<Index>& rows) {
  LinkSummaries summaries(rows);
  std::vector<char> step_rows(7, 0);
  step_rows[static_cast<std::size_t>(rows[2])] = 1;
  summaries.set_step_forces(step_rows);
  std::vector<LinkSummary> reference(rows.size());
  std::vector<double> previous_force(rows.size()), previous_penetration(rows.size());
  std::uint64_t seed = 12345;
  const auto uniform = [&seed] {  // in [0, 1), the same on every platform
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(seed >> 11) * 0x1.0p-53;
  };
  double time = 0.0;
  for (int step = 0; step < 2000; ++step) {
    Vector force = Vector::Zero(7), penetration = Vector::Zero(7);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const Index row = rows[k];
      penetration[row] = 0.02 * (uniform() - 0.5);
      const bool contact = (step == 0 && k == 1) || uniform() < 0.3;
      force[row] = contact ? 1e6 * (uniform() - 0.2) : 0.0;
    }
    const double dt = step == 0 ? 0.0 : 0.001 + 0.001 * uniform();
    time += dt;
    summaries.record(link_state(time, force, penetration));
    for (std::size_t k = 0; k < rows.size(); ++k) {
      LinkSummary& s = reference[k];
      const double f = force[rows[k]], d = penetration[rows[k]];
      const bool contact = f != 0.0, was = step > 0 && previous_force[k] != 0.0;
      if (step > 0) {
        const double average = k == 2 ? f : 0.5 * (f + previous_force[k]);
        s.impulse += average * dt;
        s.work += average * (d - previous_penetration[k]);
        s.engagement_work += average * (d - previous_penetration[k]);
      }
      if (contact && !was) {
        ++s.impacts;
        s.engaged_at_start = s.engaged_at_start || step == 0;
        if (s.first_contact < 0.0) s.first_contact = time;
      }
      if (!contact && was) {
        if (!s.engaged_at_start) s.finished_created_energy += std::max(0.0, -s.engagement_work);
        s.engagement_work = 0.0;
        s.engaged_at_start = false;
      }
      if (contact) s.last_contact = time;
      s.peak_force = std::max(s.peak_force, f);
      s.peak_tension = std::max(s.peak_tension, -f);
      s.peak_penetration = std::max(s.peak_penetration, d);
      s.peak_opening = std::max(s.peak_opening, -d);
      s.final_force = f;
      s.final_deformation = d;
      previous_force[k] = f;
      previous_penetration[k] = d;
    }
  }
  // Sums within rounding (the library may fuse a product into its sum, this file does not);
  // everything else exactly.
  double worst = 0.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const LinkSummary &s = summaries.summaries()[k], &r = reference[k];
    EXPECT_GE(r.impacts, 100) << "link " << k << ": too few engagements to test";
    EXPECT_EQ(s.impacts, r.impacts) << "link " << k;
    EXPECT_EQ(s.engaged_at_start, r.engaged_at_start) << "link " << k;
    EXPECT_EQ(s.first_contact, r.first_contact) << "link " << k;
    EXPECT_EQ(s.last_contact, r.last_contact) << "link " << k;
    EXPECT_EQ(s.peak_force, r.peak_force) << "link " << k;
    EXPECT_EQ(s.peak_tension, r.peak_tension) << "link " << k;
    EXPECT_EQ(s.peak_penetration, r.peak_penetration) << "link " << k;
    EXPECT_EQ(s.peak_opening, r.peak_opening) << "link " << k;
    EXPECT_EQ(s.final_force, r.final_force) << "link " << k;
    EXPECT_EQ(s.final_deformation, r.final_deformation) << "link " << k;
    const double scale = 1e6 * 0.02 * 2000;  // |F| |d delta| summed over the steps
    for (const auto& [got, expected] :
         {std::pair{s.impulse, r.impulse}, std::pair{s.work, r.work},
          std::pair{s.engagement_work, r.engagement_work},
          std::pair{s.finished_created_energy, r.finished_created_energy}})
      worst = std::max(worst, std::abs(got - expected) / scale);
  }
  std::cout << "largest difference of a sum, relative to its scale: " << worst << "\n";
  EXPECT_LT(worst, 1e-14);
}

TEST(LinkSummaries, EachLinkGetsWhatFollowingItAloneGives) {
  expect_each_link_followed_alone({0, 2, 3, 5, 6});
  expect_each_link_followed_alone({1, 2, 3, 4, 5});
}

}  // namespace
}  // namespace pound::results
