// What a batch folder holds: the lock that keeps a second batch out, the content hashes of the
// inputs and the marker that says a case is whole.
#include "io/batch_files.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/document.hpp"
#include "io/folder_lock.hpp"
#include "io/output.hpp"
#include "support/process.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

using BatchFiles = pound::testing::PoundProcess;

TEST_F(BatchFiles, ASecondLockIsRefusedNamingTheFolderAndTheHolder) {
  const std::string folder = folder_.string();
  {
    const FolderLock held(folder);
    // flock conflicts between two opens even in one process, which stands in for a second batch.
    try {
      const FolderLock second(folder);
      ADD_FAILURE() << "the folder was locked twice";
    } catch (const FolderInUse& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(folder + ": in use by another batch"), std::string::npos) << message;
      EXPECT_NE(message.find(fmt::format("process {}", ::getpid())), std::string::npos) << message;
    }
  }
  const FolderLock again(folder);  // released with its holder
}

TEST_F(BatchFiles, TheLockOfAKilledProcessDoesNotBlock) {
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const FolderLock held(folder_.string());
    ::_exit(0);  // without the destructor: only the kernel releases the lock
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_TRUE(fs::is_regular_file(path(kLockFileName)));  // the file stays, the lock does not
  EXPECT_NO_THROW(FolderLock(folder_.string()));
}

TEST(Fnv1a64, GivesThePublishedValues) {
  EXPECT_EQ(fnv1a_64(""), 0xcbf29ce484222325ULL);
  EXPECT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv1a_64("foobar"), 0x85944171f73967e8ULL);
  // In pieces as in one go, as files are hashed.
  EXPECT_EQ(fnv1a_64("bar", fnv1a_64("foo")), fnv1a_64("foobar"));
}

TEST_F(BatchFiles, FileHashesTellAnEditedFile) {
  std::ofstream(path("model.json")) << R"({"nodes": []})";
  EXPECT_EQ(file_hash(path("model.json").string()),
            fmt::format("{:016x}", fnv1a_64(R"({"nodes": []})")));
  EXPECT_EQ(file_hash(path("missing.json").string()), "unreadable");
  const std::string plan =
      Document()
          .set("inputs", std::vector<Document>{Document()
                                                   .set("file", path("model.json").string())
                                                   .set("fnv1a_64", "0123456789abcdef")})
          .dump();
  std::ofstream(path("batch_plan.json")) << plan;
  const std::vector<InputFile> inputs = read_plan_inputs(path("batch_plan.json").string());
  ASSERT_EQ(inputs.size(), 1u);
  EXPECT_EQ(inputs[0].path, path("model.json").string());
  EXPECT_EQ(inputs[0].hash, "0123456789abcdef");
  EXPECT_TRUE(read_plan_inputs(path("missing.json").string()).empty());
}

TEST_F(BatchFiles, ACaseIsCompleteOnlyWithItsMarkerAndEveryFileItLists) {
  const std::string folder = path("case").string();
  create_output_folder(folder);
  write_text_atomic(path("case/joint.csv").string(), "t,u\n0,0\n");
  write_text_atomic(path("case/case.csv").string(), "name\nm/r/x1\n");
  EXPECT_FALSE(is_complete_case(folder, "m/r/x1"));  // no marker yet
  write_case_marker(folder, "m/r/x1");
  EXPECT_TRUE(is_complete_case(folder, "m/r/x1"));
  EXPECT_FALSE(is_complete_case(folder, "m/r/x2"));  // another case's folder

  write_text_atomic(path("case/joint.csv").string(), "t,u\n");  // cut short
  EXPECT_FALSE(is_complete_case(folder, "m/r/x1"));
  fs::remove(path("case/joint.csv"));  // what a kill while the folder was replaced leaves
  EXPECT_FALSE(is_complete_case(folder, "m/r/x1"));
  EXPECT_FALSE(is_complete_case(path("nowhere").string(), "m/r/x1"));
}

TEST_F(BatchFiles, AFolderWithOnlyALockIsEmpty) {
  EXPECT_TRUE(is_empty_but_for_lock(path("missing").string()));
  create_output_folder(path("out").string());
  EXPECT_TRUE(is_empty_but_for_lock(path("out").string()));
  { const FolderLock lock(path("out").string()); }
  EXPECT_TRUE(is_empty_but_for_lock(path("out").string()));
  std::ofstream(path("out/notes.txt")) << "mine";
  EXPECT_FALSE(is_empty_but_for_lock(path("out").string()));
}

}  // namespace
}  // namespace pound::io
