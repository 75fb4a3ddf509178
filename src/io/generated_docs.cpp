#include "io/generated_docs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <string_view>

#include "core/errors.hpp"

namespace pound::io {
namespace {

constexpr std::string_view kBegin = "<!-- pound docs: ";
constexpr std::string_view kBeginEnd = " -->";
constexpr std::string_view kEnd = "<!-- end pound docs -->";
constexpr std::string_view kCommented = "# ";

// A piece of a docs file: prose and markers as they are (no name), or a section's text.
struct Piece {
  std::string name;
  std::string text;
};

// The section a line opens, if it is a begin marker.
std::string_view opened_section(std::string_view line) {
  if (!line.starts_with(kBegin) || !line.ends_with(kBeginEnd)) return {};
  line.remove_prefix(kBegin.size());
  line.remove_suffix(kBeginEnd.size());
  return line;
}

// The section named `name`; `where` names the line of a marker, for the error.
const GeneratedSection& find_section(const GeneratedFile& file, std::string_view name,
                                     const std::string& where) {
  const auto found = std::find_if(file.sections.begin(), file.sections.end(),
                                  [name](const GeneratedSection& s) { return s.name == name; });
  if (found == file.sections.end()) {
    std::string names;
    for (const GeneratedSection& section : file.sections)
      names += (names.empty() ? "" : ", ") + section.name;
    throw InputError(file.path, where,
                     fmt::format("no generated section '{}' (there are: {})", name, names));
  }
  return *found;
}

std::vector<Piece> split(const std::string& text, const GeneratedFile& file) {
  std::vector<Piece> pieces(1);
  std::set<std::string> seen;
  std::size_t number = 0, opened_at = 0;
  for (std::size_t start = 0; start < text.size(); ++number) {
    const std::size_t end = std::min(text.find('\n', start), text.size() - 1) + 1;
    const std::string_view line(text.data() + start, end - start);
    std::string_view bare = line.substr(0, line.find_last_not_of("\r\n") + 1);
    // In a file whose lines must all mean something (a fuzz dictionary), markers are comments.
    if (bare.starts_with(kCommented)) bare.remove_prefix(kCommented.size());
    start = end;
    const std::string where = fmt::format("line {}", number + 1);
    if (!pieces.back().name.empty()) {  // inside a section
      if (bare == kEnd) pieces.emplace_back();
      pieces.back().text += line;
      continue;
    }
    if (bare == kEnd) throw InputError(file.path, where, "an end marker that opens no section");
    pieces.back().text += line;
    if (const std::string_view name = opened_section(bare); !name.empty()) {
      const GeneratedSection& section = find_section(file, name, where);
      if (!seen.insert(section.name).second)
        throw InputError(file.path, where, fmt::format("section '{}' given twice", name));
      pieces.push_back({section.name, ""});
      opened_at = number + 1;
    }
  }
  if (!pieces.back().name.empty())
    throw InputError(file.path, fmt::format("line {}", opened_at),
                     fmt::format("section '{}' has no '{}'", pieces.back().name, kEnd));
  for (const GeneratedSection& section : file.sections)
    if (!seen.count(section.name))
      throw InputError(file.path, "",
                       fmt::format("no '{}{}{}' for section '{}'", kBegin, section.name, kBeginEnd,
                                   section.name));
  return pieces;
}

// A table row: a '|' in a cell would end it.
std::string table_row(const std::vector<std::string>& cells) {
  std::string row = "|";
  for (const std::string& cell : cells) {
    row += ' ';
    for (const char c : cell) row += c == '|' ? std::string("\\|") : std::string(1, c);
    row += " |";
  }
  return row + "\n";
}

std::string rendered(const GeneratedFile& file, const std::string& name) {
  return find_section(file, name, "").render();
}

}  // namespace

std::string markdown_table(const std::vector<std::string>& header,
                           const std::vector<std::vector<std::string>>& rows) {
  std::string table = table_row(header) + table_row(std::vector<std::string>(header.size(), "---"));
  for (const std::vector<std::string>& row : rows) table += table_row(row);
  return table;
}

std::string regenerate(const std::string& text, const GeneratedFile& file) {
  std::string result;
  for (const Piece& piece : split(text, file))
    result += piece.name.empty() ? piece.text : rendered(file, piece.name);
  return result;
}

std::vector<std::string> stale_sections(const std::string& text, const GeneratedFile& file) {
  std::vector<std::string> stale;
  for (const Piece& piece : split(text, file))
    if (!piece.name.empty() && piece.text != rendered(file, piece.name))
      stale.push_back(piece.name);
  return stale;
}

}  // namespace pound::io
