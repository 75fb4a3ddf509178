#include "verification/error_study.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "verification/rod_impact_report.hpp"

namespace pound::verification {

std::vector<StudyResult> error_study(const ErrorStudyOptions& options) {
  std::vector<StudyResult> results;
  for (const std::string& benchmark : options.benchmarks)
    for (const integrators::IntegratorChoice& integrator : options.methods)
      for (const std::string& law : options.laws)
        for (int elements : options.elements)
          for (double courant : options.courants) {
            StudyResult r{{benchmark, integrator.label(), law, elements, courant}};
            RodImpactOptions run;
            run.pair = rod_impact_case(benchmark, elements, 1.0, law);
            run.courant = courant;
            run.integrator = integrator;
            try {
              // The metrics once; the solve timed alone over the repeats (median).
              r.metrics = run_rod_impact(run).metrics;
              RodPairSimulation simulation(run);
              RodImpactResult scratch;
              std::vector<double> times;
              for (int k = 0; k < std::max(1, options.repeats); ++k) {
                const Stopwatch stopwatch;
                simulation.solve(scratch);
                times.push_back(stopwatch.seconds());
              }
              std::nth_element(times.begin(), times.begin() + static_cast<long>(times.size() / 2),
                               times.end());
              r.metrics.run_time_s = times[times.size() / 2];
            } catch (const InputError& error) {
              r.refused = true;
              r.refusal = error.reason();
            } catch (const SolveError& error) {
              r.refused = true;
              r.refusal = error.what();
            }
            results.push_back(std::move(r));
          }
  mark_pareto_front(results);
  return results;
}

void mark_pareto_front(std::vector<StudyResult>& results) {
  for (StudyResult& r : results) {
    if (r.refused) continue;
    r.pareto = std::none_of(results.begin(), results.end(), [&r](const StudyResult& other) {
      if (&other == &r || other.refused || other.input.benchmark != r.input.benchmark) return false;
      const bool no_worse = other.metrics.force_l2_error <= r.metrics.force_l2_error &&
                            other.metrics.run_time_s <= r.metrics.run_time_s;
      const bool better = other.metrics.force_l2_error < r.metrics.force_l2_error ||
                          other.metrics.run_time_s < r.metrics.run_time_s;
      return no_worse && better;
    });
  }
}

std::string format_error_study(const std::vector<StudyResult>& results) {
  std::string text =
      fmt::format("{:<13} {:<29} {:<17} {:>5} {:>7} {:>10} {:>10} {:>10} {:>7} {:>11}  {}\n",
                  "case", "integrator", "law", "n", "Courant", "force_L2", "duration", "sep_vel",
                  "peak", "run time s", "");
  for (const StudyResult& r : results) {
    const StudyCase& c = r.input;
    if (r.refused) {
      text += fmt::format("{:<13} {:<29} {:<17} {:>5} {:>7g} refused: {}\n", c.benchmark,
                          c.integrator, c.law, c.elements, c.courant, r.refusal.substr(0, 60));
      continue;
    }
    const RodImpactMetrics& m = r.metrics;
    text += fmt::format(
        "{:<13} {:<29} {:<17} {:>5} {:>7g} {:>10.4f} {:>+10.4f} {:>+10.4f} {:>7.3f} {:>11.3e}  "
        "{}\n",
        c.benchmark, c.integrator, c.law, c.elements, c.courant, m.force_l2_error, m.duration_error,
        m.separation_velocity_error, m.peak_force_ratio, m.run_time_s, r.pareto ? "* Pareto" : "");
  }
  return text;
}

io::TextTable error_study_table(const std::vector<StudyResult>& results) {
  io::TextTable table{
      {"case", "integrator", "law", "elements", "courant", "refused", "force_l2_error",
       "duration_error", "separation_velocity_error", "peak_force_ratio", "max_penetration",
       "min_force", "run_time_s", "steps", "newton_iterations", "pareto"},
      {}};
  auto number = [](double value) { return fmt::format("{:.17g}", value); };
  for (const StudyResult& r : results) {
    const RodImpactMetrics& m = r.metrics;
    table.rows.push_back(
        {r.input.benchmark, r.input.integrator, r.input.law, std::to_string(r.input.elements),
         number(r.input.courant), r.refused ? "1" : "0", number(m.force_l2_error),
         number(m.duration_error), number(m.separation_velocity_error), number(m.peak_force_ratio),
         number(m.max_penetration), number(m.min_force), number(m.run_time_s),
         std::to_string(m.steps), std::to_string(m.newton_iterations), r.pareto ? "1" : "0"});
  }
  return table;
}

io::Document to_document(const std::vector<StudyResult>& results) {
  auto row = [](const StudyResult& r) {
    io::Document doc;
    doc.set("case", r.input.benchmark)
        .set("integrator", r.input.integrator)
        .set("law", r.input.law)
        .set("elements", r.input.elements)
        .set("courant", r.input.courant)
        .set("refused", r.refused);
    if (r.refused)
      doc.set("refusal", r.refusal);
    else
      doc.set("metrics", to_document(r.metrics)).set("pareto", r.pareto);
    return doc;
  };
  io::Document root;
  root.set("runs", io::documents(results, row));
  return root;
}

}  // namespace pound::verification
