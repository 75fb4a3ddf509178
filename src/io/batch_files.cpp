#include "io/batch_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "io/document.hpp"
#include "io/folder_lock.hpp"
#include "io/output.hpp"

namespace pound::io {
namespace {

namespace fs = std::filesystem;

// The text of a small file, or nothing if it cannot be read.
std::optional<std::string> read_if_possible(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return std::nullopt;
  std::string text;
  std::array<char, 4096> buffer{};
  std::size_t size = 0;
  while ((size = std::fread(buffer.data(), 1, buffer.size(), file)) > 0)
    text.append(buffer.data(), size);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  if (failed) return std::nullopt;
  return text;
}

}  // namespace

std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash) {
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;
  }
  return hash;
}

std::string file_hash(const std::string& path) {
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return "unreadable";
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) return "unreadable";
  std::uint64_t hash = fnv1a_64({});
  std::array<char, 65536> buffer{};
  std::size_t size = 0;
  while ((size = std::fread(buffer.data(), 1, buffer.size(), file)) > 0)
    hash = fnv1a_64(std::string_view(buffer.data(), size), hash);
  const bool failed = std::ferror(file) != 0;
  std::fclose(file);
  return failed ? "unreadable" : fmt::format("{:016x}", hash);
}

std::vector<InputFile> read_plan_inputs(const std::string& plan_file) {
  std::vector<InputFile> inputs;
  const std::optional<std::string> text = read_if_possible(plan_file);
  if (!text) return inputs;
  const nlohmann::json plan = nlohmann::json::parse(*text, nullptr, false);
  if (!plan.is_object() || !plan.contains("inputs") || !plan["inputs"].is_array()) return inputs;
  for (const nlohmann::json& input : plan["inputs"])
    if (input.is_object() && input.value("file", nlohmann::json()).is_string() &&
        input.value("fnv1a_64", nlohmann::json()).is_string())
      inputs.push_back({input["file"].get<std::string>(), input["fnv1a_64"].get<std::string>()});
  return inputs;
}

void write_case_marker(const std::string& folder, const std::string& name) {
  std::vector<std::pair<std::string, std::uintmax_t>> files;
  std::error_code error;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string file = entry.path().filename().string();
    if (file == kCaseMarkerName || !entry.is_regular_file()) continue;
    files.emplace_back(file, entry.file_size());
  }
  if (error)
    throw OutputError(fmt::format("{}: cannot list the case's files: {}", folder, error.message()));
  std::sort(files.begin(), files.end());
  std::vector<Document> listed;
  for (const auto& [file, bytes] : files)
    listed.push_back(Document().set("file", file).set("bytes", static_cast<long>(bytes)));
  write_text_atomic((fs::path(folder) / kCaseMarkerName).string(),
                    Document().set("case", name).set("files", listed).dump() + "\n");
}

bool is_complete_case(const std::string& folder, const std::string& name) {
  const std::optional<std::string> text =
      read_if_possible((fs::path(folder) / kCaseMarkerName).string());
  if (!text) return false;
  const nlohmann::json marker = nlohmann::json::parse(*text, nullptr, false);
  if (!marker.is_object() || marker.value("case", nlohmann::json()) != name ||
      !marker.value("files", nlohmann::json()).is_array())
    return false;
  for (const nlohmann::json& listed : marker["files"]) {
    if (!listed.is_object() || !listed.value("file", nlohmann::json()).is_string() ||
        !listed.value("bytes", nlohmann::json()).is_number_unsigned())
      return false;
    std::error_code error;
    const fs::path file = fs::path(folder) / listed["file"].get<std::string>();
    if (!fs::is_regular_file(file, error) ||
        fs::file_size(file, error) != listed["bytes"].get<std::uintmax_t>() || error)
      return false;
  }
  return true;
}

bool is_empty_but_for_lock(const std::string& folder) {
  std::error_code error;
  if (!fs::exists(folder, error)) return true;
  if (!fs::is_directory(folder, error)) return false;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error))
    if (entry.path().filename() != kLockFileName) return false;
  return !error;
}

}  // namespace pound::io
