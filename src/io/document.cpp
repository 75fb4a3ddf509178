#include "io/document.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace pound::io {

struct Document::Impl {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
};

Document::Document() : impl_(std::make_unique<Impl>()) {}
Document::~Document() = default;
Document::Document(const Document& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Document& Document::operator=(const Document& other) {
  *impl_ = *other.impl_;
  return *this;
}
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;

Document& Document::set(const std::string& key, double value) {
  if (std::isfinite(value))
    impl_->json[key] = value;
  else
    impl_->json[key] = nullptr;
  return *this;
}
Document& Document::set(const std::string& key, long value) {
  impl_->json[key] = value;
  return *this;
}
Document& Document::set(const std::string& key, bool value) {
  impl_->json[key] = value;
  return *this;
}
Document& Document::set(const std::string& key, const std::string& value) {
  impl_->json[key] = value;
  return *this;
}
Document& Document::set(const std::string& key, const Document& child) {
  impl_->json[key] = child.impl_->json;
  return *this;
}
Document& Document::set(const std::string& key, const std::vector<Document>& items) {
  auto array = nlohmann::ordered_json::array();
  for (const Document& item : items) array.push_back(item.impl_->json);
  impl_->json[key] = std::move(array);
  return *this;
}
Document& Document::set(const std::string& key, const std::vector<double>& values) {
  auto array = nlohmann::ordered_json::array();
  for (double value : values)
    array.push_back(std::isfinite(value) ? nlohmann::ordered_json(value) : nullptr);
  impl_->json[key] = std::move(array);
  return *this;
}

std::string Document::dump(int indent) const { return impl_->json.dump(indent); }

std::vector<Document> warning_documents(const std::vector<std::string>& warnings) {
  return documents(warnings, [](const std::string& w) { return Document().set("warning", w); });
}

}  // namespace pound::io
