#include "io/output.hpp"

#include <fmt/compile.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace pound::io {

void write_text_atomic(const std::string& path, std::string_view text) {
  const std::string temporary = fmt::format("{}.tmp.{}", path, ::getpid());
  std::FILE* file = std::fopen(temporary.c_str(), "wb");
  if (!file) throw OutputError(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int write_errno = errno;
  const bool flushed = std::fflush(file) == 0 && ::fsync(::fileno(file)) == 0;
  const int flush_errno = errno;
  const bool closed = std::fclose(file) == 0;
  if (!written || !flushed || !closed) {
    std::remove(temporary.c_str());
    throw OutputError(fmt::format("{}: cannot write: {}", path,
                                  std::strerror(!written ? write_errno : flush_errno)));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int rename_errno = errno;
    std::remove(temporary.c_str());
    throw OutputError(fmt::format("{}: cannot write: {}", path, std::strerror(rename_errno)));
  }
}

namespace {

// Numbers in their shortest form that reads back to the same double (fmt's Dragonbox): exact,
// and several times faster to write than a fixed 17 digits, which matters for a batch's histories.
void format_csv(const Table& table, fmt::memory_buffer& text) {
  const std::size_t rows = table.values.empty() ? 0 : table.values.front().size();
  text.reserve(64 + (rows + 1) * table.columns.size() * 24);  // one allocation for most tables
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    fmt::format_to(std::back_inserter(text), "{}{}", c ? "," : "", table.columns[c]);
  text.push_back('\n');
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < table.values.size(); ++c) {
      if (c) text.push_back(',');
      fmt::format_to(std::back_inserter(text), FMT_COMPILE("{}"), table.values[c][r]);
    }
    text.push_back('\n');
  }
}

}  // namespace

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
