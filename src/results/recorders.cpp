#include "results/recorders.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

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
    const bool rotational = links_[k].rotational;
    add(ids[k] + ".force", rotational ? Dimension::moment : Dimension::force);
    add(ids[k] + ".penetration", rotational ? Dimension::angle : Dimension::length);
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

namespace {
// Row `force` of `map` (end forces x the element's DOFs) over the equations: each DOF's readings
// weighted by the row's entry, the terms on one equation added, in the equations' order.
std::vector<model::DofTerm> end_force_terms(const Matrix& map, std::size_t force,
                                            const std::vector<DofReading>& readings) {
  std::map<Index, double> by_equation;
  for (std::size_t j = 0; j < readings.size(); ++j) {
    const double entry = map(static_cast<Index>(force), static_cast<Index>(j));
    if (entry == 0.0) continue;
    for (const model::DofTerm& term : readings[j])
      by_equation[term.equation] += entry * term.coefficient;
  }
  std::vector<model::DofTerm> terms;
  for (const auto& [equation, coefficient] : by_equation)
    if (coefficient != 0.0) terms.push_back({equation, coefficient});
  return terms;
}
}  // namespace

ElementQuantities::ElementQuantities(std::vector<std::shared_ptr<const model::Element>> elements,
                                     std::vector<std::vector<DofReading>> readings,
                                     std::vector<std::vector<std::size_t>> wanted) {
  for (std::size_t k = 0; k < elements.size(); ++k) {
    const model::Element& element = *elements[k];
    const std::span<const model::EndForce> names = element.end_force_names();
    std::vector<std::size_t> all(names.size());
    std::iota(all.begin(), all.end(), std::size_t{0});
    const std::vector<std::size_t>& taken = wanted.empty() ? all : wanted[k];
    const Matrix map = model::end_force_map(element);
    for (const std::size_t s : taken) {
      add(element.id() + "." + std::string(names[s].name), names[s].dimension);
      forces_.add(end_force_terms(map, s, readings[k]));
    }
  }
}

void ElementQuantities::take(const integrators::State& state, double* values) const {
  forces_.evaluate(support_ ? support_->total(state) : state.displacement, values);
  // A sum of products that are all -0 (negative entries on zero displacements) is -0; the
  // elements sum theirs from +0, which x + 0 gives without changing any other value.
  for (std::size_t s = 0; s < forces_.size(); ++s) values[s] += 0.0;
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

// The rows kept after `steps` steps over `duration`.
double HistoryRecorder::rows_after(double steps, double duration) const {
  return sampling_.interval > 0.0 ? std::min(steps, std::floor(duration / sampling_.interval) + 1.0)
                                  : std::ceil(steps / sampling_.every);
}

double HistoryRecorder::held_values(double steps, double duration) const {
  return rows_after(steps, duration) * static_cast<double>(table_.columns.size());
}

// At most 2^26 values (512 MiB) ahead: the memory check has passed the whole, but a run may stop
// early, and an adaptive step may take fewer steps than the first step's size says.
void HistoryRecorder::reserve(double steps, double duration) {
  constexpr double kMostReserved = 67108864.0;
  const double columns = static_cast<double>(table_.columns.size());
  const double rows = std::min(rows_after(steps, duration), kMostReserved / columns);
  if (!(rows > 0.0)) return;
  for (std::vector<double>& column : table_.values) column.reserve(static_cast<std::size_t>(rows));
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
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    if (shear_rows_[k].count == 0) continue;
    summaries_[k].shear = ShearSummary{};
    any_shear_ = true;
  }
  const std::size_t count = rows_.size();
  for (std::vector<double>* column :
       {&running_.force, &running_.penetration, &running_.previous_force,
        &running_.previous_penetration, &running_.peak_force, &running_.peak_tension,
        &running_.peak_penetration, &running_.peak_opening, &running_.impulse, &running_.work,
        &running_.engagement_work})
    column->assign(count, 0.0);
  running_.last_contact.assign(count, -1.0);
}

const std::vector<LinkSummary>& LinkSummaries::summaries() const {
  const Running& r = running_;
  for (std::size_t k = 0; k < summaries_.size(); ++k) {
    LinkSummary& s = summaries_[k];
    s.peak_force = r.peak_force[k];
    s.peak_tension = r.peak_tension[k];
    s.peak_penetration = r.peak_penetration[k];
    s.peak_opening = r.peak_opening[k];
    s.impulse = r.impulse[k];
    s.work = r.work[k];
    s.engagement_work = r.engagement_work[k];
    s.last_contact = r.last_contact[k];
    s.final_force = r.force[k];
    s.final_deformation = r.penetration[k];
  }
  return summaries_;
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
    s.final_deformations[along] = deformation;
    s.peak_deformations[along] = std::max(s.peak_deformations[along], std::abs(deformation));
    s.peak_forces[along] = std::max(s.peak_forces[along], std::abs(s.final_forces[along]));
    const double ratio = deformation / rows.yield_deformation[along];
    ductility += ratio * ratio;
  }
  s.peak_ductility = std::max(s.peak_ductility, std::sqrt(ductility));
}

