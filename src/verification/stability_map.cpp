#include "verification/stability_map.hpp"

#include <fmt/format.h>

#include <cmath>
#include <map>

#include "core/errors.hpp"
#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::verification {

std::vector<StabilityCell> stability_map(const StabilityOptions& options) {
  std::vector<StabilityCell> cells;
  for (const integrators::IntegratorChoice& integrator : options.methods)
    for (const std::string& law : options.laws)
      for (double ratio : options.stiffness_ratios)
        for (double step : options.step_ratios) {
          StabilityCell cell{integrator.label(), law, ratio, step};
          RodImpactOptions run;
          run.pair = rod_impact_case("kawashima", options.elements, ratio, law);
          if (law == "extended_penalty") {
            // The penalty spring alpha0 = ratio E A / h; alpha2 (eq. 29) and alpha1 (eq. 34) follow
            // from it: the sweep is over Suzuki & Toi's xi.
            const double adjacent = 100.0 * 1.0 / (10.0 / options.elements);
            run.pair.law.parameters["alpha0"] = ratio * adjacent;
          }
          run.dt_ratio = step;
          run.integrator = integrator;
          try {
            const RodImpactMetrics m = run_rod_impact(run).metrics;
            cell.force_l2_error = m.force_l2_error;
            cell.duration_error = m.duration_error;
            cell.separation_velocity_error = m.separation_velocity_error;
            cell.energy_ratio = m.energy_ratio;
            const bool finite = std::isfinite(m.force_l2_error) && std::isfinite(m.energy_ratio);
            if (!finite || m.energy_ratio > 1.1) {
              cell.verdict = StabilityVerdict::unstable;
              cell.note =
                  finite ? fmt::format("energy grew to {:.3g} x", m.energy_ratio) : "not finite";
            } else if (std::abs(m.duration_error) <= 0.05 &&
                       std::abs(m.separation_velocity_error) <= 0.05 && m.force_l2_error <= 0.1) {
              cell.verdict = StabilityVerdict::accurate;
            } else {
              cell.verdict = StabilityVerdict::inaccurate;
            }
          } catch (const InputError& error) {
            cell.verdict = StabilityVerdict::refused;
            cell.note = error.reason();
          } catch (const SolveError& error) {
            cell.verdict = StabilityVerdict::unstable;
            cell.note = error.what();
          }
          cells.push_back(std::move(cell));
        }
  return cells;
}

const char* verdict_name(StabilityVerdict verdict) {
  switch (verdict) {
    case StabilityVerdict::accurate:
      return "accurate";
    case StabilityVerdict::inaccurate:
      return "inaccurate";
    case StabilityVerdict::unstable:
      return "unstable";
    case StabilityVerdict::refused:
      return "refused";
  }
  return "";
}

std::string format_stability_map(const std::vector<StabilityCell>& cells) {
  // One grid per integrator and law: rows stiffness ratio, columns dt / T.
  static const std::map<StabilityVerdict, char> symbol = {{StabilityVerdict::accurate, 'A'},
                                                          {StabilityVerdict::inaccurate, 'i'},
                                                          {StabilityVerdict::unstable, 'X'},
                                                          {StabilityVerdict::refused, 'r'}};
  std::string text =
      "A accurate, i inaccurate, X unstable (NaN/Inf or energy growth > 10 %), r refused before "
      "running\n";
  std::vector<double> steps;
  for (const StabilityCell& c : cells)
    if (std::find(steps.begin(), steps.end(), c.step_ratio) == steps.end())
      steps.push_back(c.step_ratio);
  std::string current;
  for (const StabilityCell& c : cells) {
    const std::string group = c.integrator + ", " + c.law;
    if (group != current) {
      current = group;
      text += fmt::format("\n{}\n{:>10}", group, "k / kEA\\dt/T");
      for (double s : steps) text += fmt::format(" {:>6g}", s);
      text += "\n";
    }
    if (c.step_ratio == steps.front()) text += fmt::format("{:>10g}", c.stiffness_ratio);
    text += fmt::format(" {:>6}", std::string(1, symbol.at(c.verdict)));
    if (c.step_ratio == steps.back()) text += "\n";
  }
  return text;
}

io::TextTable stability_table(const std::vector<StabilityCell>& cells) {
  io::TextTable table{
      {"integrator", "law", "stiffness_ratio", "step_ratio", "verdict", "force_l2_error",
       "duration_error", "separation_velocity_error", "energy_ratio", "note"},
      {}};
  auto number = [](double value) { return fmt::format("{:.6g}", value); };
  for (const StabilityCell& c : cells) {
    std::string note = c.note;
    std::replace(note.begin(), note.end(), ',', ';');
    table.rows.push_back({c.integrator, c.law, number(c.stiffness_ratio), number(c.step_ratio),
                          verdict_name(c.verdict), number(c.force_l2_error),
                          number(c.duration_error), number(c.separation_velocity_error),
                          number(c.energy_ratio), note});
  }
  return table;
}

}  // namespace pound::verification
