#include "results/recorders.hpp"

#include <algorithm>

namespace pound::results {

LinkRecorder::LinkRecorder(std::string file, std::vector<LinkRows> links,
                           const std::vector<std::string>& ids)
    : file_(std::move(file)), links_(std::move(links)) {
  table_.columns.push_back("time");
  for (std::size_t k = 0; k < ids.size(); ++k) {
    table_.columns.push_back(ids[k] + ".force");
    table_.columns.push_back(ids[k] + ".penetration");
    if (links_[k].friction) {
      table_.columns.push_back(ids[k] + ".tangential_force");
      table_.columns.push_back(ids[k] + ".slide");
    }
  }
  table_.values.resize(table_.columns.size());
}

void LinkRecorder::record(const integrators::State& state) {
  std::size_t column = 0;
  table_.values[column++].push_back(state.time);
  for (const LinkRows& link : links_) {
    const Index rows = link.friction ? 2 : 1;
    for (Index r = link.row; r < link.row + rows; ++r) {
      table_.values[column++].push_back(state.link_force[r]);
      table_.values[column++].push_back(state.link_penetration[r]);
    }
  }
}

NodeRecorder::NodeRecorder(std::string file, std::vector<std::vector<Index>> equations,
                           std::vector<Index> nodes, const std::vector<std::string>& ids,
                           builder::AccelerationFrame accelerations, GroundAcceleration& ground)
    : file_(std::move(file)),
      equations_(std::move(equations)),
      nodes_(std::move(nodes)),
      relative_(accelerations != builder::AccelerationFrame::absolute),
      absolute_(accelerations != builder::AccelerationFrame::relative),
      ground_(ground) {
  static const char* kDirection[] = {"x", "y", "rz"};
  table_.columns.push_back("time");
  for (std::size_t k = 0; k < ids.size(); ++k)
    for (std::size_t d = 0; d < equations_[k].size(); ++d) {
      const std::string name = ids[k] + ".";
      table_.columns.push_back(name + "u_" + kDirection[d]);
      table_.columns.push_back(name + "v_" + kDirection[d]);
      if (relative_) table_.columns.push_back(name + "a_rel_" + kDirection[d]);
      if (absolute_) table_.columns.push_back(name + "a_abs_" + kDirection[d]);
    }
  table_.values.resize(table_.columns.size());
}

void NodeRecorder::record(const integrators::State& state) {
  std::size_t column = 0;
  table_.values[column++].push_back(state.time);
  for (std::size_t k = 0; k < equations_.size(); ++k)
    for (std::size_t d = 0; d < equations_[k].size(); ++d) {
      const Index equation = equations_[k][d];
      const bool free = equation >= 0;
      table_.values[column++].push_back(free ? state.displacement[equation] : 0.0);
      table_.values[column++].push_back(free ? state.velocity[equation] : 0.0);
      if (relative_) table_.values[column++].push_back(free ? state.acceleration[equation] : 0.0);
      if (absolute_)
        table_.values[column++].push_back(
            ground_.absolute(state, equation, nodes_[k], static_cast<int>(d)));
    }
}

void LinkSummaries::record(const integrators::State& state) {
  for (std::size_t k = 0; k < summaries_.size(); ++k) {
    LinkSummary& s = summaries_[k];
    const Index link = rows_[k];
    const double force = state.link_force[link];
    const double penetration = state.link_penetration[link];
    const bool contact = force != 0.0;
    if (started_) {
      const double previous_force = previous_.link_force[link];
      const double dt = state.time - previous_.time;
      s.impulse += 0.5 * (force + previous_force) * dt;
      s.work += 0.5 * (force + previous_force) * (penetration - previous_.link_penetration[link]);
      if (contact && previous_force == 0.0) ++s.impacts;
    } else if (contact) {
      ++s.impacts;
    }
    if (contact) {
      if (s.first_contact < 0.0) s.first_contact = state.time;
      s.last_contact = state.time;
    }
    s.peak_force = std::max(s.peak_force, force);
    s.peak_tension = std::max(s.peak_tension, -force);
    s.peak_penetration = std::max(s.peak_penetration, penetration);
    s.peak_opening = std::max(s.peak_opening, -penetration);
    s.final_force = force;
    s.final_deformation = penetration;
  }
  previous_.time = state.time;
  previous_.link_force = state.link_force;
  previous_.link_penetration = state.link_penetration;
  started_ = true;
}

}  // namespace pound::results
