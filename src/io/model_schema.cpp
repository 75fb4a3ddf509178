#include "io/model_schema.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include "links/coupled_shear.hpp"
#include "model/direction.hpp"

namespace pound::io {
namespace {

using builder::AdjacentBuildingsSpec;
using builder::AnalysisSpec;
using builder::BlockSpec;
using builder::BuildingSpec;
using builder::ConstraintSpec;
using builder::ContactSpec;
using builder::DampingSpec;
using builder::DriftMonitorSpec;
using builder::ElementSpec;
using builder::ExcitationSpec;
using builder::FrictionSpec;
using builder::GirderBridgeSpec;
using builder::InitialVelocitySpec;
using builder::JointMonitorSpec;
using builder::JointSpec;
using builder::LinkSpec;
using builder::LoadSpec;
using builder::MassSpec;
using builder::MaterialSpec;
using builder::ModelSpec;
using builder::NodalVectorSpec;
using builder::NodeSpec;
using builder::RecorderSpec;
using builder::RodPairSpec;
using builder::RodSpec;
using builder::SectionSpec;
using builder::StoreySpec;
using builder::SupportSpec;
using builder::SurfaceSpec;
using builder::UnitsSpec;
using integrators::AdaptiveStepping;

// A bound on counting (2e9 elements ran out of memory: std::bad_alloc, a crash rather than a
// message); what a machine can hold is checked against its memory before building.
constexpr double kMostRodElements = 1e8;
constexpr int kMostBlockElementsPerSide = 10000;

// ---- Kinds of values that model files have beyond io/schema.hpp ----

// A contact law object, checked against the law catalog.
struct Law {
  using value_type = builder::LawSpec;
  LawPlace place = LawPlace::link;
  // What the law stands for where a force law is needed (a bearing, a restrainer): a constraint
  // such as hard_contact is refused there. Empty where any contact law goes.
  std::string member;

  void read(const JsonValue& value, builder::LawSpec& target, Context&) const {
    target = read_law_in(value, place);
    const links::LawEntry* entry = links::find_law(target.type);
    if (!member.empty() && entry && entry->traits.constraint)
      JsonObject(value).at("type").fail(fmt::format(
          "{} is a contact constraint with no force law of its own; {} needs a force law",
          target.type, member));
  }
  OrderedJson write(const builder::LawSpec& law, const Context&) const { return law_json(law); }
  std::string type() const { return "object"; }
};

// An integrator object or the name of a preset.
struct Integrator {
  using value_type = builder::IntegratorSpec;

  void read(const JsonValue& value, builder::IntegratorSpec& target, Context&) const {
    target = read_integrator(value);
  }
  OrderedJson write(const builder::IntegratorSpec& integrator, const Context&) const {
    return integrator_json(integrator);
  }
  std::string type() const { return "object or string"; }
};

Choice<bool> mass_choice() { return {{{"lumped", false}, {"consistent", true}}}; }
Choice<bool> plane_choice() { return {{{"stress", false}, {"strain", true}}}; }

// ---- Nodes, materials, elements ----

const Fields<NodeSpec>& node_fields() {
  static const Fields<NodeSpec> fields = {
      unique_id(&NodeSpec::id, "nodes", "the node's name"),
      required("x", &NodeSpec::x, Number<>{}, "coordinate [L]"),
      optional("y", &NodeSpec::y, Number<>{}, "coordinate [L]")
          .in_dimensions(2, 3)
          .always_written(),
      optional("z", &NodeSpec::z, Number<>{}, "coordinate [L]").in_space().always_written(),
  };
  return fields;
}

const Fields<MaterialSpec>& material_fields() {
  static const Fields<MaterialSpec> fields = {
      unique_id(&MaterialSpec::id, "materials", "the material's name"),
      required("youngs_modulus", &MaterialSpec::youngs_modulus, Number<>{positive},
               "Young's modulus E [F/L²]"),
      required("density", &MaterialSpec::density, Number<>{non_negative},
               "ρ, mass per volume [M/L³]"),
      optional("poisson_ratio", &MaterialSpec::poisson_ratio,
               Number<>{non_negative, below(0.5, "must be < 0.5 (incompressible), got {}")},
               "Poisson's ratio ν, needed by quads"),
      optional("shear_modulus", &MaterialSpec::shear_modulus, Number<>{positive},
               "G of 3-D beams' torsion [F/L²]")
          .default_text("E / (2 (1 + ν))"),
  };
  return fields;
}

bool is_beam(const ElementSpec& element) { return element.type == builder::ElementKind::beam; }
bool is_quad(const ElementSpec& element) { return element.type == builder::ElementKind::quad; }
bool is_truss(const ElementSpec& element) { return element.type == builder::ElementKind::truss; }

// Two nodes, or four counter-clockwise for a quad; the struct keeps the first two apart.
Field<ElementSpec> element_nodes() {
  return custom<ElementSpec>(
      {"nodes", "2 node ids (4 for a quad)", "required", "its nodes; a quad's counter-clockwise"},
      [](JsonObject& object, ElementSpec& element, Context& context) {
        const std::size_t count = is_quad(element) ? 4 : 2;
        std::vector<std::string> nodes;
        Names{.min_count = count, .max_count = count}.read(object.at("nodes"), nodes, context);
        element.node_i = nodes[0];
        element.node_j = nodes[1];
        element.more_nodes.assign(nodes.begin() + 2, nodes.end());
      },
      [](const ElementSpec& element, const Context&) -> std::optional<OrderedJson> {
        std::vector<std::string> nodes = {element.node_i, element.node_j};
        nodes.insert(nodes.end(), element.more_nodes.begin(), element.more_nodes.end());
        return nodes;
      });
}

// A 3-D beam's rigid end offsets: [[x, y, z] at i, [x, y, z] at j].
struct RigidOffsets {
  using value_type = std::array<std::array<double, 3>, 2>;

  void read(const JsonValue& value, value_type& target, Context& context) const {
    const std::vector<JsonValue> ends = value.elements(2, 2);
    for (std::size_t k = 0; k < 2; ++k) Triple{}.read(ends[k], target[k], context);
  }
  OrderedJson write(const value_type& value, const Context& context) const {
    return OrderedJson::array(
        {Triple{}.write(value[0], context), Triple{}.write(value[1], context)});
  }
  std::string type() const { return "[[x, y, z], [x, y, z]]"; }
};

// A link's rigid offsets: [[x, y], [x, y]] in a plane, [[x, y, z], [x, y, z]] in space.
struct LinkOffsets {
  using value_type = std::array<std::array<double, 3>, 2>;

