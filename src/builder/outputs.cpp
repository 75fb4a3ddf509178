#include "builder/outputs.hpp"

#include <cmath>

#include "model/ground_motion.hpp"

namespace pound::builder {
namespace {

std::vector<Index> every(std::size_t count) {
  std::vector<Index> items(count);
  for (std::size_t i = 0; i < count; ++i) items[i] = static_cast<Index>(i);
  return items;
}

ResolvedRecorder resolve_recorder(const Resolver& resolver, const RecorderSpec& recorder,
                                  std::size_t index, std::size_t link_count) {
  ResolvedRecorder resolved{recorder.type,
                            {},
                            recorder.file,
                            recorder.accelerations,
                            {recorder.every, recorder.interval.value_or(0.0)},
                            recorder.envelope,
                            recorder.damping_ratios,
                            recorder.periods};
  // Under moving supports u is measured from their quasi-static motion R u_s, which deforms the
  // members too: K_e u_e alone would miss it.
  if (recorder.type == RecorderKind::element)
    for (std::size_t k = 0; k < resolver.spec().excitations.size(); ++k)
      if (!resolver.spec().excitations[k].supports.empty())
        resolver.fail(fmt::format("/recorders/{}/type", index),
                      fmt::format("element forces under moving supports (/excitations/{}/supports) "
                                  "are not available yet: they would miss the members' "
                                  "deformation by the supports' quasi-static motion (record node "
                                  "displacements, or links, instead)",
                                  k));
  if (recorder.type == RecorderKind::spectrum && resolved.periods.empty()) {
    const double second = resolver.spec().units.second();
    for (double period : model::default_spectrum_periods())
      resolved.periods.push_back(period * second);
  }
  for (std::size_t i = 0; i < recorder.ids.size(); ++i) {
    const std::string& id = recorder.ids[i];
    switch (recorder.type) {
      case RecorderKind::link:
        resolved.items.push_back(
            resolver.link(id, fmt::format("/recorders/{}/links/{}", index, i)));
        break;
      case RecorderKind::element:
        resolved.items.push_back(
            resolver.element(id, fmt::format("/recorders/{}/elements/{}", index, i)));
        break;
      case RecorderKind::node:
      case RecorderKind::spectrum:
        resolved.items.push_back(
            resolver.node(id, fmt::format("/recorders/{}/nodes/{}", index, i)));
        break;
    }
  }
  if (recorder.type == RecorderKind::link && recorder.ids.empty())
    resolved.items = every(link_count);
  return resolved;
}

// Where monitor k was given: the user's own, or a generator.
std::string monitor_path(std::size_t k, std::size_t user_count, const char* kind) {
  return k < user_count ? fmt::format("/monitors/{}/{}", kind, k) : "/generators";
}

// Which force of a monitor's shear link is its shear: the link's own (0), or, for a link with a
// coupled shear, the one along the tangent the monitor names (1, 2).
int shear_link_direction(const Resolver& resolver, const DriftMonitorSpec& m, Index link,
                         const std::string& path) {
  const bool coupled = resolver.spec().links[static_cast<std::size_t>(link)].shear.has_value();
  if (coupled && !m.shear_link_direction)
    resolver.fail(path + "/shear_link",
                  fmt::format("link '{}' carries a shear in two directions: give "
                              "'shear_link_direction', 1 or 2, the tangent of this drift's shear",
                              *m.shear_link));
  if (!coupled && m.shear_link_direction)
    resolver.fail(
        path + "/shear_link_direction",
        fmt::format("link '{}' has no coupled shear: its force is the shear", *m.shear_link));
  return m.shear_link_direction.value_or(0);
}

// A monitor's hinge: a uniaxial one, or one direction of a hinge that bends about two axes.
DriftMonitor::Curvature curvature_of(const Resolver& resolver, const DriftMonitorSpec& m,
                                     const std::string& path) {
  const Index hinge = resolver.link(*m.hinge, path + "/hinge");
  const LinkSpec& link = resolver.spec().links[static_cast<std::size_t>(hinge)];
  const bool biaxial = link.rotational && link.shear;
  if (biaxial && !m.hinge_direction)
    resolver.fail(path + "/hinge",
                  fmt::format("hinge '{}' bends about two axes (its `shear`): give "
                              "'hinge_direction', 1 or 2, the tangent this drift bends it about",
                              *m.hinge));
  if (!biaxial && m.hinge_direction)
    resolver.fail(path + "/hinge_direction",
                  fmt::format("hinge '{}' bends about one axis: no direction to pick", *m.hinge));
  return {hinge, *m.yield_curvature, *m.plastic_hinge_length, m.hinge_direction.value_or(0)};
}

}  // namespace

std::vector<ResolvedRecorder> resolve_recorders(const Resolver& resolver, std::size_t link_count) {
  const ModelSpec& spec = resolver.spec();
  std::vector<ResolvedRecorder> recorders;
  if (!spec.recorders_given && link_count > 0)
    recorders.push_back({RecorderKind::link, every(link_count), "links.csv"});
  for (std::size_t k = 0; k < spec.recorders.size(); ++k)
    recorders.push_back(resolve_recorder(resolver, spec.recorders[k], k, link_count));
  return recorders;
}

std::vector<DriftMonitor> resolve_drift_monitors(const Resolver& resolver) {
  const std::vector<DriftMonitorSpec>& specs = resolver.spec().drift_monitors;
  const std::size_t user_count = resolver.user_spec().drift_monitors.size();
  const std::map<std::string, Index> by_id = resolver.index_ids(
      specs, "drift monitor", [&](std::size_t k) { return monitor_path(k, user_count, "drifts"); });
  std::vector<DriftMonitor> monitors;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const DriftMonitorSpec& m = specs[k];
    const std::string path = monitor_path(k, resolver.user_spec().drift_monitors.size(), "drifts");
    DriftMonitor monitor{m.id,
                         m.kind,
                         m.group,
                         resolver.node(m.bottom, path + "/bottom"),
                         resolver.node(m.top, path + "/top"),
                         m.height,
                         m.yield_drift,
                         m.yields};
    monitor.direction = m.direction;
    monitor.corners = m.corners;
    if (m.axis) {
      const std::array<double, 3>& a = *m.axis;
      const double length = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
      monitor.axis = std::array{a[0] / length, a[1] / length, a[2] / length};
    }
    if (m.hinge) monitor.curvature = curvature_of(resolver, m, path);
    if (m.base_element)
      monitor.base_element = resolver.element(*m.base_element, path + "/base_element");
    for (std::size_t e = 0; e < m.upper_elements.size(); ++e)
      monitor.upper_elements.push_back(
          resolver.element(m.upper_elements[e], fmt::format("{}/upper_elements/{}", path, e)));
    if (m.shear_link) {
      monitor.shear_link = resolver.link(*m.shear_link, path + "/shear_link");
      monitor.shear_link_direction = shear_link_direction(resolver, m, *monitor.shear_link, path);
    }
    if (m.yields_with)  // a generator's own pair: the id is there
      monitor.yields_with = static_cast<std::size_t>(by_id.at(*m.yields_with));
    monitors.push_back(monitor);
  }
  return monitors;
}

std::vector<JointMonitor> resolve_joint_monitors(const Resolver& resolver) {
  const std::vector<JointMonitorSpec>& specs = resolver.spec().joint_monitors;
  const std::size_t user_count = resolver.user_spec().joint_monitors.size();
  resolver.index_ids(specs, "joint monitor",
                     [&](std::size_t k) { return monitor_path(k, user_count, "joints"); });
  std::vector<JointMonitor> monitors;
  for (std::size_t k = 0; k < specs.size(); ++k) {
    const JointMonitorSpec& m = specs[k];
    const std::string path = monitor_path(k, resolver.user_spec().joint_monitors.size(), "joints");
    const Index link = resolver.link(m.link, path + "/link");
    JointMonitor monitor{m.id, link, resolver.node(m.girder, path + "/girder"),
                         resolver.node(m.seat, path + "/seat"), m.seat_width};
    monitor.point = m.point;
    if (m.direction) {
      const std::array<double, 3>& d = *m.direction;
      const double length = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      monitor.direction = std::array{d[0] / length, d[1] / length, d[2] / length};
    } else if (m.point) {
      monitor.direction = std::array{1.0, 0.0, 0.0};
    }
    monitors.push_back(monitor);
  }
  return monitors;
}

}  // namespace pound::builder
