// Input files are regular files of bounded size: a FIFO, a device or a huge file named as a model
// or record is refused at once, naming it, instead of blocking or filling memory (issue 14).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.hpp"
#include "io/json_reader.hpp"
#include "support/process.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

class InputFile : public pound::testing::PoundProcess {
 protected:
  // The message of the FileAccessError reading `path` throws.
  static std::string refusal(const std::string& path,
                             std::uintmax_t max_bytes = kMaxDocumentBytes) {
    try {
      (void)read_text_file(path, max_bytes);
    } catch (const FileAccessError& error) {
      EXPECT_EQ(error.file().rfind(path.substr(0, path.find('\0')), 0), 0u) << error.file();
      return error.what();
    }
    ADD_FAILURE() << "read " << path;
    return {};
  }
};

TEST_F(InputFile, FifoIsRefusedWithoutWaitingForAWriter) {
  const std::string fifo = path("model.json").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(refusal(fifo), fifo + ": not a regular file (a FIFO)");
}

TEST_F(InputFile, DevicesAndFoldersAreRefused) {
  EXPECT_EQ(refusal("/dev/zero"), "/dev/zero: not a regular file (a character device)");
  EXPECT_EQ(refusal(folder_.string()), folder_.string() + ": is a folder, not a file");
  EXPECT_EQ(refusal(path("none").string()), path("none").string() + ": no such file");
}

TEST_F(InputFile, SymlinkToAFileIsReadAndToADeviceIsRefused) {
  const fs::path file = path("a.json");
  std::ofstream(file) << "{}";
  fs::create_symlink(file, path("link.json"));
  EXPECT_EQ(read_text_file(path("link.json").string()), "{}");
  fs::create_symlink("/dev/zero", path("zero.json"));
  EXPECT_NE(refusal(path("zero.json").string()).find("a character device"), std::string::npos);
}

TEST_F(InputFile, FileLargerThanTheBoundIsRefusedBeforeReading) {
  const fs::path file = path("big.AT2");
  std::ofstream(file) << std::string(2000, '1');
  EXPECT_EQ(read_text_file(file.string(), 2000).size(), 2000u);
  EXPECT_NE(refusal(file.string(), 1999).find("larger than"), std::string::npos);
  EXPECT_THROW(check_input_file(file.string(), 1999), FileAccessError);
  EXPECT_NO_THROW(check_input_file(file.string(), 2000));
}

TEST_F(InputFile, NulInAFileNameIsRefused) {
  EXPECT_NE(refusal(std::string("a\0b", 3)).find("NUL"), std::string::npos);
}

TEST_F(InputFile, NulInAJsonStringIsRefusedNamingItsPath) {
  const nlohmann::json document = nlohmann::json::parse(R"({"record": "a\u0000b"})");
  const JsonValue value(document["record"], "m.json", "/record");
  try {
    (void)value.as<std::string>();
    ADD_FAILURE() << "accepted a NUL";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "m.json: /record: a NUL character (\\u0000) in the string");
  }
}

}  // namespace
}  // namespace pound::io