namespace {

// Element by element, without branches (both averages formed, one kept), the arrays unaliased
// (as parameters, so GCC knows it): the loops vectorise. The impulse and work by the trapezoidal
// rule, or the rectangle rule for a step force.
void add_step_work(std::size_t count, double dt, const double* __restrict__ force,
                   const double* __restrict__ previous_force, const char* __restrict__ step_force,
                   const double* __restrict__ penetration,
                   const double* __restrict__ previous_penetration, double* __restrict__ impulse,
                   double* __restrict__ work, double* __restrict__ engagement_work) {
  for (std::size_t k = 0; k < count; ++k) {
    const double trapezoid = 0.5 * (force[k] + previous_force[k]);
    const double average = step_force[k] ? force[k] : trapezoid;
    impulse[k] += average * dt;
    const double step_work = average * (penetration[k] - previous_penetration[k]);
    work[k] += step_work;
    engagement_work[k] += step_work;
  }
}

void raise_peaks(std::size_t count, double time, const double* __restrict__ force,
                 const double* __restrict__ penetration, double* __restrict__ last_contact,
                 double* __restrict__ peak_force, double* __restrict__ peak_tension,
                 double* __restrict__ peak_penetration, double* __restrict__ peak_opening) {
  for (std::size_t k = 0; k < count; ++k) {
    last_contact[k] = force[k] != 0.0 ? time : last_contact[k];
    peak_force[k] = std::max(peak_force[k], force[k]);
    peak_tension[k] = std::max(peak_tension[k], -force[k]);
    peak_penetration[k] = std::max(peak_penetration[k], penetration[k]);
    peak_opening[k] = std::max(peak_opening[k], -penetration[k]);
  }
}

// Whether any link's force went from 0 to not 0 or back: one vectorised pass, so the steps
// without such an event (nearly all) skip the loop with its branches.
bool any_engagement_changed(std::size_t count, const double* __restrict__ force,
                            const double* __restrict__ previous_force) {
  int changed = 0;
  for (std::size_t k = 0; k < count; ++k)
    changed |= static_cast<int>(force[k] != 0.0) ^ static_cast<int>(previous_force[k] != 0.0);
  return changed != 0;
}

}  // namespace

void LinkSummaries::record_engagements(double time) {
  Running& r = running_;
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    const bool contact = r.force[k] != 0.0;
    const bool was_in_contact = started_ && r.previous_force[k] != 0.0;
    if (contact == was_in_contact) continue;
    LinkSummary& s = summaries_[k];
    if (contact) {
      ++s.impacts;
      if (!started_) s.engaged_at_start = true;
      if (s.first_contact < 0.0) s.first_contact = time;
    } else {  // an engagement ended this step
      if (!s.engaged_at_start) s.finished_created_energy += std::max(0.0, -r.engagement_work[k]);
      r.engagement_work[k] = 0.0;
      s.engaged_at_start = false;
    }
  }
}

void LinkSummaries::add_work(const Vector& by_row) {
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    running_.work[k] += by_row[rows_[k]];
    running_.engagement_work[k] += by_row[rows_[k]];
    if (summaries_[k].shear)
      summaries_[k].shear->work += by_row.segment(rows_[k] + 1, shear_rows_[k].count).sum();
  }
}

void LinkSummaries::record_initial_forces(const integrators::State& state) {
  // Moving, a link's force may hold a dashpot's part, which stores nothing; at rest it is all the
  // law's own (a preload, or a static state's yield).
  if (!state.velocity.isZero(0.0)) return;
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    summaries_[k].initial_force = state.link_force[rows_[k]];
    summaries_[k].initial_deformation = state.link_penetration[rows_[k]];
    if (summaries_[k].shear)
      for (Index a = 0; a < shear_rows_[k].count; ++a) {
        summaries_[k].shear->initial_forces[static_cast<std::size_t>(a)] =
            state.link_force[rows_[k] + 1 + a];
        summaries_[k].shear->initial_deformations[static_cast<std::size_t>(a)] =
            state.link_penetration[rows_[k] + 1 + a];
      }
  }
}

void LinkSummaries::record(const integrators::State& state) {
  Running& r = running_;
  const std::size_t count = rows_.size();
  r.force.swap(r.previous_force);
  r.penetration.swap(r.previous_penetration);
  for (std::size_t k = 0; k < count; ++k) {
    r.force[k] = state.link_force[rows_[k]];
    r.penetration[k] = state.link_penetration[rows_[k]];
  }
  if (started_)
    add_step_work(count, state.time - previous_time_, r.force.data(), r.previous_force.data(),
                  step_forces_.data(), r.penetration.data(), r.previous_penetration.data(),
                  r.impulse.data(), r.work.data(), r.engagement_work.data());
  if (!started_ || any_engagement_changed(count, r.force.data(), r.previous_force.data()))
    record_engagements(state.time);
  if (!started_) record_initial_forces(state);
  raise_peaks(count, state.time, r.force.data(), r.penetration.data(), r.last_contact.data(),
              r.peak_force.data(), r.peak_tension.data(), r.peak_penetration.data(),
              r.peak_opening.data());
  if (any_shear_) {
    for (std::size_t k = 0; k < count; ++k)
      if (summaries_[k].shear) record_shear(state, k);
    previous_.link_force = state.link_force;
    previous_.link_penetration = state.link_penetration;
  }
  previous_time_ = state.time;
  started_ = true;
}

}  // namespace pound::results
