#pragma once
// What a run records and watches, resolved against the model: recorders (the histories written
// as CSV) and monitors (storey and pier drifts, joints), each naming nodes and links by index.
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "builder/resolver.hpp"

namespace pound::builder {

struct ResolvedRecorder {
  RecorderKind kind = RecorderKind::link;
  std::vector<Index> items;  // links or nodes
  std::string file;
  AccelerationFrame accelerations = AccelerationFrame::both;  // node recorders
  OutputSampling sampling;                                    // histories
  bool envelope = false;
  std::vector<double> damping_ratios, periods;  // spectrum recorders; periods in model units
};

struct DriftMonitor {
  std::string id;
  DriftKind kind = DriftKind::storey;
  std::string group;          // the building or bridge
  Index bottom = 0, top = 0;  // nodes
  double height = 0.0;
  std::optional<double> yield_drift;
  // The yield drift is where the model itself yields (hinged piers, a user's monitor), so
  // drift / yield drift is a ductility; for an elastic pier it is only a demand ratio.
  bool yields = true;
  // The member's plastic hinge (a link) with its section's phi_y and L_p, for the curvature
  // ductility 1 + theta_p / (phi_y L_p) (Priestley, Seible & Calvi 1996).
  struct Curvature {
    Index hinge = 0;
    double yield_curvature = 0.0, plastic_hinge_length = 0.0;
    // 0: theta_p of the link's own law; 1, 2: of its coupled bending about t_1, t_2.
    int hinge_direction = 0;
  };
  std::optional<Curvature> curvature;
  // What carries the shear (DriftMonitorSpec): an element (end i at the bottom) or a link.
  std::optional<Index> base_element, shear_link;
  // With a base element, the member's elements above it, whose shears the peak shear takes too.
  std::vector<Index> upper_elements;
  // 0: the shear link's own force; 1, 2: its coupled shear's along t_1, t_2.
  int shear_link_direction = 0;
  int direction = 0;  // of the drift and the top's acceleration: a translation (model/direction)
  std::optional<std::array<double, 3>> axis;  // a unit vector instead of `direction`
  // The unit vector the drift is measured along: `axis`, or `direction`'s.
  std::array<double, 3> along() const {
    if (axis) return *axis;
    std::array<double, 3> unit{};
    unit[static_cast<std::size_t>(direction)] = 1.0;
    return unit;
  }
  // Points of the top floor from the top node (DriftMonitorSpec::corners): their drifts and the
  // storey's twist are reported too.
  std::vector<std::array<double, 3>> corners;
  // The monitor (index) whose drift yields together with this one's (DriftMonitorSpec::
  // yields_with): the summary gives the pair's resultant ductility.
  std::optional<std::size_t> yields_with;
};

struct JointMonitor {
  std::string id;
  Index link = 0;              // the pounding link across the joint
  Index girder = 0, seat = 0;  // nodes
  double seat_width = 0.0;
  // A point offset from both nodes and a unit direction (builder::JointMonitorSpec); none: the
  // nodes' movement along x.
  std::optional<std::array<double, 3>> point, direction;
};

// Without a "recorders" field every link is recorded into links.csv; a link recorder without ids
// records every link.
std::vector<ResolvedRecorder> resolve_recorders(const Resolver& resolver, std::size_t link_count);
// The user's monitors first, then the generated ones (reported at "/generators").
std::vector<DriftMonitor> resolve_drift_monitors(const Resolver& resolver);
std::vector<JointMonitor> resolve_joint_monitors(const Resolver& resolver);

}  // namespace pound::builder
