#include "builder/start_check.hpp"

#include <fmt/format.h>

#include <cmath>

#include "assembly/modal_analysis.hpp"
#include "assembly/static_equilibrium.hpp"

namespace pound::builder {
namespace {

struct NodeDirection {
  Index node = -1;
  int direction = 0;
};

NodeDirection node_of(const model::Model& model, const model::DofMap& dofs, Index equation) {
  for (Index node = 0; node < static_cast<Index>(model.nodes.size()); ++node)
    for (int d = 0; d < dofs.dofs_per_node(); ++d)
      if (dofs.own_equation(node, d) == equation) return {node, d};
  return {};
}

// "node 'id', direction x" and the node's JSON path (its entry, or the generator that made it).
std::string node_words(const BuiltModel& built, const NodeDirection& place) {
  return fmt::format("node '{}', direction {}",
                     built.model.nodes[static_cast<std::size_t>(place.node)].id,
                     model::direction(place.direction, built.model.dimension).words);
}
std::string node_path(const BuiltModel& built, const NodeDirection& place) {
  const auto node = static_cast<std::size_t>(place.node);
  return node < built.node_origins.size() ? built.node_origins[node] : "";
}

// With P-Delta the negative stiffness is most likely gravity's, -P/L: at a node that only links
// hold (a floor between yielding storeys), a mass near zero leaves nothing against it, as the
// first step's matrix is the structure's without its links.
std::string not_positive_words(const model::Model& model) {
  if (!(model.gravity && model.gravity->p_delta))
    return "the matrix is not positive there (a negative stiffness or mass?)";
  return "the matrix is not positive there: gravity's P-Delta (the negative geometric stiffness "
         "-P/L of the elements there) is more than the node's mass and elements hold (a mass "
         "near zero at a node that only links hold, such as a floor between yielding storeys? "
         "give it its real mass)";
}

}  // namespace

std::string equation_words(const BuiltModel& built, const model::DofMap& dofs, Index equation) {
  const NodeDirection place = node_of(built.model, dofs, equation);
  return place.node < 0 ? fmt::format("equation {}", equation) : node_words(built, place);
}

InputError not_held_error(const BuiltModel& built, const model::DofMap& dofs,
                          const assembly::NotPositiveDefinite& failure, const std::string& during,
                          const std::string& source) {
  const NodeDirection place = node_of(built.model, dofs, failure.equation());
  if (place.node < 0) return InputError(source, "", fmt::format("{}: {}", during, failure.what()));
  const std::string mechanism =
      "it belongs to a part that can move with neither mass nor stiffness against it (a "
      "mechanism without mass; add mass to that part, e.g. a girder's extra_mass, or an element, "
      "bearing or support that restrains it)";
  const std::string what =
      !std::isfinite(failure.pivot())
          ? "the matrix overflows the number range there (a mass, stiffness or damping far "
            "beyond physical ones, or one near zero beside them?)"
      : failure.cancelled()
          ? fmt::format(
                "nothing holds it to double precision: its diagonal {:.3e} cancels to "
                "round-off against the equations before it, where {}, or where "
                "stiffnesses (or masses) that meet there are {:g} or more times apart (a "
                "value far beyond physical ones?)",
                failure.diagonal(), mechanism, 1.0 / assembly::kLostPivot)
      : failure.pivot() < 0.0 ? not_positive_words(built.model)
                              : "nothing holds it: " + mechanism;
  return InputError(source, node_path(built, place),
                    fmt::format("{} fails at {}: {} (pivot {:.3e})", during,
                                node_words(built, place), what, failure.pivot()));
}

InputError extreme_mode_error(const BuiltModel& built, const assembly::StructuralSystem& system,
                              const std::string& reason, const std::string& source) {
  const Vector mass = system.mass_matrix().diagonal();
  const Vector stiffness = assembly::stiffness_diagonal_with_links(system);
  Index worst = -1;
  double worst_ratio = 0.0;
  for (Index i = 0; i < mass.size(); ++i) {
    if (!(mass[i] > 0.0)) continue;
    const double ratio = std::abs(stiffness[i]) / mass[i];
    if (worst < 0 || !(ratio <= worst_ratio)) {  // a NaN ratio is the worst of all
      worst = i;
      worst_ratio = ratio;
    }
  }
  const NodeDirection place =
      worst < 0 ? NodeDirection{} : node_of(built.model, system.dofs(), worst);
  if (place.node < 0)
    return InputError(source, "", fmt::format("the modes cannot be found: {}", reason));
  return InputError(source, node_path(built, place),
                    fmt::format("the modes cannot be found: {}; the largest stiffness-to-mass "
                                "ratio is at {} ({:.3g} / {:.3g})",
                                reason, node_words(built, place), stiffness[worst], mass[worst]));
}

void check_first_step(const BuiltModel& built, const AnalysisSpec& analysis,
                      assembly::StructuralSystem& system, const std::string& source) {
  const std::unique_ptr<integrators::Integrator> integrator = make_integrator(analysis);
  integrators::State start, next;
  start.velocity = system.initial_velocity(built.model);
  std::string during = "the static equilibrium at t = 0";
  try {
    if (analysis.static_initial_state)
      start.displacement = assembly::static_equilibrium(system, 0.0).displacement;
    during = fmt::format("the first step of {}", analysis.integrator.label());
    integrator->initialize(system, start, analysis.time_step);
    integrator->advance(system, start, analysis.time_step, start.time + analysis.time_step, next);
    system.links().revert();
  } catch (const assembly::NotPositiveDefinite& failure) {
    system.links().revert();
    throw not_held_error(built, system.dofs(), failure, during, source);
  }
}

}  // namespace pound::builder
