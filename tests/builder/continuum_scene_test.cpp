// What the block generator, surfaces and contacts expand into.
#include <gtest/gtest.h>

#include <cmath>

#include "assembly/quad.hpp"
#include "builder/build.hpp"
#include "builder/generators.hpp"
#include "io/model_reader.hpp"
#include "support/elements.hpp"

namespace pound::builder {
namespace {

constexpr const char* kTwoBlocks = R"({
  "dimension": 2,
  "materials": [{"id": "m", "youngs_modulus": 100, "poisson_ratio": 0.25, "density": 1}],
  "generators": [
    {"type": "block", "id": "a", "origin": [-2, 0], "width": 2, "height": 1, "elements": [2, 4],
     "material": "m", "thickness": 0.5, "pressure": {"top": 3.0}},
    {"type": "block", "id": "b", "origin": [0, 0], "width": 2, "height": 1, "elements": [2, 3],
     "material": "m", "thickness": 0.5, "fixed_edges": ["right"]}
  ],
  "surfaces": [{"id": "floor", "point": [0, -0.25], "normal": [0, 1], "velocity": [2, 0],
                "nodes": ["a.bottom"], "law": {"type": "extended_penalty"},
                "friction": {"coefficient": 0.3}}],
  "contacts": [{"id": "c", "nodes": ["a.right"], "segments": ["b.left"],
                "law": {"type": "extended_penalty"}}],
  "analysis": {"integrator": "central_difference", "time_step": "auto", "duration": 1}
})";

TEST(ContinuumScene, BlocksSurfacesAndContactsExpandAsDocumented) {
  const ModelSpec spec = expand(io::parse_model(kTwoBlocks, "two.json"));
  // Node sets run counter-clockwise round each block.
  const std::vector<std::string> bottom = {"a.0.0", "a.1.0", "a.2.0"};
  EXPECT_EQ(spec.node_sets.at("a.bottom"), bottom);
  const std::vector<std::string> left = {"b.0.3", "b.0.2", "b.0.1", "b.0.0"};
  EXPECT_EQ(spec.node_sets.at("b.left"), left);
  // A pressure of 3 on a's top (width 2, thickness 0.5): 3 in all, downwards, 1/4 at the ends.
  double total = 0.0, corner = 0.0;
  for (const LoadSpec& load : spec.loads) {
    total += load.y;
    if (load.node == "a.0.4") corner += load.y;
    EXPECT_EQ(load.x, 0.0);
  }
  EXPECT_NEAR(total, -3.0, 1e-12);
  EXPECT_NEAR(corner, -0.75, 1e-12);
  // b's right edge fixed.
  EXPECT_EQ(spec.supports.size(), 4u + 1u);  // 4 nodes, and the floor's own node
  int surface_links = 0, node_to_node = 0, node_to_segment = 0;
  for (const LinkSpec& link : spec.links) {
    if (link.id.starts_with("floor.")) {
      ++surface_links;
      EXPECT_EQ(link.node_j, "floor");
      EXPECT_NEAR(link.gap, 0.25, 1e-15);  // a's bottom is 0.25 above the floor
      EXPECT_EQ((*link.axis)[1], -1.0);
      EXPECT_EQ(link.velocity_j[0], 2.0);
      EXPECT_TRUE(link.friction.has_value());
    } else {
      // a's right edge (5 nodes, y = 0, .25, .5, .75, 1) against b's left (y = 0, 1/3, 2/3, 1).
      EXPECT_NEAR((*link.axis)[0], 1.0, 1e-15);
      EXPECT_NEAR(link.gap, 0.0, 1e-15);
      (link.segment_end ? node_to_segment : node_to_node)++;
    }
  }
  EXPECT_EQ(surface_links, 3);
  EXPECT_EQ(node_to_node, 2);
  EXPECT_EQ(node_to_segment, 3);
  // The built model: the node at y = 0.5 sits halfway along b's segment (1/3, 2/3).
  const BuiltModel built = build(io::parse_model(kTwoBlocks, "two.json"));
  const model::Link& middle =
      built.model.links.at(static_cast<std::size_t>(built.link_index.at("c.a.2.2")));
  ASSERT_TRUE(middle.segment_end.has_value());
  EXPECT_NEAR(middle.segment_weight, 0.5, 1e-12);
  EXPECT_EQ(testing::element_count<assembly::Quad>(built.model), 8u + 6u);
}

}  // namespace
}  // namespace pound::builder
