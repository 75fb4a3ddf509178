#pragma once
// Spec links -> the model's links: their nodes (two distinct ones, or a node and a segment of two
// others), their axis (given, the segment's normal, or from node i to node j), their law from the
// law registry (a tension law with a gap of 0) and their friction (2-D, a normal law that can
// press). Errors are InputErrors at the link's JSON path, or at its generator's.
#include <optional>
#include <vector>

#include "builder/resolver.hpp"
#include "model/model.hpp"

namespace pound::builder {

// `model`: its nodes and dimension, already built.
std::vector<model::Link> resolve_links(const Resolver& resolver, const model::Model& model);

// Wraps the laws of links with `rayleigh` in their stiffness-proportional damping
// (links/stiffness_damping.hpp), a1 given or the model's (known once its damping is).
void add_link_damping(const Resolver& resolver,
                      const std::optional<model::RayleighDamping>& damping,
                      std::vector<model::Link>& links);

}  // namespace pound::builder
