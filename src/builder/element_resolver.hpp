#pragma once
// Spec elements -> the model's elements (assembly/ truss, beam, quad), each checked against the
// nodes and materials it names: two distinct nodes of a length > 0 and finite, a quad's four
// distinct nodes counter-clockwise round a convex quadrilateral and its material's Poisson's
// ratio, and no quads in a scene with beams. Errors are InputErrors with the JSON path of the
// offending entry.
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "builder/spec.hpp"
#include "model/model.hpp"

namespace pound::builder {

// Index of the node `id`, named at `path` (throws InputError when there is none).
using NodeLookup = std::function<Index(const std::string& id, const std::string& path)>;

// `model`: its nodes and dimension, already built; `materials`: index of each material id in
// spec.materials; `origin(k)`: the JSON path of spec.elements[k].
std::vector<std::shared_ptr<const model::Element>> resolve_elements(
    const ModelSpec& spec, const model::Model& model, const std::map<std::string, Index>& materials,
    const std::function<std::string(std::size_t)>& origin, const NodeLookup& node);

}  // namespace pound::builder
