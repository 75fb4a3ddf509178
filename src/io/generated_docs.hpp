#pragma once
// Sections of the docs that are generated from code (the field tables of the model format). In a
// docs file each one stands between its markers,
//
//   <!-- pound docs: nodes -->
//   | field | type | default | meaning |  ...
//   <!-- end pound docs -->
//
// with prose written by hand around them (in a file whose every line must mean something, such as
// a fuzz dictionary, the markers may be comments: "# <!-- pound docs: NAME -->"). `pound docs`
// rewrites the sections and `pound docs --check` names the stale ones.
#include <functional>
#include <string>
#include <vector>

namespace pound::io {

struct GeneratedSection {
  std::string name;
  std::function<std::string()> render;  // markdown, ending in a newline
};

// A docs file and the sections it holds.
struct GeneratedFile {
  std::string path;  // from the project's root: "docs/model_format.md"
  std::vector<GeneratedSection> sections;
};

// `text`, the file's contents, with every section rendered anew. A marker that names no section
// of `file`, a section without its marker or given twice, and a marker without its end are
// InputErrors naming the file and the line.
std::string regenerate(const std::string& text, const GeneratedFile& file);

// The sections whose text in `text` differs from what they render, in the order of the file.
std::vector<std::string> stale_sections(const std::string& text, const GeneratedFile& file);

// A markdown table, for a section to render; a '|' in a cell is escaped.
std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows);

}  // namespace pound::io
