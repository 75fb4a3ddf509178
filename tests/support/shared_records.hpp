#pragma once
// The real ground-motion records CI keeps beside the checkout, in ../shared/ground_motions
// (PROVENANCE.md there says where each comes from). A fresh clone has no such folder: the tests
// that read them skip, saying why, and the rest of the suite still runs.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace pound::testing {

inline constexpr char kSharedRecordsFolder[] = POUND_SOURCE_DIR "/../shared/ground_motions";

inline bool shared_records_present() { return std::filesystem::is_directory(kSharedRecordsFolder); }

// The path of one of the real records.
inline std::string shared_record(const std::string& file) {
  return std::string(kSharedRecordsFolder) + "/" + file;
}

}  // namespace pound::testing

// Skips (returns from) the current test when the real records are absent. The empty branch
// keeps a following `else` from binding to the macro's `if`.
#define POUND_SKIP_WITHOUT_SHARED_RECORDS()                                                  \
  if (::pound::testing::shared_records_present()) {                                          \
  } else                                                                                     \
    GTEST_SKIP() << "needs ../shared/ground_motions (the real records), absent beside this " \
                    "checkout"
