#include "builder/element_resolver.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <string_view>

#include "assembly/beam.hpp"
#include "assembly/beam_3d.hpp"
#include "assembly/quad.hpp"
#include "assembly/truss.hpp"
#include "core/errors.hpp"

namespace pound::builder {
namespace {

// What making one element needs besides its own spec.
struct Scene {
  const Resolver& resolver;
  const model::Model& model;

  [[noreturn]] void fail(const std::string& path, const std::string& what) const {
    resolver.fail(path, what);
  }
  Index node(const std::string& id, const std::string& path) const {
    return resolver.node(id, path);
  }
  model::ElementNode at(Index index) const {
    return {index, model.nodes[static_cast<std::size_t>(index)].position};
  }
};

std::shared_ptr<const model::Element> make_quad(const Scene& scene, const ElementSpec& element,
                                                const std::string& path,
                                                const std::array<Index, 2>& first_nodes,
                                                const MaterialSpec& material,
                                                std::optional<model::RayleighDamping> damping) {
  std::array<Index, 4> nodes{first_nodes[0], first_nodes[1], 0, 0};
  std::array<model::ElementNode, 4> corners;
  assembly::QuadCorners positions;
  for (std::size_t a = 0; a < 4; ++a) {
    if (a >= 2)
      nodes[a] = scene.node(element.more_nodes[a - 2], fmt::format("{}/nodes/{}", path, a));
    for (std::size_t b = 0; b < a; ++b)
      if (nodes[a] == nodes[b])
        scene.fail(path + "/nodes",
                   fmt::format("quad '{}' names node '{}' twice", element.id,
                               scene.model.nodes[static_cast<std::size_t>(nodes[a])].id));
    corners[a] = scene.at(nodes[a]);
    positions[a] = corners[a].position;
  }
  const double jacobian = assembly::quad_smallest_jacobian(positions);
  if (!(jacobian > 0.0) || !std::isfinite(jacobian))
    scene.fail(path + "/nodes",
               fmt::format("quad '{}' is degenerate, inverted or numbered clockwise (its "
                           "nodes must go counter-clockwise round a convex quadrilateral)",
                           element.id));
  if (!material.poisson_ratio)
    scene.fail(path + "/material",
               fmt::format("material '{}' needs a 'poisson_ratio' for a quad", element.material));
  return std::make_shared<const assembly::Quad>(
      element.id, corners,
      assembly::Quad::Material{.youngs_modulus = material.youngs_modulus,
                               .poisson_ratio = *material.poisson_ratio,
                               .thickness = element.thickness,
                               .density = material.density,
                               .plane_strain = element.plane_strain},
      element.consistent_mass, damping);
}

// A 3-D beam-column: G from the material (given, or from E and nu), local axes from its
// orientation vector.
std::shared_ptr<const model::Element> make_beam_3d(const Scene& scene, const ElementSpec& element,
                                                   const std::string& path,
                                                   const std::array<model::ElementNode, 2>& ends,
                                                   const MaterialSpec& material,
                                                   std::optional<model::RayleighDamping> damping) {
  double shear_modulus = material.shear_modulus.value_or(0.0);
  if (!material.shear_modulus && material.poisson_ratio)
    shear_modulus = material.youngs_modulus / (2.0 * (1.0 + *material.poisson_ratio));
  if (!(shear_modulus > 0.0))
    scene.fail(path + "/material",
               fmt::format("material '{}' needs a 'shear_modulus' (or a 'poisson_ratio') for the "
                           "torsion of a 3-D beam",
                           element.material));
  const auto point = [](const auto& xyz) { return assembly::Point3(xyz[0], xyz[1], xyz[2]); };
  const std::array<assembly::Beam3d::End, 2> beam_ends{
      assembly::Beam3d::End{ends[0].index, point(ends[0].position), point(element.offsets[0])},
      assembly::Beam3d::End{ends[1].index, point(ends[1].position), point(element.offsets[1])}};
  try {
    return std::make_shared<const assembly::Beam3d>(
        element.id, beam_ends, point(element.orientation),
        assembly::Beam3d::Section{.youngs_modulus = material.youngs_modulus,
                                  .shear_modulus = shear_modulus,
                                  .area = element.area,
                                  .inertia_y = element.inertia_y,
                                  .inertia_z = element.inertia_z,
                                  .torsion = element.torsion,
                                  .density = material.density,
                                  .extra_mass = element.extra_mass},
        element.consistent_mass, damping);
  } catch (const std::invalid_argument& error) {
    // Its flexible part has no length (offsets meeting), or the orientation is along it.
    const std::string_view what = error.what();
    scene.fail(path + (what.starts_with("the beam's ends")      ? "/rigid_offsets"
                       : what.starts_with("the beam is longer") ? "/nodes"
                                                                : "/orientation"),
               fmt::format("beam '{}': {}", element.id, error.what()));
  }
}

// A truss or a beam.
std::shared_ptr<const model::Element> make_two_node(const Scene& scene, const ElementSpec& element,
                                                    const std::string& path,
                                                    const std::array<Index, 2>& nodes,
                                                    const MaterialSpec& material,
                                                    std::optional<model::RayleighDamping> damping) {
  const std::array<model::ElementNode, 2> ends{scene.at(nodes[0]), scene.at(nodes[1])};
  const double length = model::distance(ends[0].position, ends[1].position, scene.model.dimension);
  if (!(length > 0.0))
    scene.fail(path + "/nodes", fmt::format("element '{}' has zero length (nodes '{}' and '{}' "
                                            "are at the same place)",
                                            element.id, element.node_i, element.node_j));
  // Coordinates of ±1e308 are each finite, their distance is not (and the element's stiffness
  // would be 0, reported later as a node without stiffness).
  if (!std::isfinite(length))
    scene.fail(path + "/nodes", fmt::format("element '{}' is infinitely long (nodes '{}' and '{}' "
                                            "are {:g} apart)",
                                            element.id, element.node_i, element.node_j, length));
  if (element.type == ElementKind::beam && scene.model.dimension == 3)
    return make_beam_3d(scene, element, path, ends, material, damping);
  if (element.type == ElementKind::beam)
    return std::make_shared<const assembly::Beam>(
        element.id, ends,
        assembly::Beam::Section{.youngs_modulus = material.youngs_modulus,
                                .area = element.area,
                                .inertia = element.inertia,
                                .density = material.density,
                                .extra_mass = element.extra_mass},
        element.consistent_mass, damping);
  return std::make_shared<const assembly::Truss>(
      element.id, ends, scene.model.dimension,
      assembly::Truss::Section{.youngs_modulus = material.youngs_modulus,
                               .area = element.area,
                               .density = material.density,
                               .axial_force = element.axial_force},
      damping);
}

// E, A, I, a density or a length at the ends of the double range overflow an element's matrices:
// refused here, naming the element, before they make the assembled ones non-finite.
void check_finite_matrices(const Scene& scene, const model::Element& element,
                           const ElementSpec& spec, const std::string& path) {
  const model::ElementMass mass = element.mass();
  const bool finite =
      element.stiffness().allFinite() &&
      (mass.is_consistent() ? mass.consistent.allFinite() : mass.lumped.allFinite());
  if (!finite)
    scene.fail(path, fmt::format("element '{}': its stiffness or mass is not finite (its "
                                 "material, section or length overflows the number range)",
                                 spec.id));
}

}  // namespace

std::vector<std::shared_ptr<const model::Element>> resolve_elements(const Resolver& resolver,
                                                                    const model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  const Origin origin =
      origin_of(resolver.user_spec().elements.size(), "elements", spec.generated_from.elements);
  const std::map<std::string, Index>& materials = resolver.material_index();
  const Scene scene{resolver, model};
  std::vector<std::shared_ptr<const model::Element>> elements;
  bool quads = false, beams = false;
  for (std::size_t k = 0; k < spec.elements.size(); ++k) {
    const ElementSpec& element = spec.elements[k];
    const std::string path = origin(k);
    const std::array<Index, 2> nodes{scene.node(element.node_i, path + "/nodes/0"),
                                     scene.node(element.node_j, path + "/nodes/1")};
    if (nodes[0] == nodes[1]) scene.fail(path + "/nodes", "an element needs two different nodes");
    auto material = materials.find(element.material);
    if (material == materials.end())
      scene.fail(path + "/material", fmt::format("material '{}' does not exist", element.material));
    const MaterialSpec& m = spec.materials[static_cast<std::size_t>(material->second)];
    std::optional<model::RayleighDamping> own;
    if (element.rayleigh)
      own = model::RayleighDamping{(*element.rayleigh)[0], (*element.rayleigh)[1]};
    quads = quads || element.type == ElementKind::quad;
    beams = beams || element.type == ElementKind::beam;
    elements.push_back(element.type == ElementKind::quad
                           ? make_quad(scene, element, path, nodes, m, own)
                           : make_two_node(scene, element, path, nodes, m, own));
    check_finite_matrices(scene, *elements.back(), element, path);
  }
  if (quads && beams)
    for (std::size_t k = 0; k < spec.elements.size(); ++k)
      if (spec.elements[k].type == ElementKind::quad)
        scene.fail(origin(k) + "/type",
                   "quads (2 DOFs per node) cannot share a scene with beams (3 DOFs per node)");
  return elements;
}

}  // namespace pound::builder
