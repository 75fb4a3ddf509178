// `pound batch` end to end: real records read in place from ../shared, the project's records, a
// deliberately broken record, determinism over --jobs and MPI ranks, kill and --resume.
#include "app/batch.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "app/cluster.hpp"
#include "io/folder_lock.hpp"
#include "support/collapsing_column.hpp"
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

  // The bridge model under the four bundled records at three scales: 12 cases, each long enough
  // to stop the batch between them.
  std::string write_bridge_set() {
    std::ofstream(path("set.json")) << fmt::format(
        R"({{"models": ["{0}/models/three_span_bridge.json"],
           "records": [{{"folder": "{0}/ground_motions", "pattern": "*.AT2", "scale": {{"pga": 0.3}}}}],
           "scales": [0.5, 1, 1.5]}})",
        kSource);
    return path("set.json").string();
  }

  // A set of the two-girder model under the bundled records, with the model and one record copied
  // into the test's folder so that a test can edit them.
  std::string write_bundled_set(const std::string& scales) {
    fs::copy_file(kSource + "/models/two_sdof_girders.json", path("model.json"));
    fs::copy_file(kSource + "/ground_motions/synthetic_firm_01.AT2", path("record.AT2"));
    std::ofstream(path("set.json")) << fmt::format(
        R"({{"models": ["model.json"],
             "records": [{{"file": "record.AT2"}},
                         {{"folder": "{}/ground_motions", "pattern": "*soft*.AT2"}}],
             "scales": {}}})",
        kSource, scales);
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
  const std::string set = write_bridge_set();
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
  // The killed batch's lock file stays; its lock died with it and blocks nothing below.
  EXPECT_TRUE(fs::is_regular_file(path("killed/.lock")));

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

