// Generated sections of docs files: rewritten between their markers, prose kept, stale ones named,
// and every marker mistake an error that names the line.
#include "io/generated_docs.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/errors.hpp"

namespace pound::io {
namespace {

const GeneratedFile kFile = {"docs/x.md",
                             {{"one", [] { return std::string("| a |\n"); }},
                              {"two", [] { return std::string("| b |\n| c |\n"); }}}};

constexpr const char* kCurrent =
    "# Title\n\nProse.\n<!-- pound docs: one -->\n| a |\n<!-- end pound docs -->\nMore prose.\n"
    "<!-- pound docs: two -->\n| b |\n| c |\n<!-- end pound docs -->\n";

std::string error_of(const std::string& text) {
  try {
    (void)regenerate(text, kFile);
  } catch (const InputError& error) {
    return error.what();
  }
  return "accepted";
}

TEST(GeneratedDocs, RewritesSectionsAndKeepsTheProse) {
  const std::string stale =
      "# Title\n\nProse.\n<!-- pound docs: one -->\nold\nlines\n<!-- end pound docs -->\nMore "
      "prose.\n<!-- pound docs: two -->\n<!-- end pound docs -->\n";
  EXPECT_EQ(regenerate(stale, kFile), kCurrent);
  EXPECT_EQ(stale_sections(stale, kFile), (std::vector<std::string>{"one", "two"}));
  EXPECT_EQ(regenerate(kCurrent, kFile), kCurrent);
  EXPECT_TRUE(stale_sections(kCurrent, kFile).empty());
}

TEST(GeneratedDocs, NamesOnlyTheStaleSections) {
  std::string text = kCurrent;
  text.replace(text.find("| c |"), 5, "| d |");
  EXPECT_EQ(stale_sections(text, kFile), std::vector<std::string>{"two"});
}

TEST(GeneratedDocs, MarkerMistakesNameTheLine) {
  EXPECT_EQ(error_of("<!-- pound docs: one -->\n<!-- end pound docs -->\n<!-- pound docs: three "
                     "-->\n<!-- end pound docs -->\n"),
            "docs/x.md: line 3: no generated section 'three' (there are: one, two)");
  EXPECT_EQ(error_of("x\n<!-- pound docs: one -->\n| a |\n"),
            "docs/x.md: line 2: section 'one' has no '<!-- end pound docs -->'");
  EXPECT_EQ(error_of("<!-- pound docs: one -->\n<!-- end pound docs -->\n"),
            "docs/x.md: no '<!-- pound docs: two -->' for section 'two'");
  EXPECT_EQ(error_of(std::string(kCurrent) + "<!-- pound docs: one -->\n<!-- end pound docs -->\n"),
            "docs/x.md: line 12: section 'one' given twice");
  EXPECT_EQ(error_of("text\n<!-- end pound docs -->\n"),
            "docs/x.md: line 2: an end marker that opens no section");
}

TEST(GeneratedDocs, MarkdownTableEscapesBars) {
  EXPECT_EQ(markdown_table({"a", "b"}, {{"1", "|x|"}, {"2", ""}}),
            "| a | b |\n| --- | --- |\n| 1 | \\|x\\| |\n| 2 |  |\n");
}

}  // namespace
}  // namespace pound::io
