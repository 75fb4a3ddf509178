// Nothing lost: a result file is either complete under its real name or not there, and a failed
// write names the path and the reason and leaves the previous result as it was.
#include "io/output.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "support/process.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;
using pound::testing::read_text;

class Output : public pound::testing::PoundProcess {
 protected:
  // Files in the test's folder other than the expected ones: a temporary left behind shows here.
  std::vector<std::string> names() const {
    std::vector<std::string> found;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder_))
      found.push_back(entry.path().filename().string());
    std::sort(found.begin(), found.end());
    return found;
  }

  // Expects `write` to throw an OutputError naming `file`; returns its message.
  template <class Write>
  std::string expect_output_error(const fs::path& file, Write write) {
    try {
      write();
    } catch (const OutputError& error) {
      std::cout << "error: " << error.what() << "\n";
      EXPECT_NE(std::string(error.what()).find(file.string()), std::string::npos) << error.what();
      return error.what();
    }
    ADD_FAILURE() << "no OutputError for " << file;
    return {};
  }
};

TEST_F(Output, OverwriteReplacesTheWholeFileAndLeavesNoTemporary) {
  const fs::path file = path("summary.json");
  write_text_atomic(file.string(), std::string(10000, 'a'));
  write_text_atomic(file.string(), "short");
  EXPECT_EQ(read_text(file), "short");
  EXPECT_EQ(names(), std::vector<std::string>{"summary.json"});
}

TEST_F(Output, FolderInTheWayIsAnErrorAndTheFolderIsKept) {
  const fs::path file = path("history.csv");
  fs::create_directory(file);
  const std::string message =
      expect_output_error(file, [&] { write_text_atomic(file.string(), "t,u\n0,0\n"); });
  EXPECT_NE(message.find("cannot write"), std::string::npos) << message;
  EXPECT_TRUE(fs::is_directory(file));
  EXPECT_EQ(names(), std::vector<std::string>{"history.csv"});  // no temporary left behind
}

TEST_F(Output, FileInPlaceOfTheFolderIsAnError) {
  std::ofstream(path("not_a_folder")) << "x";
  const fs::path file = path("not_a_folder") / "summary.json";
  expect_output_error(file, [&] { write_text_atomic(file.string(), "{}"); });
  expect_output_error(path("not_a_folder"),
                      [&] { create_output_folder(path("not_a_folder").string()); });
  EXPECT_EQ(read_text(path("not_a_folder")), "x");
}

// A destination that fills up part way (the file-size limit stands in for a full disk: the write
// fails with EFBIG instead of ENOSPC, through the same path) keeps the previous result intact.
TEST_F(Output, FullDestinationKeepsThePreviousResult) {
  const fs::path file = path("link_force.csv");
  write_text_atomic(file.string(), "previous\n");

  rlimit saved{};
  ASSERT_EQ(::getrlimit(RLIMIT_FSIZE, &saved), 0);
  const auto previous_handler = std::signal(SIGXFSZ, SIG_IGN);  // fail the write, not the process
  rlimit small = saved;
  small.rlim_cur = 4096;
  ASSERT_EQ(::setrlimit(RLIMIT_FSIZE, &small), 0);
  const std::string message = expect_output_error(
      file, [&] { write_text_atomic(file.string(), std::string(1 << 20, 'x')); });
  ::setrlimit(RLIMIT_FSIZE, &saved);
  std::signal(SIGXFSZ, previous_handler);

  EXPECT_NE(message.find("too large"), std::string::npos) << message;  // strerror(EFBIG)
  EXPECT_EQ(read_text(file), "previous\n");
  EXPECT_EQ(names(), std::vector<std::string>{"link_force.csv"});
}

TEST_F(Output, ReadOnlyFolderKeepsThePreviousResult) {
  if (::geteuid() == 0) GTEST_SKIP() << "root writes into read-only folders; covered for users";
  const fs::path file = path("summary.json");
  write_text_atomic(file.string(), "previous");
  fs::permissions(folder_, fs::perms::owner_write, fs::perm_options::remove);
  const std::string message =
      expect_output_error(file, [&] { write_text_atomic(file.string(), "new"); });
  fs::permissions(folder_, fs::perms::owner_write, fs::perm_options::add);
  EXPECT_NE(message.find("Permission denied"), std::string::npos) << message;
  EXPECT_EQ(read_text(file), "previous");
  EXPECT_EQ(names(), std::vector<std::string>{"summary.json"});
}

TEST(OutputCsv, FullPrecisionSoAHistoryReadsBackBitForBit) {
  Table table;
  table.columns = {"time", "force"};
  table.values = {{0.0, 0.1, 1e-3 * 7}, {1.0 / 3.0, -2.5e-300, 6.02214076e23}};
  const std::string text = to_csv(table);
  std::istringstream lines(text);
  std::string line;
  std::getline(lines, line);
  EXPECT_EQ(line, "time,force");
  for (std::size_t row = 0; row < 3; ++row) {
    ASSERT_TRUE(std::getline(lines, line)) << text;
    const std::size_t comma = line.find(',');
    EXPECT_EQ(std::stod(line.substr(0, comma)), table.values[0][row]) << line;
    EXPECT_EQ(std::stod(line.substr(comma + 1)), table.values[1][row]) << line;
  }
  EXPECT_FALSE(std::getline(lines, line)) << text;
}

TEST_F(Output, StagedFilesAppearTogetherOrNotAtAll) {
  {
    StagedFiles files;
    files.write(path("links.csv").string(), "a\n");
    files.write(path("summary.json").string(), "{}");
    EXPECT_EQ(names().size(), 2u);  // the temporaries
    // Not committed (an error or an interrupt on the way): nothing is left.
  }
  EXPECT_TRUE(names().empty());
  std::ofstream(path("summary.json")) << "old";
  StagedFiles files;
  files.write(path("links.csv").string(), "a\n");
  files.write(path("summary.json").string(), "{}");
  files.commit();
  EXPECT_EQ(names(), (std::vector<std::string>{"links.csv", "summary.json"}));
  EXPECT_EQ(read_text(path("summary.json")), "{}");
}

TEST_F(Output, StaleTemporariesOfDeadProcessesAreRemoved) {
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ASSERT_GT(dead, 0);
  int status = 0;
  ::waitpid(dead, &status, 0);
  const std::string stale = fmt::format("links.csv.tmp.{}", dead);
  const std::string mine = fmt::format("summary.json.tmp.{}", ::getpid());
  std::ofstream(path(stale)) << "x";
  std::ofstream(path(mine)) << "x";
  std::ofstream(path("notes.tmp.txt")) << "x";
  remove_stale_temporaries(folder_.string());
  EXPECT_EQ(names(), (std::vector<std::string>{"notes.tmp.txt", mine}));
}

}  // namespace
}  // namespace pound::io
