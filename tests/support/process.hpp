#pragma once
// Running the real `pound` binary from tests: a temporary folder per test, the command's exit
// code and captured output, and small file helpers.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pound::testing {

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

inline bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

struct Outcome {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// A fixture with its own temporary folder (removed afterwards) that runs `pound`.
class PoundProcess : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterised tests: "Test/case"
    folder_ =
        std::filesystem::temp_directory_path() / fmt::format("pound_test_{}_{}", name, ::getpid());
    std::filesystem::remove_all(folder_);
    ASSERT_TRUE(std::filesystem::create_directories(folder_)) << folder_;
  }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(folder_, ignored);
  }

  std::filesystem::path path(const std::string& name) const { return folder_ / name; }

  // Runs `pound <arguments>` with stdout and stderr captured.
  Outcome pound(const std::vector<std::string>& arguments) const {
    std::string command = shell_quoted(POUND_BINARY);
    for (const std::string& argument : arguments)
      command.append(" ").append(shell_quoted(argument));
    const std::filesystem::path out = path("stdout.txt"), err = path("stderr.txt");
    command.append(
        fmt::format(" >{} 2>{}", shell_quoted(out.string()), shell_quoted(err.string())));
    const int status = std::system(command.c_str());
    Outcome outcome;
    outcome.exit_code = status != -1 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    outcome.out = read_text(out);
    outcome.err = read_text(err);
    return outcome;
  }

  std::filesystem::path folder_;
};

}  // namespace pound::testing
