#include <fmt/format.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numbers>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "app/model_queries.hpp"
#include "app/run_report.hpp"
#include "builder/start_check.hpp"
#include "core/errors.hpp"
#include "io/document.hpp"
#include "links/extended_penalty.hpp"
#include "model/direction.hpp"
#include "verification/model_check.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kCheckUsage = R"(usage: pound check MODEL.json [--json] [--strict]

Before a run: the model's DOFs and first periods, the stable step of explicit central difference
with the contacts open and in contact, how the run will step (its integrator, the time step and
the rule that chose it, the duration and the number of steps), and for every contact link its
stiffness against the adjacent elements (Kawashima's k-ratio), Suzuki & Toi's automatic penalty
numbers, the expected contact duration and whether the time step resolves it (Kawashima: dt <=
T_contact / 20). Every setting the benchmarks show to be meaningless is a warning. Exit code 0 (1
with --strict when there are warnings).

options)";

// The integrator as a model file names it: a preset's name, else the method with its parameters.
std::string integrator_words(const integrators::IntegratorChoice& integrator) {
  const std::string label = integrator.label();
  std::string parameters;
  if (label == integrator.method().name)
    for (const auto& [name, value] : integrator.values())
      parameters += fmt::format("{}{} {:g}", parameters.empty() ? "" : ", ", name, value);
  return parameters.empty() ? label : fmt::format("{} ({})", label, parameters);
}

// How the run will step: its integrator, the step and the rule that chose it, the duration and
// the number of steps, so that a run's length is known before it starts.
std::string analysis_text(const builder::AnalysisSpec& analysis, const UnitNames& units) {
  const std::string& time = units.of(Dimension::time);
  const std::string step = with_unit(analysis.time_step, time);
  const std::string rule = analysis.time_step_rule();
  std::string how;
  if (rule == "adaptive")
    how = fmt::format("adaptive time steps from {} at first, between {} and {} (tolerance {:g})",
                      step, with_unit(analysis.shortest_step(), time),
                      with_unit(analysis.longest_step(), time), analysis.adaptive->tolerance);
  else if (rule == "given")
    how = "time step " + step;
  else {
    const std::string chosen = automatic_step_words(analysis.time_step_defaulted);
    if (!analysis.stable_time_step)  // nothing vibrates: the record's step alone
      how = fmt::format("time step {}, the record's step, with no stable limit ({})", step, chosen);
    else
      how =
          fmt::format("time step {}{}{:g} x the stable step {} ({})", step,
                      rule == "auto_record_step" ? ", the record's step, below " : ", ",
                      analysis.safety_factor, with_unit(*analysis.stable_time_step, time), chosen);
  }
  const double fewest = analysis.fewest_steps(), most = analysis.most_steps();
  return fmt::format("  analysis: {}, {}, over {}{}: {}\n", integrator_words(analysis.integrator),
                     how, with_unit(analysis.duration, time),
                     analysis.duration_from_records ? " (the records' length)" : "",
                     fewest == most ? fmt::format("{:.15g} steps", fewest)
                                    : fmt::format("{:.15g} to {:.15g} steps", fewest, most));
}

