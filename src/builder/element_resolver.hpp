#pragma once
// Spec elements -> the model's elements (assembly/ truss, beam, quad), each checked against the
// nodes and materials it names: two distinct nodes of a length > 0 and finite, a quad's four
// distinct nodes counter-clockwise round a convex quadrilateral and its material's Poisson's
// ratio, and no quads in a scene with beams. Errors are InputErrors with the JSON path of the
// offending entry.
#include <memory>
#include <string>
#include <vector>

#include "builder/resolver.hpp"
#include "model/model.hpp"

namespace pound::builder {

// `model`: its nodes and dimension, already built.
std::vector<std::shared_ptr<const model::Element>> resolve_elements(const Resolver& resolver,
                                                                    const model::Model& model);

}  // namespace pound::builder
