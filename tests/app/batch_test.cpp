// `pound batch` end to end: real records read in place from ../shared, the project's records, a
// deliberately broken record, determinism over --jobs and MPI ranks, kill and --resume.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/process.hpp"
#include "support/shared_records.hpp"

namespace pound::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSource = POUND_SOURCE_DIR;

// Every line of a CSV without its last cell (run_time_s, the one column that may vary).
std::string without_run_time(const std::string& csv) {
  std::istringstream in(csv);
  std::string line, out;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

std::vector<std::vector<std::string>> rows_of(const std::string& csv) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(csv);
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
      if (c == '"')
        quoted = !quoted;
      else if (c == ',' && !quoted)
        cells.push_back(std::exchange(cell, std::string()));
      else
        cell += c;
    }
    cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

std::string cell(const std::vector<std::vector<std::string>>& rows, std::size_t row,
                 const std::string& column) {
  const auto& header = rows.front();
  const auto found = std::find(header.begin(), header.end(), column);
  EXPECT_NE(found, header.end()) << column;
  return rows.at(row).at(static_cast<std::size_t>(found - header.begin()));
}

class Batch : public PoundProcess {
 protected:
  // A set of the textbook two-girder model (fast) under three real records in three formats,
  // one bundled record and one broken record, at two scales.
  std::string write_set(const std::string& extra = "") {
    std::ofstream(path("broken.AT2")) << "PEER STRONG MOTION DATABASE RECORD\nbroken\nUNITS OF G\n"
                                         "NPTS=   100, DT=   .0100 SEC\n 0.1 0.2 abc 0.3\n";
    const std::string set = fmt::format(
        R"({{
  "title": "two girders, real records",
  "models": ["{0}/models/two_sdof_girders.json"],
  "records": [
    {{"file": "{1}/Northridge1994_Rinaldi_228.AT2"}},
    {{"file": "{1}/ImperialValley1940_ElCentroArray9_180_PEER2000.AT2"}},
    {{"file": "{1}/Kobe1995_JMA_NS-EW_cms2_dt0.005.txt", "format": "columns", "column": 2,
      "units": "cm/s2", "time_step": 0.005}},
    {{"file": "broken.AT2"}},
    {{"file": "{0}/ground_motions/synthetic_firm_01.AT2", "scale": {{"pga": 0.3}}}}
  ],
  "scales": [1, 2],
  "limits": {{"max_joint_opening": 0.05}}{2}
}})",
        kSource, kSharedRecordsFolder, extra);
    std::ofstream(path("set.json")) << set;
    return path("set.json").string();
  }
};

TEST_F(Batch, RunsRealRecordsInPlaceAndIsolatesABrokenRecord) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const std::string set = write_set();
  const Outcome outcome = pound({"batch", set, "--out", path("out").string(), "--jobs", "2"});
  EXPECT_EQ(outcome.exit_code, 3) << outcome.err;  // one record is broken
  EXPECT_NE(outcome.err.find("2 of 10 cases failed"), std::string::npos) << outcome.err;
  const auto rows = rows_of(read_text(path("out/batch_summary.csv")));
  ASSERT_EQ(rows.size(), 11u);
  // Plan order: record by record, scale by scale.
  EXPECT_EQ(cell(rows, 1, "name"), "two_sdof_girders/Northridge1994_Rinaldi_228/x1");
  EXPECT_EQ(cell(rows, 6, "name"), "two_sdof_girders/Kobe1995_JMA_NS-EW_cms2_dt0.005_col2/x2");
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const std::string name = cell(rows, r, "name");
    const bool broken = name.find("/broken/") != std::string::npos;
    EXPECT_EQ(cell(rows, r, "status"), broken ? "input_error" : "completed") << name;
    EXPECT_TRUE(fs::is_regular_file(path("out") / name / "summary.json")) << name;
    EXPECT_TRUE(fs::is_regular_file(path("out") / name / "case.csv")) << name;
    EXPECT_EQ(fs::is_regular_file(path("out") / name / "joint.csv"), !broken) << name;
    if (broken) {
      EXPECT_NE(cell(rows, r, "reason").find("broken.AT2: line 5"), std::string::npos)
          << cell(rows, r, "reason");
    }
  }
  // The records were read right: the PGA at scale 1 is the one PROVENANCE.md computed.
  EXPECT_NEAR(std::stod(cell(rows, 1, "pga_g")), 0.874, 0.0005);  // Rinaldi 228
  EXPECT_NEAR(std::stod(cell(rows, 3, "pga_g")), 0.313, 0.0005);  // El Centro PEER 2000
  EXPECT_NEAR(std::stod(cell(rows, 5, "pga_g")), 0.631, 0.0005);  // Kobe JMA, column 2 (EW)
  EXPECT_NEAR(std::stod(cell(rows, 6, "pga_g")), 2 * 0.631, 0.001);
  EXPECT_NEAR(std::stod(cell(rows, 9, "pga_g")), 0.3, 1e-12);  // scaled to a target
  EXPECT_NEAR(std::stod(cell(rows, 10, "pga_g")), 0.6, 1e-12);
  // Statistics over the completed cases, with the exceedance of the limit per scale.
  const nlohmann::json stats = nlohmann::json::parse(read_text(path("out/batch_stats.json")));
  EXPECT_EQ(stats["cases"], 10);
  EXPECT_EQ(stats["completed"], 8);
  EXPECT_EQ(stats["input_errors"], 2);
  ASSERT_EQ(stats["groups"].size(), 2u);
  EXPECT_EQ(stats["groups"][0]["completed"], 4);
  const auto& opening = stats["groups"][0]["responses"]["max_joint_opening"];
  EXPECT_LE(opening["median"].get<double>(), opening["p84"].get<double>());
  EXPECT_LE(opening["p84"].get<double>(), opening["max"].get<double>());
  EXPECT_EQ(stats["groups"][0]["exceedance"]["max_joint_opening"]["count"], 4);
  EXPECT_EQ(stats["fragility"].size(), 1u);
  EXPECT_FALSE(fs::exists(path("out/.partial")) && !fs::is_empty(path("out/.partial")));
}

