#include "io/output.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <bit>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <future>
#include <span>
#include <string>
#include <thread>

#include "core/interrupt.hpp"

namespace pound::io {

namespace {

// Writes `text` to <path>.tmp.<pid>, synced to disk; returns that name.
// `parts` one after the other (a table formatted in blocks is written without joining them).
std::string write_temporary(const std::string& path, std::span<const std::string_view> parts) {
  throw_if_interrupted();
  const std::string temporary = fmt::format("{}.tmp.{}", path, ::getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) throw OutputError(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
  bool written = true;
  for (const std::string_view part : parts)
    written = written && std::fwrite(part.data(), 1, part.size(), file) == part.size();
  const int write_errno = errno;
  const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !flushed || !closed) {
    std::remove(temporary.c_str());
    throw OutputError(fmt::format("{}: cannot write: {}", path,
                                  std::strerror(!written ? write_errno : flush_errno)));
  }
  return temporary;
}

}  // namespace

StagedFiles::~StagedFiles() {
  for (const auto& [temporary, destination] : staged_) std::remove(temporary.c_str());
}

void StagedFiles::write(const std::string& path, std::string_view text) {
  write_parts(path, {&text, 1});
}

void StagedFiles::write_parts(const std::string& path, std::span<const std::string_view> parts) {
  // Staged before it is written, so an interrupt while writing removes it too.
  staged_.emplace_back(fmt::format("{}.tmp.{}", path, ::getpid()), path);
  write_temporary(path, parts);
}

void StagedFiles::commit() {
  throw_if_interrupted();  // the last point at which nothing has been put in place
  // Of several files the last marks them complete: an older one goes first, so a crash between
  // the renames leaves no marker beside a mix of old and new files.
  if (staged_.size() > 1) std::remove(staged_.back().second.c_str());
  while (!staged_.empty()) {
    const auto& [temporary, destination] = staged_.front();
    if (std::rename(temporary.c_str(), destination.c_str()) != 0)
      throw OutputError(fmt::format("{}: cannot write: {}", destination, std::strerror(errno)));
    staged_.erase(staged_.begin());
  }
}

void write_text_atomic(const std::string& path, std::string_view text) {
  StagedFiles file;
  file.write(path, text);
  file.commit();
}

void remove_stale_temporaries(const std::string& folder) {
  std::error_code error;
  for (const std::filesystem::directory_entry& entry :
       std::filesystem::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    const std::size_t mark = name.rfind(".tmp.");
    if (mark == std::string::npos || mark + 5 == name.size()) continue;
    const std::string digits = name.substr(mark + 5);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    const auto pid = static_cast<pid_t>(std::stol(digits));
    // Only a process that no longer exists: another run may be writing into the same folder.
    if (pid == ::getpid() || ::kill(pid, 0) == 0 || errno != ESRCH) continue;
    std::filesystem::remove(entry.path(), error);
  }
}

namespace {

// A text cell: quoted (with quotes doubled) when it holds a comma, quote or line break.
std::string csv_cell(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// Numbers in their shortest form that reads back to the same double (fmt's Dragonbox): exact,
// and several times faster to write than a fixed 17 digits, which matters for a batch's histories.
void format_csv_header(const Table& table, fmt::memory_buffer& text) {
  for (const TextColumn& column : table.text_columns)
    fmt::format_to(std::back_inserter(text), "{},", csv_cell(column.name));
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const bool unit = c < table.units.size() && !table.units[c].empty();
    fmt::format_to(std::back_inserter(text), "{}{}", c ? "," : "",
                   unit ? csv_cell(table.columns[c] + " [" + table.units[c] + "]")
                        : csv_cell(table.columns[c]));
  }
  text.push_back('\n');
}

std::size_t row_count(const Table& table) {
  return table.values.empty() ? 0 : table.values.front().size();
}

// Rows [first, last) of the table.
void format_csv_rows(const Table& table, std::size_t first, std::size_t last,
                     fmt::memory_buffer& text) {
  text.reserve(text.size() + (last - first) * table.columns.size() * 24);
  for (std::size_t r = first; r < last; ++r) {
    for (const TextColumn& column : table.text_columns)
      fmt::format_to(std::back_inserter(text), "{},", csv_cell(column.values.at(r)));
    for (std::size_t c = 0; c < table.values.size(); ++c) {
      if (c) text.push_back(',');
      // + 0.0: a -0 (a force that rounded to zero from below) is written 0, as a reader expects.
      fmt::format_to(std::back_inserter(text), FMT_COMPILE("{}"), table.values[c][r] + 0.0);
    }
    text.push_back('\n');
  }
}

void format_csv(const Table& table, fmt::memory_buffer& text) {
  format_csv_header(table, text);
  format_csv_rows(table, 0, row_count(table), text);
}

// UTF-8 text as the code points of NumPy's '<U' fields (an invalid byte stands for itself).
std::u32string code_points(const std::string& text) {
  std::u32string points;
  for (std::size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const int length = byte < 0x80         ? 1
                       : (byte >> 5) == 6  ? 2
                       : (byte >> 4) == 14 ? 3
                       : (byte >> 3) == 30 ? 4
                                           : 1;
    char32_t point = length == 1 ? byte : byte & (0x7f >> length);
    bool valid = i + static_cast<std::size_t>(length) <= text.size();
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + static_cast<std::size_t>(k)]);
      valid = (next >> 6) == 2;
      point = (point << 6) | (next & 0x3f);
    }
    points.push_back(valid ? point : byte);
    i += valid ? static_cast<std::size_t>(length) : 1;
  }
  return points;
}

