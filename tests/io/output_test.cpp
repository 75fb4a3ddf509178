// Nothing lost: a result file is either complete under its real name or not there, and a failed
// write names the path and the reason and leaves the previous result as it was.
#include "io/output.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
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

// Tables formatted in blocks of rows on several threads are the files each gives alone: a long
// CSV (with units and text columns), a short one and a .npy, in one commit.
TEST_F(Output, TablesWrittenTogetherAreTheFilesEachGivesAlone) {
  Table long_table = table_with_columns({"time", "a.force"});
  long_table.units = {"s", "kN"};
  TextColumn& labels = long_table.text_columns.emplace_back(TextColumn{"quantity", {}});
  for (int r = 0; r < 5000; ++r) {
    append_row(long_table, {1e-3 * r, std::sin(0.01 * r) * 1e6 / 3.0});
    labels.values.push_back(fmt::format("q{}", r));
  }
  Table short_table = table_with_columns({"x"});
  append_row(short_table, {0.1});
  StagedFiles files;
  files.write_tables({{path("long.csv").string(), &long_table},
                      {path("short.csv").string(), &short_table},
                      {path("long.npy").string(), &long_table}});
  files.commit();
  EXPECT_EQ(read_text(path("long.csv")), to_csv(long_table));
  EXPECT_EQ(read_text(path("short.csv")), to_csv(short_table));
  EXPECT_EQ(read_text(path("long.npy")), to_npy(long_table));
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

// The .npy writer against the format's definition (numpy.lib.format): magic, version, a
// little-endian header length, a header dict padded to 64 bytes ending in a newline, then each
// row's doubles as they are.
TEST(Npy, StructuredArrayOfTheColumnsAsNumPyDefinesIt) {
  Table table = table_with_columns({"time", "joint's.force"});
  append_row(table, {0.0, 1.5});
  append_row(table, {0.01, -2.25e-300});
  const std::string npy = to_npy(table);
  ASSERT_GT(npy.size(), 10u);
  EXPECT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t length =
      static_cast<unsigned char>(npy[8]) + 256u * static_cast<unsigned char>(npy[9]);
  EXPECT_EQ((10 + length) % 64, 0u);
  const std::string header = npy.substr(10, length);
  EXPECT_EQ(header.back(), '\n');
  EXPECT_NE(header.find("'descr': [('time', '<f8'), ('joint\\'s.force', '<f8'), ]"),
            std::string::npos)
      << header;
  EXPECT_NE(header.find("'fortran_order': False, 'shape': (2,)"), std::string::npos) << header;
  ASSERT_EQ(npy.size(), 10 + length + 4 * sizeof(double));
  double values[4];
  std::memcpy(values, npy.data() + 10 + length, sizeof(values));
  EXPECT_EQ(values[0], 0.0);
  EXPECT_EQ(values[1], 1.5);
  EXPECT_EQ(values[2], 0.01);
  EXPECT_EQ(values[3], -2.25e-300);
}

// A labelled table (an envelope): the labels are its first column, quoted in CSV where they
// hold a comma or quote, and a '<U' field of NumPy (UTF-32, NUL-padded to the longest).
TEST(OutputCsv, LabelsAreTheFirstColumnQuotedWhereNeeded) {
  Table table = table_with_columns({"max", "min"});
  table.text_columns = {{"quantity", {"a.force", "b,\"c\".force"}}};
  append_row(table, {1.5, -2.0});
  append_row(table, {3.0, 0.25});
  EXPECT_EQ(to_csv(table), "quantity,max,min\na.force,1.5,-2\n\"b,\"\"c\"\".force\",3,0.25\n");
}

// A negative zero (a force that rounded to 0 from below) is written "0": "-0" in a history read
// as a sign where there is none. .npy keeps the bits.
TEST(OutputCsv, NegativeZeroIsWrittenAsZero) {
  Table table = table_with_columns({"time", "force"});
  append_row(table, {0.0, -0.0});
  append_row(table, {-0.0, -1e-300});
  EXPECT_EQ(to_csv(table), "time,force\n0,0\n0,-1e-300\n");
}

// Units follow a column's name in brackets; a column without one keeps its bare name, and .npy
// field names are always bare.
TEST(OutputCsv, HeadersNameTheUnitsAfterTheColumns) {
  Table table = table_with_columns({"time", "a.force", "a.count"});
  table.units = {"s", "kN", ""};
  table.text_columns = {{"quantity", {"x"}}, {"unit", {"m/s^2"}}};
  append_row(table, {0.5, 2.0, 3.0});
  EXPECT_EQ(to_csv(table), "quantity,unit,time [s],a.force [kN],a.count\nx,m/s^2,0.5,2,3\n");
  const std::string npy = to_npy(table);
  EXPECT_NE(npy.find("('time', '<f8'), ('a.force', '<f8')"), std::string::npos);
  EXPECT_NE(npy.find("('quantity', '<U1'), ('unit', '<U5')"), std::string::npos);
}

TEST(Npy, LabelsAreAUnicodeFieldBeforeTheNumbers) {
  Table table = table_with_columns({"max"});
  table.text_columns = {{"quantity", {"u", "\xc3\xa9t\xc3\xa9"}}};  // "été": 3 code points
  append_row(table, {1.0});
  append_row(table, {-4.0});
  const std::string npy = to_npy(table);
  const std::size_t length =
      static_cast<unsigned char>(npy[8]) + 256u * static_cast<unsigned char>(npy[9]);
  const std::string header = npy.substr(10, length);
  EXPECT_NE(header.find("'descr': [('quantity', '<U3'), ('max', '<f8'), ]"), std::string::npos)
      << header;
  const std::size_t record = 3 * 4 + 8;
  ASSERT_EQ(npy.size(), 10 + length + 2 * record);
  const char* second = npy.data() + 10 + length + record;
  const char32_t expected[] = {U'\u00e9', U't', U'\u00e9'};
  for (int k = 0; k < 3; ++k) {
    char32_t point = 0;
    for (int b = 3; b >= 0; --b)
      point = point * 256 + static_cast<unsigned char>(second[4 * k + b]);
    EXPECT_EQ(point, expected[k]);
  }
  double value = 0.0;
  std::memcpy(&value, second + 12, sizeof(value));
  EXPECT_EQ(value, -4.0);
  EXPECT_EQ(npy[10 + length + 4], '\0');  // "u" padded with NULs
}

// A header past 64 KiB (thousands of columns) takes version 2.0's 4-byte length.
TEST(Npy, ManyColumnsTakeVersionTwo) {
  std::vector<std::string> columns{"time"};
  for (int k = 0; k < 3000; ++k) columns.push_back(fmt::format("node_{}.u_x", k));
  Table table = table_with_columns(columns);
  for (auto& column : table.values) column.push_back(1.0);
  const std::string npy = to_npy(table);
  EXPECT_EQ(npy[6], '\x02');
  std::size_t length = 0;
  for (int b = 3; b >= 0; --b) length = length * 256 + static_cast<unsigned char>(npy[8 + b]);
  EXPECT_EQ((12 + length) % 64, 0u);
  EXPECT_EQ(npy.size(), 12 + length + columns.size() * sizeof(double));
}

}  // namespace
}  // namespace pound::io