TEST_F(Batch, StoppedBySigtermSaysSoKeepsTheEndedCasesAndResumes) {
  const std::string set = write_bridge_set();
  const std::string out = path("stopped").string(), messages = path("stderr.txt").string();
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int file = ::open(messages.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(file, STDERR_FILENO);
    ::execl(POUND_BINARY, POUND_BINARY, "batch", set.c_str(), "--out", out.c_str(), "--jobs", "2",
            "-q", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!fs::exists(path("stopped/three_span_bridge")) &&
         std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal, not by pound";
  EXPECT_EQ(WEXITSTATUS(status), 143);
  const std::string err = read_text(path("stderr.txt"));
  EXPECT_NE(err.find("pound batch: interrupted by SIGTERM: the cases that ended are kept; add "
                     "--resume to run the rest"),
            std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(path("stopped/batch_summary.csv")));
  const Outcome resumed = pound({"batch", set, "--out", out, "--resume", "-q"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const Outcome whole = pound({"batch", set, "--out", path("whole").string(), "-q"});
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  EXPECT_EQ(without_run_time(read_text(path("whole/batch_summary.csv"))),
            without_run_time(read_text(path("stopped/batch_summary.csv"))));
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
  EXPECT_NE(outcome.err.find("changed since the batch in"), std::string::npos) << outcome.err;
  EXPECT_NE(outcome.err.find(set), std::string::npos) << outcome.err;
}

// Issue 14: a --resume started while the first batch still ran wrote into the same case folders
// (one of the two exited 4, or a case kept case.csv without its histories). The folder is locked
// for the whole batch: the second is refused, naming the folder and the first one's PID, and
// the first completes untouched.
TEST_F(Batch, ASecondBatchInABusyFolderIsRefusedAndTheFirstCompletes) {
  const std::string set = write_bundled_set("[0.5, 1, 1.5, 2, 2.5, 3]");
  const std::string out = path("out").string();
  const pid_t first = ::fork();
  ASSERT_GE(first, 0);
  if (first == 0) {
    ::execl(POUND_BINARY, POUND_BINARY, "batch", set.c_str(), "--out", out.c_str(), "--jobs", "1",
            "-q", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  // The plan is written under the lock, and the holder's PID before it.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!fs::exists(path("out/batch_plan.json")) && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const Outcome resumed = pound({"batch", set, "--out", out, "--resume"});
  const Outcome again = pound({"batch", set, "--out", out});
  int status = 0;
  ::waitpid(first, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the first batch was killed";
  EXPECT_EQ(WEXITSTATUS(status), 0);

  for (const Outcome& second : {resumed, again}) {
    EXPECT_EQ(second.exit_code, 4) << second.err;
    EXPECT_NE(second.err.find(out + ": in use by another batch (process " + std::to_string(first)),
              std::string::npos)
        << second.err;
  }
  const auto rows = rows_of(read_text(path("out/batch_summary.csv")));
  ASSERT_EQ(rows.size(), 19u);
  for (std::size_t r = 1; r < rows.size(); ++r) {
    EXPECT_EQ(cell(rows, r, "status"), "completed") << cell(rows, r, "name");
    EXPECT_TRUE(fs::is_regular_file(path("out") / cell(rows, r, "name") / "joint.csv"));
  }
  // Once it has finished, the folder is free again (the lock file stays, the lock does not).
  const Outcome after = pound({"batch", set, "--out", out, "--resume"});
  EXPECT_EQ(after.exit_code, 0) << after.err;
  EXPECT_NE(after.out.find("18 cases (18 resumed, 0 run"), std::string::npos) << after.out;
}

#ifdef POUND_TEST_MPIRUN
// Under mpirun, rank 0 takes the lock for every rank: all of them stop, with rank 0's message
// and exit code 4 (not an MPI abort), when another process holds the folder (here, this test).
TEST_F(Batch, UnderMpirunABusyFolderStopsEveryRank) {
  const std::string set = write_bundled_set("[1]");
  const std::string out = path("out").string();
  ASSERT_EQ(pound({"batch", set, "--out", out, "-q"}).exit_code, 0);
  const io::FolderLock held(out);
  const std::string command = fmt::format(
      "ASAN_OPTIONS=detect_leaks=0 {} --oversubscribe --allow-run-as-root "
      "-x ASAN_OPTIONS -np 2 {} batch {} --out {} --resume >{} 2>{}",
      shell_quoted(POUND_TEST_MPIRUN), shell_quoted(POUND_BINARY), shell_quoted(set),
      shell_quoted(out), shell_quoted(path("mpi_out.txt").string()),
      shell_quoted(path("mpi_err.txt").string()));
  const int status = std::system(command.c_str());
  const std::string err = read_text(path("mpi_err.txt"));
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 4) << err;
  EXPECT_NE(err.find(fmt::format("{}: in use by another batch (process {}", out, ::getpid())),
            std::string::npos)
      << err;
  EXPECT_EQ(err.find("MPI_ABORT"), std::string::npos) << err;
}
#endif

// A case counts as done only with its marker (case_complete.json, written last) and every file
// it lists at its size: a case left without its histories (issue 14), without its marker or with
// a file cut short runs again on --resume, to the same results.
TEST_F(Batch, ResumeRedoesEveryIncompleteCase) {
  const std::string set = write_bundled_set("[1, 2]");
  const std::string out = path("out").string();
  ASSERT_EQ(pound({"batch", set, "--out", out, "-q"}).exit_code, 0);
  const std::string summary = read_text(path("out/batch_summary.csv"));
  const fs::path firm = path("out/model/record/x1"), soft = path("out/model/synthetic_soft_01/x2");
  const std::string history = read_text(firm / "joint.csv");
  fs::remove(firm / "joint.csv");  // case.csv without its histories
  fs::remove(soft / "case_complete.json");
  std::ofstream(path("out/model/synthetic_soft_02/x1/summary.json"), std::ios::trunc) << "{";

  const Outcome resumed = pound({"batch", set, "--out", out, "--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("6 cases (3 resumed, 3 run"), std::string::npos) << resumed.out;
  EXPECT_EQ(read_text(firm / "joint.csv"), history);
  EXPECT_TRUE(fs::is_regular_file(soft / "case_complete.json"));
  EXPECT_EQ(without_run_time(read_text(path("out/batch_summary.csv"))), without_run_time(summary));
}

// The same set typed another way ("dir/./set.json" for "dir/set.json": ./sets/a.json for
// sets/a.json, or an absolute path) is the same batch: --resume finishes it (it was refused as
// "the cases ... are not those of the batch", the plan keeping paths as typed).
TEST_F(Batch, ResumesASetTypedAnotherWay) {
  const std::string set = write_bundled_set("[1]");
  const std::string out = path("out").string();
  ASSERT_EQ(pound({"batch", set, "--out", out, "-q", "--jobs", "1"}).exit_code, 0);
  const std::string summary = read_text(path("out/batch_summary.csv"));
  fs::remove(path("out/model/record/x1/case_complete.json"));
  const std::string respelt = (fs::path(set).parent_path() / "." / "set.json").string();
  const Outcome resumed = pound({"batch", respelt, "--out", out, "--resume"});
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("(2 resumed, 1 run"), std::string::npos) << resumed.out;
  EXPECT_EQ(without_run_time(read_text(path("out/batch_summary.csv"))), without_run_time(summary));
}

// A case that completes with warnings on its results (here a column that collapses under
// P-Delta once its hinge yields, support/collapsing_column.hpp: drifts of hundreds of percent) is
// named on the console and counted in the row's `warnings` column, which is 0 for a plain result
// (the column barely shaken stays elastic); it stays in the statistics as any completed case.
TEST_F(Batch, CompletedCasesWithWarningsAreNamedAndCounted) {
  std::ofstream(path("column.json")) << testing::collapsing_column(4e6);
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["column.json"],
           "records": [{{"file": "{}/ground_motions/synthetic_firm_01.AT2", "id": "firm",
                         "scale": {{"pga": 0.6}}}}],
           "scales": [0.01, 1], "histories": false}})",
      kSource);
  const Outcome outcome =
      pound({"batch", path("set.json").string(), "--out", path("out").string(), "--jobs", "1"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  std::cout << outcome.out;
  EXPECT_NE(outcome.out.find("1 completed case(s) with warnings on their results"),
            std::string::npos)
      << outcome.out;
  EXPECT_NE(outcome.out.find("as the others: column/firm/x1\n"), std::string::npos) << outcome.out;
  const auto rows = rows_of(read_text(path("out/batch_summary.csv")));
  EXPECT_EQ(cell(rows, 1, "name"), "column/firm/x0.01");
  EXPECT_EQ(cell(rows, 1, "warnings"), "0");
  EXPECT_GE(std::stod(cell(rows, 2, "warnings")), 1.0);
}

// A case's summary.json says how its record was scaled, the set's scaling and then the IDA
// scale: at x2 its factor is twice the x1 case's, and `ida_scale` says why (it showed the set's
// scaling alone beside the doubled factor).
TEST_F(Batch, ACaseSummaryNamesItsIdaScale) {
  const std::string set = write_bundled_set("[1, 2]");
  ASSERT_EQ(pound({"batch", set, "--out", path("out").string(), "-q"}).exit_code, 0);
  const auto excitation = [&](const char* scale) {
    return nlohmann::json::parse(
        read_text(path("out/model/record") / scale / "summary.json"))["excitations"][0];
  };
  const nlohmann::json once = excitation("x1"), twice = excitation("x2");
  EXPECT_FALSE(once["scaling"].contains("ida_scale")) << once["scaling"];
  EXPECT_EQ(twice["scaling"]["ida_scale"], 2.0) << twice["scaling"];
  EXPECT_DOUBLE_EQ(twice["factor"].get<double>(), 2.0 * once["factor"].get<double>());
}

// Issue 14: --resume after editing a model (or a record, or the set) mixed rows of the old and
// the new file, as only paths were compared. batch_plan.json keeps a hash of each input's
// content, and a resume with any of them changed is refused, naming the file.
TEST_F(Batch, RefusesAResumeAfterAnInputFileChanged) {
  const std::string set = write_bundled_set("[1]");
  const std::string out = path("out").string();
  ASSERT_EQ(pound({"batch", set, "--out", out, "-q"}).exit_code, 0);
  const std::string model = read_text(path("model.json")), record = read_text(path("record.AT2"));

  auto expect_refused = [&](const std::string& changed) {
    const Outcome outcome = pound({"batch", set, "--out", out, "--resume"});
    EXPECT_EQ(outcome.exit_code, 2) << outcome.err;
    EXPECT_NE(outcome.err.find("changed since the batch in " + out + " began: " + changed),
              std::string::npos)
        << outcome.err;
    EXPECT_NE(outcome.err.find("choose another --out, or remove " + out), std::string::npos)
        << outcome.err;
  };
  std::ofstream(path("model.json"), std::ios::app) << "\n";  // any edit, however small
  expect_refused(path("model.json").string());
  std::ofstream(path("record.AT2"), std::ios::app) << "\n";
  expect_refused(path("model.json").string() + ", " + path("record.AT2").string());
  std::ofstream(path("model.json")) << model;
  std::ofstream(path("record.AT2")) << record;
  std::ofstream(path("set.json"), std::ios::app) << "\n";
  expect_refused(set);

  // The inputs as they were: the batch resumes.
  std::string text = read_text(path("set.json"));
  text.pop_back();
  std::ofstream(path("set.json")) << text;
  const Outcome resumed = pound({"batch", set, "--out", out, "--resume"});
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_NE(resumed.out.find("3 cases (3 resumed, 0 run"), std::string::npos) << resumed.out;
}

// "ensemble": each case runs with copies of its record perturbed by 1 +- k 1e-4; ensemble.json in
// its folder, and its row the copies' medians ("rows": "median"), or the unperturbed run's numbers,
// which are then those of a batch without the ensemble.
TEST_F(Batch, AnEnsembleSetRowsTheCopiesMedians) {
  auto write = [&](const std::string& name, const std::string& ensemble) {
    std::ofstream(path(name)) << fmt::format(
        R"({{"models": ["{0}/models/three_span_bridge.json"],
             "records": [{{"folder": "{0}/ground_motions", "pattern": "*soft*.AT2",
                           "scale": {{"pga": 0.4}}}}]{1}}})",
        kSource, ensemble);
    return path(name).string();
  };
  const std::string median = write("median.json", R"(, "ensemble": {"copies": 4})");
  const std::string unperturbed =
      write("unperturbed.json", R"(, "ensemble": {"copies": 4, "rows": "unperturbed"})");
  const std::string plain = write("plain.json", "");
  for (const auto& [set, out] :
       {std::pair{median, "median"}, {unperturbed, "unperturbed"}, {plain, "plain"}}) {
    const Outcome outcome = pound({"batch", set, "--out", path(out).string(), "-q"});
    ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  }
  EXPECT_EQ(without_run_time(read_text(path("unperturbed/batch_summary.csv"))),
            without_run_time(read_text(path("plain/batch_summary.csv"))));
  const auto medians = rows_of(read_text(path("median/batch_summary.csv")));
  const auto singles = rows_of(read_text(path("plain/batch_summary.csv")));
  ASSERT_GE(medians.size(), 3u);  // header and two records
  int differ = 0;
  for (std::size_t row = 1; row < medians.size(); ++row) {
    const std::string name = cell(medians, row, "name");
    const nlohmann::json ensemble =
        nlohmann::json::parse(read_text(path("median") / name / "ensemble.json"));
    EXPECT_EQ(ensemble["record_factors"].size(), 4u);
    const std::string m = cell(medians, row, "max_pounding_force"),
                      u = cell(singles, row, "max_pounding_force");
    std::cout << name << ": max pounding force, median of 4 copies " << m << ", unperturbed " << u
              << "\n";
    differ += m != u;
  }
  EXPECT_GT(differ, 0) << "the abutment peaks are chaotic: some median differs";
  const Outcome bad = pound({"batch", write("bad.json", R"(, "ensemble": {"copies": 0})"), "--out",
                             path("bad").string()});
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("/ensemble/copies"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(path("bad")));
}

// A set serves models of any unit of time, so its times are seconds: the same oscillator (T = 1 s,
// 5 % damped) written in seconds and in milliseconds, under a record scaled to Sa(1 s) = 0.25 g
// and one of columns at a 0.01 s step, with the intensity measure Sa(1 s), gives the same rows.
// The millisecond model read the period as 1 ms (another record factor: drifts 0.0354 against
// 0.0620, and its intensity near the PGA) while the plan said "at 1 s" (audit 71).
TEST_F(Batch, ASetsTimesAreSecondsWhateverTheModelsUnitOfTime) {
  const auto oscillator = [&](const std::string& name, const std::string& time, double second) {
    std::ofstream(path(name)) << fmt::format(
        R"({{"dimension": 1, "units": {{"length": "m", "time": "{}", "mass": "kg"}},
  "nodes": [{{"id": "ground", "x": 0}}, {{"id": "top", "x": 1}}],
  "materials": [{{"id": "col", "youngs_modulus": {}, "density": 0}}],
  "elements": [{{"id": "col", "type": "truss", "nodes": ["ground", "top"], "material": "col", "area": 1}}],
  "masses": [{{"node": "top", "mass": 1000, "mass_damping": {}}}],
  "supports": [{{"node": "ground", "fix": ["x"]}}],
  "monitors": {{"drifts": [{{"id": "col", "bottom": "ground", "top": "top", "height": 1.0}}]}},
  "analysis": {{"time_step": {}, "duration": {}}}}})",
        time, 4e3 * M_PI * M_PI / (second * second), 0.2 * M_PI / second, 0.002 * second,
        8.0 * second);
    return path(name).string();
  };
  std::string columns;
  for (int k = 0; k < 400; ++k) columns += fmt::format("{:.17g}\n", 0.2 * std::sin(0.05 * k));
  std::ofstream(path("sine.txt")) << columns;
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["{}", "{}"],
  "records": [{{"file": "{}/ground_motions/synthetic_firm_01.AT2", "scale": {{"sa": 0.25, "period": 1.0}}}},
              {{"file": "sine.txt", "format": "columns", "time_step": 0.01, "id": "sine"}}],
  "intensity_measure": {{"type": "sa", "period": 1.0}}}})",
      oscillator("seconds.json", "s", 1.0), oscillator("milliseconds.json", "ms", 1000.0), kSource);
  const Outcome outcome = pound(
      {"batch", path("set.json").string(), "--out", path("out").string(), "-q", "--jobs", "1"});
  ASSERT_EQ(outcome.exit_code, 0) << outcome.err;
  const auto rows = rows_of(read_text(path("out/batch_summary.csv")));
  ASSERT_EQ(rows.size(), 5u);  // two models under two records
  for (std::size_t row = 1; row <= 2; ++row) {
    const std::size_t in_ms = row + 2;
    ASSERT_EQ(cell(rows, row, "record"), cell(rows, in_ms, "record"));
    for (const char* column : {"intensity", "max_drift_ratio", "pga_g"}) {
      const double seconds = std::stod(cell(rows, row, column)),
                   milliseconds = std::stod(cell(rows, in_ms, column));
      std::cout << cell(rows, row, "record") << " " << column << ": model in s " << seconds
                << ", in ms " << milliseconds << "\n";
      EXPECT_NEAR(milliseconds / seconds, 1.0, 1e-9) << column;
    }
  }
  EXPECT_NEAR(std::stod(cell(rows, 1, "intensity")), 0.25, 1e-12);
}