// A Python string literal's body: quotes and backslashes escaped.
std::string python_literal(const std::string& text) {
  std::string literal;
  for (char c : text)
    literal += (c == '\'' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return literal;
}

}  // namespace

std::string to_npy(const Table& table) {
  static_assert(std::endian::native == std::endian::little, "the .npy writer assumes '<f8'");
  // Each text column as code points, and its field's width (the longest value, at least 1).
  std::vector<std::vector<std::u32string>> texts;
  std::vector<std::size_t> widths;
  std::string fields;
  for (const TextColumn& column : table.text_columns) {
    std::vector<std::u32string>& points = texts.emplace_back();
    std::size_t& width = widths.emplace_back(1);
    for (const std::string& value : column.values) {
      points.push_back(code_points(value));
      width = std::max(width, points.back().size());
    }
    fmt::format_to(std::back_inserter(fields), "('{}', '<U{}'), ", python_literal(column.name),
                   width);
  }
  for (const std::string& column : table.columns)
    fmt::format_to(std::back_inserter(fields), "('{}', '<f8'), ", python_literal(column));
  const std::size_t rows = table.values.empty() ? 0 : table.values.front().size();
  std::string header =
      fmt::format("{{'descr': [{}], 'fortran_order': False, 'shape': ({},), }}", fields, rows);
  // magic (6) + version (2) + header length (2, or 4 in 2.0) + header, padded with spaces and a
  // newline to a multiple of 64 bytes.
  const bool version2 = header.size() + 11 > 65535;
  const std::size_t preamble = version2 ? 12 : 10;
  header.append(63 - (preamble + header.size()) % 64, ' ');
  header.push_back('\n');
  std::string out("\x93NUMPY", 6);
  out.push_back(version2 ? '\x02' : '\x01');
  out.push_back('\x00');
  const std::size_t length = header.size();
  for (std::size_t b = 0; b < (version2 ? 4u : 2u); ++b)
    out.push_back(static_cast<char>((length >> (8 * b)) & 0xff));
  out += header;
  const std::size_t columns = table.values.size();
  std::vector<double> record(columns);
  out.reserve(out.size() + rows * columns * sizeof(double));
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t t = 0; t < texts.size(); ++t) {
      const std::u32string& text = texts[t].at(r);
      for (std::size_t i = 0; i < widths[t]; ++i) {
        const char32_t point = i < text.size() ? text[i] : U'\0';  // NumPy pads with NUL
        for (int b = 0; b < 4; ++b) out.push_back(static_cast<char>((point >> (8 * b)) & 0xff));
      }
    }
    for (std::size_t c = 0; c < columns; ++c) record[c] = table.values[c][r];
    out.append(reinterpret_cast<const char*>(record.data()), columns * sizeof(double));
  }
  return out;
}

void StagedFiles::write_table(const std::string& path, const Table& table) {
  if (path.ends_with(".npy"))
    write(path, to_npy(table));
  else
    write_csv(path, table);
}

