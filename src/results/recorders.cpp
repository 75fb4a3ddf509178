#include "results/recorders.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "model/direction.hpp"

namespace pound::results {

std::vector<std::string> unit_names(const UnitNames& units,
                                    const std::vector<Dimension>& dimensions) {
  std::vector<std::string> names;
  for (Dimension dimension : dimensions) names.push_back(units.of(dimension));
  return names;
}

LinkQuantities::LinkQuantities(std::vector<LinkRows> links, const std::vector<std::string>& ids)
    : links_(std::move(links)) {
  for (std::size_t k = 0; k < ids.size(); ++k) {
    add(ids[k] + ".force", Dimension::force);
    add(ids[k] + ".penetration", Dimension::length);
    const Index tangents = links_[k].tangents;
    for (Index t = 1; t <= tangents; ++t) {
      const std::string along = tangents == 1 ? "" : fmt::format("_{}", t);
      add(ids[k] + ".tangential_force" + along, Dimension::force);
      add(ids[k] + ".slide" + along, Dimension::length);
    }
  }
}

void LinkQuantities::take(const integrators::State& state, double* values) const {
  for (const LinkRows& link : links_) {
    for (Index r = link.row; r <= link.row + link.tangents; ++r) {
      *values++ = state.link_force[r];
      *values++ = state.link_penetration[r];
    }
  }
}

NodeQuantities::NodeQuantities(std::vector<std::vector<DofReading>> readings,
                               std::vector<std::vector<int>> directions, int dimension,
                               std::vector<Index> nodes, const std::vector<std::string>& ids,
                               builder::AccelerationFrame accelerations, GroundAcceleration& ground)
    : readings_(std::move(readings)),
      nodes_(std::move(nodes)),
      relative_(accelerations != builder::AccelerationFrame::absolute),
      absolute_(accelerations != builder::AccelerationFrame::relative),
      ground_(ground),
      directions_(std::move(directions)) {
  for (std::size_t k = 0; k < ids.size(); ++k)
    for (std::size_t i = 0; i < readings_[k].size(); ++i) {
      const std::string name = ids[k] + ".";
      const model::Direction along = model::direction(directions_[k].at(i), dimension);
      const std::string direction = along.symbol;
      const bool rotation = along.rotation;
      add(name + "u_" + direction, rotation ? Dimension::angle : Dimension::length);
      add(name + "v_" + direction, rotation ? Dimension::angular_velocity : Dimension::velocity);
      const Dimension acceleration =
          rotation ? Dimension::angular_acceleration : Dimension::acceleration;
      if (relative_) add(name + "a_rel_" + direction, acceleration);
      if (absolute_) add(name + "a_abs_" + direction, acceleration);
    }
}

void NodeQuantities::take(const integrators::State& state, double* values) const {
  for (std::size_t k = 0; k < readings_.size(); ++k)
    for (std::size_t i = 0; i < readings_[k].size(); ++i) {
      const DofReading& reading = readings_[k][i];
      *values++ = model::value_of(reading, state.displacement);
      *values++ = model::value_of(reading, state.velocity);
      if (relative_) *values++ = model::value_of(reading, state.acceleration);
      if (absolute_) *values++ = ground_.absolute(state, reading, nodes_[k], directions_[k][i]);
    }
}

ElementQuantities::ElementQuantities(std::vector<std::shared_ptr<const model::Element>> elements,
                                     std::vector<std::vector<DofReading>> readings)
    : elements_(std::move(elements)) {
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    for (const model::EndForce& force : elements_[k]->end_force_names())
      add(elements_[k]->id() + "." + std::string(force.name), force.dimension);
    force_counts_.push_back(elements_[k]->end_force_names().size());
    TermSums& dofs = dofs_.emplace_back();
    for (const DofReading& reading : readings[k]) dofs.add(reading);
    displacements_.emplace_back(static_cast<Index>(dofs.size()));
  }
}

void ElementQuantities::take(const integrators::State& state, double* values) const {
  for (std::size_t k = 0; k < elements_.size(); ++k) {
    dofs_[k].evaluate(state.displacement, displacements_[k].data());
    elements_[k]->write_end_forces(displacements_[k], values);
    values += force_counts_[k];
  }
}

HistoryRecorder::HistoryRecorder(std::string file, std::unique_ptr<Quantities> quantities,
                                 builder::OutputSampling sampling, const UnitNames& units)
    : file_(std::move(file)),
      quantities_(std::move(quantities)),
      sampling_(sampling),
      row_(quantities_->names().size()) {
  table_.columns.push_back("time");
  for (const std::string& name : quantities_->names()) table_.columns.push_back(name);
  table_.values.resize(table_.columns.size());
  table_.units.push_back(units.of(Dimension::time));
  for (std::string& unit : unit_names(units, quantities_->dimensions()))
    table_.units.push_back(std::move(unit));
}

bool HistoryRecorder::due(double time) {
  const long step = step_++;
  if (sampling_.interval <= 0.0) return step % sampling_.every == 0;
  // Times are k dt rounded: a step a rounding error short of the multiple is on it.
  const double interval = sampling_.interval;
  if (step > 0 && time < next_time_ - 1e-9 * interval) return false;
  next_time_ = interval * (std::floor(time / interval + 1e-9) + 1.0);
  return true;
}