// While cases run the batch reports them in flight (the bar of `pound batch` on a terminal
// moves before a case ends): how many and the fractions of them done, an ensemble case's run and
// copies each an equal share, so that cases done and in flight only grow. Its solving time counts
// the copies' solves (they were "the rest" of the workers' time).
TEST_F(Batch, ReportsTheCasesInFlightAndCountsAnEnsemblesCopiesAsSolving) {
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["{0}/models/three_span_bridge.json"],
           "records": [{{"folder": "{0}/ground_motions", "pattern": "*soft*.AT2",
                         "scale": {{"pga": 0.4}}}}],
           "ensemble": {{"copies": 2}}}})",
      kSource);
  app::BatchOptions options;
  options.set_path = path("set.json").string();
  options.out = path("out").string();
  options.jobs = 2;
  std::vector<app::BatchProgress> reports;
  options.progress = [&](const app::BatchProgress& p) { reports.push_back(p); };
  const app::Cluster cluster;
  const app::BatchReport report = app::run_batch(options, cluster);
  ASSERT_EQ(report.completed, 2u);
  std::size_t in_flight = 0;
  double reached = 0.0;
  for (const app::BatchProgress& p : reports) {
    in_flight += p.last == nullptr;
    EXPECT_LE(p.running, 2u);
    EXPECT_GE(p.running_done, 0.0);
    EXPECT_LE(p.running_done, static_cast<double>(p.running));
    const double now = static_cast<double>(p.done) + p.running_done;
    EXPECT_GE(now, reached) << "done " << p.done << ", running " << p.running;
    reached = now;
  }
  std::cout << reports.size() << " reports, " << in_flight << " of cases in flight\n";
  EXPECT_GT(in_flight, 10u);  // 3 x 16,667 steps a case, a report every 64 steps (or fewer)
  EXPECT_EQ(reports.back().done, 2u);
  EXPECT_EQ(reports.back().running, 0u);
  const auto rows = rows_of(read_text(path("out/batch_summary.csv")));
  double unperturbed_s = 0.0;
  for (std::size_t row = 1; row < rows.size(); ++row)
    unperturbed_s += std::stod(cell(rows, row, "run_time_s"));
  std::cout << "solving " << report.solve_s << " s, of which the unperturbed runs " << unperturbed_s
            << " s\n";
  // Three solves a case, the copies' without histories: about 3x the unperturbed ones.
  EXPECT_GT(report.solve_s, 1.5 * unperturbed_s);
}

