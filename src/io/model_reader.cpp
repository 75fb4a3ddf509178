#include "io/model_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

#include "io/json_reader.hpp"
#include "links/law_registry.hpp"

namespace pound::io {

void read_record_fields(JsonObject& object, builder::ExcitationSpec& excitation) {
  excitation.format = object.one_of("format", {"auto", "at2", "columns"}, "auto");
  excitation.column = object.optional<int>("column", 1, at_least(1));
  excitation.time_step = object.if_present<double>("time_step", positive);
  excitation.time_column = object.optional<bool>("time_column", false);
  excitation.units = object.one_of("units", {"g", "m/s2", "cm/s2", "model"}, "g");
  if (const std::optional<JsonValue> scale = object.find("scale")) {
    read_object(*scale, [&excitation](JsonObject& s) {
      excitation.scale_factor = s.if_present<double>("factor", positive);
      excitation.target_pga = s.if_present<double>("pga", positive);
      excitation.target_sa = s.if_present<double>("sa", positive);
      const int given = excitation.scale_factor.has_value() + excitation.target_pga.has_value() +
                        excitation.target_sa.has_value();
      if (given != 1) s.fail("give exactly one of 'factor', 'pga' [g], 'sa' [g] (with 'period')");
      if (excitation.target_sa) {
        excitation.sa_period = s.required<double>("period", positive);
        excitation.sa_damping = s.optional<double>("damping", 0.05, non_negative);
      }
    });
  }
}

namespace {

using builder::AnalysisSpec;
using builder::ElementSpec;
using builder::InitialVelocitySpec;
using builder::IntegratorSpec;
using builder::LawSpec;
using builder::LinkSpec;
using builder::MassSpec;
using builder::MaterialSpec;
using builder::ModelSpec;
using builder::NodeSpec;
using builder::RecorderSpec;
using builder::RodPairSpec;
using builder::RodSpec;
using builder::SupportSpec;

constexpr double kAxisLengthTolerance = 1e-9;

// Where a contact law is given: a stiffness_ratio refers to the elements next to the contact,
// which only a rod_pair generator knows.
enum class LawPlace { link, rod_pair };

std::string read_unique_id(JsonObject& object, UniqueNames& ids) {
  const JsonValue value = object.at("id");
  std::string id = value.as<std::string>(non_empty);
  ids.add(id, value);
  return id;
}

// A list of distinct non-empty names (node ids, link ids) of min_count..max_count entries.
std::vector<std::string> read_names(
    const JsonValue& value, const std::string& what, std::size_t min_count,
    std::size_t max_count = std::numeric_limits<std::size_t>::max()) {
  UniqueNames seen(what);
  std::vector<std::string> names;
  for (const JsonValue& element : value.elements(min_count, max_count)) {
    names.push_back(element.as<std::string>(non_empty));
    seen.add(names.back(), element);
  }
  return names;
}

// The y direction exists only in a plane (2-D) scene.
void require_plane(const JsonValue& value, int dimension) {
  if (dimension != 2) value.fail("only allowed when dimension is 2");
}

double read_plane_component(JsonObject& object, std::string_view key, int dimension) {
  const std::optional<JsonValue> value = object.find(key);
  if (!value) return 0.0;
  require_plane(*value, dimension);
  return value->as<double>();
}

int read_dimension(JsonObject& top) {
  const std::optional<JsonValue> value = top.find("dimension");
  if (!value) return ModelSpec{}.dimension;
  const int dimension = value->as<int>();
  if (dimension != 1 && dimension != 2)
    value->fail(fmt::format("must be 1 or 2, got {}", dimension));
  return dimension;
}

NodeSpec read_node(JsonObject& object, int dimension, UniqueNames& ids) {
  NodeSpec node;
  node.id = read_unique_id(object, ids);
  node.x = object.required<double>("x");
  node.y = read_plane_component(object, "y", dimension);
  return node;
}

MaterialSpec read_material(JsonObject& object, UniqueNames& ids) {
  MaterialSpec material;
  material.id = read_unique_id(object, ids);
  material.youngs_modulus = object.required<double>("youngs_modulus", positive);
  material.density = object.required<double>("density", non_negative);
  if (const std::optional<JsonValue> nu = object.find("poisson_ratio")) {
    const double value = nu->as<double>(non_negative);
    if (!(value < 0.5)) nu->fail(fmt::format("must be < 0.5 (incompressible), got {}", value));
    material.poisson_ratio = value;
  }
  return material;
}

ElementSpec read_element(JsonObject& object, int dimension, UniqueNames& ids) {
  ElementSpec element;
  element.id = read_unique_id(object, ids);
  element.type = object.one_of("type", {"truss", "beam", "quad"});
  const bool quad = element.type == "quad";
  const std::size_t count = quad ? 4 : 2;
  const std::vector<std::string> nodes = read_names(object.at("nodes"), "node", count, count);
  element.node_i = nodes[0];
  element.node_j = nodes[1];
  element.material = object.required<std::string>("material", non_empty);
  if (quad) {
    if (dimension != 2) object.at("type").fail("a quad needs a 2-D scene (\"dimension\": 2)");
    element.more_nodes = {nodes[2], nodes[3]};
    element.thickness = object.required<double>("thickness", positive);
    element.plane_strain = object.one_of("plane", {"stress", "strain"}, "stress") == "strain";
    element.consistent_mass =
        object.one_of("mass", {"lumped", "consistent"}, "lumped") == "consistent";
  } else {
    element.area = object.required<double>("area", positive);
  }
  if (element.type == "beam") {
    if (dimension != 2) object.at("type").fail("a beam needs a 2-D scene (\"dimension\": 2)");
    element.inertia = object.required<double>("inertia", positive);
    element.extra_mass = object.optional<double>("extra_mass", 0.0, non_negative);
    element.consistent_mass =
        object.one_of("mass", {"lumped", "consistent"}, "lumped") == "consistent";
  }
  if (const std::optional<JsonValue> damping = object.find("damping"))
    element.rayleigh = read_object(*damping, [](JsonObject& d) {
      return std::array<double, 2>{d.optional<double>("mass_coefficient", 0.0, non_negative),
                                   d.optional<double>("stiffness_coefficient", 0.0, non_negative)};
    });
  return element;
}

MassSpec read_mass(JsonObject& object) {
  MassSpec mass;
  mass.node = object.required<std::string>("node", non_empty);
  mass.mass = object.required<double>("mass", positive);
  mass.rotary_inertia = object.optional<double>("rotary_inertia", 0.0, non_negative);
  mass.mass_damping = object.if_present<double>("mass_damping", non_negative);
  return mass;
}

SupportSpec read_support(JsonObject& object, int dimension) {
  SupportSpec support;
  support.node = object.required<std::string>("node", non_empty);
  UniqueNames directions("direction");
  for (const JsonValue& value : object.at("fix").elements(1)) {
    const std::string direction = value.as_one_of({"x", "y", "rz"});
    directions.add(direction, value);
    if (direction != "x") require_plane(value, dimension);
    (direction == "x"   ? support.fix_x
     : direction == "y" ? support.fix_y
                        : support.fix_rotation) = true;
  }
  return support;
}

builder::LoadSpec read_load(JsonObject& object, int dimension) {
  builder::LoadSpec load;
  load.node = object.required<std::string>("node", non_empty);
  load.x = object.optional<double>("x", load.x);
  load.y = read_plane_component(object, "y", dimension);
  return load;
}

InitialVelocitySpec read_initial_velocity(JsonObject& object, int dimension) {
  InitialVelocitySpec velocity;
  velocity.node = object.required<std::string>("node", non_empty);
  velocity.x = object.optional<double>("x", velocity.x);
  velocity.y = read_plane_component(object, "y", dimension);
  return velocity;
}

std::vector<double> read_axis(const JsonValue& value, int dimension) {
  std::vector<double> axis;
  double length_squared = 0.0;
  for (const JsonValue& component :
       value.elements(static_cast<std::size_t>(dimension), static_cast<std::size_t>(dimension))) {
    axis.push_back(component.as<double>());
    length_squared += axis.back() * axis.back();
  }
  const double length = std::sqrt(length_squared);
  if (std::abs(length - 1.0) > kAxisLengthTolerance)
    value.fail(fmt::format("must be a unit vector (length 1 within {}), got length {}",
                           kAxisLengthTolerance, length));
  return axis;
}

Minimum lower_bound(links::LawParameter::Range range) {
  using Range = links::LawParameter::Range;
  return range == Range::positive || range == Range::restitution ? positive : non_negative;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += fmt::format("{}'{}'", k == 0 ? "" : (k + 1 == names.size() ? " or " : ", "), names[k]);
  return text;
}

// A law object checked against its entry in the law registry.
LawSpec read_law(JsonObject& object, LawPlace place) {
  using Range = links::LawParameter::Range;
  LawSpec law;
  law.type = object.one_of("type", links::law_names());
  const links::LawEntry& type = *links::find_law(law.type);
  for (const std::string& name : type.required) (void)object.at(name);
  for (const links::LawParameter& parameter : type.parameters) {
    const std::optional<JsonValue> value = object.find(parameter.name);
    if (!value) continue;
    const double number = value->as<double>(lower_bound(parameter.range));
    if (parameter.range == Range::restitution && number > 1.0)
      value->fail(fmt::format("must be <= 1 (a coefficient of restitution), got {}", number));
    if (parameter.range == Range::fraction && number >= 1.0)
      value->fail(fmt::format("must be < 1, got {}", number));
    if (parameter.generator_only && place == LawPlace::link)
      value->fail("only allowed inside a rod_pair generator");
    law.parameters[parameter.name] = number;
  }
  for (const links::LawChoice& choice : type.choices)
    law.choices[choice.name] = object.one_of(choice.name, choice.values, choice.values.front());
  object.finish();  // so that a misspelt parameter is reported as such, not as a missing one
  auto given = [&law](const std::string& name) { return law.parameters.count(name) > 0; };
  for (const std::vector<std::string>& group : type.exactly_one_of) {
    const auto count = std::count_if(group.begin(), group.end(), given);
    if (count > 1)
      object.fail(group.size() == 2
                      ? fmt::format("give either '{}' or '{}', not both", group[0], group[1])
                      : fmt::format("give only one of {}", quoted_list(group)));
    if (count == 0) {
      std::vector<std::string> allowed = group;
      if (place == LawPlace::link)
        std::erase_if(allowed, [&type](const std::string& name) {
          return type.parameter(name)->generator_only;
        });
      object.fail(fmt::format("{} needs {}", law.type, quoted_list(allowed)));
    }
  }
  for (const auto& [name, needed] : type.needs)
    for (const std::string& other : needed)
      if (given(name) && !given(other)) object.fail(fmt::format("'{}' needs '{}'", name, other));
  for (const auto& [name, excluded] : type.excludes)
    for (const std::string& other : excluded)
      if (given(name) && given(other))
        object.at(other).fail(fmt::format("not allowed together with '{}'", name));
  return law;
}

LawSpec read_law_in(const JsonValue& value, LawPlace place) {
  return read_object(value, [place](JsonObject& law) { return read_law(law, place); });
}

builder::FrictionSpec read_friction(const JsonValue& value) {
  return read_object(value, [](JsonObject& f) {
    builder::FrictionSpec spec;
    spec.coefficient = f.required<double>("coefficient", non_negative);
    spec.stick_stiffness = f.if_present<double>("stick_stiffness", positive);
    spec.stick_damping = f.if_present<double>("stick_damping", non_negative);
    spec.stick_mass = f.if_present<double>("stick_mass", non_negative);
    return spec;
  });
}

LinkSpec read_link(JsonObject& object, int dimension, UniqueNames& ids) {
  LinkSpec link;
  link.id = read_unique_id(object, ids);
  const std::vector<std::string> nodes = read_names(object.at("nodes"), "node", 1, 2);
  link.node_i = nodes[0];
  if (const std::optional<JsonValue> segment = object.find("segment")) {
    if (nodes.size() != 1) object.at("nodes").fail("give one node with a 'segment'");
    require_plane(*segment, dimension);
    const std::vector<std::string> ends = read_names(*segment, "node", 2, 2);
    link.node_j = ends[0];
    link.segment_end = ends[1];
  } else {
    if (nodes.size() != 2) object.at("nodes").fail("needs 2 entries (or one with a 'segment')");
    link.node_j = nodes[1];
  }
  link.gap = object.optional<double>("gap", link.gap, non_negative);
  if (const std::optional<JsonValue> axis = object.find("axis"))
    link.axis = read_axis(*axis, dimension);
  if (const std::optional<JsonValue> velocity = object.find("surface_velocity")) {
    require_plane(*velocity, dimension);
    const std::vector<JsonValue> components = velocity->elements(2, 2);
    link.velocity_j = {components[0].as<double>(), components[1].as<double>()};
  }
  link.law = read_law_in(object.at("law"), LawPlace::link);
  link.rotational = object.one_of("dof", {"translation", "rotation"}, "translation") == "rotation";
  if (link.rotational && dimension != 2)
    object.at("dof").fail("a rotational link needs a 2-D scene");
  if (link.rotational && link.axis) object.at("axis").fail("a rotational link has no axis");
  if (const std::optional<JsonValue> friction = object.find("friction"))
    link.friction = read_friction(*friction);
  return link;
}

std::array<double, 2> read_pair(const JsonValue& value) {
  const std::vector<JsonValue> components = value.elements(2, 2);
  return {components[0].as<double>(), components[1].as<double>()};
}

// Node ids and node-set names ("block.bottom").
std::vector<std::string> read_node_list(const JsonValue& value) {
  return read_names(value, "node", 1);
}

builder::SurfaceSpec read_surface(JsonObject& object, int index, UniqueNames& ids) {
  builder::SurfaceSpec surface;
  surface.index = index;
  surface.id = read_unique_id(object, ids);
  surface.point = read_pair(object.at("point"));
  const JsonValue normal = object.at("normal");
  const std::vector<double> unit = read_axis(normal, 2);
  surface.normal = {unit[0], unit[1]};
  if (const std::optional<JsonValue> velocity = object.find("velocity"))
    surface.velocity = read_pair(*velocity);
  surface.nodes = read_node_list(object.at("nodes"));
  surface.law = read_law_in(object.at("law"), LawPlace::link);
  if (const std::optional<JsonValue> friction = object.find("friction"))
    surface.friction = read_friction(*friction);
  return surface;
}

builder::ContactSpec read_contact(JsonObject& object, int index, UniqueNames& ids) {
  builder::ContactSpec contact;
  contact.index = index;
  contact.id = read_unique_id(object, ids);
  contact.nodes = read_node_list(object.at("nodes"));
  contact.segments = read_node_list(object.at("segments"));
  contact.law = read_law_in(object.at("law"), LawPlace::link);
  if (const std::optional<JsonValue> friction = object.find("friction"))
    contact.friction = read_friction(*friction);
  return contact;
}

builder::BlockSpec read_block(JsonObject& object, UniqueNames& ids) {
  builder::BlockSpec block;
  block.id = read_unique_id(object, ids);
  if (const std::optional<JsonValue> origin = object.find("origin"))
    block.origin = read_pair(*origin);
  block.width = object.required<double>("width", positive);
  block.height = object.required<double>("height", positive);
  const std::vector<JsonValue> counts = object.at("elements").elements(2, 2);
  block.columns = counts[0].as<int>(at_least(1));
  block.rows = counts[1].as<int>(at_least(1));
  constexpr int kMostSides = 10000;
  for (const JsonValue& count : counts)
    if (count.as<int>() > kMostSides)
      count.fail(fmt::format("must be <= {} elements per side", kMostSides));
  block.material = object.required<std::string>("material", non_empty);
  block.thickness = object.required<double>("thickness", positive);
  block.plane_strain = object.one_of("plane", {"stress", "strain"}, "stress") == "strain";
  block.consistent_mass = object.one_of("mass", {"lumped", "consistent"}, "lumped") == "consistent";
  if (const std::optional<JsonValue> velocity = object.find("initial_velocity"))
    block.initial_velocity = read_pair(*velocity);
  if (const std::optional<JsonValue> pressure = object.find("pressure"))
    read_object(*pressure, [&block](JsonObject& p) {
      constexpr const char* kEdges[] = {"bottom", "right", "top", "left"};
      for (std::size_t e = 0; e < 4; ++e) block.pressure[e] = p.optional<double>(kEdges[e], 0.0);
      return 0;
    });
  if (const std::optional<JsonValue> fixed = object.find("fixed_edges")) {
    UniqueNames seen("edge");
    for (const JsonValue& edge : fixed->elements(1, 4)) {
      block.fixed_edges.push_back(edge.as_one_of({"bottom", "right", "top", "left"}));
      seen.add(block.fixed_edges.back(), edge);
    }
  }
  return block;
}

constexpr int kMostRodElements = 100000000;

RodSpec read_rod(JsonObject& object) {
  RodSpec rod;
  rod.youngs_modulus = object.required<double>("youngs_modulus", positive);
  rod.density = object.required<double>("density", positive);
  rod.area = object.required<double>("area", positive);
  rod.length = object.required<double>("length", positive);
  rod.elements = object.required<int>("elements", at_least(1));
  // A bound on counting (2e9 elements ran out of memory: std::bad_alloc, a crash rather than a
  // message); what a machine can hold is checked against its memory before building.
  if (rod.elements > kMostRodElements)
    object.at("elements")
        .fail(fmt::format("must be <= {}, got {}", kMostRodElements, rod.elements));
  rod.initial_velocity = object.optional<double>("initial_velocity", rod.initial_velocity);
  rod.far_end_fixed = object.one_of("far_end", {"free", "fixed"}, "free") == "fixed";
  return rod;
}

RodPairSpec read_rod_pair(JsonObject& object, UniqueNames& ids) {
  RodPairSpec pair;
  pair.id = read_unique_id(object, ids);
  pair.left = read_object(object.at("left"), read_rod);
  pair.right = read_object(object.at("right"), read_rod);
  pair.gap = object.optional<double>("gap", pair.gap, non_negative);
  pair.law = read_law_in(object.at("law"), LawPlace::rod_pair);
  return pair;
}

builder::BuildingSpec read_building(JsonObject& object) {
  builder::BuildingSpec building;
  for (const JsonValue& value : object.at("storeys").elements(1))
    building.storeys.push_back(read_object(value, [](JsonObject& storey) {
      return builder::StoreySpec{storey.required<double>("height", positive),
                                 storey.required<double>("mass", positive),
                                 storey.required<double>("stiffness", positive)};
    }));
  building.damping_ratio = object.optional<double>("damping_ratio", 0.0, non_negative);
  if (building.damping_ratio >= 1.0) object.at("damping_ratio").fail("must be < 1");
  return building;
}

builder::AdjacentBuildingsSpec read_adjacent_buildings(JsonObject& object, UniqueNames& ids) {
  builder::AdjacentBuildingsSpec pair;
  pair.id = read_unique_id(object, ids);
  pair.left = read_object(object.at("left"), read_building);
  pair.right = read_object(object.at("right"), read_building);
  pair.separation = object.required<double>("separation", non_negative);
  pair.law = read_law_in(object.at("law"), LawPlace::link);
  return pair;
}

builder::SectionSpec read_section(JsonObject& object, int default_elements) {
  builder::SectionSpec section;
  section.youngs_modulus = object.required<double>("youngs_modulus", positive);
  section.area = object.required<double>("area", positive);
  section.inertia = object.required<double>("inertia", positive);
  section.density = object.optional<double>("density", 0.0, non_negative);
  section.extra_mass = object.optional<double>("extra_mass", 0.0, non_negative);
  section.elements = object.optional<int>("elements", default_elements, at_least(1));
  if (section.elements > 1000) object.at("elements").fail("must be <= 1000");
  return section;
}

builder::JointSpec read_joint(JsonObject& object) {
  builder::JointSpec joint;
  joint.gap = object.required<double>("gap", non_negative);
  joint.law = read_law_in(object.at("law"), LawPlace::link);
  if (const std::optional<JsonValue> restrainer = object.find("restrainer"))
    joint.restrainer = read_law_in(*restrainer, LawPlace::link);
  joint.seat_width = object.optional<double>("seat_width", 0.0, non_negative);
  return joint;
}

builder::GirderBridgeSpec read_girder_bridge(JsonObject& object, UniqueNames& ids) {
  builder::GirderBridgeSpec bridge;
  bridge.id = read_unique_id(object, ids);
  for (const JsonValue& span : object.at("spans").elements(1, 100))
    bridge.spans.push_back(span.as<double>(positive));
  bridge.girder =
      read_object(object.at("girder"), [](JsonObject& o) { return read_section(o, 4); });
  bridge.pier = read_object(object.at("pier"), [](JsonObject& o) { return read_section(o, 2); });
  bridge.pier_height = object.required<double>("pier_height", positive);
  bridge.pier_yield_drift = object.if_present<double>("pier_yield_drift", positive);
  bridge.bearing = read_law_in(object.at("bearing"), LawPlace::link);
  bridge.bearing_vertical_stiffness =
      object.required<double>("bearing_vertical_stiffness", positive);
  UniqueNames joints("expansion joint");
  if (const std::optional<JsonValue> list = object.find("expansion_joints"))
    for (const JsonValue& value : list->elements()) {
      const int pier = value.as<int>(at_least(1));
      if (pier >= static_cast<int>(bridge.spans.size()))
        value.fail(fmt::format("is pier {}, but the bridge has piers 1 to {}", pier,
                               bridge.spans.size() - 1));
      joints.add(std::to_string(pier), value);
      bridge.expansion_joints.push_back(pier);
    }
  if (!bridge.expansion_joints.empty() || object.has("joint"))
    bridge.joint = read_object(object.at("joint"), read_joint);
  bridge.abutment = read_object(object.at("abutment"), read_joint);
  if (const std::optional<JsonValue> backfill = object.find("backfill")) {
    bridge.backfill = read_law_in(*backfill, LawPlace::link);
    bridge.backwall_mass = object.required<double>("backwall_mass", positive);
  }
  return bridge;
}

void read_generators(JsonObject& top, ModelSpec& spec) {
  UniqueNames ids("id");
  const std::vector<JsonValue> generators = top.array("generators");
  for (std::size_t k = 0; k < generators.size(); ++k) {
    const int index = static_cast<int>(k);
    read_object(generators[k], [&](JsonObject& generator) {
      const std::string type =
          generator.one_of("type", {"rod_pair", "adjacent_buildings", "girder_bridge", "block"});
      if (type == "block") {
        if (spec.dimension != 2)
          generator.at("type").fail("a block needs a 2-D scene (\"dimension\": 2)");
        spec.blocks.push_back(read_block(generator, ids));
        spec.blocks.back().generator_index = index;
      } else if (type == "rod_pair") {
        spec.rod_pairs.push_back(read_rod_pair(generator, ids));
        spec.rod_pair_generator_index.push_back(index);
      } else if (type == "adjacent_buildings") {
        spec.building_pairs.push_back(read_adjacent_buildings(generator, ids));
        spec.building_pairs.back().generator_index = index;
      } else {
        spec.bridges.push_back(read_girder_bridge(generator, ids));
        spec.bridges.back().generator_index = index;
      }
      return 0;
    });
  }
}

void read_monitors(JsonObject& object, ModelSpec& spec) {
  for (const JsonValue& value : object.array("drifts"))
    spec.drift_monitors.push_back(read_object(value, [](JsonObject& m) {
      builder::DriftMonitorSpec monitor;
      monitor.id = m.required<std::string>("id", non_empty);
      monitor.kind = m.one_of("kind", {"storey", "pier"}, "storey");
      monitor.group = m.optional<std::string>("group", "");
      monitor.bottom = m.required<std::string>("bottom", non_empty);
      monitor.top = m.required<std::string>("top", non_empty);
      monitor.height = m.required<double>("height", positive);
      monitor.yield_drift = m.if_present<double>("yield_drift", positive);
      return monitor;
    }));
  for (const JsonValue& value : object.array("joints"))
    spec.joint_monitors.push_back(read_object(value, [](JsonObject& m) {
      builder::JointMonitorSpec monitor;
      monitor.id = m.required<std::string>("id", non_empty);
      monitor.link = m.required<std::string>("link", non_empty);
      monitor.girder = m.required<std::string>("girder", non_empty);
      monitor.seat = m.required<std::string>("seat", non_empty);
      monitor.seat_width = m.optional<double>("seat_width", 0.0, non_negative);
      return monitor;
    }));
}

// A method's object ({"type": "hht", "alpha": -0.05}) or the name of a preset.
IntegratorSpec read_integrator(const JsonValue& value) {
  if (value.json().is_string())
    return IntegratorSpec::preset(value.as_one_of(integrators::preset_names()));
  if (!value.json().is_object())
    value.fail("expected an object or a preset name string, got " + value.kind());
  return read_object(value, [](JsonObject& object) {
    IntegratorSpec integrator(
        *integrators::find_integrator(object.one_of("type", integrators::integrator_names())));
    for (const integrators::IntegratorParameter& parameter : integrator.method().parameters) {
      const std::optional<JsonValue> given = object.find(parameter.name);
      if (!given) continue;
      const double number = given->as<double>(Minimum{parameter.minimum, parameter.minimum_strict});
      if (parameter.maximum && number > *parameter.maximum)
        given->fail(fmt::format("must be <= {}, got {}", *parameter.maximum, number));
      integrator.set(parameter.name, number);
    }
    return integrator;
  });
}

builder::UnitsSpec read_units(JsonObject& object) {
  builder::UnitsSpec units;
  units.length = object.one_of("length", {"m", "cm", "mm", "km", "in", "ft"}, "m");
  units.time = object.one_of("time", {"s", "ms"}, "s");
  return units;
}

builder::DampingSpec read_damping(JsonObject& object) {
  builder::DampingSpec damping;
  (void)object.one_of("type", {"rayleigh"}, "rayleigh");
  const bool coefficients = object.has("mass_coefficient") || object.has("stiffness_coefficient");
  if (coefficients) {
    damping.mass_coefficient = object.optional<double>("mass_coefficient", 0.0, non_negative);
    damping.stiffness_coefficient =
        object.optional<double>("stiffness_coefficient", 0.0, non_negative);
    return damping;
  }
  damping.ratio = object.required<double>("ratio", non_negative);
  if (damping.ratio >= 1.0)
    object.at("ratio").fail(fmt::format("must be < 1, got {}", damping.ratio));
  const std::optional<JsonValue> periods = object.find("periods"), modes = object.find("modes");
  if (periods.has_value() == modes.has_value())
    object.fail(
        "give the two 'periods' or the two 'modes' Rayleigh damping matches the ratio at "
        "(or 'mass_coefficient' and 'stiffness_coefficient')");
  if (periods) {
    const std::vector<JsonValue> values = periods->elements(2, 2);
    damping.periods = {values[0].as<double>(positive), values[1].as<double>(positive)};
    if ((*damping.periods)[0] == (*damping.periods)[1])
      periods->fail("needs two different periods");
  } else {
    const std::vector<JsonValue> values = modes->elements(2, 2);
    damping.modes = {values[0].as<int>(at_least(1)), values[1].as<int>(at_least(1))};
    if ((*damping.modes)[0] == (*damping.modes)[1]) modes->fail("needs two different modes");
  }
  return damping;
}

builder::ExcitationSpec read_excitation(JsonObject& object, int dimension) {
  builder::ExcitationSpec excitation;
  excitation.record = object.required<std::string>("record", non_empty);
  read_record_fields(object, excitation);
  if (const std::optional<JsonValue> direction = object.find("direction"))
    excitation.direction = read_axis(*direction, dimension);
  if (const std::optional<JsonValue> supports = object.find("supports"))
    excitation.supports = read_names(*supports, "node", 1);
  if (const std::optional<JsonValue> wave = object.find("wave_passage")) {
    if (excitation.supports.empty()) wave->fail("a wave passage needs the 'supports' it reaches");
    read_object(*wave, [&excitation](JsonObject& w) {
      excitation.apparent_velocity = w.required<double>("apparent_velocity", positive);
      excitation.wave_origin = w.optional<double>("origin", 0.0);
      return 0;
    });
  }
  return excitation;
}

AnalysisSpec read_analysis(JsonObject& object) {
  AnalysisSpec analysis;
  if (const std::optional<JsonValue> integrator = object.find("integrator"))
    analysis.integrator = read_integrator(*integrator);
  if (const JsonValue step = object.at("time_step"); step.json().is_string()) {
    (void)step.as_one_of({"auto"});
    if (!analysis.integrator.is_explicit())
      step.fail(
          "\"auto\" is the stable step of central difference; implicit integrators need a number");
    analysis.time_step_auto = true;
    analysis.safety_factor =
        object.optional<double>("safety_factor", analysis.safety_factor, positive);
    if (analysis.safety_factor > 1.0) object.at("safety_factor").fail("must be <= 1");
  } else {
    analysis.time_step = step.as<double>(positive);
  }
  analysis.duration = object.optional<double>("duration", 0.0, positive);
  if (const std::optional<JsonValue> convergence = object.find("convergence")) {
    read_object(*convergence, [&analysis](JsonObject& settings) {
      analysis.relative_tolerance =
          settings.optional<double>("relative_tolerance", analysis.relative_tolerance, positive);
      analysis.absolute_tolerance = settings.optional<double>(
          "absolute_tolerance", analysis.absolute_tolerance, non_negative);
      analysis.max_iterations =
          settings.optional<int>("max_iterations", analysis.max_iterations, at_least(1));
    });
  }
  analysis.max_step_cuts =
      object.optional<int>("max_step_cuts", analysis.max_step_cuts, non_negative);
  // 2^-30 of a step is already below any meaningful time resolution.
  if (analysis.max_step_cuts > 30)
    object.at("max_step_cuts").fail(fmt::format("must be <= 30, got {}", analysis.max_step_cuts));
  analysis.max_steps = object.optional<long>("max_steps", analysis.max_steps, non_negative);
  analysis.static_initial_state =
      object.one_of("initial_state", {"unloaded", "static"}, "unloaded") == "static";
  if (const std::optional<JsonValue> adaptive = object.find("adaptive")) {
    if (analysis.integrator.is_explicit())
      adaptive->fail(
          "adaptive stepping is for the implicit integrators; central difference "
          "takes its stable step (\"time_step\": \"auto\")");
    integrators::AdaptiveStepping settings;
    if (adaptive->json().is_boolean()) {
      if (adaptive->as<bool>()) analysis.adaptive = settings;
    } else {
      read_object(*adaptive, [&](JsonObject& a) {
        settings.tolerance = a.optional<double>("tolerance", settings.tolerance, positive);
        settings.min_time_step = a.optional<double>("min_time_step", 0.0, positive);
        settings.max_time_step = a.optional<double>("max_time_step", 0.0, positive);
        if (settings.min_time_step > 0.0 && settings.max_time_step > 0.0 &&
            settings.min_time_step > settings.max_time_step)
          a.at("min_time_step").fail("must be <= max_time_step");
      });
      analysis.adaptive = settings;
    }
  }
  return analysis;
}

// Recorder files are written inside the output folder: a name must not lead out of it.
void check_file_name(const std::string& name, const JsonValue& where) {
  const bool plain = name.size() > 4 && name.ends_with(".csv") &&
                     name.find_first_of("/\\") == std::string::npos &&
                     name.find("..") == std::string::npos;
  if (!plain)
    where.fail(
        fmt::format("must be a plain file name ending in .csv (no folders), got '{}'", name));
}

RecorderSpec read_recorder(JsonObject& object, std::size_t index, UniqueNames& files) {
  RecorderSpec recorder;
  recorder.type = object.one_of("type", {"link", "node"});
  if (recorder.type == "link") {
    if (const std::optional<JsonValue> links = object.find("links"))
      recorder.ids = read_names(*links, "link", 1);  // absent: every link
  } else {
    recorder.ids = read_names(object.at("nodes"), "node", 1);
  }
  const std::optional<JsonValue> file = object.find("file");
  const JsonValue& where = file ? *file : object.value();
  recorder.file = file ? file->as<std::string>() : fmt::format("{}_{}.csv", recorder.type, index);
  check_file_name(recorder.file, where);
  files.add(recorder.file, where);
  return recorder;
}

std::vector<RecorderSpec> read_recorders(JsonObject& top) {
  UniqueNames files("file name");
  std::vector<RecorderSpec> recorders;
  const std::vector<JsonValue> values = top.array("recorders");
  for (std::size_t k = 0; k < values.size(); ++k) {
    recorders.push_back(read_object(
        values[k], [k, &files](JsonObject& object) { return read_recorder(object, k, files); }));
  }
  return recorders;
}

ModelSpec read_model(JsonObject& top) {
  ModelSpec spec;
  spec.source = top.value().file();
  spec.title = top.optional<std::string>("title", spec.title);
  spec.dimension = read_dimension(top);
  const int dimension = spec.dimension;

  UniqueNames node_ids("id");
  UniqueNames material_ids("id");
  UniqueNames element_ids("id");
  UniqueNames link_ids("id");
  spec.nodes = read_each(
      top, "nodes", [&](JsonObject& object) { return read_node(object, dimension, node_ids); });
  spec.materials = read_each(
      top, "materials", [&](JsonObject& object) { return read_material(object, material_ids); });
  spec.elements = read_each(top, "elements", [&](JsonObject& object) {
    return read_element(object, dimension, element_ids);
  });
  spec.masses = read_each(top, "masses", read_mass);
  spec.supports = read_each(
      top, "supports", [dimension](JsonObject& object) { return read_support(object, dimension); });
  spec.loads = read_each(top, "loads",
                         [dimension](JsonObject& object) { return read_load(object, dimension); });
  spec.initial_velocities = read_each(top, "initial_velocities", [dimension](JsonObject& object) {
    return read_initial_velocity(object, dimension);
  });
  spec.links = read_each(
      top, "links", [&](JsonObject& object) { return read_link(object, dimension, link_ids); });
  read_generators(top, spec);
  UniqueNames surface_ids("id");
  const std::vector<JsonValue> surfaces = top.array("surfaces");
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    require_plane(surfaces[k], dimension);
    spec.surfaces.push_back(read_object(surfaces[k], [&](JsonObject& object) {
      return read_surface(object, static_cast<int>(k), surface_ids);
    }));
  }
  const std::vector<JsonValue> contacts = top.array("contacts");
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    require_plane(contacts[k], dimension);
    spec.contacts.push_back(read_object(contacts[k], [&](JsonObject& object) {
      return read_contact(object, static_cast<int>(k), link_ids);
    }));
  }
  if (const std::optional<JsonValue> monitors = top.find("monitors"))
    read_object(*monitors, [&spec](JsonObject& object) {
      read_monitors(object, spec);
      return 0;
    });
  if (const std::optional<JsonValue> units = top.find("units"))
    spec.units = read_object(*units, read_units);
  if (const std::optional<JsonValue> damping = top.find("damping"))
    spec.damping = read_object(*damping, read_damping);
  spec.excitations = read_each(top, "excitations", [dimension](JsonObject& object) {
    return read_excitation(object, dimension);
  });
  spec.analysis = read_object(top.at("analysis"), read_analysis);
  if (spec.analysis.duration == 0.0 && spec.excitations.empty())
    top.at("analysis").fail("needs 'duration' (it may be left out only with 'excitations')");
  spec.recorders_given = top.has("recorders");
  spec.recorders = read_recorders(top);
  return spec;
}

}  // namespace

ModelSpec parse_model(const std::string& text, const std::string& source) {
  const nlohmann::json document = parse_json(text, source);
  return read_object(JsonValue(document, source, ""), read_model);
}

ModelSpec read_model_file(const std::string& path) {
  return parse_model(read_text_file(path), path);
}

}  // namespace pound::io
