// What a user reads of an error: the file, where in it, and what is wrong; the time and reason
// of a failed analysis.
#include "core/errors.hpp"

#include <gtest/gtest.h>

namespace pound {
namespace {

TEST(InputError, NamesTheFileThePlaceAndTheReason) {
  const InputError error("models/x.json", "/links/0/gap", "must be >= 0, got -0.01");
  EXPECT_STREQ(error.what(), "models/x.json: /links/0/gap: must be >= 0, got -0.01");
  EXPECT_EQ(error.file(), "models/x.json");
  EXPECT_EQ(error.where(), "/links/0/gap");
  EXPECT_EQ(error.reason(), "must be >= 0, got -0.01");
}

TEST(InputError, LeavesOutWhatIsNotKnown) {
  EXPECT_STREQ(InputError("", "line 4", "expected NPTS").what(), "line 4: expected NPTS");
  EXPECT_STREQ(InputError("r.AT2", "", "no such file").what(), "r.AT2: no such file");
  EXPECT_STREQ(InputError("", "", "bad").what(), "bad");
}

TEST(InputError, CanBePlacedInAFileLearnedLater) {
  const InputError error = InputError("", "line 4", "expected NPTS").in_file("r.AT2");
  EXPECT_STREQ(error.what(), "r.AT2: line 4: expected NPTS");
  EXPECT_EQ(error.where(), "line 4");
  EXPECT_EQ(error.reason(), "expected NPTS");
}

TEST(SolveError, SaysWhenAndWhy) {
  const SolveError error(3.25, "Newton did not converge");
  EXPECT_STREQ(error.what(), "analysis failed at t = 3.25: Newton did not converge");
  EXPECT_EQ(error.time(), 3.25);
  EXPECT_EQ(error.reason(), "Newton did not converge");
  EXPECT_STREQ(SolveError(1.0 / 3.0, "x").what(), "analysis failed at t = 0.333333: x");
}

}  // namespace
}  // namespace pound
