#include <fmt/format.h>

#include <boost/program_options.hpp>
#include <cmath>
#include <iostream>
#include <numbers>

#include "app/command_line.hpp"
#include "app/commands.hpp"
#include "app/model_loading.hpp"
#include "assembly/modal_analysis.hpp"
#include "core/errors.hpp"
#include "integrators/central_difference.hpp"
#include "io/document.hpp"
#include "links/extended_penalty.hpp"

namespace pound::app {
namespace po = boost::program_options;

namespace {

constexpr const char* kCheckUsage = R"(usage: pound check MODEL.json [--json]

Before a run: the model's DOFs and first periods, the stable step of explicit central difference
with the contacts open and in contact, and for every contact link its stiffness against the
adjacent elements (Kawashima's k-ratio), Suzuki & Toi's automatic penalty numbers, the expected
contact duration and whether the time step resolves it (Kawashima: dt <= T_contact / 20). Every
setting the benchmarks show to be meaningless is a warning. Exit code 0 (1 with --strict when
there are warnings).

options)";

struct LinkCheck {
  std::string id, law;
  double stiffness = 0.0, adjacent = 0.0, contact_duration = 0.0;
  links::ExtendedPenalty::Numbers automatic{};
};

}  // namespace

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
  LoadedModel loaded = load_model(model_path);
  std::unique_ptr<assembly::StructuralSystem> system;
  try {
    system = std::make_unique<assembly::StructuralSystem>(loaded.built.model);
  } catch (const InputError& error) {
    throw error.file().empty() ? error.in_file(model_path) : error;
  }
  const builder::AnalysisSpec& analysis = loaded.built.analysis;
  std::vector<std::string> warnings;
  std::string text =
      fmt::format("{}: {} DOFs ({} per node), {} links\n", model_path, system->size(),
                  system->dofs().dofs_per_node(), system->links().count());

  std::vector<double> periods;
  if (system->size() <= 4000) {
    periods = assembly::natural_periods(*system, 6);
    text += "  periods:";
    for (double t : periods) text += fmt::format(" {:.4g}", t);
    text += "\n";
  }
  double open_limit = 0.0, contact_limit = 0.0;
  const bool lumped = system->lumped_mass() && (system->lumped_mass()->array() > 0.0).all();
  if (lumped) {
    open_limit = integrators::stable_time_step(*system, false);
    contact_limit = integrators::stable_time_step(*system, true);
    text += fmt::format(
        "  central difference stable step: {:.4g} with contacts open, {:.4g} in contact\n",
        open_limit, contact_limit);
    if (analysis.integrator.is_explicit() && !analysis.time_step_auto &&
        analysis.time_step > contact_limit)
      warnings.push_back(
          fmt::format("time step {:.4g} is above the explicit stable limit {:.4g}: the "
                      "run will be refused",
                      analysis.time_step, contact_limit));
  } else {
    text += "  central difference: not available (a DOF has no lumped mass)\n";
  }