// A case whose analysis fails before its first step (a block on a floor whose static equilibrium
// cannot hold: a steady push of 0.61 of its weight against friction 0.5) fails alone, in its row,
// as one that fails during its run: the batch goes on and exits 3, not as if its results could not
// be written.
TEST_F(Batch, ACaseFailingBeforeItsFirstStepFailsAlone) {
  std::ofstream(path("pushed.json")) << R"({
    "dimension": 2,
    "nodes": [{"id": "block", "x": 0.0, "y": 0.0}, {"id": "floor", "x": 0.0, "y": 0.0}],
    "masses": [{"node": "block", "mass": 10.0}],
    "supports": [{"node": "floor", "fix": ["x", "y"]}],
    "loads": [{"node": "block", "x": 60.0, "y": -98.1}],
    "links": [{"id": "contact", "nodes": ["block", "floor"], "axis": [0, -1],
               "law": {"type": "kelvin_voigt", "stiffness": 1.0e7, "damping": 2.0e4},
               "friction": {"coefficient": 0.5}}],
    "analysis": {"time_step": 1.0e-3, "duration": 1.0, "initial_state": "static"}})";
  std::ofstream(path("set.json")) << fmt::format(
      R"({{"models": ["{1}", "{0}/models/two_sdof_girders.json"],
           "records": [{{"file": "{0}/ground_motions/synthetic_firm_01.AT2", "id": "firm",
                         "scale": {{"pga": 0.3}}}}],
           "histories": false}})",
      kSource, path("pushed.json").string());
  const Outcome outcome =
      pound({"batch", path("set.json").string(), "--out", path("out").string(), "--quiet"});
  EXPECT_EQ(outcome.exit_code, 3) << outcome.err;
  EXPECT_NE(outcome.err.find("1 of 2 cases failed"), std::string::npos) << outcome.err;
  std::ifstream in(path("out") / "batch_summary.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto rows = rows_of(csv);
  ASSERT_EQ(rows.size(), 3u) << csv;
  for (std::size_t row = 1; row < rows.size(); ++row) {
    const bool pushed = cell(rows, row, "model") == "pushed";
    EXPECT_EQ(cell(rows, row, "status"), pushed ? "failed" : "completed") << csv;
    if (pushed) {
      EXPECT_NE(cell(rows, row, "reason").find("analysis failed at t = 0: static equilibrium"),
                std::string::npos)
          << csv;
      // No static state exists, and the reason names the cause and the link.
      EXPECT_NE(cell(rows, row, "reason").find("ask more of friction than it holds"),
                std::string::npos)
          << csv;
    }
  }
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
  // A model file given for the set: said to be one, not only that "models" is missing.
  const std::string bridge = kSource + "/models/three_span_bridge.json";
  const Outcome mistaken = pound({"batch", bridge, "--out", path("out").string()});
  EXPECT_EQ(mistaken.exit_code, 2);
  EXPECT_NE(mistaken.err.find(bridge + ": this is a model file"), std::string::npos)
      << mistaken.err;
  EXPECT_NE(mistaken.err.find("pound run"), std::string::npos) << mistaken.err;
  EXPECT_FALSE(fs::exists(path("out")));
}

