#pragma once
// Scene generators: each turns a few lines of a model file into the nodes, elements, supports,
// initial velocities and links a user would otherwise write by hand. expand() returns a spec
// with no generators left, which is what the builder builds (and what `pound expand` could show).
#include "builder/spec.hpp"
#include "links/law_registry.hpp"

namespace pound::builder {

// The axial stiffness E A / h of the softer element adjacent to a rod pair's contact, which a
// law's stiffness_ratio multiplies.
double rod_pair_adjacent_stiffness(const RodPairSpec& pair);

// The spec with every generator replaced by what it generates (appended after the user's own
// entries, in generator order).
ModelSpec expand(const ModelSpec& spec);

// Appends what one generator makes to `out` (used by expand()).
void add_adjacent_buildings(const AdjacentBuildingsSpec& pair, ModelSpec& out);
void add_girder_bridge(const GirderBridgeSpec& bridge, ModelSpec& out);
void add_block(const BlockSpec& block, ModelSpec& out);
void add_surface(const SurfaceSpec& surface, ModelSpec& out);
void add_contact(const ContactSpec& contact, ModelSpec& out);
std::string block_node_id(const BlockSpec& block, int column, int row);
std::string building_node_id(const AdjacentBuildingsSpec& pair, int side, int floor);

// Parts the generators share.
inline constexpr const char* kPairSides[] = {"left", "right"};  // side 0 and 1 in generated ids
LinkSpec make_link(const std::string& id, const std::string& node_i, const std::string& node_j,
                   std::vector<double> axis, double gap, const LawSpec& law);
// A generator's law in the role its links need, else an InputError at `path` (its "type"): a
// pounding or stop link needs a contact law (compression only) and a restrainer a tension law; a
// spring law there would act both ways from the link's rest length, pulling with k x gap at rest.
// An unknown type is left to the link's own check.
void require_law_role(const LawSpec& law, links::LinkRole role, const std::string& what,
                      const std::string& source, const std::string& path,
                      const std::string& hint = "");
ElementSpec make_beam(const std::string& id, const std::string& node_i, const std::string& node_j,
                      const std::string& material, double area, double inertia);

// Generated ids, shared with whoever looks the generated parts up again.
std::string rod_node_id(const RodPairSpec& pair, int rod, int index);  // rod 0 left, 1 right
std::string rod_link_id(const RodPairSpec& pair);
std::string rod_wall_id(const RodPairSpec& pair);  // the fixed node of a right_wall

}  // namespace pound::builder