  // Contact links: how stiff against the adjacent elements, and how long a contact lasts.
  std::vector<LinkCheck> checks;
  const integrators::LinkSet& links = system->links();
  for (Index k = 0; k < links.count(); ++k) {
    const model::Link& link = loaded.built.model.links[static_cast<std::size_t>(k)];
    if (link.role() != links::LinkRole::contact) continue;
    const std::string law = links.law(k).name();
    const links::LawTraits traits = link.law ? link.law->traits : links::LawTraits{};
    const links::LinkContext context = system->link_context(link);
    LinkCheck c{link.id, law};
    // Hertz-type laws stiffen with penetration: no stiffness or duration before the impact.
    const bool hertzian = !traits.stiff_at_first_touch;
    const links::LawResponse touch = links.law(k).clone()->set_trial({1e-9, 1e-9, 0.0});
    if (!hertzian) c.stiffness = touch.stiffness;
    const double k_i = context.fixed_i ? 0.0 : context.stiffness_i,
                 k_j = context.fixed_j ? 0.0 : context.stiffness_j;
    c.adjacent = (k_i > 0.0 && k_j > 0.0) ? std::min(k_i, k_j) : std::max(k_i, k_j);
    if (c.adjacent > 0.0) c.automatic = links::ExtendedPenalty::automatic(context, 1e-3, 1.0);
    const double m_eff = context.effective_mass();
    // When the link is much stiffer than what holds its nodes (or they are bare masses), a
    // contact is the two end masses on the link: it lasts half a period of that pair. Against
    // comparably stiff neighbours (a rod at k-ratio ~1) the contact lasts as long as the
    // structure takes (a wave), so no duration is claimed.
    const bool link_governs = c.adjacent == 0.0 || c.stiffness >= 10.0 * c.adjacent;
    if (c.stiffness > 0.0 && m_eff > 0.0 && link_governs)
      c.contact_duration = std::numbers::pi * std::sqrt(m_eff / c.stiffness);
    text += hertzian ? fmt::format("  link {} ({}): stiffness grows with penetration", c.id, law)
                     : fmt::format("  link {} ({}): stiffness {:.4g}", c.id, law, c.stiffness);
    if (c.adjacent > 0.0 && !hertzian) {
      const double ratio = c.stiffness / c.adjacent;
      text += fmt::format(", k-ratio {:.3g} (adjacent {:.4g})", ratio, c.adjacent);
      // A penalty spring without the extended penalty's mass: Kawashima's advice.
      if (traits.penalty && touch.mass == 0.0) {
        if (ratio > 100.0)
          warnings.push_back(
              fmt::format("link {}: k-ratio {:.3g}: a link this stiff against its neighbours "
                          "separates and recontacts inside the true contact with peaks many "
                          "times the exact force (Kawashima); use k-ratio ~1 or the extended "
                          "penalty",
                          c.id, ratio));
        if (ratio < 0.1)
          warnings.push_back(
              fmt::format("link {}: k-ratio {:.3g}: a link this soft lets the bodies overlap "
                          "and holds contact far too long (Kawashima)",
                          c.id, ratio));
      }
    }
    if (c.adjacent > 0.0)
      text +=
          fmt::format("; automatic extended penalty alpha0 {:.4g}, alpha1 {:.4g}, alpha2 {:.4g}",
                      c.automatic.alpha0, c.automatic.alpha1, c.automatic.alpha2);
    if (c.contact_duration > 0.0) {
      text += fmt::format("; contact lasts ~{:.4g}", c.contact_duration);
      if (!analysis.time_step_auto && analysis.time_step > 0.5 * c.contact_duration)
        warnings.push_back(
            fmt::format("link {}: the time step {:.4g} is more than half the contact duration "
                        "{:.4g}: the impact is not resolved and the result is meaningless",
                        c.id, analysis.time_step, c.contact_duration));
      else if (!analysis.time_step_auto && analysis.time_step > c.contact_duration / 20.0)
        warnings.push_back(
            fmt::format("link {}: the time step {:.4g} gives fewer than 20 steps per contact "
                        "({:.4g}); Kawashima asks dt <= T_contact / 20",
                        c.id, analysis.time_step, c.contact_duration));
    }
    text += "\n";
    checks.push_back(c);
  }
  if (!periods.empty() && !analysis.time_step_auto && analysis.time_step > periods.back() / 10.0)
    warnings.push_back(
        fmt::format("the time step {:.4g} resolves the {}th period {:.4g} with fewer than 10 "
                    "steps",
                    analysis.time_step, periods.size(), periods.back()));

  if (vm.count("json")) {
    io::Document doc;
    doc.set("model", model_path)
        .set("dofs", static_cast<long>(system->size()))
        .set("dofs_per_node", system->dofs().dofs_per_node())
        .set("periods", periods);
    if (lumped)
      doc.set("explicit_stable_step_open", open_limit)
          .set("explicit_stable_step_contact", contact_limit);
    std::vector<io::Document> link_documents;
    for (const LinkCheck& c : checks) {
      io::Document l;
      l.set("id", c.id)
          .set("law", c.law)
          .set("stiffness", c.stiffness)
          .set("adjacent_stiffness", c.adjacent)
          .set("contact_duration", c.contact_duration)
          .set("automatic_alpha0", c.automatic.alpha0)
          .set("automatic_alpha1", c.automatic.alpha1)
          .set("automatic_alpha2", c.automatic.alpha2);
      link_documents.push_back(l);
    }
    doc.set("links", link_documents);
    std::vector<io::Document> items;
    for (const std::string& w : warnings) items.push_back(io::Document().set("warning", w));
    doc.set("warnings", items);
    std::cout << doc.dump() << "\n";
  } else {
    std::cout << text;
    for (const std::string& w : warnings) std::cout << "warning: " << w << "\n";
    if (warnings.empty()) std::cout << "no warnings\n";
  }
  return vm.count("strict") && !warnings.empty() ? 1 : 0;
}

}  // namespace pound::app