TEST_F(Batch, GivesTheSameResultsWhateverTheNumberOfWorkers) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const std::string set = write_set();
  const Outcome one = pound({"batch", set, "--out", path("one").string(), "--jobs", "1", "-q"});
  const Outcome two = pound({"batch", set, "--out", path("two").string(), "--jobs", "3", "-q"});
  ASSERT_EQ(one.exit_code, 3) << one.err;
  ASSERT_EQ(two.exit_code, 3) << two.err;
  EXPECT_EQ(without_run_time(read_text(path("one/batch_summary.csv"))),
            without_run_time(read_text(path("two/batch_summary.csv"))));
  EXPECT_EQ(read_text(path("one/batch_stats.json")), read_text(path("two/batch_stats.json")));
  const std::string history = "two_sdof_girders/Northridge1994_Rinaldi_228/x2/joint.csv";
  EXPECT_EQ(read_text(path("one") / history), read_text(path("two") / history));
}

#ifdef POUND_TEST_MPIRUN
TEST_F(Batch, UnderMpirunWithTwoRanksGivesTheThreadedResults) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const std::string set = write_set();
  const Outcome threads = pound({"batch", set, "--out", path("threads").string(), "-q"});
  ASSERT_EQ(threads.exit_code, 3) << threads.err;
  // Open MPI leaks at exit (its operation tables and plugins, which LeakSanitizer reports in
  // the sanitizer build): leak checking is off for the ranks only. The threaded runs above and
  // the other tests keep it.
  const std::string command = fmt::format(
      "ASAN_OPTIONS=detect_leaks=0 {} --oversubscribe --allow-run-as-root "
      "-x ASAN_OPTIONS -np 2 {} batch {} --out {} >{} 2>{}",
      shell_quoted(POUND_TEST_MPIRUN), shell_quoted(POUND_BINARY), shell_quoted(set),
      shell_quoted(path("ranks").string()), shell_quoted(path("mpi_out.txt").string()),
      shell_quoted(path("mpi_err.txt").string()));
  const int status = std::system(command.c_str());
  const std::string out = read_text(path("mpi_out.txt"));
  // mpirun passes on the highest exit code of its ranks: rank 0 reports the failed cases.
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 3)
      << out << read_text(path("mpi_err.txt"));
  EXPECT_NE(out.find("run on 2 rank(s) x 1 worker(s)"), std::string::npos) << out;
  EXPECT_EQ(without_run_time(read_text(path("threads/batch_summary.csv"))),
            without_run_time(read_text(path("ranks/batch_summary.csv"))));
  EXPECT_EQ(read_text(path("threads/batch_stats.json")), read_text(path("ranks/batch_stats.json")));
}
#endif

