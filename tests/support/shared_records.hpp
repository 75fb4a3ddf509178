#pragma once
// The real ground-motion records CI keeps beside the checkout, in ../shared/ground_motions
// (PROVENANCE.md there says where each comes from). A fresh clone has no such folder: the tests
// that read them skip, saying why, and the rest of the suite still runs.
#include <gtest/gtest.h>

#include <cstddef>
#include <filesystem>
#include <string>

#include "io/ground_motion_reader.hpp"
#include "model/ground_motion.hpp"

namespace pound::testing {

inline constexpr char kSharedRecordsFolder[] = POUND_SOURCE_DIR "/../shared/ground_motions";

inline bool shared_records_present() { return std::filesystem::is_directory(kSharedRecordsFolder); }

// The path of one of the real records.
inline std::string shared_record(const std::string& file) {
  return std::string(kSharedRecordsFolder) + "/" + file;
}

// The first `samples` of El Centro 1940 (array 9, 180 degrees, PEER 2000 AT2) in m/s^2.
inline model::GroundMotion el_centro(std::size_t samples) {
  io::RecordFormat format;
  format.format = "at2";
  model::GroundMotion motion = io::read_ground_motion(
      shared_record("ImperialValley1940_ElCentroArray9_180_PEER2000.AT2"), format, 9.80665);
  motion.acceleration.resize(samples);
  return motion;
}

}  // namespace pound::testing

// Skips (returns from) the current test when the real records are absent. The empty branch
// keeps a following `else` from binding to the macro's `if`.
#define POUND_SKIP_WITHOUT_SHARED_RECORDS()                                                  \
  if (::pound::testing::shared_records_present()) {                                          \
  } else                                                                                     \
    GTEST_SKIP() << "needs ../shared/ground_motions (the real records), absent beside this " \
                    "checkout"
