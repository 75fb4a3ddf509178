// A model or a run too large for the memory this process may use is refused before it is
// allocated, with the file, the JSON path and the sizes, not killed by the kernel or aborted by
// std::bad_alloc. The tests give pound a small address space (ulimit -v), as a cluster job
// limit would; AddressSanitizer reserves terabytes of address space at start, so they cannot
// run in the sanitizer build.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "support/process.hpp"
#include "support/sanitizers.hpp"

namespace pound::testing {
namespace {

// A macro: GTEST_SKIP returns from the test itself.
#define POUND_SKIP_UNDER_ASAN() \
  if (kUnderAddressSanitizer) GTEST_SKIP() << "ulimit -v cannot be used under AddressSanitizer"

class Resources : public PoundProcess {
 protected:
  // `pound run MODEL` with at most `kilobytes` of address space.
  Outcome run_limited(const std::string& model, long kilobytes) {
    std::ofstream(path("run.sh")) << fmt::format(
        "ulimit -v {} && exec {} run {} --out {} >{} 2>{}\n", kilobytes, shell_quoted(POUND_BINARY),
        shell_quoted(model), shell_quoted(path("out").string()),
        shell_quoted(path("stdout.txt").string()), shell_quoted(path("stderr.txt").string()));
    const int status = std::system(("bash " + shell_quoted(path("run.sh").string())).c_str());
    Outcome outcome;
    outcome.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.out = read_text(path("stdout.txt"));
    outcome.err = read_text(path("stderr.txt"));
    return outcome;
  }

  std::string rods(int elements, double duration, const std::string& recorders) {
    const double time_step = 10.0 / elements / 31.622776601683793;
    std::ofstream(path("model.json")) << fmt::format(
        R"({{"dimension": 1,
  "generators": [{{"type": "rod_pair", "id": "rods",
    "left": {{"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": {0}, "initial_velocity": 0.1}},
    "right": {{"youngs_modulus": 100, "density": 0.1, "area": 1, "length": 10, "elements": {0}, "initial_velocity": -0.1}},
    "law": {{"type": "gap_spring", "stiffness_ratio": 1}}}}],
  "analysis": {{"time_step": {1}, "duration": {2}}}{3}}})",
        elements, time_step, duration, recorders);
    return path("model.json").string();
  }
};

TEST_F(Resources, AModelTooLargeForMemoryIsRefusedBeforeItIsBuilt) {
  POUND_SKIP_UNDER_ASAN();
  // 10^6 DOFs: about 0.85 GiB to run, refused in a 0.6 GiB address space.
  const Outcome outcome = run_limited(rods(500000, 1e-3, ""), 600000);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("model.json: /generators/0: the model would have up to 1000002 DOFs"),
            std::string::npos)
      << outcome.err;
  EXPECT_NE(outcome.err.find("GiB of memory available"), std::string::npos) << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

TEST_F(Resources, HistoriesTooLargeForMemoryAreRefusedBeforeTheRun) {
  POUND_SKIP_UNDER_ASAN();
  // 2002 nodes x 4 columns (u, v, a_rel, a_abs) + time over 3.2e5 steps: about 57 GiB of history.
  std::string nodes;
  for (int k = 0; k <= 1000; ++k)
    nodes += fmt::format("{}\"rods.left.{}\", \"rods.right.{}\"", k ? ", " : "", k, k);
  const std::string model = rods(
      1000, 100.0, fmt::format(R"(, "recorders": [{{"type": "node", "nodes": [{}]}}])", nodes));
  const Outcome outcome = run_limited(model, 2000000);
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("model.json: /recorders: recording 2.53e+09 values over"),
            std::string::npos)
      << outcome.err;
  EXPECT_FALSE(std::filesystem::exists(path("out")));
}

// The same limit does not stop a model that fits: 10^5 DOFs run in 0.6 GiB (measured peak
// resident memory 90 MB for 200 steps).
TEST_F(Resources, ATenToTheFiveDofModelRunsInALimitedAddressSpace) {
  POUND_SKIP_UNDER_ASAN();
  const Outcome outcome =
      run_limited(rods(50000, 200 * 10.0 / 50000 / 31.622776601683793, ""), 600000);
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
}

// A record read whole but used for a sliver of its length is worth a warning: the duration may
// be a typo.
TEST_F(Resources, ARecordMuchLongerThanTheAnalysisIsPointedOut) {
  std::string model = read_text(std::string(POUND_SOURCE_DIR) + "/models/two_sdof_girders.json");
  const std::string step = "\"time_step\": 0.002", records = "../ground_motions";
  model.replace(model.find(step), step.size(), step + ", \"duration\": 1.5");
  model.replace(model.find(records), records.size(),
                std::string(POUND_SOURCE_DIR) + "/ground_motions");
  std::ofstream(path("model.json")) << model;
  const Outcome outcome =
      pound({"run", path("model.json").string(), "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_NE(outcome.err.find("lasts 30 s but the analysis stops at 1.5 s: only its first 5.0 %"),
            std::string::npos)
      << outcome.err;
}

}  // namespace
}  // namespace pound::testing
