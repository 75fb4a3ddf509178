#include "io/output.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace pound::io {

void write_text_atomic(const std::string& path, const std::string& text) {
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

std::string to_csv(const Table& table) {
  std::string text;
  for (std::size_t c = 0; c < table.columns.size(); ++c)
    text += (c ? "," : "") + table.columns[c];
  text += '\n';
  const std::size_t rows = table.values.empty() ? 0 : table.values.front().size();
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < table.values.size(); ++c) {
      if (c) text += ',';
      text += fmt::format("{:.17g}", table.values[c][r]);
    }
    text += '\n';
  }
  return text;
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
  write_text_atomic(path, to_csv(table));
}

void create_output_folder(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (error || !std::filesystem::is_directory(path))
    throw OutputError(fmt::format("{}: cannot create output folder: {}", path,
                                  error ? error.message() : "a file of that name exists"));
}

}  // namespace pound::io
