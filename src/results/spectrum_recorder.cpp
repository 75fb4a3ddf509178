#include "results/spectrum_recorder.hpp"

#include <fmt/format.h>

namespace pound::results {

SpectrumRecorder::SpectrumRecorder(std::string file, std::vector<SpectrumPlace> places,
                                   std::vector<double> periods, std::vector<double> damping_ratios,
                                   GroundAcceleration& ground, const UnitNames& units)
    : file_(std::move(file)),
      places_(std::move(places)),
      periods_(std::move(periods)),
      damping_ratios_(std::move(damping_ratios)),
      ground_(ground),
      units_(units),
      previous_(places_.size()) {
  for (std::size_t p = 0; p < places_.size(); ++p)
    for (double damping : damping_ratios_)
      for (double period : periods_) oscillators_.emplace_back(period, damping);
}

void SpectrumRecorder::record(const integrators::State& state) {
  const double dt = state.time - previous_time_;
  const std::size_t per_place = periods_.size() * damping_ratios_.size();
  for (std::size_t p = 0; p < places_.size(); ++p) {
    const SpectrumPlace& place = places_[p];
    const double acceleration = ground_.absolute(state, place.reading, place.node, place.direction);
    if (started_ && dt > 0.0)
      for (std::size_t k = p * per_place; k < (p + 1) * per_place; ++k)
        oscillators_[k].advance(previous_[p], acceleration, dt);
    previous_[p] = acceleration;
  }
  previous_time_ = state.time;
  started_ = true;
}

Table SpectrumRecorder::table() const {
  Table table = table_with_columns({"period"});
  table.values[0] = periods_;
  table.units.push_back(units_.of(Dimension::time));
  std::size_t k = 0;
  for (const SpectrumPlace& place : places_)
    for (double damping : damping_ratios_) {
      table.columns.push_back(
          fmt::format("{}.sa_{}_{:g}%", place.id, place.symbol, 100.0 * damping));
      table.units.push_back(units_.of(Dimension::acceleration));
      std::vector<double>& column = table.values.emplace_back();
      for (std::size_t p = 0; p < periods_.size(); ++p)
        column.push_back(oscillators_[k++].pseudo_acceleration());
    }
  return table;
}

}  // namespace pound::results
