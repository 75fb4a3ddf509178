#pragma once
// What every part of building a model shares: the expanded spec beside the user's own (so an
// entry a generator made is reported at its generator), the indices of the node and link ids, and
// errors with the file and JSON path.
#include <fmt/format.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "builder/spec.hpp"
#include "core/errors.hpp"
#include "core/types.hpp"

namespace pound::builder {

// The JSON path of entry k of an expanded array: the user's own entries keep their path
// ("/links/3"), generated ones point at their generator ("/generators/1").
using Origin = std::function<std::string(std::size_t)>;
Origin origin_of(std::size_t user_count, const char* array,
                 const std::vector<std::string>& generated_from);

class Resolver {
 public:
  // Indexes the ids of `spec`'s nodes, materials, elements and links (expanded from
  // `user_spec`): a repeated id is an error naming both places.
  Resolver(const ModelSpec& user_spec, const ModelSpec& spec);

  const ModelSpec& spec() const { return spec_; }
  const ModelSpec& user_spec() const { return user_spec_; }
  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    throw InputError(spec_.source, path, what);
  }

  // Index of node / element / link `id`, named at `path` (an error when there is none).
  Index node(const std::string& id, const std::string& path) const;
  Index element(const std::string& id, const std::string& path) const;
  Index link(const std::string& id, const std::string& path) const;
  const std::map<std::string, Index>& node_index() const { return nodes_; }
  const std::map<std::string, Index>& link_index() const { return links_; }
  const std::map<std::string, Index>& material_index() const { return materials_; }

  // Index of the ids of `items` (anything with an `id`); a repeat is an error at origin(k).
  template <typename Item>
  std::map<std::string, Index> index_ids(const std::vector<Item>& items, const char* kind,
                                         const Origin& origin) const {
    std::map<std::string, Index> index;
    for (std::size_t k = 0; k < items.size(); ++k) {
      auto [it, inserted] = index.emplace(items[k].id, static_cast<Index>(k));
      if (!inserted)
        fail(origin(k), fmt::format("duplicate {} id '{}' (also at {})", kind, items[k].id,
                                    origin(static_cast<std::size_t>(it->second))));
    }
    return index;
  }

 private:
  const ModelSpec& user_spec_;
  const ModelSpec& spec_;
  std::map<std::string, Index> nodes_, materials_, elements_, links_;
};

}  // namespace pound::builder
