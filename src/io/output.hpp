#pragma once
// Writing results. Every file is written to a temporary name beside its destination and renamed
// when complete, so a crash or a full disk never leaves a half-written result under the real
// name. Failures throw OutputError naming the path and the system's reason.
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/table.hpp"

namespace pound::io {

class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using pound::Table;

// A table of text cells (names and numbers already formatted), for results with categories.
struct TextTable {
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> rows;
};

void write_text_atomic(const std::string& path, std::string_view text);

// Files written under temporary names (<path>.tmp.<pid>) and put in place together: commit()
// renames them in the order they were written, so the last one (a run's summary.json) appears
// only after all the others; of several, the last one's older version is removed first. Whatever is
// not committed is removed when this goes out of scope (an error, Ctrl-C: the writers throw
// Interrupted once a signal arrived).
class StagedFiles {
 public:
  StagedFiles() = default;
  StagedFiles(const StagedFiles&) = delete;
  StagedFiles& operator=(const StagedFiles&) = delete;
  ~StagedFiles();

  void write(const std::string& path, std::string_view text);
  // The parts one after the other, as one file.
  void write_parts(const std::string& path, std::span<const std::string_view> parts);
  void write_csv(const std::string& path, const Table& table);
  // As CSV, or as NumPy's .npy when `path` ends in .npy (to_npy).
  void write_table(const std::string& path, const Table& table);
  // write_table for each (path, table), the formatting of several tables in parallel.
  void write_tables(const std::vector<std::pair<std::string, const Table*>>& tables);
  void commit();

 private:
  std::vector<std::pair<std::string, std::string>> staged_;  // temporary, destination
};

// Removes the <name>.tmp.<pid> files in `folder` whose process is no longer running: what a run
// killed by SIGKILL (which cannot be handled) or a power cut left behind.
void remove_stale_temporaries(const std::string& folder);
std::string to_csv(const TextTable& table);
void write_csv_atomic(const std::string& path, const Table& table);
std::string to_csv(const Table& table);
// NumPy's .npy format 1.0 (2.0 when the header needs it): a structured array of little-endian
// float64 fields named by the columns, one record per row, so that np.load gives the named
// columns and pandas.DataFrame(np.load(path)) the table. Exact (the doubles' own bytes) and far
// cheaper to write than decimal text.
std::string to_npy(const Table& table);

// Creates a folder (and its parents) for outputs; fails if a file of that name exists.
void create_output_folder(const std::string& path);

// Puts a completed folder of results in place in one rename (creating the destination's parents
// and removing an older folder there first), so a reader sees either no folder or a whole one.
void move_folder_into_place(const std::string& temporary, const std::string& destination);

// Removes a folder and everything in it (nothing if it does not exist).
void remove_folder(const std::string& path);

bool is_file(const std::string& path);
bool is_empty_or_missing_folder(const std::string& path);

}  // namespace pound::io