// A limit is one number in each model's units: over a model in metres and the same in millimetres
// the joint opening's 0.03 was compared with millimetres (every case "exceeded" it, its fragility
// "not fitted"). Such a set is refused naming the limit; a dimensionless limit, or one over
// models in the same units, is not.
TEST_F(Batch, RefusesALimitOverModelsInDifferentUnits) {
  nlohmann::json model =
      nlohmann::json::parse(read_text(kSource + "/models/two_sdof_girders.json"));
  model["excitations"][0]["record"] = kSource + "/ground_motions/synthetic_firm_02.AT2";
  std::ofstream(path("metres.json")) << model.dump();
  model["units"]["length"] = "mm";
  model["units"]["mass"] = "t";
  std::ofstream(path("millimetres.json")) << model.dump();
  const auto batch = [&](const std::string& models, const std::string& limits) {
    std::ofstream(path("set.json")) << fmt::format(
        R"({{"models": [{}], "records": [{{"file": "{}/ground_motions/synthetic_firm_01.AT2"}}],
             "limits": {}}})",
        models, kSource, limits);
    fs::remove_all(path("out"));
    return pound({"batch", path("set.json").string(), "--out", path("out").string(), "-q"});
  };
  const Outcome mixed =
      batch(R"("metres.json", "millimetres.json")", R"({"max_joint_opening": 0.03})");
  EXPECT_EQ(mixed.exit_code, 2);
  EXPECT_NE(mixed.err.find("set.json: /limits/max_joint_opening: a limit is read in each "
                           "model's units, and the set's models give max_joint_opening in "
                           "different ones ('metres' in m, 'millimetres' in mm)"),
            std::string::npos)
      << mixed.err;
  EXPECT_FALSE(fs::exists(path("out")));
  EXPECT_EQ(batch(R"("metres.json", "millimetres.json")", R"({"max_drift_ratio": 0.01})").exit_code,
            0);
  EXPECT_EQ(batch(R"("metres.json")", R"({"max_joint_opening": 0.03})").exit_code, 0);
}

// --jobs 0 is every core, as for `pound run --ensemble` and Python's pound.batch; below 0 a
// usage error.
TEST_F(Batch, JobsZeroIsEveryCore) {
  const std::string set = write_bundled_set("[1]");
  const Outcome every = pound({"batch", set, "--out", path("every").string(), "--jobs", "0", "-q"});
  EXPECT_EQ(every.exit_code, 0) << every.err;
  const Outcome one = pound({"batch", set, "--out", path("one").string(), "--jobs", "1", "-q"});
  EXPECT_EQ(without_run_time(read_text(path("every/batch_summary.csv"))),
            without_run_time(read_text(path("one/batch_summary.csv"))));
  const Outcome negative = pound({"batch", set, "--out", path("bad").string(), "--jobs", "-1"});
  EXPECT_EQ(negative.exit_code, 1) << negative.err;
  EXPECT_FALSE(fs::exists(path("bad")));
}

}  // namespace
}  // namespace pound::testing
