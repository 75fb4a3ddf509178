// `pound docs`: the generated sections (docs/model_format.md's field tables here), checked and
// rewritten in a copy of the generated files (ctest's docs.up_to_date checks the project's own).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "support/process.hpp"

namespace pound {
namespace {

namespace fs = std::filesystem;
using testing::read_text;

const fs::path kModelFormat = fs::path(POUND_SOURCE_DIR) / "docs" / "model_format.md";

class DocsCommand : public testing::PoundProcess {
 protected:
  // The project's generated files copied into the test's folder, docs/model_format.md with
  // `from` replaced by `to`.
  fs::path copy_docs(const std::string& from, const std::string& to) {
    for (const char* other : {"docs/laws.md", "fuzz/model.dict"}) {
      fs::create_directories(path(fs::path(other).parent_path().string()));
      fs::copy_file(fs::path(POUND_SOURCE_DIR) / other, path(other));
    }
    std::string text = read_text(kModelFormat);
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    fs::create_directories(path("docs"));
    std::ofstream(path("docs") / "model_format.md", std::ios::binary) << text;
    return path("docs") / "model_format.md";
  }
};

TEST_F(DocsCommand, CheckNamesTheStaleFileAndSectionAndWritesNothing) {
  const fs::path docs = copy_docs("| `x` | number | required | coordinate [L] |", "| `x` | old |");
  const std::string before = read_text(docs);
  const testing::Outcome outcome = pound({"docs", folder_.string(), "--check"});
  EXPECT_EQ(outcome.exit_code, 1);
  EXPECT_NE(outcome.err.find(docs.string() + ": section 'nodes' differs from what pound generates"),
            std::string::npos)
      << outcome.err;
  EXPECT_EQ(read_text(docs), before);
}

TEST_F(DocsCommand, RewritesTheStaleSectionsAndKeepsTheProse) {
  const fs::path docs = copy_docs("| `x` | number | required | coordinate [L] |", "| `x` | old |");
  const testing::Outcome outcome = pound({"docs", folder_.string()});
  EXPECT_EQ(outcome.exit_code, 0) << outcome.err;
  EXPECT_EQ(outcome.out, docs.string() + ": rewrote nodes\n");
  EXPECT_EQ(read_text(docs), read_text(kModelFormat));
  EXPECT_EQ(pound({"docs", folder_.string(), "--check"}).exit_code, 0);
}

TEST_F(DocsCommand, AMisspeltMarkerIsAnInputError) {
  copy_docs("<!-- pound docs: nodes -->", "<!-- pound docs: node -->");
  const testing::Outcome outcome = pound({"docs", folder_.string(), "--check"});
  EXPECT_EQ(outcome.exit_code, 2);
  EXPECT_NE(outcome.err.find("no generated section 'node' (there are: model, nodes,"),
            std::string::npos)
      << outcome.err;
}

}  // namespace
}  // namespace pound