  void read(const JsonValue& value, value_type& target, Context& context) const {
    const std::vector<JsonValue> ends = value.elements(2, 2);
    const auto count = static_cast<std::size_t>(context.dimension);
    for (std::size_t k = 0; k < 2; ++k) {
      const std::vector<JsonValue> components = ends[k].elements(count, count);
      target[k] = {};
      for (std::size_t d = 0; d < count; ++d) target[k][d] = components[d].as<double>();
    }
  }
  OrderedJson write(const value_type& value, const Context& context) const {
    OrderedJson ends = OrderedJson::array();
    for (const auto& end : value)
      ends.push_back(std::vector<double>(end.begin(), end.begin() + context.dimension));
    return ends;
  }
  std::string type() const { return "[[x, y], [x, y]] in 2-D, [[x, y, z], [x, y, z]] in 3-D"; }
};

using Coefficients = std::array<double, 2>;

const Fields<Coefficients>& rayleigh_fields() {
  static const Fields<Coefficients> fields = {
      optional("mass_coefficient", Entry<Coefficients, 0>{}, Number<>{non_negative},
               "a0 of C = a0·M + a1·K [1/T]")
          .always_written(),
      optional("stiffness_coefficient", Entry<Coefficients, 1>{}, Number<>{non_negative}, "a1 [T]")
          .always_written(),
  };
  return fields;
}

const Fields<ElementSpec>& element_fields() {
  static const Fields<ElementSpec> fields = {
      unique_id(&ElementSpec::id, "elements", "the element's name"),
      required("type", &ElementSpec::type,
               Choice<builder::ElementKind>{{{"truss", builder::ElementKind::truss},
                                             {"beam", builder::ElementKind::beam},
                                             {"quad", builder::ElementKind::quad}}},
               "an axial rod, a beam-column or a plane quadrilateral"),
      element_nodes(),
      required("material", &ElementSpec::material, Text{true}, "id of its material"),
      required("area", &ElementSpec::area, Number<>{positive}, "cross-section area A [L²]")
          .when(std::not_fn(is_quad), "truss and beam"),
      rule<ElementSpec>([](JsonObject& object, ElementSpec& element, Context& context) {
        if (is_quad(element) && context.dimension != 2)
          object.at("type").fail("a quad needs a 2-D scene (\"dimension\": 2)");
        if (is_beam(element) && context.dimension == 1)
          object.at("type").fail("a beam needs a 2-D or 3-D scene (\"dimension\": 2 or 3)");
      }),
      required("inertia", &ElementSpec::inertia, Number<>{positive}, "second moment of area I [L⁴]")
          .when(is_beam, "beam only")
          .in_plane(),
      required("inertia_y", &ElementSpec::inertia_y, Number<>{positive},
               "second moment of area I_y about the local y' axis: bending in the x'-z' plane "
               "[L⁴]")
          .when(is_beam, "beam only")
          .in_space(),
      required("inertia_z", &ElementSpec::inertia_z, Number<>{positive},
               "second moment of area I_z about the local z' axis: bending in the x'-y' plane "
               "[L⁴]")
          .when(is_beam, "beam only")
          .in_space(),
      required("torsion", &ElementSpec::torsion, Number<>{positive},
               "Saint-Venant torsion constant J (G J / L per radian of twist) [L⁴]")
          .when(is_beam, "beam only")
          .in_space(),
      required("orientation", &ElementSpec::orientation, Triple{.nonzero = true},
               "a vector in the local x'-z' plane, not along the element (OpenSees' vecxz): "
               "y' = v × x', z' = x' × y'")
          .when(is_beam, "beam only")
          .in_space(),
      optional("rigid_offsets", &ElementSpec::offsets, RigidOffsets{},
               "rigid end offsets from node i and node j to the ends of the flexible part, "
               "global axes [L]")
          .when(is_beam, "beam only")
          .in_space(),
      optional("extra_mass", &ElementSpec::extra_mass, Number<>{non_negative},
               "added mass per length: deck, barriers, floors [M/L]")
          .when(is_beam, "beam only"),
      required("thickness", &ElementSpec::thickness, Number<>{positive}, "thickness t [L]")
          .when(is_quad, "quad only"),
      optional("plane", &ElementSpec::plane_strain, plane_choice(),
               "plane stress, or plane strain per thickness t")
          .when(is_quad, "quad only"),
      optional("mass", &ElementSpec::consistent_mass, mass_choice(), "lumped or consistent mass")
          .when([](const ElementSpec& element) { return is_beam(element) || is_quad(element); },
                "beam and quad"),
      optional("damping", &ElementSpec::rayleigh, Object<Coefficients>{rayleigh_fields()},
               "its own Rayleigh coefficients instead of the model's"),
      optional("axial_force", &ElementSpec::axial_force, Number<>{},
               "with gravity P-Delta: the axial force N of its geometric stiffness, tension + "
               "(a leaning column whose ends are held vertically carries the weight above it) "
               "[F]")
          .when(is_truss, "truss only"),
  };
  return fields;
}

// ---- Masses, supports, loads, initial velocities ----

// Rotary inertia: about z in a plane (a number); about x, y and z in 3-D ([I_x, I_y, I_z], or
// one number for all three).
Field<MassSpec> rotary_inertia() {
  return custom<MassSpec>(
      {"rotary_inertia", "number >= 0; in 3-D [number, number, number], each >= 0, or a number",
       "`0`", "rotary inertia about z in 2-D, about x, y and z in 3-D; frame scenes [M·L²]"},
      [](JsonObject& object, MassSpec& mass, Context& context) {
        const std::optional<JsonValue> value = object.find("rotary_inertia");
        if (!value) return;
        if (context.dimension == 3 && value->json().is_array()) {
          const std::vector<JsonValue> items = value->elements(3, 3);
          for (std::size_t k = 0; k < 3; ++k)
            mass.rotary_inertia[k] = items[k].as<double>(non_negative);
        } else if (context.dimension == 3) {
          mass.rotary_inertia.fill(value->as<double>(non_negative));
        } else {
          mass.rotary_inertia[2] = value->as<double>(non_negative);
        }
      },
      [](const MassSpec& mass, const Context& context) -> std::optional<OrderedJson> {
        if (mass.rotary_inertia == std::array<double, 3>{}) return std::nullopt;
        if (context.dimension != 3) return mass.rotary_inertia[2];
        return OrderedJson::array(
            {mass.rotary_inertia[0], mass.rotary_inertia[1], mass.rotary_inertia[2]});
      });
}

const Fields<MassSpec>& mass_fields() {
  static const Fields<MassSpec> fields = {
      required("node", &MassSpec::node, Text{true}, "id of the node"),
      required("mass", &MassSpec::mass, Number<>{},
               "mass in every translational direction, > 0; or 0 with a rotary inertia (a "
               "beam's node, whose translational mass the beam lumps) [M]"),
      rotary_inertia(),
      rule<MassSpec>([](JsonObject& object, MassSpec& mass, Context&) {
        if (mass.mass < 0.0) object.at("mass").fail(fmt::format("must be > 0, got {}", mass.mass));
        if (mass.mass == 0.0 && mass.rotary_inertia == std::array<double, 3>{})
          object.at("mass").fail("must be > 0, got 0 (0 only with a rotary_inertia)");
      }),
      optional("mass_damping", &MassSpec::mass_damping, Number<>{non_negative},
               "its own a0 instead of the model's [1/T]"),
  };
  return fields;
}

// A list of directions (`key`: ["x", "rz"]), each once, named as the scene names its directions
// (model/direction.hpp), into a flag per direction.
template <class Spec>
Field<Spec> direction_list(const std::string& key, std::array<bool, 6> Spec::*flags,
                           const std::string& meaning) {
  return custom<Spec>(
      {key, quoted_names({"x", "y", "z", "rx", "ry", "rz"}) + ", each once", "required", meaning},
      [key, flags](JsonObject& object, Spec& spec, Context& context) {
        UniqueNames directions("direction");
        for (const JsonValue& value : object.at(key).elements(1)) {
          const std::string name = value.as_one_of({"x", "y", "z", "rx", "ry", "rz"});
          directions.add(name, value);
          if (name == "y" || name == "rz") require_dimension(value, context, 2, 3);
          if (name == "z" || name == "rx" || name == "ry") require_dimension(value, context, 3, 3);
          for (int d = 0; d < model::direction_count(context.dimension); ++d)
            if (model::direction(d, context.dimension).symbol == name)
              (spec.*flags)[static_cast<std::size_t>(d)] = true;
        }
      },
      [flags](const Spec& spec, const Context& context) -> std::optional<OrderedJson> {
        OrderedJson fixed = OrderedJson::array();
        for (int d = 0; d < model::direction_count(context.dimension); ++d)
          if ((spec.*flags)[static_cast<std::size_t>(d)])
            fixed.push_back(model::direction(d, context.dimension).symbol);
        return fixed;
      });
}

const Fields<SupportSpec>& support_fields() {
  static const Fields<SupportSpec> fields = {
      required("node", &SupportSpec::node, Text{true}, "id of the node"),
      direction_list("fix", &SupportSpec::fixed,
                     "the fixed directions: x in 1-D; x, y, rz in 2-D; x, y, z, rx, ry, rz in 3-D"),
  };
  return fields;
}

const Fields<ConstraintSpec>& constraint_fields() {
  using builder::ConstraintKind;
  static const auto is_equal_dofs = [](const ConstraintSpec& constraint) {
    return constraint.type == ConstraintKind::equal_dofs;
  };
  static const auto is_diaphragm = [](const ConstraintSpec& constraint) {
    return constraint.type == ConstraintKind::rigid_diaphragm;
  };
  static const Fields<ConstraintSpec> fields = {
      required("type", &ConstraintSpec::type,
               Choice<ConstraintKind>{{{"rigid_diaphragm", ConstraintKind::rigid_diaphragm},
                                       {"rigid_beam", ConstraintKind::rigid_beam},
                                       {"rigid_bar", ConstraintKind::rigid_bar},
                                       {"equal_dofs", ConstraintKind::equal_dofs}}},
               "rigid_diaphragm: a floor rigid in its plane (3-D; the slaves' translations in "
               "the plane and rotation about its normal); rigid_beam: a rigid body (every DOF); "
               "rigid_bar: the translations alone (pinned ends); equal_dofs: the directions in "
               "`dofs`, equal to the master's"),
      rule<ConstraintSpec>([](JsonObject& object, ConstraintSpec& constraint, Context& context) {
        if (constraint.type == ConstraintKind::rigid_diaphragm && context.dimension != 3)
          object.at("type").fail(
              "a rigid_diaphragm needs a 3-D scene (\"dimension\": 3); in a plane, tie the "
              "floor's nodes along x with equal_dofs");
        if (constraint.type == ConstraintKind::rigid_beam && context.dimension == 1)
          object.at("type").fail(
              "a rigid_beam needs a 2-D or 3-D scene; in 1-D, use equal_dofs or rigid_bar");
      }),
      required("master", &ConstraintSpec::master, Text{true},
               "id of the master node, whose DOFs the slaves follow"),
      required("slaves", &ConstraintSpec::slaves, Names{}, "ids of the nodes tied to it"),
      direction_list("dofs", &ConstraintSpec::dofs, "the directions tied")
          .when(is_equal_dofs, "equal_dofs only"),
      optional("normal", &ConstraintSpec::normal, Choice<int>{{{"x", 0}, {"y", 1}, {"z", 2}}},
               "the axis the floor's plane is perpendicular to")
          .when(is_diaphragm, "rigid_diaphragm only")
          .in_space(),
  };
  return fields;
}

// Loads and initial velocities: a vector at a node.
Fields<NodalVectorSpec> nodal_vector_fields(const std::string& quantity) {
  return {
      required("node", &NodalVectorSpec::node, Text{true}, "id of the node"),
      optional("x", &NodalVectorSpec::x, Number<>{}, quantity).always_written(),
      optional("y", &NodalVectorSpec::y, Number<>{}, quantity).in_dimensions(2, 3).always_written(),
      optional("z", &NodalVectorSpec::z, Number<>{}, quantity).in_space().always_written(),
  };
}

const Fields<InitialVelocitySpec>& initial_velocity_fields() {
  static const Fields<InitialVelocitySpec> fields = nodal_vector_fields("velocity [L/T]");
  return fields;
}

const Fields<LoadSpec>& load_fields() {
  static const Fields<LoadSpec> fields = nodal_vector_fields("force [F]");
  return fields;
}

// ---- Links ----

const Fields<FrictionSpec>& friction_fields() {
  static const Fields<FrictionSpec> fields = {
      required("coefficient", &FrictionSpec::coefficient, Number<>{non_negative},
               "μ, static = kinetic; above 1 (more than any bearing or pounding surface) the "
               "check warns"),
      optional("stick_stiffness", &FrictionSpec::stick_stiffness, Number<>{positive},
               "stiffness while sticking; default: the normal law's [F/L]; on a friction "
               "pendulum at least 1e4·N/R, or its residual displacement may be off by more "
               "than 2 % of μR (the run warns; laws.md)"),
      optional("stick_damping", &FrictionSpec::stick_damping, Number<>{non_negative},
               "damping while sticking; default: the normal law's [F·T/L]"),
      optional("stick_mass", &FrictionSpec::stick_mass, Number<>{non_negative},
               "mass while sticking; default: the normal law's [M]"),
      optional("radius", &FrictionSpec::radius, Number<>{positive},
               "a friction pendulum's effective radius of curvature R: R_t gains R_n·s/R; "
               "without it a flat slider; links and bridge bearings only [L]"),
  };
  return fields;
}

Object<FrictionSpec> friction_object() { return {friction_fields(), Docs::own_table}; }

Choice<links::DampingStiffness> damping_stiffness_choice() {
  return {{{"initial", links::DampingStiffness::initial},
           {"committed", links::DampingStiffness::committed}}};
}

const Fields<builder::LinkRayleighSpec>& link_rayleigh_fields() {
  using builder::LinkRayleighSpec;
  static const Fields<LinkRayleighSpec> fields = {
      required("stiffness", &LinkRayleighSpec::stiffness, damping_stiffness_choice(),
               "k of a1·k·δ̇: the law's initial stiffness, or its tangent at the last converged "
               "step"),
      optional("stiffness_coefficient", &LinkRayleighSpec::stiffness_coefficient,
               Number<>{non_negative}, "a1 [T]")
          .default_text("the model's"),
  };
  return fields;
}

// Stiffness-proportional damping belongs to a member that deforms both ways, a spring or a
// hinge; a contact or a restrainer law carries its own damping.
Field<LinkSpec> link_rayleigh_role() {
  return rule<LinkSpec>([](JsonObject& object, LinkSpec& link, Context&) {
    if (!link.rayleigh) return;
    const links::LawEntry* law = links::find_law(link.law.type);
    if (law && law->traits.role != links::LinkRole::spring)
      object.at("rayleigh")
          .fail(fmt::format(
              "Rayleigh damping is for structural springs and hinges; a {} law is a {} and carries "
              "its own damping parameters",
              link.law.type,
              law->traits.role == links::LinkRole::contact ? "contact" : "restrainer"));
  });
}

// A shear link is a bearing: a force law along its axis, one law on its tangential rows, and one
// that has a coupled form.
Field<LinkSpec> shear_rules() {
  return rule<LinkSpec>([](JsonObject& object, LinkSpec& link, Context& context) {
    if (link.shear_2 && !link.shear)
      object.at("shear_2").fail("shear_2 is the second direction of a `shear`: give `shear` too");
    if (!link.shear) return;
    const auto refuse = [&](const std::string& key, const std::string& why) {
      object.at(key).fail(why);
    };
    if (link.friction) refuse("friction", "a link has friction or a bearing's shear, not both");
    if (link.rotational && context.dimension != 3)
      refuse("dof",
             "a hinge's coupled bending turns about the two axes across its own: a 3-D scene "
             "(in a plane a hinge turns about z alone)");
    const links::LawEntry* axial = links::find_law(link.law.type);
    if (axial && axial->traits.constraint)
      refuse("law",
             fmt::format("a shear link's axial law must be a force law, not a {}", link.law.type));
    const auto numbers = [&](const std::string& key, const links::LawSpec& law) {
      const JsonValue shear = object.at(key);
      const std::optional<links::ShearNumbers> found =
          links::CoupledShear::numbers_of(law, {shear.file(), shear.path()});
      if (!found)
        JsonObject(shear).at("type").fail(
            fmt::format("a bearing's shear couples its two directions as {} can; a {} cannot "
                        "(give it along each direction as links of their own)",
                        links::CoupledShear::kLaws, law.type));
      return *found;
    };
    const links::ShearNumbers first = numbers("shear", *link.shear);
    if (!link.shear_2) return;
    if (link.shear_2->type != link.shear->type)
      JsonObject(object.at("shear_2"))
          .at("type")
          .fail(fmt::format("the second direction takes the first's law, a {}", link.shear->type));
    if (const std::optional<std::string> why =
            links::CoupledShear::mismatch(first, numbers("shear_2", *link.shear_2)))
      object.at("shear_2").fail(*why);
  });
}

// A surface or a contact is not a bearing: a radius there would give every touching node its
// own dish, which no structure has.
template <class Spec>
Field<Spec> no_pendulum(std::optional<FrictionSpec> Spec::*friction) {
  return rule<Spec>([friction](JsonObject& object, Spec& spec, Context&) {
    if (spec.*friction && (spec.*friction)->radius)
      JsonObject(object.at("friction"))
          .at("radius")
          .fail(
              "a friction pendulum's radius belongs to a link (a bearing), not to a surface or "
              "a contact");
  });
}

// Two nodes, or one with a "segment".
Field<LinkSpec> link_nodes() {
  return custom<LinkSpec>(
      {"nodes", "1 or 2 node ids", "required", "node i and node j, or node i of a segment link"},
      [](JsonObject& object, LinkSpec& link, Context& context) {
        std::vector<std::string> nodes;
        Names{.max_count = 2}.read(object.at("nodes"), nodes, context);
        link.node_i = nodes[0];
        if (nodes.size() == 2) link.node_j = nodes[1];
      },
      [](const LinkSpec& link, const Context&) -> std::optional<OrderedJson> {
        if (link.segment_end) return std::vector<std::string>{link.node_i};
        return std::vector<std::string>{link.node_i, link.node_j};
      });
}

Field<LinkSpec> link_segment() {
  return custom<LinkSpec>(
      {"segment", "2 node ids", "–",
       "instead of node j: the point of segment a–b nearest node i at t = 0"},
      [](JsonObject& object, LinkSpec& link, Context& context) {
        const std::optional<JsonValue> value = object.find("segment");
        if (!value) return;
        std::vector<std::string> ends;
        Names{.min_count = 2, .max_count = 2}.read(*value, ends, context);
        link.node_j = ends[0];
        link.segment_end = ends[1];
      },
      [](const LinkSpec& link, const Context&) -> std::optional<OrderedJson> {
        if (!link.segment_end) return std::nullopt;
        return std::vector<std::string>{link.node_j, *link.segment_end};
      });
}

const Fields<LinkSpec>& link_fields() {
  static const Fields<LinkSpec> fields = {
      unique_id(&LinkSpec::id, "links", "the link's name"),
      link_nodes(),
      rule<LinkSpec>([](JsonObject& object, LinkSpec&, Context&) {
        const std::size_t nodes = object.at("nodes").json().size();
        if (object.has("segment") && nodes != 1)
          object.at("nodes").fail("give one node with a 'segment'");
        if (!object.has("segment") && nodes != 2)
          object.at("nodes").fail("needs 2 entries (or one with a 'segment')");
      }),
      link_segment().in_plane(),
      optional("gap", &LinkSpec::gap, Number<>{non_negative}, "clear distance at t = 0 [L]")
          .always_written(),
      optional("axis", &LinkSpec::axis, UnitVector<std::vector<double>>{},
               "from node i towards node j; needed when they are at the same place")
          .default_text("from the coordinates"),
      optional("rigid_offsets", &LinkSpec::offsets, LinkOffsets{},
               "from node i and node j to the points that touch, rigidly tied to the nodes, "
               "which turn with them (a deck or floor corner) [L]")
          .in_dimensions(2, 3),
      optional("surface_velocity", &LinkSpec::velocity_j, Pair<>{},
               "the j side's own constant velocity [L/T]")
          .in_plane(),
      optional("dof", &LinkSpec::rotational,
               Choice<bool>{{{"translation", false}, {"rotation", true}}},
               "rotation: acts on θ_i − θ_j (frame scenes): about z in 2-D, about its axis in 3-D"),
      required("law", &LinkSpec::law, Law{}, "the contact law: `{\"type\": ..., parameters}`"),
      rule<LinkSpec>([](JsonObject& object, LinkSpec& link, Context& context) {
        if (link.rotational && context.dimension == 1)
          object.at("dof").fail("a rotational link needs a 2-D or 3-D scene");
        if (link.rotational && context.dimension == 2 && link.axis)
          object.at("axis").fail(
              "a rotational link of a plane scene turns about z: it has no axis");
        if (link.rotational && context.dimension == 3 && !link.axis)
          object.at("dof").fail(
              "a rotational link of a 3-D scene needs the \"axis\" it turns about (a unit "
              "vector)");
      }),
      optional("friction", &LinkSpec::friction, friction_object(),
               "Coulomb friction: along the tangent in a plane, in the contact plane in 3-D"),
      optional("shear", &LinkSpec::shear, Law{LawPlace::link, "a bearing's shear"},
               "a bearing's shear law across the axis, along the friction's tangents, its two "
               "directions coupled in 3-D (a circular yield surface); `law` is then the axial "
               "law. " +
                   std::string(links::CoupledShear::kLaws) +
                   ". A rotational link's (3-D): the hinge's bending about the two tangents, "
                   "`law` its torsion")
          .in_dimensions(2, 3),
      optional("shear_2", &LinkSpec::shear_2, Law{LawPlace::link, "the shear's second direction"},
               "the shear law along the second tangent when it differs from `shear` (then "
               "along the first alone): an elliptic yield surface, (F_1/F_y1)² + (F_2/F_y2)² = "
               "1. Same type and hardening ratio as `shear`")
          .in_space(),
      optional("tangent", &LinkSpec::tangent, UnitVector<std::vector<double>>{},
               "t_1 of the friction's or the shear's plane, its part across the axis (t_2 = "
               "axis × t_1): a bearing's or a hinge's local axes, which `shear` and `shear_2` "
               "act along or about")
          .in_space()
          .default_text("for a vertical axis x (t_2 = y); else horizontal, z × axis"),
      rule<LinkSpec>([](JsonObject& object, LinkSpec& link, Context&) {
        if (link.tangent && !link.friction && !link.shear)
          object.at("tangent").fail(
              "orients a friction's or a shear's plane, and this link has neither");
      }),
      optional("rayleigh", &LinkSpec::rayleigh,
               Object<builder::LinkRayleighSpec>{link_rayleigh_fields(), Docs::own_table},
               "stiffness-proportional damping a1·k·δ̇ of a spring or hinge (none without it)"),
      link_rayleigh_role(),
      shear_rules(),
  };
  return fields;
}

// ---- Generators ----

const Fields<RodSpec>& rod_fields() {
  static const Fields<RodSpec> fields = {
      required("youngs_modulus", &RodSpec::youngs_modulus, Number<>{positive}, "E [F/L²]"),
      required("density", &RodSpec::density, Number<>{positive}, "ρ [M/L³]"),
      required("area", &RodSpec::area, Number<>{positive}, "A [L²]"),
      required("length", &RodSpec::length, Number<>{positive}, "L [L]"),
      required("elements", &RodSpec::elements, Number<int>{at_least(1), at_most(kMostRodElements)},
               "n, equal elements"),
      optional("initial_velocity", &RodSpec::initial_velocity, Number<>{}, "along +x [L/T]")
          .always_written(),
      optional("far_end", &RodSpec::far_end_fixed, Choice<bool>{{{"free", false}, {"fixed", true}}},
               "the end away from the contact")
          .always_written(),
  };
  return fields;
}

const Fields<RodPairSpec>& rod_pair_fields() {
  static const Object<RodSpec> rod{rod_fields(), Docs::own_table};
  static const Fields<RodPairSpec> fields = {
      tag<RodPairSpec>("type", "rod_pair", "the generator"),
      unique_id(&RodPairSpec::id, "generators", "prefix of the generated ids"),
      required("left", &RodPairSpec::left, rod, "the rod on [−L1, 0]"),
      optional("right_wall", &RodPairSpec::right_wall, Flag{},
               "a fixed rigid wall at x = 0 (node `<id>.wall`) struck by the left rod across the "
               "gap, in place of a right rod"),
      rule<RodPairSpec>([](JsonObject& object, RodPairSpec& pair, Context&) {
        if (pair.right_wall && object.find("right"))
          object.at("right").fail(
              "a rod pair with \"right_wall\": true has no right rod; give one or the other");
      }),
      required("right", &RodPairSpec::right, rod, "the rod from x = 0")
          .when([](const RodPairSpec& pair) { return !pair.right_wall; }, "unless right_wall"),
      optional("gap", &RodPairSpec::gap, Number<>{non_negative}, "clear distance [L]")
          .always_written(),
      required("law", &RodPairSpec::law, Law{LawPlace::rod_pair},
               "the contact law, as for links; a gap_spring may give `stiffness_ratio`"),
  };
  return fields;
}

const Fields<StoreySpec>& storey_fields() {
  static const Fields<StoreySpec> fields = {
      required("height", &StoreySpec::height, Number<>{positive}, "h [L]"),
      required("mass", &StoreySpec::mass, Number<>{positive},
               "floor mass [M], at least a millionth of the building's heaviest floor"),
      required("stiffness", &StoreySpec::stiffness, Number<>{positive},
               "lateral storey stiffness k [F/L]"),
      optional("law", &StoreySpec::law, Law{LawPlace::storey, "a storey"},
               "a yielding storey: its shear–drift law, a spring law without `stiffness` (the "
               "storey's); in 3-D along x and along y, each with its stiffness"),
      optional("stiffness_y", &StoreySpec::stiffness_y, Number<>{positive},
               "lateral storey stiffness along y [F/L]; `stiffness` acts along x")
          .in_space()
          .default_text("`stiffness`"),
      optional("torsional_stiffness", &StoreySpec::torsional_stiffness, Number<>{positive},
               "the storey's stiffness against twist about its stiffness centre [F·L/rad]")
          .in_space()
          .default_text(
              "(k_x b² + k_y a²) / 12: the lateral stiffness spread evenly over the plan"),
      optional("rotary_inertia", &StoreySpec::rotary_inertia, Number<>{positive},
               "the floor's polar moment of inertia about its mass centre [M·L²]")
          .in_space()
          .default_text("m (a² + b²) / 12: a uniform slab"),
  };
  return fields;
}

const Fields<BuildingSpec>& building_fields() {
  static const Fields<BuildingSpec> fields = {
      optional("damping_ratio", &BuildingSpec::damping_ratio,
               Number<>{non_negative, below(1.0, "must be < 1")},
               "Rayleigh damping ratio at its own modes 1 and 2")
          .always_written(),
      required("storeys", &BuildingSpec::storeys, Objects<StoreySpec>{storey_fields(), 1},
               "from the ground up"),
      optional("storey_damping", &BuildingSpec::storey_damping,
               Choice<builder::StoreyDamping>{{{"initial", builder::StoreyDamping::initial},
                                               {"committed", builder::StoreyDamping::committed},
                                               {"none", builder::StoreyDamping::none}}},
               "the stiffness-proportional damping of its yielding storeys: a1 times their "
               "initial stiffness (the elastic column's), a1 times their tangent at the last "
               "converged step, or none (the link's `rayleigh`)")
          .when(
              [](const BuildingSpec& building) {
                return std::any_of(building.storeys.begin(), building.storeys.end(),
                                   [](const StoreySpec& storey) { return storey.law.has_value(); });
              },
              "with a yielding storey, one that has a `law`"),
      optional("storey_interaction", &BuildingSpec::storeys_coupled,
               Choice<bool>{{{"elliptic", true}, {"none", false}}},
               "elliptic: each yielding storey one link `<storey>` whose shears along x and y "
               "yield together, (V_x/V_yx)² + (V_y/V_yy)² = 1 (a circle when stiffness_y = "
               "stiffness); none: a link per direction (`<storey>`, `<storey>.y`)")
          .in_space()
          .default_text("elliptic, for a storey law that has the coupled form"),
      rule<BuildingSpec>([](JsonObject& object, BuildingSpec& building, Context&) {
        if (!building.storeys_coupled.value_or(false)) return;
        const JsonValue storeys = object.at("storeys");
        for (std::size_t s = 0; s < building.storeys.size(); ++s) {
          const StoreySpec& storey = building.storeys[s];
          if (storey.law &&
              !storey.law_couples({storeys.file(), fmt::format("{}/{}/law", storeys.path(), s)}))
            object.at("storey_interaction")
                .fail(fmt::format(
                    "storey {} has a {} law, which has no coupled form ({} have): give \"none\"",
                    s + 1, storey.law->type, links::CoupledShear::kLaws));
        }
      }),
      required("plan", &BuildingSpec::plan, Pair<>{positive},
               "plan dimensions [a, b]: a along x (toward the other building), b along y [L]")
          .in_space(),
      optional("mass_centre", &BuildingSpec::mass_centre, Pair<>{},
               "where the floors' mass centre lies from the plan's centre, [x, y] [L]")
          .in_space()
          .default_text("`[0, 0]`"),
      optional("stiffness_centre", &BuildingSpec::stiffness_centre, Pair<>{},
               "where the storeys' stiffness centre lies from the plan's centre, [x, y] [L]")
          .in_space()
          .default_text("`[0, 0]`"),
      rule<BuildingSpec>([](JsonObject& object, BuildingSpec& building, Context& context) {
        if (context.dimension != 3) return;
        for (const char* name : {"mass_centre", "stiffness_centre"}) {
          const std::array<double, 2>& centre =
              name[0] == 'm' ? building.mass_centre : building.stiffness_centre;
          for (std::size_t k = 0; k < 2; ++k)
            if (std::abs(centre[k]) > 0.5 * building.plan[k])
              object.at(name).fail(fmt::format(
                  "must lie within the plan: |{}| <= {:g} (half the plan's {}), got {:g}",
                  k == 0 ? "x" : "y", 0.5 * building.plan[k], k == 0 ? "a" : "b", centre[k]));
        }
      }),
  };
  return fields;
}

// A storey law is a spring law in place of the storey's column, so nothing may hit the storey
// between its floors: a floor of the other building there needs the column (docs/model_format.md).
void check_storey_laws(JsonObject& object, const AdjacentBuildingsSpec& pair) {
  const std::array<const BuildingSpec*, 2> buildings{&pair.left, &pair.right};
  std::array<std::vector<double>, 2> floors;
  for (std::size_t side = 0; side < 2; ++side) {
    floors[side] = {0.0};
    for (const StoreySpec& storey : buildings[side]->storeys)
      floors[side].push_back(floors[side].back() + storey.height);
  }
  const double top = std::min(floors[0].back(), floors[1].back());
  const double tolerance = builder::level_tolerance(pair);
  for (std::size_t side = 0; side < 2; ++side)
    for (std::size_t s = 0; s < buildings[side]->storeys.size(); ++s) {
      const std::optional<links::LawSpec>& law = buildings[side]->storeys[s].law;
      if (!law) continue;
      const auto where = [&] {
        return JsonObject(JsonObject(object.at(side == 0 ? "left" : "right")).array("storeys")[s])
            .at("law");
      };
      const links::LawEntry& entry = *links::find_law(law->type);
      if (entry.traits.role != links::LinkRole::spring || !entry.parameter("stiffness"))
        where().fail(
            fmt::format("'{}' cannot be a storey's shear–drift law: give a spring law "
                        "with a stiffness (bilinear_spring, takeda, clough, bouc_wen, "
                        "elastic_perfectly_plastic, elastic_spring...)",
                        law->type));
      const double bottom = floors[side][s], upper = floors[side][s + 1];
      for (double h : floors[1 - side])
        if (h > bottom + tolerance && h < upper - tolerance && h <= top + tolerance)
          where().fail(fmt::format(
              "the {} building's floor at {:g} meets this storey between its floors ({:g} to "
              "{:g}): a yielding storey is a shear link with no column to hit there; give the "
              "two buildings floors at the same heights here, or leave this storey elastic",
              side == 0 ? "right" : "left", h, bottom, upper));
    }
}

const Fields<AdjacentBuildingsSpec>& adjacent_buildings_fields() {
  static const Object<BuildingSpec> building{building_fields(), Docs::own_table};
  static const Fields<AdjacentBuildingsSpec> fields = {
      tag<AdjacentBuildingsSpec>("type", "adjacent_buildings", "the generator"),
      unique_id(&AdjacentBuildingsSpec::id, "generators", "prefix of the generated ids"),
      required("left", &AdjacentBuildingsSpec::left, building, "the left building"),
      required("right", &AdjacentBuildingsSpec::right, building, "the right building"),
      required("separation", &AdjacentBuildingsSpec::separation, Number<>{non_negative},
               "clear gap between the facades [L]"),
      rule<AdjacentBuildingsSpec>([](JsonObject& object, AdjacentBuildingsSpec& pair, Context&) {
        check_storey_laws(object, pair);
      }),
      required("law", &AdjacentBuildingsSpec::law, Law{}, "pounding law of every link"),
      optional("offset", &AdjacentBuildingsSpec::offset, Number<>{},
               "the right building's plan centre from the left's, along y [L]")
          .in_space()
          .default_text("`0`"),
      optional("contact_points", &AdjacentBuildingsSpec::contact_points,
               Number<int>{at_least(1), at_most(20, "must be <= 20")},
               "pounding points at each contact height, spread along the stretch where the "
               "facades face each other: 2 its ends (the corners that meet), 1 its middle; each "
               "takes the law")
          .in_space()
          .default_text("`2`"),
      rule<AdjacentBuildingsSpec>([](JsonObject& object, AdjacentBuildingsSpec& pair,
                                     Context& context) {
        if (context.dimension != 3) return;
        const auto [low, high] = builder::facing_stretch(pair);
        if (!(high > low))
          (object.has("offset") ? object.at("offset") : object.at("right"))
              .fail(fmt::format(
                  "the facades do not face each other: the right building spans y = {:g} … {:g}, "
                  "the left one {:g} … {:g}, so they cannot pound",
                  pair.offset - 0.5 * pair.right.plan[1], pair.offset + 0.5 * pair.right.plan[1],
                  -0.5 * pair.left.plan[1], 0.5 * pair.left.plan[1]));
      }),
  };
  return fields;
}

const Fields<SectionSpec>& section_fields() {
  static const Fields<SectionSpec> fields = {
      required("youngs_modulus", &SectionSpec::youngs_modulus, Number<>{positive}, "E [F/L²]"),
      required("area", &SectionSpec::area, Number<>{positive}, "A [L²]"),
      required("inertia", &SectionSpec::inertia, Number<>{positive}, "I [L⁴]"),
      optional("density", &SectionSpec::density, Number<>{non_negative}, "ρ [M/L³]")
          .always_written(),
      optional("extra_mass", &SectionSpec::extra_mass, Number<>{non_negative},
               "added mass per length [M/L]")
          .always_written(),
      optional("elements", &SectionSpec::elements,
               Number<int>{at_least(1), at_most(1000, "must be <= 1000")},
               "per span (girder) or per pier")
          .always_written()
          .default_text("`4` (girder), `2` (pier)"),
      required("inertia_lateral", &SectionSpec::inertia_lateral, Number<>{positive},
               "I for bending across the bridge (a girder's about the vertical, a pier's in the "
               "transverse plane) [L⁴]; `inertia` bends in the vertical plane along the bridge")
          .in_space(),
      required("torsion", &SectionSpec::torsion, Number<>{positive},
               "Saint-Venant torsion constant J [L⁴]")
          .in_space(),
      optional("poisson_ratio", &SectionSpec::poisson_ratio,
               Number<>{non_negative, below(0.5, "must be < 0.5, got {}")},
               "ν for the shear modulus G = E / (2 (1 + ν)) of the torsion")
          .in_space()
          .default_text("`0.2` (concrete)"),
  };
  return fields;
}

const Fields<builder::ShearKeySpec>& shear_key_fields() {
  using builder::ShearKeySpec;
  static const Fields<ShearKeySpec> fields = {
      required("gap", &ShearKeySpec::gap, Number<>{non_negative},
               "clear distance between the deck end and each key [L]"),
      required("law", &ShearKeySpec::law, Law{}, "the key's law in compression"),
  };
  return fields;
}

const Fields<JointSpec>& joint_fields() {
  static const Fields<JointSpec> fields = {
      required("gap", &JointSpec::gap, Number<>{non_negative}, "clear distance [L]"),
      required("law", &JointSpec::law, Law{}, "pounding law"),
      optional("restrainer", &JointSpec::restrainer, Law{LawPlace::link, "a restrainer"},
               "a tension law (restrainer, hook) across the joint"),
      optional("seat_width", &JointSpec::seat_width, Number<>{non_negative},
               "[L]; 0: unseating not checked")
          .always_written(),
  };
  return fields;
}

Field<GirderBridgeSpec> expansion_joints() {
  return custom<GirderBridgeSpec>(
      {"expansion_joints", "array of integers", "–", "piers (1 … spans − 1) where the deck is cut"},
      [](JsonObject& object, GirderBridgeSpec& bridge, Context&) {
        const std::optional<JsonValue> list = object.find("expansion_joints");
        if (!list) return;
        UniqueNames joints("expansion joint");
        for (const JsonValue& value : list->elements()) {
          const int pier = value.as<int>(at_least(1));
          if (pier >= static_cast<int>(bridge.spans.size()))
            value.fail(bridge.spans.size() == 1
                           ? fmt::format("is pier {}, but a one-span bridge has no piers, so no "
                                         "joint over one (its ends are the abutments')",
                                         pier)
                           : fmt::format("is pier {}, but the bridge has piers 1 to {}", pier,
                                         bridge.spans.size() - 1));
          joints.add(std::to_string(pier), value);
          bridge.expansion_joints.push_back(pier);
        }
      },
      [](const GirderBridgeSpec& bridge, const Context&) -> std::optional<OrderedJson> {
        if (bridge.expansion_joints.empty()) return std::nullopt;
        return bridge.expansion_joints;
      });
}

// Needed with expansion joints; a spec without it has a joint with no law.
Field<GirderBridgeSpec> joint_at_expansion_joints() {
  const Object<JointSpec> joint{joint_fields(), Docs::own_table};
  return custom<GirderBridgeSpec>(
      {"joint", joint.type(), "–", "gap, law, restrainer and seat of the expansion joints"},
      [joint](JsonObject& object, GirderBridgeSpec& bridge, Context& context) {
        if (!bridge.expansion_joints.empty() || object.has("joint"))
          joint.read(object.at("joint"), bridge.joint, context);
      },
      [joint](const GirderBridgeSpec& bridge,
              const Context& context) -> std::optional<OrderedJson> {
        if (bridge.expansion_joints.empty() && bridge.joint.law.type.empty()) return std::nullopt;
        return joint.write(bridge.joint, context);
      });
}

const Fields<builder::PierHingeSpec>& pier_hinge_fields() {
  using builder::PierHingeSpec;
  static const Fields<PierHingeSpec> fields = {
      optional("yield_moment", &PierHingeSpec::yield_moment, Number<>{positive}, "M_y [F L]"),
      optional("yield_curvature", &PierHingeSpec::yield_curvature, Number<>{positive},
               "φ_y [1/L]: M_y = E I φ_y with the pier section's E I"),
      optional("plastic_hinge_length", &PierHingeSpec::plastic_hinge_length, Number<>{positive},
               "L_p [L], with yield_curvature: curvature ductility 1 + θ_p / (φ_y L_p)"),
      optional("yield_moment_lateral", &PierHingeSpec::yield_moment_lateral, Number<>{positive},
               "M_y across the bridge, with yield_moment [F L]")
          .in_space()
          .default_text("`yield_moment`"),
      optional("yield_curvature_lateral", &PierHingeSpec::yield_curvature_lateral,
               Number<>{positive},
               "φ_y across the bridge, with yield_curvature: M_y = E I_lateral φ_y [1/L]")
          .in_space()
          .default_text("`yield_curvature`"),
      rule<PierHingeSpec>([](JsonObject& object, PierHingeSpec& hinge, Context&) {
        if (hinge.yield_moment.has_value() == hinge.yield_curvature.has_value())
          object.fail("give either 'yield_moment' or 'yield_curvature', not both");
        if (hinge.plastic_hinge_length && !hinge.yield_curvature)
          object.at("plastic_hinge_length").fail("needs 'yield_curvature'");
        if (hinge.yield_moment_lateral && !hinge.yield_moment)
          object.at("yield_moment_lateral")
              .fail("goes with 'yield_moment' (not 'yield_curvature')");
        if (hinge.yield_curvature_lateral && !hinge.yield_curvature)
          object.at("yield_curvature_lateral")
              .fail("goes with 'yield_curvature' (not 'yield_moment')");
      }),
      optional("stiffness_factor", &PierHingeSpec::stiffness_factor, Number<>{positive},
               "n: hinge stiffness (n + 1)·3 E I / h, pier E I raised to (n + 1)/n E I")
          .always_written(),
      required("law", &PierHingeSpec::law, Law{LawPlace::pier_hinge, "a pier hinge"},
               "moment–rotation law of the hinges, without `stiffness` and `yield_force` (the "
               "generator sets them)"),
      optional("damping", &PierHingeSpec::damping, damping_stiffness_choice(),
               "stiffness-proportional damping of the hinges with the model's a1: times their "
               "initial stiffness (the elastic pier's damping), or their tangent at the last "
               "converged step (the link's `rayleigh`)")
          .default_text("none"),
      optional("interaction", &PierHingeSpec::coupled,
               Choice<bool>{{{"elliptic", true}, {"none", false}}},
               "elliptic: one hinge `<pier>.hinge` bending about x and y, yielding on "
               "(M_x/M_yx)² + (M_y/M_yy)² = 1 (a circle when the two are equal); none: a hinge "
               "per axis, each on its own (`.hinge`, `.hinge.across`)")
          .in_space()
          .default_text("elliptic, for a law that has the coupled form"),
      rule<PierHingeSpec>([](JsonObject& object, PierHingeSpec& hinge, Context&) {
        if (!hinge.coupled.value_or(false)) return;
        const JsonValue law = object.at("law");
        if (!hinge.law_couples({law.file(), law.path()}))
          object.at("interaction")
              .fail(fmt::format("a {} hinge has no coupled form ({} have): give \"none\"",
                                hinge.law.type, links::CoupledShear::kLaws));
      }),
  };
  return fields;
}

// A displacement [L] named `key`, also read under its older name `old_key` (which read as a
// ratio): one of the two, written under `key`.
template <class Spec>
Field<Spec> renamed_displacement(std::string key, std::string old_key,
                                 std::optional<double> Spec::*member, std::string meaning) {
  return custom<Spec>(
      {key, "number > 0", "–",
       fmt::format("{} [L]: a displacement, not a ratio (also read as `{}`, its older name)",
                   meaning, old_key)},
      [key, old_key, member](JsonObject& object, Spec& spec, Context&) {
        const std::optional<JsonValue> value = object.find(key);
        const std::optional<JsonValue> old = object.find(old_key);
        if (value && old)
          old->fail(fmt::format("'{}' is the older name of '{}': give one of them", old_key, key));
        if (value || old) spec.*member = (value ? *value : *old).template as<double>(positive);
      },
      [member](const Spec& spec, const Context&) -> std::optional<OrderedJson> {
        if (!(spec.*member)) return std::nullopt;
        return *(spec.*member);
      });
}

const Fields<GirderBridgeSpec>& girder_bridge_fields() {
  static const Object<SectionSpec> section{section_fields(), Docs::own_table};
  static const Fields<GirderBridgeSpec> fields = {
      tag<GirderBridgeSpec>("type", "girder_bridge", "the generator"),
      unique_id(&GirderBridgeSpec::id, "generators", "prefix of the generated ids"),
      required("spans", &GirderBridgeSpec::spans, Numbers{1, 100, positive}, "span lengths [L]"),
      required("girder", &GirderBridgeSpec::girder, section, "the girders' section"),
      required("pier", &GirderBridgeSpec::pier, section, "the piers' section"),
      required("pier_height", &GirderBridgeSpec::pier_height, Number<>{positive},
               "deck level above the pier bases [L]"),
      renamed_displacement<GirderBridgeSpec>(
          "pier_yield_displacement", "pier_yield_drift", &GirderBridgeSpec::pier_yield_drift,
          "the pier top's drift at yield, for the piers' displacement ductility"),
      optional("pier_hinge", &GirderBridgeSpec::pier_hinge,
               Object<builder::PierHingeSpec>{pier_hinge_fields(), Docs::own_table},
               "plastic hinges at the piers' bases (yielding piers)"),
      rule<GirderBridgeSpec>([](JsonObject& object, GirderBridgeSpec& bridge, Context&) {
        if (bridge.pier_hinge && bridge.pier_yield_drift)
          (object.has("pier_yield_displacement") ? object.at("pier_yield_displacement")
                                                 : object.at("pier_yield_drift"))
              .fail("not with 'pier_hinge': the hinges' yield moment gives the yield drift");
      }),
      optional("bearing", &GirderBridgeSpec::bearing, Law{LawPlace::link, "a bearing"},
               "horizontal law of every bearing; required without bearing_friction, in "
               "parallel with it otherwise"),
      required("bearing_vertical_stiffness", &GirderBridgeSpec::bearing_vertical_stiffness,
               Number<>{positive},
               "the bearings' vertical stiffness: elastic, or compression-only with "
               "bearing_friction [F/L]"),
      optional("bearing_friction", &GirderBridgeSpec::bearing_friction, friction_object(),
               "sliding bearings: the vertical bearing becomes a compression-only gap_spring "
               "that carries this friction (with a radius: a friction pendulum, whose "
               "stick_stiffness defaults to max(bearing_vertical_stiffness, 1e4·W/R), W the "
               "deck's weight); the friction follows its normal force, so the girders need "
               "their weight (\"gravity\")"),
      optional("bearing_interaction", &GirderBridgeSpec::bearing_coupled,
               Choice<bool>{{{"circular", true}, {"none", false}}},
               "circular: the bearing law's two horizontal directions coupled, yielding on a "
               "circle (one link `.bearing`); none: each direction on its own (`.bearing_x`, "
               "`.bearing_y`)")
          .in_space()
          .default_text("circular, for a law that has the coupled form and no bearing_friction"),
      rule<GirderBridgeSpec>([](JsonObject& object, GirderBridgeSpec& bridge, Context&) {
        if (!bridge.bearing_coupled.value_or(false)) return;
        if (bridge.bearing_friction)
          object.at("bearing_interaction")
              .fail(
                  "with bearing_friction the bearing law acts beside the friction, each "
                  "direction on its own: give \"none\"");
        if (!bridge.bearing)
          object.at("bearing_interaction").fail("couples the 'bearing' law, which is not given");
        const JsonValue law = object.at("bearing");
        if (!links::CoupledShear::numbers_of(*bridge.bearing, {law.file(), law.path()}))
          object.at("bearing_interaction")
              .fail(fmt::format("a {} bearing has no coupled form ({} have): give \"none\"",
                                bridge.bearing->type, links::CoupledShear::kLaws));
      }),
      rule<GirderBridgeSpec>([](JsonObject& object, GirderBridgeSpec& bridge, Context&) {
        if (!bridge.bearing && !bridge.bearing_friction)
          object.fail(
              "needs 'bearing' (the bearings' horizontal law), 'bearing_friction' "
              "(sliding bearings) or both");
      }),
      expansion_joints(),
      joint_at_expansion_joints(),
      required("abutment", &GirderBridgeSpec::abutment,
               Object<JointSpec>{joint_fields(), Docs::own_table},
               "girder end against the backwall"),
      optional("backfill", &GirderBridgeSpec::backfill, Law{LawPlace::link, "the backfill"},
               "a compression-only law behind each backwall; without it the backwall is fixed"),
      required("backwall_mass", &GirderBridgeSpec::backwall_mass, Number<>{positive},
               "mass of each backwall [M]")
          .when([](const GirderBridgeSpec& bridge) { return bridge.backfill.has_value(); },
                "with backfill"),
      required("deck_width", &GirderBridgeSpec::deck_width, Number<>{positive},
               "the deck's width square to its axis, as drawings give it; a skewed "
               "deck's ends, from corner to corner, are deck_width / cos(skew) long [L]")
          .in_space(),
      optional("bearing_spacing", &GirderBridgeSpec::bearing_spacing, Number<>{positive},
               "distance across the deck (square to its axis) between its outer bearings, "
               "whose vertical stiffness holds the deck's twist on a seat: k_v s² / 4 per seat "
               "[L]")
          .in_space()
          .default_text("half the deck_width"),
      optional(
          "skew", &GirderBridgeSpec::skew,
          Number<>{Minimum{-80.0, true}, below(80.0, "must be within (-80, 80) degrees, got {}")},
          "angle of the deck ends, joints and backwalls from the transverse axis y, "
          "counter-clockwise in plan [deg]")
          .in_space()
          .default_text("`0`"),
      optional("contact_points", &GirderBridgeSpec::contact_points,
               Number<int>{at_least(1), at_most(20, "must be <= 20")},
               "pounding points along each deck end: 2 its corners, more spread evenly between "
               "them, 1 its centre; each takes the joint's law")
          .in_space()
          .default_text("`2`"),
      optional("shear_keys", &GirderBridgeSpec::shear_keys,
               Object<builder::ShearKeySpec>{shear_key_fields(), Docs::own_table},
               "transverse stops on each abutment seat, either side of the deck end")
          .in_space(),
      optional("plan_radius", &GirderBridgeSpec::plan_radius, Number<>{},
               "radius of the deck's centreline in plan, positive turning toward +y "
               "(counter-clockwise from above); the bridge may turn less than 90 degrees [L]")
          .in_space()
          .default_text("straight"),
      rule<GirderBridgeSpec>([](JsonObject& object, GirderBridgeSpec& bridge, Context&) {
        if (!bridge.plan_radius) return;
        double length = 0.0;
        for (double span : bridge.spans) length += span;
        const double smallest = length / (0.5 * std::numbers::pi);
        if (!(std::abs(*bridge.plan_radius) > smallest))
          object.at("plan_radius")
              .fail(fmt::format("|R| must be > {:g} (the {:g} long bridge would turn 90 degrees "
                                "or more), got {:g}",
                                smallest, length, *bridge.plan_radius));
      }),
  };
  return fields;
}

// "elements": [columns, rows].
Field<BlockSpec> block_elements() {
  return custom<BlockSpec>(
      {"elements", fmt::format("[integer, integer], each ≥ 1, ≤ {}", kMostBlockElementsPerSide),
       "required", "elements along x and along y"},
      [](JsonObject& object, BlockSpec& block, Context&) {
        const std::vector<JsonValue> counts = object.at("elements").elements(2, 2);
        block.columns = counts[0].as<int>(at_least(1));
        block.rows = counts[1].as<int>(at_least(1));
        for (const JsonValue& count : counts)
          if (count.as<int>() > kMostBlockElementsPerSide)
            count.fail(fmt::format("must be <= {} elements per side", kMostBlockElementsPerSide));
      },
      [](const BlockSpec& block, const Context&) -> std::optional<OrderedJson> {
        return OrderedJson::array({block.columns, block.rows});
      });
}

using Pressures = std::array<double, 4>;

const Fields<Pressures>& pressure_fields() {
  static const Fields<Pressures> fields = {
      optional("bottom", Entry<Pressures, 0>{}, Number<>{}, "[F/L²]"),
      optional("right", Entry<Pressures, 1>{}, Number<>{}, "[F/L²]"),
      optional("top", Entry<Pressures, 2>{}, Number<>{}, "[F/L²]"),
      optional("left", Entry<Pressures, 3>{}, Number<>{}, "[F/L²]"),
  };
  return fields;
}

const Fields<BlockSpec>& block_fields() {
  static const Fields<BlockSpec> fields = {
      tag<BlockSpec>("type", "block", "the generator"),
      unique_id(&BlockSpec::id, "generators", "prefix of the generated ids and node sets"),
      optional("origin", &BlockSpec::origin, Pair<>{}, "lower left corner [L]").always_written(),
      required("width", &BlockSpec::width, Number<>{positive}, "along x [L]"),
      required("height", &BlockSpec::height, Number<>{positive}, "along y [L]"),
      block_elements(),
      required("material", &BlockSpec::material, Text{true},
               "id of a material with a poisson_ratio"),
      required("thickness", &BlockSpec::thickness, Number<>{positive}, "t [L]"),
      optional("plane", &BlockSpec::plane_strain, plane_choice(), "as for a quad"),
      optional("mass", &BlockSpec::consistent_mass, mass_choice(), "as for a quad"),
      optional("initial_velocity", &BlockSpec::initial_velocity, Pair<>{}, "of every node [L/T]"),
      optional("pressure", &BlockSpec::pressure, Object<Pressures>{pressure_fields()},
               "uniform pressure on each edge, positive into the block"),
      optional("fixed_edges", &BlockSpec::fixed_edges,
               Names{.what = "edge", .max_count = 4, .options = {"bottom", "right", "top", "left"}},
               "edges whose nodes are fixed in x and y"),
  };
  return fields;
}

// One entry of "generators", whose "type" picks the kind; each kind keeps its entries in a list
// of its own with their index in the array.
void read_generator(JsonObject& generator, int index, ModelSpec& spec, Context& context) {
  const std::string type =
      generator.one_of("type", {"rod_pair", "adjacent_buildings", "girder_bridge", "block"});
  if (type == "block") {
    if (context.dimension != 2)
      generator.at("type").fail("a block needs a 2-D scene (\"dimension\": 2)");
    read_fields(generator, block_fields(), spec.blocks.emplace_back(), context);
    spec.blocks.back().generator_index = index;
  } else if (type == "rod_pair") {
    read_fields(generator, rod_pair_fields(), spec.rod_pairs.emplace_back(), context);
    spec.rod_pair_generator_index.push_back(index);
  } else if (type == "adjacent_buildings") {
    read_fields(generator, adjacent_buildings_fields(), spec.building_pairs.emplace_back(),
                context);
    spec.building_pairs.back().generator_index = index;
  } else {
    read_fields(generator, girder_bridge_fields(), spec.bridges.emplace_back(), context);
    spec.bridges.back().generator_index = index;
  }
}

void read_generators(JsonObject& top, ModelSpec& spec, Context& context) {
  const std::vector<JsonValue> values = top.array("generators");
  for (std::size_t k = 0; k < values.size(); ++k) {
    JsonObject generator(values[k]);
    read_generator(generator, static_cast<int>(k), spec, context);
    generator.finish();
  }
}

// The generators in the file's order, restored from their indices (a spec made in code may leave
// the rod pairs' out: then they come first).
std::optional<OrderedJson> generators_json(const ModelSpec& spec, const Context& context) {
  std::vector<std::pair<int, OrderedJson>> entries;
  for (std::size_t k = 0; k < spec.rod_pairs.size(); ++k)
    entries.emplace_back(k < spec.rod_pair_generator_index.size() ? spec.rod_pair_generator_index[k]
                                                                  : static_cast<int>(k),
                         write_object(spec.rod_pairs[k], rod_pair_fields(), context));
  for (const AdjacentBuildingsSpec& pair : spec.building_pairs)
    entries.emplace_back(pair.generator_index,
                         write_object(pair, adjacent_buildings_fields(), context));
  for (const GirderBridgeSpec& bridge : spec.bridges)
    entries.emplace_back(bridge.generator_index,
                         write_object(bridge, girder_bridge_fields(), context));
  for (const BlockSpec& block : spec.blocks)
    entries.emplace_back(block.generator_index, write_object(block, block_fields(), context));
  if (entries.empty()) return std::nullopt;
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  OrderedJson json = OrderedJson::array();
  for (auto& entry : entries) json.push_back(std::move(entry.second));
  return json;
}

Field<ModelSpec> generators() {
  return custom<ModelSpec>({"generators", "array of objects", "–",
                            "scene generators that add nodes, elements, links and monitors"},
                           read_generators, generators_json);
}

// ---- Surfaces and contacts ----

const Fields<SurfaceSpec>& surface_fields() {
  static const Fields<SurfaceSpec> fields = {
      array_index(&SurfaceSpec::index),
      unique_id(&SurfaceSpec::id, "surfaces", "the surface's name, and its generated node's"),
      required("point", &SurfaceSpec::point, Pair<>{}, "a point on the surface [L]"),
      required("normal", &SurfaceSpec::normal, UnitVector<std::array<double, 2>>{},
               "pointing out of the surface towards the nodes"),
      optional("velocity", &SurfaceSpec::velocity, Pair<>{}, "its own velocity (a belt) [L/T]"),
      required("nodes", &SurfaceSpec::nodes, Names{}, "node ids or node sets that may touch it"),
      required("law", &SurfaceSpec::law, Law{}, "the contact law, as for links"),
      optional("friction", &SurfaceSpec::friction, friction_object(), "as for links"),
      no_pendulum(&SurfaceSpec::friction),
  };
  return fields;
}

const Fields<ContactSpec>& contact_fields() {
  static const Fields<ContactSpec> fields = {
      array_index(&ContactSpec::index),
      unique_id(&ContactSpec::id, "links", "the contact's name, unique among links too"),
      required("nodes", &ContactSpec::nodes, Names{}, "the contacting nodes: ids or node sets"),
      required("segments", &ContactSpec::segments, Names{},
               "the facing boundary, a chain of nodes counter-clockwise round its body"),
      required("law", &ContactSpec::law, Law{}, "the contact law, as for links"),
      optional("friction", &ContactSpec::friction, friction_object(), "as for links"),
      no_pendulum(&ContactSpec::friction),
  };
  return fields;
}

// ---- Monitors, units, damping ----

const Fields<DriftMonitorSpec>& drift_monitor_fields() {
  static const Fields<DriftMonitorSpec> fields = {
      required("id", &DriftMonitorSpec::id, Text{true}, "its name in the summary"),
      optional("kind", &DriftMonitorSpec::kind,
               Choice<builder::DriftKind>{
                   {{"storey", builder::DriftKind::storey}, {"pier", builder::DriftKind::pier}}},
               "how the summary groups it")
          .always_written(),
      optional("group", &DriftMonitorSpec::group, Text{}, "building or bridge it belongs to"),
      required("bottom", &DriftMonitorSpec::bottom, Text{true}, "id of the lower node"),
      required("top", &DriftMonitorSpec::top, Text{true}, "id of the upper node"),
      required("height", &DriftMonitorSpec::height, Number<>{positive}, "for the drift ratio [L]"),
      optional("direction", &DriftMonitorSpec::direction, Choice<int>{{{"x", 0}, {"y", 1}}},
               "of the drift and the top's absolute acceleration")
          .in_space(),
      optional("axis", &DriftMonitorSpec::axis, Triple{.nonzero = true},
               "a direction the drift is measured along instead of `direction` (a curved "
               "bridge's local tangent), normalised")
          .in_space(),
      optional("corners", &DriftMonitorSpec::corners, Triples{},
               "points of the top floor, from the top node (rigidly tied to it and to the bottom "
               "node: the floor's plan corners), whose drift along `direction` the summary reports "
               "too, with the storey's twist [L]")
          .in_space(),
      renamed_displacement<DriftMonitorSpec>("yield_displacement", "yield_drift",
                                             &DriftMonitorSpec::yield_drift,
                                             "the drift at yield, for the displacement ductility"),
      optional("yields", &DriftMonitorSpec::yields, Flag{},
               "whether the model yields at `yield_displacement` (peak / yield drift is a "
               "ductility); "
               "false for an elastic member, whose ratio is only a demand"),
      optional("hinge", &DriftMonitorSpec::hinge, Text{true},
               "id of the member's plastic-hinge link, for its curvature ductility "
               "1 + θ_p / (φ_y L_p)"),
      optional("yield_curvature", &DriftMonitorSpec::yield_curvature, Number<>{positive},
               "φ_y of the hinge's section, with hinge [1/L]"),
      optional("plastic_hinge_length", &DriftMonitorSpec::plastic_hinge_length, Number<>{positive},
               "L_p, with hinge [L]"),
      optional("hinge_direction", &DriftMonitorSpec::hinge_direction,
               Number<int>{at_least(1), at_most(2)},
               "with a hinge that bends about two axes (a rotational link with `shear`): the "
               "tangent t_1 or t_2 this drift bends it about, whose plastic rotation θ_p counts"),
      optional("base_element", &DriftMonitorSpec::base_element, Text{true},
               "id of the member's lowest element, end i at the bottom: the summary's peak "
               "`shear` |V_i| and, for a beam, `base_moment` |M_i|"),
      optional("upper_elements", &DriftMonitorSpec::upper_elements, Names{.what = "element"},
               "with base_element: the member's elements above it (a storey's column cut where a "
               "floor of the other building strikes it between floors), whose shear |V_i| the "
               "peak `shear` takes too: across a strike the column's shear changes by its force"),
      optional("shear_link", &DriftMonitorSpec::shear_link, Text{true},
               "id of a link whose force is the storey shear (a yielding storey): the summary's "
               "peak `shear`"),
      optional("shear_link_direction", &DriftMonitorSpec::shear_link_direction,
               Number<int>{at_least(1), at_most(2)},
               "with a shear link whose `shear` acts in two directions (a coupled storey): the "
               "tangent t_1 or t_2 whose force is this drift's shear"),
      rule<DriftMonitorSpec>([](JsonObject& object, DriftMonitorSpec& monitor, Context&) {
        if (monitor.base_element && monitor.shear_link)
          object.at("shear_link").fail("give 'base_element' or 'shear_link', not both");
        if (!monitor.upper_elements.empty() && !monitor.base_element)
          object.at("upper_elements").fail("give 'base_element' with it: the member's lowest");
      }),
      rule<DriftMonitorSpec>([](JsonObject& object, DriftMonitorSpec& monitor, Context&) {
        const bool all = monitor.hinge && monitor.yield_curvature && monitor.plastic_hinge_length;
        const bool none =
            !monitor.hinge && !monitor.yield_curvature && !monitor.plastic_hinge_length;
        if (!all && !none)
          object.fail("give 'hinge', 'yield_curvature' and 'plastic_hinge_length' together");
      }),
  };
  return fields;
}

const Fields<JointMonitorSpec>& joint_monitor_fields() {
  static const Fields<JointMonitorSpec> fields = {
      required("id", &JointMonitorSpec::id, Text{true}, "its name in the summary"),
      required("link", &JointMonitorSpec::link, Text{true}, "the pounding link across the joint"),
      required("girder", &JointMonitorSpec::girder, Text{true}, "id of the girder end's node"),
      required("seat", &JointMonitorSpec::seat, Text{true}, "id of the node it sits on"),
      optional("seat_width", &JointMonitorSpec::seat_width, Number<>{non_negative},
               "[L]; 0: unseating not checked")
          .always_written(),
      optional("point", &JointMonitorSpec::point, Triple{},
               "the point whose movement on the seat counts, from the girder node (a skewed "
               "deck's corner, rigidly tied to the girder node and to the seat) [L]")
          .in_space()
          .default_text("the girder node"),
      optional("direction", &JointMonitorSpec::direction, Triple{.nonzero = true},
               "the direction the seat's width is measured in (across the support line)")
          .in_space()
          .default_text("`[1, 0, 0]`"),
  };
  return fields;
}

const Fields<UnitsSpec>& unit_fields() {
  static const Fields<UnitsSpec> fields = {
      optional("length", &UnitsSpec::length, names_choice({"m", "cm", "mm", "km", "in", "ft"}),
               "length unit of the model")
          .always_written(),
      optional("time", &UnitsSpec::time, names_choice({"s", "ms"}), "time unit of the model")
          .always_written(),
      optional("mass", &UnitsSpec::mass, names_choice({"kg", "t"}),
               "mass unit of the model: with it the outputs name the force unit (kg m/s²: N, "
               "t m/s²: kN, t mm/s²: N ...)"),
  };
  return fields;
}

bool by_coefficients(const DampingSpec& damping) {
  return damping.mass_coefficient || damping.stiffness_coefficient;
}
bool by_ratio(const DampingSpec& damping) { return !by_coefficients(damping); }

const Fields<DampingSpec>& damping_fields() {
  static const Fields<DampingSpec> fields = {
      tag<DampingSpec>("type", "rayleigh", "C = a0·M + a1·K of the linear elements")
          .default_text("`\"rayleigh\"`"),
      // The coefficients themselves (each 0 unless given), or a ratio at two periods or modes.
      rule<DampingSpec>([](JsonObject& object, DampingSpec& damping, Context&) {
        if (object.has("mass_coefficient") || object.has("stiffness_coefficient"))
          damping.mass_coefficient = damping.stiffness_coefficient = 0.0;
      }),
      optional("mass_coefficient", &DampingSpec::mass_coefficient, Number<>{non_negative},
               "a0 [1/T]")
          .default_text("`0`")
          .when(by_coefficients, "instead of a ratio"),
      optional("stiffness_coefficient", &DampingSpec::stiffness_coefficient, Number<>{non_negative},
               "a1 [T]")
          .default_text("`0`")
          .when(by_coefficients, "instead of a ratio"),
      required("ratio", &DampingSpec::ratio, Number<>{non_negative, below(1.0)},
               "damping ratio ξ at two periods or two modes")
          .when(by_ratio, "instead of coefficients"),
      rule<DampingSpec>([](JsonObject& object, DampingSpec& damping, Context&) {
        if (by_coefficients(damping)) return;
        if (object.has("periods") == object.has("modes"))
          object.fail(
              "give the two 'periods' or the two 'modes' Rayleigh damping matches the ratio at "
              "(or 'mass_coefficient' and 'stiffness_coefficient')");
      }),
      optional("periods", &DampingSpec::periods, Pair<>{positive, "needs two different periods"},
               "the periods T1, T2 it is matched at [T]")
          .when(by_ratio, "or modes"),
      optional("modes", &DampingSpec::modes, Pair<int>{at_least(1), "needs two different modes"},
               "the modes it is matched at, counted from 1 (`pound modes`)")
          .when(by_ratio, "or periods"),
  };
  return fields;
}

// ---- Excitations ----

const Fields<ExcitationSpec>& record_format_fields() {
  static const Fields<ExcitationSpec> fields = {
      optional("format", &ExcitationSpec::format, names_choice({"auto", "at2", "columns"}),
               "auto: AT2 by the extension .AT2 or an NPTS header line, else columns")
          .always_written(),
      optional("column", &ExcitationSpec::column, Number<int>{at_least(1)},
               "columns: the column to read, from 1 (an .AT2 file has one component: none "
               "other than 1 there)")
          .default_text("1, or 2 with time_column"),
      optional("time_step", &ExcitationSpec::time_step, Number<>{positive},
               "columns: the sampling interval, unless the file gives it [T]"),
      optional("time_column", &ExcitationSpec::time_column, Flag{},
               "columns: the first column is time [s]"),
      // As `pound run --time-column` and `pound spectrum --time-column`: the values follow the
      // time column unless the column is given.
      rule<ExcitationSpec>([](JsonObject& object, ExcitationSpec& excitation, Context&) {
        if (excitation.time_column && !object.has("column")) excitation.column = 2;
      }),
      optional("units", &ExcitationSpec::units, names_choice({"g", "m/s2", "cm/s2", "model"}),
               "of the file's values (AT2 files are in g; a unit its header states must be this, "
               "or with `\"model\"` the model's length over its time squared)")
          .always_written(),
  };
  return fields;
}

bool by_sa(const ExcitationSpec& excitation) { return excitation.target_sa.has_value(); }

Field<ExcitationSpec> pair_needs_a_component() {
  return rule<ExcitationSpec>([](JsonObject& object, ExcitationSpec& excitation, Context&) {
    if (excitation.pair && !excitation.pair->record && !excitation.pair->column)
      object.at("pair").fail(
          "give the second component's 'record' (another file) or 'column' (of this one)");
  });
}

const Fields<builder::PairSpec>& pair_fields() {
  using builder::PairSpec;
  static const Fields<PairSpec> fields = {
      optional("record", &PairSpec::record, Text{true},
               "the second component's file, relative to the model file"),
      optional("column", &PairSpec::column, Number<int>{at_least(1)},
               "columns: the second component's column (not of an .AT2 file, which has one "
               "component)"),
      optional("angle", &PairSpec::angle, Number<>{Minimum{-360.0, true}, below(360.0)},
               "the pair turned about +z: the first component along (cos a, sin a, 0), the "
               "second along (−sin a, cos a, 0) [degrees]"),
  };
  return fields;
}

Field<ExcitationSpec> scale_field() {
  return nested<ExcitationSpec>(
      "scale",
      {
          optional("factor", &ExcitationSpec::scale_factor, Number<>{positive}, "a factor"),
          optional("pga", &ExcitationSpec::target_pga, Number<>{positive},
                   "to this peak ground acceleration [g]"),
          optional("sa", &ExcitationSpec::target_sa, Number<>{positive},
                   "to this spectral acceleration at `period` [g]"),
          rule<ExcitationSpec>([](JsonObject& object, ExcitationSpec& excitation, Context&) {
            const int given = excitation.scale_factor.has_value() +
                              excitation.target_pga.has_value() + by_sa(excitation);
            if (given != 1)
              object.fail("give exactly one of 'factor', 'pga' [g], 'sa' [g] (with 'period')");
          }),
          // At most 1000 s, pound spectrum's range: checked where the unit of time is known.
          required("period", &ExcitationSpec::sa_period, Number<>{positive}, "of Sa [T]")
              .when(by_sa, "with sa"),
          optional("damping", &ExcitationSpec::sa_damping,
                   Number<>{non_negative, Maximum{1.0, true,
                                                  "must be below 1 (an underdamped "
                                                  "oscillator), got {}"}},
                   "damping ratio of Sa")
              .always_written()
              .when(by_sa, "with sa"),
      },
      "one of factor, pga, sa");
}

const Fields<ExcitationSpec>& excitation_fields() {
  static const Fields<ExcitationSpec> fields = [] {
    Fields<ExcitationSpec> list = record_format_fields();
    list.insert(
        list.begin(),
        required("record", &ExcitationSpec::record, Text{true},
                 "the record file, relative to the model file: a regular file of at most 1 GB"));
    list.insert(
        list.end(),
        {
            optional("direction", &ExcitationSpec::direction, UnitVector<std::vector<double>>{},
                     "of the ground motion")
                .default_text("+x"),
            optional("supports", &ExcitationSpec::supports, Names{},
                     "the supports it moves (multi-support excitation)")
                .default_text("every support"),
            rule<ExcitationSpec>([](JsonObject& object, ExcitationSpec& excitation, Context&) {
              const std::optional<JsonValue> wave = object.find("wave_passage");
              if (wave && excitation.supports.empty())
                wave->fail("a wave passage needs the 'supports' it reaches");
            }),
            nested<ExcitationSpec>(
                "wave_passage",
                {
                    required("apparent_velocity", &ExcitationSpec::apparent_velocity,
                             Number<>{positive}, "c [L/T]"),
                    optional("origin", &ExcitationSpec::wave_origin, Number<>{}, "x0 [L]")
                        .always_written(),
                },
                "delays each support by |x − x0|/c"),
            scale_field(),
            optional("pair", &ExcitationSpec::pair, Object<builder::PairSpec>{pair_fields()},
                     "the station's second horizontal component, acting with this one; a "
                     "target scales the pair to its RotD50")
                .in_space(),
            rule<ExcitationSpec>([](JsonObject& object, ExcitationSpec& excitation, Context&) {
              if (excitation.pair && object.has("direction"))
                object.at("direction")
                    .fail("a pair acts in the horizontal x-y plane: turn it with 'pair.angle'");
            }),
            pair_needs_a_component(),
        });
    return list;
  }();
  return fields;
}

// ---- Analysis, recorders ----

Field<AnalysisSpec> time_step_field() {
  return custom<AnalysisSpec>(
      {"time_step", "number > 0 or `\"auto\"`", "required (implicit), `\"auto\"` (explicit)",
       "Δt [T], no longer than the duration; `\"auto\"` (central difference): safety_factor × "
       "the stable step, no more than the shortest record step; also when an explicit "
       "integrator is given no step; not with a Hertz-type contact law (hertz, hertz_damp, "
       "jankowski, bilinear_impact), which has no stiffness until it touches to find that step "
       "from"},
      [](JsonObject& object, AnalysisSpec& analysis, Context&) {
        // An explicit method has one right step, its stable one: without a number it takes it.
        if (analysis.integrator.is_explicit() && !object.find("time_step")) {
          analysis.time_step_auto = true;
          analysis.time_step_defaulted = true;
          return;
        }
        const JsonValue step = object.at("time_step");
        if (!step.json().is_string()) {
          analysis.time_step = step.as<double>(positive);
          return;
        }
        (void)step.as_one_of({"auto"});
        if (!analysis.integrator.is_explicit())
          step.fail(
              "\"auto\" is the stable step of central difference; implicit integrators need a "
              "number");
        analysis.time_step_auto = true;
      },
      [](const AnalysisSpec& analysis, const Context&) -> std::optional<OrderedJson> {
        // Left out as it was, so that the written model says the same of its step.
        if (analysis.time_step_defaulted) return std::nullopt;
        if (analysis.time_step_auto) return "auto";
        return analysis.time_step;
      });
}

const Fields<AdaptiveStepping>& adaptive_fields() {
  static const Fields<AdaptiveStepping> fields = {
      optional("tolerance", &AdaptiveStepping::tolerance, Number<>{positive},
               "local error per step, relative to the largest displacement"),
      optional("min_time_step", &AdaptiveStepping::min_time_step, Number<>{positive},
               "the shortest step [T]")
          .default_text("time_step / 256"),
      optional("max_time_step", &AdaptiveStepping::max_time_step, Number<>{positive},
               "the longest step [T]")
          .default_text("the records' sampling interval, else 16 × time_step"),
      rule<AdaptiveStepping>([](JsonObject& object, AdaptiveStepping& settings, Context&) {
        if (settings.min_time_step > 0.0 && settings.max_time_step > 0.0 &&
            settings.min_time_step > settings.max_time_step)
          object.at("min_time_step").fail("must be <= max_time_step");
      }),
  };
  return fields;
}

// "adaptive": true (the default settings), false, or the settings.
struct Adaptive {
  using value_type = std::optional<AdaptiveStepping>;
  Object<AdaptiveStepping> settings{adaptive_fields()};