void HistoryRecorder::record(const integrators::State& state) {
  if (!due(state.time)) return;
  quantities_->take(state, row_.data());
  table_.values[0].push_back(state.time);
  for (std::size_t c = 0; c < row_.size(); ++c) table_.values[c + 1].push_back(row_[c]);
}

double HistoryRecorder::held_values(double steps, double duration) const {
  const double rows = sampling_.interval > 0.0
                          ? std::min(steps, std::floor(duration / sampling_.interval) + 1.0)
                          : std::ceil(steps / sampling_.every);
  return rows * static_cast<double>(table_.columns.size());
}

EnvelopeRecorder::EnvelopeRecorder(std::string file, std::unique_ptr<Quantities> quantities,
                                   const UnitNames& units)
    : file_(std::move(file)), quantities_(std::move(quantities)), units_(units) {
  const std::size_t count = quantities_->names().size();
  row_.resize(count);
  max_.resize(count);
  min_.resize(count);
  time_of_max_.resize(count);
  time_of_min_.resize(count);
}

void EnvelopeRecorder::record(const integrators::State& state) {
  quantities_->take(state, row_.data());
  for (std::size_t q = 0; q < row_.size(); ++q) {
    if (!started_ || row_[q] > max_[q]) {
      max_[q] = row_[q];
      time_of_max_[q] = state.time;
    }
    if (!started_ || row_[q] < min_[q]) {
      min_[q] = row_[q];
      time_of_min_[q] = state.time;
    }
  }
  started_ = true;
}

Table EnvelopeRecorder::table() const {
  Table table = table_with_columns({"max", "time_of_max", "min", "time_of_min", "abs_max"});
  const std::string& time = units_.of(Dimension::time);
  table.units = {"", time, "", time, ""};  // the values' units differ by row: column "unit"
  table.text_columns = {{"quantity", quantities_->names()},
                        {"unit", unit_names(units_, quantities_->dimensions())}};
  for (std::size_t q = 0; q < row_.size(); ++q)
    append_row(table, {max_[q], time_of_max_[q], min_[q], time_of_min_[q], abs_max(q)});
  return table;
}

void LinkSummaries::set_step_forces(const std::vector<char>& by_row) {
  for (std::size_t k = 0; k < rows_.size(); ++k)
    step_forces_[k] = by_row[static_cast<std::size_t>(rows_[k])];
}

LinkSummaries::LinkSummaries(std::vector<Index> normal_rows,
                             const std::vector<ShearRows>& shear_rows)
    : rows_(std::move(normal_rows)),
      shear_rows_(shear_rows),
      summaries_(rows_.size()),
      step_forces_(rows_.size(), 0) {
  shear_rows_.resize(rows_.size());
  for (std::size_t k = 0; k < rows_.size(); ++k)
    if (shear_rows_[k].count > 0) summaries_[k].shear = ShearSummary{};
}

double LinkSummaries::resultant(const Vector& values, std::size_t k) const {
  return values.segment(rows_[k] + 1, shear_rows_[k].count).norm();
}

void LinkSummaries::record_shear(const integrators::State& state, std::size_t k) {
  ShearSummary& s = *summaries_[k].shear;
  const ShearRows& rows = shear_rows_[k];
  const Index first = rows_[k] + 1, count = rows.count;
  if (started_)
    s.work +=
        0.5 * (state.link_force.segment(first, count) + previous_.link_force.segment(first, count))
                  .dot(state.link_penetration.segment(first, count) -
                       previous_.link_penetration.segment(first, count));
  s.final_force = resultant(state.link_force, k);
  s.final_deformation = resultant(state.link_penetration, k);
  s.peak_force = std::max(s.peak_force, s.final_force);
  s.peak_deformation = std::max(s.peak_deformation, s.final_deformation);
  double ductility = 0.0;
  for (Index a = 0; a < count; ++a) {
    const auto along = static_cast<std::size_t>(a);
    const double deformation = state.link_penetration[first + a];
    s.final_forces[along] = state.link_force[first + a];
    s.peak_deformations[along] = std::max(s.peak_deformations[along], std::abs(deformation));
    s.peak_forces[along] = std::max(s.peak_forces[along], std::abs(s.final_forces[along]));
    const double ratio = deformation / rows.yield_deformation[along];
    ductility += ratio * ratio;
  }
  s.peak_ductility = std::max(s.peak_ductility, std::sqrt(ductility));
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
      const double average = step_forces_[k] ? force : 0.5 * (force + previous_force);
      s.impulse += average * dt;
      const double work = average * (penetration - previous_.link_penetration[link]);
      s.work += work;
      s.engagement_work += work;
      if (contact && previous_force == 0.0) ++s.impacts;
      if (!contact && previous_force != 0.0) {  // an engagement ended this step
        if (!s.engaged_at_start) s.finished_created_energy += std::max(0.0, -s.engagement_work);
        s.engagement_work = 0.0;
        s.engaged_at_start = false;
      }
    } else if (contact) {
      ++s.impacts;
      s.engaged_at_start = true;
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
    if (s.shear) record_shear(state, k);
  }
  previous_.time = state.time;
  previous_.link_force = state.link_force;
  previous_.link_penetration = state.link_penetration;
  started_ = true;
}

}  // namespace pound::results
