#include "io/case_rows.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/errors.hpp"
#include "results/batch_quantities.hpp"

namespace pound::io {
namespace {

results::CaseSummary full_row() {
  results::CaseSummary c;
  c.name = "bridge/kobe/x1.5";
  c.model = "bridge";
  c.record = "kobe";
  c.scale = 1.5;
  c.status = results::CaseStatus::failed;
  c.reason = R"(analysis failed at t = 3.2: "Newton", did not converge)";
  c.pga_g = 0.1 + 0.2;  // 0.30000000000000004: must come back exactly
  c.intensity = std::nextafter(1.0, 2.0);
  c.end_time = 3.2;
  c.steps = 2133;
  c.impacts = 12;
  c.max_pounding_force = 1.234567890123456789e7;
  c.max_pounding_link = "bridge.a0.joint";
  c.max_joint_opening = 5e-324;  // the smallest subnormal
  c.unseated = false;
  c.max_ductility = 1.0 / 3.0;
  c.energy_balance_error = 4.5e-12;
  c.run_time_s = 0.125;
  return c;
}

TEST(CaseRows, ReadBackGivesTheSameNumbersAndTheSameText) {
  const results::CaseSummary c = full_row();
  const std::string row = case_row(c);
  const results::CaseSummary back = parse_case_row(row, "case.csv");
  EXPECT_EQ(case_row(back), row);
  EXPECT_EQ(back.reason, c.reason);
  EXPECT_EQ(back.pga_g, c.pga_g);
  EXPECT_EQ(back.intensity, c.intensity);
  EXPECT_EQ(back.max_pounding_force, c.max_pounding_force);
  EXPECT_EQ(back.max_joint_opening, c.max_joint_opening);
  EXPECT_EQ(back.max_ductility, c.max_ductility);
  EXPECT_EQ(back.unseated, std::optional<bool>(false));
  EXPECT_FALSE(back.max_drift_ratio.has_value());  // absent stays absent, not 0
  EXPECT_FALSE(back.max_restrainer_force.has_value());
}

TEST(CaseRows, HeaderHasOneNamePerCell) {
  const std::string header = case_row_header();
  const std::string row = case_row(results::CaseSummary());
  EXPECT_EQ(std::count(header.begin(), header.end(), ','), std::count(row.begin(), row.end(), ','));
  EXPECT_EQ(header.rfind("name,model,record,scale,status,reason,", 0), 0u);
}

// The columns of batch_summary.csv, which users' scripts read by name and position.
TEST(CaseRows, HeaderKeepsItsColumnsAndTheirOrder) {
  EXPECT_EQ(case_row_header(),
            "name,model,record,scale,status,reason,pga_g,intensity,end_time,steps,impacts,"
            "max_pounding_force,max_pounding_link,max_restrainer_force,max_restrainer_link,"
            "max_joint_opening,max_seat_movement,min_unseating_margin,unseated,max_drift_ratio,"
            "max_ductility,max_residual_drift_ratio,energy_balance_error,max_top_acceleration,"
            "max_deck_acceleration,warnings,run_time_s");
}

// Every quantity of the table is a column, and reads back into its own member.
TEST(CaseRows, EveryBatchQuantityIsAColumnThatReadsBack) {
  const std::string header = "," + case_row_header() + ",";
  for (const results::BatchQuantity& q : results::batch_quantities()) {
    EXPECT_NE(header.find("," + std::string(q.name) + ","), std::string::npos) << q.name;
    results::CaseSummary c;
    c.*q.value = 0.125;
    EXPECT_EQ(parse_case_row(case_row(c), "case.csv").*q.value, 0.125) << q.name;
  }
}

TEST(CaseRows, DamagedRowsAreInputErrors) {
  const std::string row = case_row(full_row());
  EXPECT_THROW(parse_case_row(row + ",extra", "x.csv"), InputError);
  EXPECT_THROW(parse_case_row("a,b", "x.csv"), InputError);
  std::string bad_number = row;
  bad_number.replace(bad_number.find("2133"), 4, "21x3");
  try {
    parse_case_row(bad_number, "x.csv");
    FAIL() << "accepted " << bad_number;
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("column steps: '21x3' is not a number"),
              std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace pound::io