// Kill a batch part-way, then --resume it: the complete cases are kept, the rest run, and the
// summary is the one an uninterrupted run gives.
TEST_F(Batch, SurvivesBeingKilledAndResumesToTheSameResults) {
  // The bridge model, so cases take long enough to kill the batch between them.
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["{0}/models/three_span_bridge.json"],
           "records": [{{"folder": "{0}/ground_motions", "pattern": "*.AT2", "scale": {{"pga": 0.3}}}}],
           "scales": [0.5, 1, 1.5]}})",
      kSource);
  const std::string set = path("set.json").string();
  const Outcome whole = pound({"batch", set, "--out", path("whole").string(), "-q"});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;

  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string out = path("killed").string();
    ::execl(POUND_BINARY, POUND_BINARY, "batch", set.c_str(), "--out", out.c_str(), "--jobs", "1",
            "-q", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // Wait for a few complete cases, then kill it without warning.
  auto complete = [&] {
    int count = 0;
    std::error_code ignored;
    for (const auto& entry : fs::recursive_directory_iterator(path("killed"), ignored))
      count += entry.path().filename() == "case.csv" &&
               entry.path().string().find(".partial") == std::string::npos;
    return count;
  };
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (complete() < 3 && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(child, SIGKILL);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the batch ended before it could be killed";
  const int kept = complete();
  EXPECT_GE(kept, 3);
  EXPECT_LT(kept, 12);
  EXPECT_FALSE(fs::exists(path("killed/batch_summary.csv")));

  const Outcome again = pound({"batch", set, "--out", path("killed").string()});
  EXPECT_EQ(again.exit_code, 2) << again.err;  // not without --resume
  EXPECT_NE(again.err.find("holds a batch already: add --resume"), std::string::npos) << again.err;

  const Outcome resumed = pound({"batch", set, "--out", path("killed").string(), "--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find(fmt::format("12 cases ({} resumed, {} run", kept, 12 - kept)),
            std::string::npos)
      << resumed.out;
  EXPECT_EQ(without_run_time(read_text(path("whole/batch_summary.csv"))),
            without_run_time(read_text(path("killed/batch_summary.csv"))));
  EXPECT_EQ(read_text(path("whole/batch_stats.json")), read_text(path("killed/batch_stats.json")));
  EXPECT_TRUE(!fs::exists(path("killed/.partial")) || fs::is_empty(path("killed/.partial")));

  // Resuming a complete batch runs nothing and changes nothing.
  const Outcome nothing = pound({"batch", set, "--out", path("killed").string(), "--resume"});
  ASSERT_EQ(nothing.exit_code, 0) << nothing.err;
  EXPECT_NE(nothing.out.find("12 cases (12 resumed, 0 run"), std::string::npos) << nothing.out;
  EXPECT_EQ(read_text(path("whole/batch_stats.json")), read_text(path("killed/batch_stats.json")));
}

TEST_F(Batch, RefusesAChangedSetOnResume) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  const std::string set = write_set();
  ASSERT_EQ(pound({"batch", set, "--out", path("out").string(), "-q"}).exit_code, 3);
  write_set(R"(, "scales": [1, 3])");
  std::string text = read_text(path("set.json"));
  text.replace(text.find(R"("scales": [1, 2],)"), std::string(R"("scales": [1, 2],)").size(), "");
  std::ofstream(path("set.json")) << text;
  const Outcome outcome = pound({"batch", set, "--out", path("out").string(), "--resume"});
  EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
  EXPECT_NE(outcome.err.find("are not those of the batch in"), std::string::npos) << outcome.err;
}

TEST_F(Batch, ABadSetWritesNothing) {
  std::ofstream(path("set.json")) << R"({"models": ["nowhere.json"], "records": []})";
  const Outcome outcome =
      pound({"batch", path("set.json").string(), "--out", path("out").string()});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find("set.json: /models/0: model file"), std::string::npos) << outcome.err;
  EXPECT_FALSE(fs::exists(path("out")));
  // A model with an error fails the batch before anything runs, naming the model file.
  std::ofstream(path("model.json")) << R"({"nodes": [], "analysis": {"time_step": -1}})";
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["model.json"], "records": [{{"file": "{}/ground_motions/synthetic_firm_01.AT2"}}]}})",
      kSource);
  const Outcome model = pound({"batch", path("set.json").string(), "--out", path("out").string()});
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_NE(model.err.find("model.json: /analysis/time_step"), std::string::npos) << model.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

}  // namespace
}  // namespace pound::testing