// The findings as text: the model, its periods and stable steps, how the run will step, a line
// per contact link.
std::string check_text(const std::string& model_path, const verification::ModelCheck& check,
                       const builder::AnalysisSpec& analysis, const UnitNames& units) {
  std::string directions;
  for (int d = 0; d < model::direction_count(check.dimension); ++d)
    if (const Index count = check.dofs_by_direction[static_cast<std::size_t>(d)]; count > 0)
      directions += fmt::format("{}{} {}", directions.empty() ? "" : ", ", count,
                                model::direction(d, check.dimension).words);
  if (check.tied_dofs > 0)
    directions += fmt::format("; {} more tied by constraints", check.tied_dofs);
  std::string text = fmt::format("{}: {} DOFs ({}), {} links\n", model_path, check.dofs,
                                 directions.empty() ? "none free" : directions, check.links);
  const std::string& time = units.of(Dimension::time);
  if (!check.periods.empty()) {
    text += "  periods:";
    for (double t : check.periods) text += fmt::format(" {:.4g}", t);
    text += time.empty() ? "\n" : " " + time + "\n";
  }
  if (check.explicit_step_contact)
    text += fmt::format(
        "  central difference stable step: {} with contacts open, {} in contact{}{}\n",
        with_unit(*check.explicit_step_open, time), with_unit(*check.explicit_step_contact, time),
        check.hertz_at_peak ? " (the Hertz-type contacts at their peak penetration in an impact "
                              "at their approach velocity below)"
                            : "",
        check.hertz_without_stiffness
            ? ", without the stiffness of the Hertz-type contacts that have no approach velocity "
              "to estimate it at"
            : "");
  else
    text += fmt::format("  central difference: not available ({})\n", check.explicit_unavailable);
  if (check.implicit_stable_step) {
    // A Hertz-type law's stiffness grows from 0 as it penetrates: at first touch it adds none.
    const bool stiffening =
        std::any_of(check.contacts.begin(), check.contacts.end(),
                    [](const verification::LinkCheck& c) { return !c.stiff_at_first_touch; });
    text += fmt::format("  {} stable step: {} in contact{} (above it the run is refused)\n",
                        analysis.integrator.label(), with_unit(*check.implicit_stable_step, time),
                        stiffening ? ", without the Hertz-type contacts' stiffness, which grows "
                                     "as they penetrate"
                                   : "");
  }
  text += analysis_text(analysis, units);
  for (const verification::LinkCheck& c : check.contacts) {
    text += c.constraint ? fmt::format("  link {} ({}): a constraint, no stiffness", c.id, c.law)
            : c.stiff_at_first_touch
                ? fmt::format("  link {} ({}): stiffness {:.4g}", c.id, c.law, c.stiffness)
                : fmt::format("  link {} ({}): stiffness grows with penetration", c.id, c.law);
    if (c.adjacent > 0.0 && c.stiff_at_first_touch)
      text +=
          fmt::format(", k-ratio {:.3g} (adjacent {:.4g})", c.stiffness / c.adjacent, c.adjacent);
    if (c.used) {
      // The law's own numbers; the automatic ones beside them where the model gave others.
      const auto numbers = [](const links::ExtendedPenalty::Numbers& n) {
        return fmt::format("alpha0 {:.4g}, alpha1 {:.4g}, alpha2 {:.4g}", n.alpha0, n.alpha1,
                           n.alpha2);
      };
      // Alike as printed: the law's own automatic numbers come from its context in another order
      // of operations and may differ in the last bits.
      const bool automatic = c.automatic && numbers(*c.automatic) == numbers(*c.used);
      text +=
          fmt::format("; extended penalty {}{}", numbers(*c.used),
                      automatic     ? " (the automatic numbers)"
                      : c.automatic ? fmt::format(" (automatic would be {})", numbers(*c.automatic))
                                    : "");
    } else if (c.automatic && c.law == "extended_penalty") {
      text +=
          fmt::format("; automatic extended penalty alpha0 {:.4g}, alpha1 {:.4g}, alpha2 {:.4g}",
                      c.automatic->alpha0, c.automatic->alpha1, c.automatic->alpha2);
    }
    if (c.contact_duration > 0.0)
      text += fmt::format("; contact lasts ~{}", with_unit(c.contact_duration, time));
    else if (!c.no_duration.empty())
      text += "; no contact duration claimed: " + c.no_duration;
    if (c.approach_velocity > 0.0)
      text += fmt::format(" at an approach velocity of {}",
                          with_unit(c.approach_velocity, units.of(Dimension::velocity), 3));
    text += "\n";
  }
  for (const std::string& w : check.warnings) text += "warning: " + w + "\n";
  if (check.warnings.empty()) text += "no warnings\n";
  return text;
}

// The analysis_text's facts: "time_step_rule" as summary.json has it; "steps" a fixed step's count,
// or "steps_at_least" and "steps_at_most" of an adaptive run; what does not apply is left out.
io::Document analysis_document(const builder::AnalysisSpec& analysis) {
  io::Document doc;
  doc.set("integrator", analysis.integrator.label());
  io::Document parameters;
  for (const auto& [name, value] : analysis.integrator.values()) parameters.set(name, value);
  doc.set("integrator_parameters", parameters)
      .set("time_step", analysis.time_step)
      .set("time_step_rule", analysis.time_step_rule());
  if (analysis.time_step_defaulted) doc.set("time_step_defaulted", true);
  if (analysis.time_step_auto) doc.set("safety_factor", analysis.safety_factor);
  if (analysis.time_step_auto && analysis.stable_time_step)
    doc.set("stable_time_step", *analysis.stable_time_step);
  if (analysis.adaptive)
    doc.set("adaptive_tolerance", analysis.adaptive->tolerance)
        .set("adaptive_min_time_step", analysis.shortest_step())
        .set("adaptive_max_time_step", analysis.longest_step());
  doc.set("duration", analysis.duration)
      .set("duration_from_records", analysis.duration_from_records);
  // Whole numbers as such, up to where a double holds every one.
  const auto set_count = [&doc](const char* key, double count) {
    if (count <= 1e15)
      doc.set(key, static_cast<long>(count));
    else
      doc.set(key, count);
  };
  if (analysis.adaptive) {
    set_count("steps_at_least", analysis.fewest_steps());
    set_count("steps_at_most", analysis.most_steps());
  } else {
    set_count("steps", analysis.step_count());
  }
  if (analysis.max_steps > 0) doc.set("max_steps", analysis.max_steps);
  return doc;
}

