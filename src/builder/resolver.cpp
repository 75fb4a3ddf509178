#include "builder/resolver.hpp"

namespace pound::builder {

Origin origin_of(std::size_t user_count, const char* array,
                 const std::vector<std::string>& generated_from) {
  return [user_count, array, &generated_from](std::size_t k) {
    if (k < user_count) return fmt::format("/{}/{}", array, k);
    return generated_from[k - user_count];
  };
}

Resolver::Resolver(const ModelSpec& user_spec, const ModelSpec& spec)
    : user_spec_(user_spec), spec_(spec) {
  nodes_ = index_ids(spec.nodes, "node",
                     origin_of(user_spec.nodes.size(), "nodes", spec.generated_from.nodes));
  materials_ =
      index_ids(spec.materials, "material",
                origin_of(user_spec.materials.size(), "materials", spec.generated_from.materials));
  elements_ =
      index_ids(spec.elements, "element",
                origin_of(user_spec.elements.size(), "elements", spec.generated_from.elements));
  links_ = index_ids(spec.links, "link",
                     origin_of(user_spec.links.size(), "links", spec.generated_from.links));
}

Index Resolver::node(const std::string& id, const std::string& path) const {
  auto found = nodes_.find(id);
  if (found == nodes_.end()) fail(path, fmt::format("node '{}' does not exist", id));
  return found->second;
}

Index Resolver::element(const std::string& id, const std::string& path) const {
  auto found = elements_.find(id);
  if (found == elements_.end()) fail(path, fmt::format("element '{}' does not exist", id));
  return found->second;
}

Index Resolver::link(const std::string& id, const std::string& path) const {
  auto found = links_.find(id);
  if (found == links_.end()) fail(path, fmt::format("link '{}' does not exist", id));
  return found->second;
}

}  // namespace pound::builder