  void read(const JsonValue& value, value_type& target, Context& context) const {
    if (!value.json().is_boolean())
      settings.read(value, target.emplace(), context);
    else if (value.as<bool>())
      target.emplace();
  }
  OrderedJson write(const value_type& value, const Context& context) const {
    if (!value) return false;
    const OrderedJson json = settings.write(*value, context);
    return json.empty() ? OrderedJson(true) : json;
  }
  std::string type() const { return "true, false or object"; }
  std::vector<FieldDoc> rows() const { return settings.rows(); }
};

const Fields<builder::GravitySpec>& gravity_fields() {
  using builder::GravitySpec, builder::PDeltaKind;
  static const Fields<GravitySpec> fields = {
      rule<GravitySpec>([](JsonObject& object, GravitySpec& gravity, Context& context) {
        if (context.dimension == 1)
          object.value().fail(
              "gravity needs a 2-D or 3-D scene (\"dimension\": 2 or 3): in a 1-D scene "
              "the weight acts across every DOF");
        if (context.dimension == 3) gravity.direction = {0.0, 0.0, -1.0};
      }),
      optional("direction", &GravitySpec::direction, UnitVector<std::vector<double>>{},
               "the direction the weight acts along")
          .always_written()
          .default_text("[0, -1] in 2-D, [0, 0, -1] in 3-D"),
      optional("acceleration", &GravitySpec::acceleration, Number<>{positive}, "g [L/T²]")
          .default_text("9.80665 m/s² in the model's units"),
      optional("p_delta", &GravitySpec::p_delta,
               Choice<PDeltaKind>{{{"none", PDeltaKind::none},
                                   {"chord", PDeltaKind::chord},
                                   {"consistent", PDeltaKind::consistent}}},
               "second-order stiffness of beams and bars under the gravity axial forces: chord "
               "(P-Δ, N/L on the chord rotation) or consistent (P-Δ and P-δ along the member, "
               "converging to the Euler loads)"),
  };
  return fields;
}

const Fields<AnalysisSpec>& analysis_fields() {
  static const Fields<AnalysisSpec> fields = {
      optional("integrator", &AnalysisSpec::integrator, Integrator{},
               "the time integrator: a method's object or a preset's name (the integrator "
               "table below)")
          .always_written()
          .default_text("`\"newmark_average_acceleration\"`"),
      time_step_field(),
      optional("safety_factor", &AnalysisSpec::safety_factor,
               Number<>{positive, at_most(1.0, "must be <= 1")},
               "the fraction of the stable step taken")
          .always_written()
          .when([](const AnalysisSpec& analysis) { return analysis.time_step_auto; },
                "with `\"time_step\": \"auto\"`"),
      optional("duration", &AnalysisSpec::duration, Number<>{positive},
               "[T]; needed unless the model has excitations")
          .default_text("the longest record's"),
      nested<AnalysisSpec>(
          "convergence",
          {
              optional("relative_tolerance", &AnalysisSpec::relative_tolerance,
                       Number<>{positive, below(0.1,
                                                "must be < 0.1 (a looser test takes a "
                                                "contact's force itself as unbalanced), got "
                                                "{}")},
                       "unbalanced force over the larger of the external and link forces")
                  .always_written(),
              optional("absolute_tolerance", &AnalysisSpec::absolute_tolerance,
                       Number<>{non_negative}, "unbalanced force [F]")
                  .always_written(),
              optional("max_iterations", &AnalysisSpec::max_iterations, Number<int>{at_least(1)},
                       "Newton iterations per step")
                  .always_written(),
          },
          "Newton iteration")
          .always_written(),
      optional("max_step_cuts", &AnalysisSpec::max_step_cuts,
               Number<int>{non_negative, at_most(30)}, "halvings of a step that does not converge")
          .always_written(),
      optional("max_steps", &AnalysisSpec::max_steps, Number<long>{non_negative},
               "the run stops beyond this many steps; 0: no limit"),
      optional("initial_state", &AnalysisSpec::static_initial_state,
               Choice<bool>{{{"unloaded", false}, {"static", true}}},
               "u = 0 at t = 0, or static equilibrium under the loads"),
      rule<AnalysisSpec>([](JsonObject& object, AnalysisSpec& analysis, Context&) {
        const std::optional<JsonValue> adaptive = object.find("adaptive");
        if (adaptive && analysis.integrator.is_explicit())
          adaptive->fail(
              "adaptive stepping is for the implicit integrators; central difference "
              "takes its stable step (\"time_step\": \"auto\")");
      }),
      optional("adaptive", &AnalysisSpec::adaptive, Adaptive{},
               "adaptive time stepping (implicit integrators)"),
  };
  return fields;
}

// Recorder files are written inside the output folder: a name must not lead out of it.
void check_file_name(const std::string& name, const JsonValue& where) {
  const bool plain = name.size() > 4 && (name.ends_with(".csv") || name.ends_with(".npy")) &&
                     name.find_first_of("/\\") == std::string::npos &&
                     name.find("..") == std::string::npos;
  if (!plain)
    where.fail(fmt::format(
        "must be a plain file name ending in .csv or .npy (no folders), got '{}'", name));
  // A batch case's folder holds the run's files and case.csv, its summary row.
  if (name == "case.csv")
    where.fail("'case.csv' is the name of a batch case's summary row: choose another file name");
}

// A file name unique among the recorders; by default "<type>_<index>.csv".
Field<RecorderSpec> recorder_file() {
  return custom<RecorderSpec>(
      {"file", "string", "`\"<type>_<k>.csv\"`",
       "a plain file name ending in .csv, or .npy for NumPy's binary format (a structured array "
       "whose fields are the columns), unique, not `case.csv` (a batch case's row); k counts "
       "the recorders from 0"},
      [](JsonObject& object, RecorderSpec& recorder, Context& context) {
        const std::optional<JsonValue> file = object.find("file");
        const JsonValue& where = file ? *file : object.value();
        static const char* kType[] = {"link", "node", "spectrum", "element"};
        recorder.file =
            file ? file->as<std::string>()
                 : fmt::format("{}_{}.csv", kType[static_cast<int>(recorder.type)], context.index);
        check_file_name(recorder.file, where);
        context.unique("recorder files", "file name").add(recorder.file, where);
      },
      [](const RecorderSpec& recorder, const Context&) -> std::optional<OrderedJson> {
        return recorder.file;
      });
}

// A list of damping ratios, each in (0, 1).
struct DampingRatios {
  using value_type = std::vector<double>;
  Numbers numbers{1, 20, positive};

