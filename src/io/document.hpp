#pragma once
// An ordered JSON object built by code that must not know JSON (verification/, app/): keys keep the
// order they were set in, numbers print in full precision, NaN/Inf print as null.
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pound::io {

class Document {
 public:
  Document();
  ~Document();
  Document(const Document& other);
  Document& operator=(const Document& other);
  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;

  Document& set(const std::string& key, double value);
  Document& set(const std::string& key, long value);
  Document& set(const std::string& key, int value) { return set(key, static_cast<long>(value)); }
  Document& set(const std::string& key, bool value);
  Document& set(const std::string& key, const std::string& value);
  Document& set(const std::string& key, const char* value) { return set(key, std::string(value)); }
  Document& set(const std::string& key, const Document& child);
  Document& set(const std::string& key, const std::vector<Document>& items);
  Document& set(const std::string& key, const std::vector<double>& values);

  // A value that is meant to be absent ("no limit"): null in the JSON, not counted below.
  Document& set_null(const std::string& key);

  std::string dump(int indent = 2) const;
  // JSON pointers of the numbers that were set non-finite (written as null): a result that
  // overflowed, which a run must not report as completed.
  const std::vector<std::string>& non_finite() const;

  // Every number in it with its path: "/links/bridge.a1.backfill/peak_force" (an array item
  // named by its "id", else by its index), in document order. Booleans and text are left out.
  std::vector<std::pair<std::string, double>> numbers() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// One document per item, in order: an array of objects for Document::set.
template <typename Items, typename ToDocument>
std::vector<Document> documents(const Items& items, ToDocument to_document) {
  std::vector<Document> result;
  for (const auto& item : items) result.push_back(to_document(item));
  return result;
}

// Warnings as the reports list them: {"warning": text} each.
std::vector<Document> warning_documents(const std::vector<std::string>& warnings);

}  // namespace pound::io
