#pragma once
// The files by which `pound batch` knows what a batch folder holds: the content hashes of its
// inputs (kept in batch_plan.json, so --resume notices an edited set, model or record) and the
// completion marker of each case (written last, so --resume notices a case left incomplete).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pound::io {

// 64-bit FNV-1a: tiny, and enough to tell an edited file from the one a batch began with (it
// guards against accidents, not against anyone forging a file).
std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash = 0xcbf29ce484222325ULL);

// A file's content hash as 16 hex digits, or "unreadable" (a missing record fails its cases, not
// the batch, and is still a state to compare).
std::string file_hash(const std::string& path);

// An input of a batch and its content hash, as batch_plan.json lists them under "inputs".
struct InputFile {
  std::string path;
  std::string hash;
};

// The "inputs" of a batch_plan.json; none if it has none (written by an older pound) or cannot
// be read.
std::vector<InputFile> read_plan_inputs(const std::string& plan_file);

// The completion marker of a case folder: the name of the case and the size of every other file
// in the folder.
inline constexpr char kCaseMarkerName[] = "case_complete.json";

// Writes the marker of the case `name` into `folder`, once every other file of it is written.
void write_case_marker(const std::string& folder, const std::string& name);

// Whether `folder` holds the whole case `name`: its marker, and every file the marker lists at
// the size it lists. A case killed while being replaced, or damaged later, is not complete.
bool is_complete_case(const std::string& folder, const std::string& name);

// Whether `folder` is missing, empty, or holds nothing but a lock file (left by a batch that
// stopped before it wrote anything).
bool is_empty_but_for_lock(const std::string& folder);

}  // namespace pound::io