void StagedFiles::write_tables(const std::vector<std::pair<std::string, const Table*>>& tables) {
  // Formatting decimals is most of a history's cost: the CSV tables are cut into blocks of rows
  // formatted side by side on the cores, then each file is written whole, in order.
  constexpr std::size_t kBlockRows = 2048;
  struct Piece {
    std::size_t table, first, last;  // rows [first, last); for .npy the whole table
  };
  std::vector<Piece> pieces;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    const std::size_t rows = row_count(*tables[k].second);
    if (tables[k].first.ends_with(".npy") || rows <= kBlockRows) {
      pieces.push_back({k, 0, rows});
      continue;
    }
    for (std::size_t first = 0; first < rows; first += kBlockRows)
      pieces.push_back({k, first, std::min(rows, first + kBlockRows)});
  }
  std::vector<fmt::memory_buffer> texts(pieces.size());
  std::vector<std::string> npy(pieces.size());  // a .npy table's bytes, in its one piece
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t p; (p = next++) < pieces.size();) {
      const Piece& piece = pieces[p];
      const auto& [path, table] = tables[piece.table];
      if (path.ends_with(".npy")) {
        npy[p] = to_npy(*table);
        continue;
      }
      if (piece.first == 0) format_csv_header(*table, texts[p]);
      format_csv_rows(*table, piece.first, piece.last, texts[p]);
    }
  };
  const std::size_t threads =
      std::min<std::size_t>(pieces.size(), std::max(1u, std::thread::hardware_concurrency()));
  std::vector<std::future<void>> helpers;
  for (std::size_t t = 1; t < threads; ++t) helpers.push_back(std::async(std::launch::async, work));
  work();
  for (std::future<void>& helper : helpers) helper.get();  // rethrows a helper's exception
  std::vector<std::string_view> parts;
  for (std::size_t p = 0; p < pieces.size();) {
    const std::size_t table = pieces[p].table;
    parts.clear();
    for (; p < pieces.size() && pieces[p].table == table; ++p)
      parts.push_back(npy[p].empty() ? std::string_view(texts[p].data(), texts[p].size())
                                     : std::string_view(npy[p]));
    write_parts(tables[table].first, parts);
  }
}

std::string to_csv(const Table& table) {
  fmt::memory_buffer text;
  format_csv(table, text);
  return fmt::to_string(text);
}

std::string to_csv(const TextTable& table) {
  auto line = [](const std::vector<std::string>& cells) {
    std::string text;
    for (std::size_t c = 0; c < cells.size(); ++c) text += (c ? "," : "") + cells[c];
    return text + "\n";
  };
  std::string text = line(table.columns);
  for (const auto& row : table.rows) text += line(row);
  return text;
}

void StagedFiles::write_csv(const std::string& path, const Table& table) {
  fmt::memory_buffer text;
  format_csv(table, text);
  write(path, std::string_view(text.data(), text.size()));
}

void write_csv_atomic(const std::string& path, const Table& table) {
  fmt::memory_buffer text;
  format_csv(table, text);
  write_text_atomic(path, std::string_view(text.data(), text.size()));
}

void create_output_folder(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error || !std::filesystem::is_directory(path))
    throw OutputError(fmt::format("{}: cannot create output folder: {}", path,
                                  error ? error.message() : "a file of that name exists"));
}

void move_folder_into_place(const std::string& temporary, const std::string& destination) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::path parent = fs::path(destination).parent_path();
  if (!parent.empty()) create_output_folder(parent.string());
  fs::remove_all(destination, error);
  if (!error) fs::rename(temporary, destination, error);
  if (error)
    throw OutputError(
        fmt::format("{}: cannot move the results into place: {}", destination, error.message()));
}

void remove_folder(const std::string& path) {
  std::error_code error;
  std::filesystem::remove_all(path, error);
  if (error) throw OutputError(fmt::format("{}: cannot remove: {}", path, error.message()));
}

bool is_file(const std::string& path) {
  std::error_code error;
  return std::filesystem::is_regular_file(path, error);
}

bool is_empty_or_missing_folder(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return true;
  return std::filesystem::is_directory(path, error) && std::filesystem::is_empty(path, error);
}

}  // namespace pound::io