io::Document check_document(const std::string& model_path, const verification::ModelCheck& check,
                            const builder::AnalysisSpec& analysis) {
  io::Document doc;
  doc.set("model", model_path)
      .set("dofs", static_cast<long>(check.dofs))
      .set("dofs_per_node", check.dofs_per_node);
  // Per direction: dofs_x, dofs_y, dofs_rotation in a plane; dofs_x ... dofs_rz in 3-D.
  for (int d = 0; d < model::direction_count(check.dimension); ++d) {
    const model::Direction along = model::direction(d, check.dimension);
    doc.set(check.dimension != 3 && along.rotation ? std::string("dofs_rotation")
                                                   : fmt::format("dofs_{}", along.symbol),
            static_cast<long>(check.dofs_by_direction[static_cast<std::size_t>(d)]));
  }
  if (check.tied_dofs > 0) doc.set("tied_dofs", static_cast<long>(check.tied_dofs));
  doc.set("periods", check.periods);
  // An unbounded stable step (nothing vibrates) is null: "no limit".
  auto set_step = [&doc](const char* key, double step) {
    if (std::isinf(step) && step > 0.0)
      doc.set_null(key);
    else
      doc.set(key, step);
  };
  if (check.explicit_step_contact) {
    set_step("explicit_stable_step_open", *check.explicit_step_open);
    set_step("explicit_stable_step_contact", *check.explicit_step_contact);
  }
  if (check.implicit_stable_step) set_step("implicit_stable_step", *check.implicit_stable_step);
  std::vector<io::Document> link_documents;
  // What does not apply to a link is null, not 0: a Hertz-type law's stiffness at first touch,
  // the adjacent stiffness of bare masses, a duration not claimed, the extended penalty's numbers
  // of any other law.
  auto set_positive = [](io::Document& link, const char* key, double value) {
    if (value > 0.0)
      link.set(key, value);
    else
      link.set_null(key);
  };
  for (const verification::LinkCheck& c : check.contacts) {
    io::Document link;
    link.set("id", c.id).set("law", c.law);
    set_positive(link, "stiffness", c.stiff_at_first_touch ? c.stiffness : 0.0);
    set_positive(link, "adjacent_stiffness", c.adjacent);
    set_positive(link, "contact_duration", c.contact_duration);
    set_positive(link, "approach_velocity", c.approach_velocity);
    const bool extended = c.automatic && c.law == "extended_penalty";
    set_positive(link, "automatic_alpha0", extended ? c.automatic->alpha0 : 0.0);
    set_positive(link, "automatic_alpha1", extended ? c.automatic->alpha1 : 0.0);
    set_positive(link, "automatic_alpha2", extended ? c.automatic->alpha2 : 0.0);
    link_documents.push_back(std::move(link));
  }
  doc.set("analysis", analysis_document(analysis));
  doc.set("links", link_documents);
  doc.set("warnings", io::warning_documents(check.warnings));
  return doc;
}

// The model's JSON path behind a pointer into the check document: the link's own entry (or its
// generator's) for "/links/N/...".
std::string model_path_of(const std::string& pointer, const verification::ModelCheck& check,
                          const builder::BuiltModel& built) {
  if (pointer.starts_with("/analysis/")) return "/analysis";
  unsigned index = 0;
  if (std::sscanf(pointer.c_str(), "/links/%u", &index) == 1 && index < check.contacts.size())
    if (auto found = built.link_index.find(check.contacts[index].id);
        found != built.link_index.end())
      return built.link_origins[static_cast<std::size_t>(found->second)];
  return "";
}

}  // namespace

ModelFindings check_findings(const LoadedModel& loaded, const std::string& model_path) {
  std::unique_ptr<assembly::StructuralSystem> system;
  try {
    system = std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
  // The step settled first, as a run does: "auto" is checked as the step it takes.
  builder::AnalysisSpec analysis = loaded.built.analysis;
  builder::settle_time_step(analysis, loaded.built.model, *system, model_path);
  verification::ModelCheck check = verification::check_model(loaded.built, analysis, *system, true);
  // After the diagnostics: the first step leaves the laws committed at the start, as a run does.
  builder::check_first_step(loaded.built, analysis, *system, model_path);
  io::Document document = check_document(model_path, check, analysis);
  document.set("units", units_document(loaded.spec.units));
  if (!document.non_finite().empty())
    throw InputError(model_path, model_path_of(document.non_finite().front(), check, loaded.built),
                     fmt::format("the model's numbers overflow: its check finds {} not finite (a "
                                 "mass, stiffness or load far beyond physical ones?)",
                                 document.non_finite().front()));
  return {std::move(check), std::move(document), analysis, loaded.built.units};
}

int check_command(const Arguments& arguments) {
  po::options_description options(kCheckUsage);
  std::string model_path;
  options.add_options()("help,h", "show this help")(
      "json", "print the findings as one JSON object")("strict", "exit 1 when there are warnings");
  const auto parsed = parse_command_line(arguments, options, "model", model_path);
  if (!parsed) return 0;
  const po::variables_map& vm = *parsed;
  if (model_path.empty()) {
    std::cerr << "pound check: name a model file (see `pound check --help`)\n";
    return 1;
  }
  const ModelFindings findings = check_findings(load_model(model_path), model_path);
  std::cout << (vm.count("json")
                    ? findings.document.dump() + "\n"
                    : check_text(model_path, findings.check, findings.analysis, findings.units));
  return vm.count("strict") && !findings.check.warnings.empty() ? 1 : 0;
}

}  // namespace pound::app
