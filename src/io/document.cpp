#include "io/document.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

namespace pound::io {

struct Document::Impl {
  nlohmann::ordered_json json = nlohmann::ordered_json::object();
  std::vector<std::string> non_finite;

  // A number under `pointer`: null when it is not finite, and then remembered.
  nlohmann::ordered_json number(double value, const std::string& pointer) {
    if (std::isfinite(value)) return value;
    non_finite.push_back(pointer);
    return nullptr;
  }
  void adopt(const Impl& child, const std::string& prefix) {
    for (const std::string& pointer : child.non_finite) non_finite.push_back(prefix + pointer);
  }
};

namespace {

void collect_numbers(const nlohmann::ordered_json& json, const std::string& path,
                     std::vector<std::pair<std::string, double>>& out) {
  if (json.is_number()) {
    out.emplace_back(path, json.get<double>());
  } else if (json.is_object()) {
    for (const auto& [key, value] : json.items()) collect_numbers(value, path + "/" + key, out);
  } else if (json.is_array()) {
    for (std::size_t k = 0; k < json.size(); ++k) {
      const nlohmann::ordered_json& item = json[k];
      const bool named = item.is_object() && item.contains("id") && item["id"].is_string();
      collect_numbers(
          item, path + "/" + (named ? item["id"].get<std::string>() : std::to_string(k)), out);
    }
  }
}

}  // namespace

std::vector<std::pair<std::string, double>> Document::numbers() const {
  std::vector<std::pair<std::string, double>> out;
  collect_numbers(impl_->json, "", out);
  return out;
}

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
  impl_->json[key] = impl_->number(value, "/" + key);
  return *this;
}
Document& Document::set_null(const std::string& key) {
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
  impl_->adopt(*child.impl_, "/" + key);
  return *this;
}
Document& Document::set(const std::string& key, const std::vector<Document>& items) {
  auto array = nlohmann::ordered_json::array();
  for (const Document& item : items) {
    impl_->adopt(*item.impl_, "/" + key + "/" + std::to_string(array.size()));
    array.push_back(item.impl_->json);
  }
  impl_->json[key] = std::move(array);
  return *this;
}
Document& Document::set(const std::string& key, const std::vector<double>& values) {
  auto array = nlohmann::ordered_json::array();
  for (double value : values)
    array.push_back(impl_->number(value, "/" + key + "/" + std::to_string(array.size())));
  impl_->json[key] = std::move(array);
  return *this;
}

std::string Document::dump(int indent) const { return impl_->json.dump(indent); }
const std::vector<std::string>& Document::non_finite() const { return impl_->non_finite; }

std::vector<Document> warning_documents(const std::vector<std::string>& warnings) {
  return documents(warnings, [](const std::string& w) { return Document().set("warning", w); });
}

}  // namespace pound::io
