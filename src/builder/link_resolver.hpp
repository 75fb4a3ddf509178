#pragma once
// Spec links -> the model's links: their nodes (two distinct ones, or a node and a segment of two
// others), their axis (given, the segment's normal, or from node i to node j), their law from the
// law registry (a tension law with a gap of 0) and their friction (2-D, a normal law that can
// press). Errors are InputErrors at the link's JSON path, or at its generator's.
#include <vector>

#include "builder/resolver.hpp"
#include "model/model.hpp"

namespace pound::builder {

// `model`: its nodes and dimension, already built.
std::vector<model::Link> resolve_links(const Resolver& resolver, const model::Model& model);

}  // namespace pound::builder