  void read(const JsonValue& value, value_type& target, Context& context) const {
    numbers.read(value, target, context);
    const std::vector<JsonValue> items = value.elements(1);
    for (std::size_t k = 0; k < target.size(); ++k)
      if (!(target[k] < 1.0))
        items[k].fail(fmt::format("a damping ratio must be in (0, 1), got {}", target[k]));
  }
  OrderedJson write(const value_type& value, const Context&) const { return value; }
  std::string type() const { return "1 to 20 numbers in (0, 1)"; }
};

const Fields<RecorderSpec>& recorder_fields() {
  using builder::RecorderKind;
  static const auto records_links = [](const RecorderSpec& recorder) {
    return recorder.type == RecorderKind::link;
  };
  static const auto records_histories = [](const RecorderSpec& recorder) {
    return recorder.type != RecorderKind::spectrum;
  };
  static const auto takes_nodes = [](const RecorderSpec& recorder) {
    return recorder.type == RecorderKind::node || recorder.type == RecorderKind::spectrum;
  };
  static const auto is_spectrum = [](const RecorderSpec& recorder) {
    return recorder.type == RecorderKind::spectrum;
  };
  static const Fields<RecorderSpec> fields = {
      required("type", &RecorderSpec::type,
               Choice<RecorderKind>{{{"link", RecorderKind::link},
                                     {"node", RecorderKind::node},
                                     {"element", RecorderKind::element},
                                     {"spectrum", RecorderKind::spectrum}}},
               "link: force and penetration; node: displacement, velocity, acceleration; "
               "element: end forces in the element's axes; spectrum: response spectra of the "
               "nodes' absolute accelerations (floor spectra)"),
      optional("links", &RecorderSpec::ids, Names{.what = "link"}, "the links recorded")
          .default_text("every link")
          .when(records_links, "link recorders"),
      required("nodes", &RecorderSpec::ids, Names{}, "the nodes recorded")
          .when(takes_nodes, "node and spectrum recorders"),
      required("elements", &RecorderSpec::ids, Names{.what = "element"}, "the elements recorded")
          .when([](const RecorderSpec& r) { return r.type == RecorderKind::element; },
                "element recorders"),
      optional(
          "accelerations", &RecorderSpec::accelerations,
          Choice<builder::AccelerationFrame>{{{"both", builder::AccelerationFrame::both},
                                              {"relative", builder::AccelerationFrame::relative},
                                              {"absolute", builder::AccelerationFrame::absolute}}},
          "which accelerations: `a_rel` relative to the ground (as u and v are), `a_abs` "
          "absolute (relative plus the ground's), or both")
          .default_text("`\"both\"`")
          .when([](const RecorderSpec& r) { return r.type == RecorderKind::node; },
                "node recorders"),
      optional("envelope", &RecorderSpec::envelope, Flag{},
               "instead of the history, a row per quantity: `max`, `time_of_max`, `min`, "
               "`time_of_min`, `abs_max` over every step (text columns `quantity` and its `unit`)")
          .when(records_histories, "link, node and element recorders"),
      rule<RecorderSpec>([](JsonObject& object, RecorderSpec& recorder, Context&) {
        const std::optional<JsonValue> every = object.find("every");
        const std::optional<JsonValue> interval = object.find("interval");
        if (every && interval) interval->fail("give \"every\" or \"interval\", not both");
        if (recorder.envelope && (every || interval))
          (every ? *every : *interval)
              .fail("an envelope takes every step; \"every\" and \"interval\" thin histories");
      }),
      optional("every", &RecorderSpec::every, Number<int>{at_least(1)},
               "keep every k-th step of the history (the start is step 0)")
          .when(records_histories, "link, node and element recorders"),
      optional("interval", &RecorderSpec::interval, Number<>{positive},
               "keep the first step at or after each multiple of this time [T] (uniform output "
               "of an adaptive run)")
          .when(records_histories, "link, node and element recorders"),
      optional("damping", &RecorderSpec::damping_ratios, DampingRatios{},
               "the oscillators' damping ratios")
          .default_text("[0.05]")
          .when(is_spectrum, "spectrum recorders"),
      optional("periods", &RecorderSpec::periods, Numbers{1, 1000, non_negative},
               "the oscillators' periods [T]; 0 gives the peak acceleration")
          .default_text("40 log-spaced from 0.02 s to 10 s")
          .when(is_spectrum, "spectrum recorders"),
      recorder_file(),
  };
  return fields;
}

// Without "recorders" `run` records every link; "recorders": [] records nothing.
Field<ModelSpec> recorders() {
  const Objects<RecorderSpec> list{recorder_fields()};
  return custom<ModelSpec>(
      {"recorders", list.type(), "every link's force", "which time histories to write"},
      [list](JsonObject& top, ModelSpec& spec, Context& context) {
        const std::optional<JsonValue> value = top.find("recorders");
        spec.recorders_given = value.has_value();
        if (value) list.read(*value, spec.recorders, context);
      },
      [list](const ModelSpec& spec, const Context& context) -> std::optional<OrderedJson> {
        if (!spec.recorders_given) return std::nullopt;
        return list.write(spec.recorders, context);
      });
}

// ---- The model ----

Field<ModelSpec> dimension() {
  return custom<ModelSpec>(
      {"dimension", "1, 2 or 3", "`1`",
       "1: axial scene, u_x at each node; 2: plane scene, u_x and u_y, and θ_z where a beam or a "
       "rotational link is; 3: space scene, u_x, u_y and u_z, and θ_x, θ_y, θ_z where a beam is"},
      [](JsonObject& top, ModelSpec& spec, Context& context) {
        if (const std::optional<JsonValue> value = top.find("dimension")) {
          spec.dimension = value->as<int>();
          if (spec.dimension < 1 || spec.dimension > 3)
            value->fail(fmt::format("must be 1, 2 or 3, got {}", spec.dimension));
        }
        context.dimension = spec.dimension;
      },
      [](const ModelSpec& spec, const Context&) -> std::optional<OrderedJson> {
        return spec.dimension;
      });
}

const Fields<ModelSpec>& model_list() {
  static const Fields<ModelSpec> fields = {
      optional("title", &ModelSpec::title, Text{}, "shown in the summary"),
      dimension(),
      optional("nodes", &ModelSpec::nodes, Objects<NodeSpec>{node_fields()}, "the nodes"),
      optional("materials", &ModelSpec::materials, Objects<MaterialSpec>{material_fields()},
               "elastic materials"),
      optional("elements", &ModelSpec::elements, Objects<ElementSpec>{element_fields()},
               "trusses, beams and quads"),
      optional("masses", &ModelSpec::masses, Objects<MassSpec>{mass_fields()},
               "lumped nodal masses"),
      optional("supports", &ModelSpec::supports, Objects<SupportSpec>{support_fields()},
               "fixed directions"),
      optional("constraints", &ModelSpec::constraints, Objects<ConstraintSpec>{constraint_fields()},
               "rigid diaphragms, rigid links and equal DOFs: master–slave ties"),
      optional("initial_velocities", &ModelSpec::initial_velocities,
               Objects<InitialVelocitySpec>{initial_velocity_fields()},
               "nodal velocities at t = 0"),
      optional("loads", &ModelSpec::loads, Objects<LoadSpec>{load_fields()},
               "constant nodal forces from t = 0"),
      optional("links", &ModelSpec::links, Objects<LinkSpec>{link_fields()},
               "contacts, restrainers and springs between two nodes, or a node and a segment"),
      generators(),
      optional("surfaces", &ModelSpec::surfaces,
               Objects<SurfaceSpec>{.fields = surface_fields(), .in_plane = true},
               "rigid flat surfaces touching a set of nodes (2-D)"),
      optional("contacts", &ModelSpec::contacts,
               Objects<ContactSpec>{.fields = contact_fields(), .in_plane = true},
               "contact between two bodies' boundaries (2-D)"),
      nested<ModelSpec>(
          "monitors",
          {
              optional("drifts", &ModelSpec::drift_monitors,
                       Objects<DriftMonitorSpec>{drift_monitor_fields()}, "storey and pier drifts"),
              optional("joints", &ModelSpec::joint_monitors,
                       Objects<JointMonitorSpec>{joint_monitor_fields()},
                       "joint openings and seats"),
          },
          "what the summary reports beyond links"),
      optional("units", &ModelSpec::units, Object<UnitsSpec>{unit_fields()},
               "the model's units: for records in g, and named in the outputs (CSV headers, "
               "summary.json, plots)"),
      optional("damping", &ModelSpec::damping,
               Object<DampingSpec>{damping_fields(), Docs::own_table},
               "Rayleigh damping of the linear elements"),
      optional("gravity", &ModelSpec::gravity,
               Object<builder::GravitySpec>{gravity_fields(), Docs::own_table},
               "the weight of every mass as constant loads from t = 0; the run starts from "
               "static equilibrium under them"),
      optional("excitations", &ModelSpec::excitations, Objects<ExcitationSpec>{excitation_fields()},
               "ground-motion records"),
      required("analysis", &ModelSpec::analysis,
               Object<AnalysisSpec>{analysis_fields(), Docs::own_table},
               "integrator, time step, duration, convergence"),
      rule<ModelSpec>([](JsonObject& top, ModelSpec& spec, Context&) {
        if (spec.analysis.duration == 0.0 && spec.excitations.empty())
          top.at("analysis").fail("needs 'duration' (it may be left out only with 'excitations')");
      }),
      recorders(),
  };
  return fields;
}

// A field list by the name of its section in docs/model_format.md.
struct NamedFields {
  std::string name;
  std::function<std::vector<FieldDoc>()> rows;
};

template <class Spec>
NamedFields named(std::string name, const Fields<Spec>& fields) {
  return {std::move(name), [&fields] { return field_docs(fields); }};
}

// Every field list of the format, in the order of docs/model_format.md.
const std::vector<NamedFields>& every_field_list() {
  static const std::vector<NamedFields> lists = {
      named("model", model_list()),
      named("nodes", node_fields()),
      named("materials", material_fields()),
      named("elements", element_fields()),
      named("masses", mass_fields()),
      named("supports", support_fields()),
      named("constraints", constraint_fields()),
      named("initial_velocities", initial_velocity_fields()),
      named("loads", load_fields()),
      named("links", link_fields()),
      named("friction", friction_fields()),
      named("rayleigh", link_rayleigh_fields()),
      named("rod_pair", rod_pair_fields()),
      named("rod", rod_fields()),
      named("adjacent_buildings", adjacent_buildings_fields()),
      named("building", building_fields()),
      named("storey", storey_fields()),
      named("girder_bridge", girder_bridge_fields()),
      named("section", section_fields()),
      named("pier_hinge", pier_hinge_fields()),
      named("joint", joint_fields()),
      named("block", block_fields()),
      named("surfaces", surface_fields()),
      named("contacts", contact_fields()),
      named("drift_monitors", drift_monitor_fields()),
      named("joint_monitors", joint_monitor_fields()),
      named("damping", damping_fields()),
      named("gravity", gravity_fields()),
      named("excitations", excitation_fields()),
      named("analysis", analysis_fields()),
      named("recorders", recorder_fields()),
  };
  return lists;
}

}  // namespace

const Fields<ModelSpec>& model_fields() { return model_list(); }

const Fields<ExcitationSpec>& record_fields() {
  static const Fields<ExcitationSpec> fields = [] {
    Fields<ExcitationSpec> list = record_format_fields();
    list.push_back(scale_field());
    // A batch record's pair: the models it meets say whether they are 3-D.
    list.push_back(optional("pair", &ExcitationSpec::pair, Object<builder::PairSpec>{pair_fields()},
                            "the second horizontal component"));
    list.push_back(pair_needs_a_component());
    return list;
  }();
  return fields;
}

std::vector<GeneratedSection> model_format_sections() {
  std::vector<GeneratedSection> sections;
  for (const NamedFields& list : every_field_list())
    sections.push_back({list.name, [&list] { return field_table(list.rows()); }});
  return sections;
}

std::vector<FieldDoc> model_field_docs() {
  std::vector<FieldDoc> rows;
  for (const NamedFields& list : every_field_list()) {
    const std::vector<FieldDoc> more = list.rows();
    rows.insert(rows.end(), more.begin(), more.end());
  }
  return rows;
}

}  // namespace pound::io
