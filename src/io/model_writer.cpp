#include "io/model_writer.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "links/law_registry.hpp"

namespace pound::io {
namespace {

using builder::LawSpec;
using builder::ModelSpec;
using Json = nlohmann::ordered_json;  // keys in the order they are set, like the format's tables

constexpr std::size_t kLineWidth = 100;

// One-line JSON with a space after ',' and ':', as model files are written by hand.
std::string inline_text(const Json& value) {
  if (!value.is_structured()) return value.dump();  // numbers in full round-trip precision
  std::string text = value.is_object() ? "{" : "[";
  for (auto item = value.begin(); item != value.end(); ++item) {
    if (item != value.begin()) text += ", ";
    if (value.is_object()) text += Json(item.key()).dump() + ": ";
    text += inline_text(item.value());
  }
  return text + (value.is_object() ? "}" : "]");
}

// Pretty-printing that keeps what fits in a line on one line (a node, a law, an axis) and puts
// the entries of anything longer one per line, so a 200-node model stays readable.
void append_pretty(const Json& value, std::size_t column, std::size_t indent, std::string& out) {
  const std::string flat = inline_text(value);
  if (!value.is_structured() || column + flat.size() < kLineWidth) {  // room for a comma
    out += flat;
    return;
  }
  const std::string inner(indent + 2, ' ');
  out += value.is_object() ? "{\n" : "[\n";
  for (auto item = value.begin(); item != value.end(); ++item) {
    if (item != value.begin()) out += ",\n";
    const std::string key = value.is_object() ? Json(item.key()).dump() + ": " : "";
    out += inner + key;
    append_pretty(item.value(), inner.size() + key.size(), indent + 2, out);
  }
  out += "\n" + std::string(indent, ' ') + (value.is_object() ? "}" : "]");
}

template <class T>
void set_unless_default(Json& object, const char* key, const T& value, const T& fallback) {
  if (value != fallback) object[key] = value;
}

void set_if_present(Json& object, const char* key, const std::optional<double>& value) {
  if (value) object[key] = *value;
}

// An array field of `items` each written by `write`, left out when empty.
template <class T, class Write>
void set_array(Json& object, const char* key, const std::vector<T>& items, Write write) {
  if (items.empty()) return;
  Json array = Json::array();
  for (const T& item : items) array.push_back(write(item));
  object[key] = std::move(array);
}

Json string_array(const std::vector<std::string>& names) {
  Json array = Json::array();
  for (const std::string& name : names) array.push_back(name);
  return array;
}

// Anything that is a node with x and y components (initial velocities, loads): y only in 2-D,
// where the reader accepts it.
template <class Spec>
Json nodal_vector(const Spec& item, int dimension) {
  Json json;
  json["node"] = item.node;
  json["x"] = item.x;
  if (dimension == 2) json["y"] = item.y;
  return json;
}

// Parameters in the registry's order (then any it does not list); choices only where they
// differ from the registry's default, which the reader fills in for every law.
Json law_json(const LawSpec& law) {
  Json json;
  json["type"] = law.type;
  const links::LawEntry* type = links::find_law(law.type);
  std::vector<std::string> order;
  if (type)
    for (const links::LawParameter& parameter : type->parameters) order.push_back(parameter.name);
  for (const auto& [name, value] : law.parameters)
    if (std::find(order.begin(), order.end(), name) == order.end()) order.push_back(name);
  for (const std::string& name : order)
    if (const std::optional<double> value = law.number(name)) json[name] = *value;
  for (const auto& [name, value] : law.choices) {
    std::optional<std::string> fallback;
    if (type)
      for (const links::LawChoice& choice : type->choices)
        if (choice.name == name) fallback = choice.values.front();
    if (value != fallback) json[name] = value;
  }
  return json;
}

Json node_json(const builder::NodeSpec& node, int dimension) {
  Json json;
  json["id"] = node.id;
  json["x"] = node.x;
  if (dimension == 2) json["y"] = node.y;
  return json;
}

Json material_json(const builder::MaterialSpec& material) {
  Json json;
  json["id"] = material.id;
  json["youngs_modulus"] = material.youngs_modulus;
  json["density"] = material.density;
  set_if_present(json, "poisson_ratio", material.poisson_ratio);
  return json;
}

Json rayleigh_coefficients_json(const std::array<double, 2>& coefficients) {
  Json json;
  json["mass_coefficient"] = coefficients[0];
  json["stiffness_coefficient"] = coefficients[1];
  return json;
}

Json element_json(const builder::ElementSpec& element) {
  Json json;
  json["id"] = element.id;
  json["type"] = element.type;
  if (element.type == "quad") {
    json["nodes"] = string_array(
        {element.node_i, element.node_j, element.more_nodes.at(0), element.more_nodes.at(1)});
    json["material"] = element.material;
    json["thickness"] = element.thickness;
    if (element.plane_strain) json["plane"] = "strain";
    if (element.consistent_mass) json["mass"] = "consistent";
    if (element.rayleigh) json["damping"] = rayleigh_coefficients_json(*element.rayleigh);
    return json;
  }
  json["nodes"] = string_array({element.node_i, element.node_j});
  json["material"] = element.material;
  json["area"] = element.area;
  if (element.type == "beam") {  // the reader rejects beam fields on a truss
    json["inertia"] = element.inertia;
    set_unless_default(json, "extra_mass", element.extra_mass, 0.0);
    if (element.consistent_mass) json["mass"] = "consistent";
  }
  if (element.rayleigh) json["damping"] = rayleigh_coefficients_json(*element.rayleigh);
  return json;
}

Json mass_json(const builder::MassSpec& mass) {
  Json json;
  json["node"] = mass.node;
  json["mass"] = mass.mass;
  set_unless_default(json, "rotary_inertia", mass.rotary_inertia, 0.0);
  set_if_present(json, "mass_damping", mass.mass_damping);
  return json;
}

Json support_json(const builder::SupportSpec& support) {
  std::vector<std::string> fixed;
  if (support.fix_x) fixed.push_back("x");
  if (support.fix_y) fixed.push_back("y");
  if (support.fix_rotation) fixed.push_back("rz");
  Json json;
  json["node"] = support.node;
  json["fix"] = string_array(fixed);
  return json;
}

Json friction_json(const builder::FrictionSpec& friction) {
  Json json;
  json["coefficient"] = friction.coefficient;
  set_if_present(json, "stick_stiffness", friction.stick_stiffness);
  set_if_present(json, "stick_damping", friction.stick_damping);
  set_if_present(json, "stick_mass", friction.stick_mass);
  return json;
}

Json link_json(const builder::LinkSpec& link) {
  Json json;
  json["id"] = link.id;
  if (link.segment_end) {
    json["nodes"] = string_array({link.node_i});
    json["segment"] = string_array({link.node_j, *link.segment_end});
  } else {
    json["nodes"] = string_array({link.node_i, link.node_j});
  }
  json["gap"] = link.gap;  // written even when 0: the clear distance is what a reader looks for
  if (link.axis) json["axis"] = *link.axis;
  if (link.velocity_j[0] != 0.0 || link.velocity_j[1] != 0.0)
    json["surface_velocity"] = std::vector<double>{link.velocity_j[0], link.velocity_j[1]};
  if (link.rotational) json["dof"] = "rotation";
  json["law"] = law_json(link.law);
  if (link.friction) json["friction"] = friction_json(*link.friction);
  return json;
}

Json rod_json(const builder::RodSpec& rod) {
  Json json;
  json["youngs_modulus"] = rod.youngs_modulus;
  json["density"] = rod.density;
  json["area"] = rod.area;
  json["length"] = rod.length;
  json["elements"] = rod.elements;
  json["initial_velocity"] = rod.initial_velocity;
  json["far_end"] = rod.far_end_fixed ? "fixed" : "free";
  return json;
}

Json rod_pair_json(const builder::RodPairSpec& pair) {
  Json json;
  json["type"] = "rod_pair";
  json["id"] = pair.id;
  json["left"] = rod_json(pair.left);
  json["right"] = rod_json(pair.right);
  json["gap"] = pair.gap;
  json["law"] = law_json(pair.law);
  return json;
}

Json building_json(const builder::BuildingSpec& building) {
  Json json;
  json["damping_ratio"] = building.damping_ratio;
  json["storeys"] = Json::array();
  for (const builder::StoreySpec& storey : building.storeys) {
    Json item;
    item["height"] = storey.height;
    item["mass"] = storey.mass;
    item["stiffness"] = storey.stiffness;
    json["storeys"].push_back(std::move(item));
  }
  return json;
}

Json adjacent_buildings_json(const builder::AdjacentBuildingsSpec& pair) {
  Json json;
  json["type"] = "adjacent_buildings";
  json["id"] = pair.id;
  json["left"] = building_json(pair.left);
  json["right"] = building_json(pair.right);
  json["separation"] = pair.separation;
  json["law"] = law_json(pair.law);
  return json;
}

// Every field, defaults included: a girder's and a pier's default element counts differ.
Json section_json(const builder::SectionSpec& section) {
  Json json;
  json["youngs_modulus"] = section.youngs_modulus;
  json["area"] = section.area;
  json["inertia"] = section.inertia;
  json["density"] = section.density;
  json["extra_mass"] = section.extra_mass;
  json["elements"] = section.elements;
  return json;
}

Json joint_json(const builder::JointSpec& joint) {
  Json json;
  json["gap"] = joint.gap;
  json["law"] = law_json(joint.law);
  if (joint.restrainer) json["restrainer"] = law_json(*joint.restrainer);
  json["seat_width"] = joint.seat_width;
  return json;
}

Json girder_bridge_json(const builder::GirderBridgeSpec& bridge) {
  Json json;
  json["type"] = "girder_bridge";
  json["id"] = bridge.id;
  json["spans"] = bridge.spans;
  json["girder"] = section_json(bridge.girder);
  json["pier"] = section_json(bridge.pier);
  json["pier_height"] = bridge.pier_height;
  set_if_present(json, "pier_yield_drift", bridge.pier_yield_drift);
  json["bearing"] = law_json(bridge.bearing);
  json["bearing_vertical_stiffness"] = bridge.bearing_vertical_stiffness;
  if (!bridge.expansion_joints.empty()) json["expansion_joints"] = bridge.expansion_joints;
  // The reader fills `joint` only when the file gives one, so an unset one has no law.
  if (!bridge.expansion_joints.empty() || !bridge.joint.law.type.empty())
    json["joint"] = joint_json(bridge.joint);
  json["abutment"] = joint_json(bridge.abutment);
  if (bridge.backfill) {
    json["backfill"] = law_json(*bridge.backfill);
    json["backwall_mass"] = bridge.backwall_mass;
  }
  return json;
}

// All generators in the order of the file's "generators" array, which each kind remembers as
// an index (a spec made in code may leave the rod pairs' indices out: then they come first).
Json pair_json(const std::array<double, 2>& pair) { return std::vector<double>{pair[0], pair[1]}; }

Json block_json(const builder::BlockSpec& block) {
  Json json;
  json["type"] = "block";
  json["id"] = block.id;
  json["origin"] = pair_json(block.origin);
  json["width"] = block.width;
  json["height"] = block.height;
  json["elements"] = std::vector<int>{block.columns, block.rows};
  json["material"] = block.material;
  json["thickness"] = block.thickness;
  if (block.plane_strain) json["plane"] = "strain";
  if (block.consistent_mass) json["mass"] = "consistent";
  if (block.initial_velocity[0] != 0.0 || block.initial_velocity[1] != 0.0)
    json["initial_velocity"] = pair_json(block.initial_velocity);
  constexpr const char* kEdges[] = {"bottom", "right", "top", "left"};
  Json pressure;
  for (std::size_t e = 0; e < 4; ++e)
    if (block.pressure[e] != 0.0) pressure[kEdges[e]] = block.pressure[e];
  if (!pressure.is_null()) json["pressure"] = std::move(pressure);
  if (!block.fixed_edges.empty()) json["fixed_edges"] = string_array(block.fixed_edges);
  return json;
}

Json surface_json(const builder::SurfaceSpec& surface) {
  Json json;
  json["id"] = surface.id;
  json["point"] = pair_json(surface.point);
  json["normal"] = pair_json(surface.normal);
  if (surface.velocity[0] != 0.0 || surface.velocity[1] != 0.0)
    json["velocity"] = pair_json(surface.velocity);
  json["nodes"] = string_array(surface.nodes);
  json["law"] = law_json(surface.law);
  if (surface.friction) json["friction"] = friction_json(*surface.friction);
  return json;
}

Json contact_json(const builder::ContactSpec& contact) {
  Json json;
  json["id"] = contact.id;
  json["nodes"] = string_array(contact.nodes);
  json["segments"] = string_array(contact.segments);
  json["law"] = law_json(contact.law);
  if (contact.friction) json["friction"] = friction_json(*contact.friction);
  return json;
}

Json generators_json(const ModelSpec& spec) {
  std::vector<std::pair<int, Json>> generators;
  for (std::size_t k = 0; k < spec.rod_pairs.size(); ++k) {
    const int index = k < spec.rod_pair_generator_index.size() ? spec.rod_pair_generator_index[k]
                                                               : static_cast<int>(k);
    generators.emplace_back(index, rod_pair_json(spec.rod_pairs[k]));
  }
  for (const builder::AdjacentBuildingsSpec& pair : spec.building_pairs)
    generators.emplace_back(pair.generator_index, adjacent_buildings_json(pair));
  for (const builder::GirderBridgeSpec& bridge : spec.bridges)
    generators.emplace_back(bridge.generator_index, girder_bridge_json(bridge));
  for (const builder::BlockSpec& block : spec.blocks)
    generators.emplace_back(block.generator_index, block_json(block));
  std::stable_sort(generators.begin(), generators.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  Json json = Json::array();
  for (auto& generator : generators) json.push_back(std::move(generator.second));
  return json;
}

Json drift_monitor_json(const builder::DriftMonitorSpec& monitor) {
  Json json;
  json["id"] = monitor.id;
  json["kind"] = monitor.kind;
  if (!monitor.group.empty()) json["group"] = monitor.group;
  json["bottom"] = monitor.bottom;
  json["top"] = monitor.top;
  json["height"] = monitor.height;
  set_if_present(json, "yield_drift", monitor.yield_drift);
  return json;
}

Json joint_monitor_json(const builder::JointMonitorSpec& monitor) {
  Json json;
  json["id"] = monitor.id;
  json["link"] = monitor.link;
  json["girder"] = monitor.girder;
  json["seat"] = monitor.seat;
  json["seat_width"] = monitor.seat_width;
  return json;
}

Json units_json(const builder::UnitsSpec& units) {
  Json json;
  json["length"] = units.length;
  json["time"] = units.time;
  return json;
}

bool default_units(const builder::UnitsSpec& units) {
  const builder::UnitsSpec fallback;
  return units.length == fallback.length && units.time == fallback.time;
}

// The reader takes coefficients when either is given, else the ratio at two periods or modes.
Json damping_json(const builder::DampingSpec& damping) {
  Json json;
  json["type"] = "rayleigh";
  if (damping.mass_coefficient || damping.stiffness_coefficient) {
    json.update(rayleigh_coefficients_json(
        {damping.mass_coefficient.value_or(0.0), damping.stiffness_coefficient.value_or(0.0)}));
    return json;
  }
  json["ratio"] = damping.ratio;
  if (damping.periods) json["periods"] = *damping.periods;
  if (damping.modes) json["modes"] = *damping.modes;
  return json;
}

Json excitation_json(const builder::ExcitationSpec& excitation) {
  const builder::ExcitationSpec fallback;
  Json json;
  json["record"] = excitation.record;
  json["format"] = excitation.format;
  set_unless_default(json, "column", excitation.column, fallback.column);
  set_if_present(json, "time_step", excitation.time_step);
  set_unless_default(json, "time_column", excitation.time_column, fallback.time_column);
  json["units"] = excitation.units;  // written always: g or m/s2 is the first thing to check
  // The default [1] means +x in any dimension; written out it would be refused in 2-D.
  set_unless_default(json, "direction", excitation.direction, fallback.direction);
  if (!excitation.supports.empty()) json["supports"] = excitation.supports;
  if (excitation.apparent_velocity)
    json["wave_passage"] = Json{{"apparent_velocity", *excitation.apparent_velocity},
                                {"origin", excitation.wave_origin}};
  Json scale;
  set_if_present(scale, "factor", excitation.scale_factor);
  set_if_present(scale, "pga", excitation.target_pga);
  set_if_present(scale, "sa", excitation.target_sa);
  if (excitation.target_sa) {
    scale["period"] = excitation.sa_period;
    scale["damping"] = excitation.sa_damping;
  }
  if (!scale.is_null()) json["scale"] = std::move(scale);
  return json;
}

Json analysis_json(const builder::AnalysisSpec& analysis) {
  Json json;
  Json integrator;  // always the object: a preset name reads back as its parameters
  integrator["type"] = analysis.integrator.method().name;
  for (const auto& [name, value] : analysis.integrator.values()) integrator[name] = value;
  json["integrator"] = std::move(integrator);
  if (analysis.time_step_auto) {
    json["time_step"] = "auto";
    json["safety_factor"] = analysis.safety_factor;
  } else {
    json["time_step"] = analysis.time_step;
  }
  // 0 stands for "the longest record's duration", which is said by leaving the field out.
  set_unless_default(json, "duration", analysis.duration, 0.0);
  Json convergence;
  convergence["relative_tolerance"] = analysis.relative_tolerance;
  convergence["absolute_tolerance"] = analysis.absolute_tolerance;
  convergence["max_iterations"] = analysis.max_iterations;
  json["convergence"] = std::move(convergence);
  json["max_step_cuts"] = analysis.max_step_cuts;
  set_unless_default(json, "max_steps", analysis.max_steps, 0L);
  if (analysis.static_initial_state) json["initial_state"] = "static";
  return json;
}

Json recorder_json(const builder::RecorderSpec& recorder) {
  Json json;
  json["type"] = recorder.type;
  // A link recorder without ids records every link; a node recorder always names its nodes.
  if (recorder.type == "node" || !recorder.ids.empty())
    json[recorder.type == "node" ? "nodes" : "links"] = string_array(recorder.ids);
  json["file"] = recorder.file;
  return json;
}

}  // namespace

std::string model_to_json(const ModelSpec& spec) {
  const int dimension = spec.dimension;
  Json json;
  if (!spec.title.empty()) json["title"] = spec.title;
  json["dimension"] = dimension;
  set_array(json, "nodes", spec.nodes,
            [dimension](const builder::NodeSpec& node) { return node_json(node, dimension); });
  set_array(json, "materials", spec.materials, material_json);
  set_array(json, "elements", spec.elements, element_json);
  set_array(json, "masses", spec.masses, mass_json);
  set_array(json, "supports", spec.supports, support_json);
  const auto nodal = [dimension](const auto& item) { return nodal_vector(item, dimension); };
  set_array(json, "initial_velocities", spec.initial_velocities, nodal);
  set_array(json, "loads", spec.loads, nodal);
  set_array(json, "links", spec.links, link_json);
  if (Json generators = generators_json(spec); !generators.empty())
    json["generators"] = std::move(generators);
  set_array(json, "surfaces", spec.surfaces, surface_json);
  set_array(json, "contacts", spec.contacts, contact_json);
  Json monitors;
  set_array(monitors, "drifts", spec.drift_monitors, drift_monitor_json);
  set_array(monitors, "joints", spec.joint_monitors, joint_monitor_json);
  if (!monitors.is_null()) json["monitors"] = std::move(monitors);
  if (!default_units(spec.units)) json["units"] = units_json(spec.units);
  if (spec.damping) json["damping"] = damping_json(*spec.damping);
  set_array(json, "excitations", spec.excitations, excitation_json);
  json["analysis"] = analysis_json(spec.analysis);
  if (spec.recorders_given) {
    json["recorders"] = Json::array();  // "recorders": [] (record nothing) differs from absent
    for (const builder::RecorderSpec& recorder : spec.recorders)
      json["recorders"].push_back(recorder_json(recorder));
  }
  std::string text;
  append_pretty(json, 0, 0, text);
  return text + "\n";
}

}  // namespace pound::io
