#include "builder/excitations.hpp"

#include <algorithm>
#include <cmath>
#include <ranges>

namespace pound::builder {

// The records, scaled as the spec says (targets in g), along their directions.
std::vector<double> resolve_excitations(const Resolver& resolver,
                                        const std::vector<model::GroundMotion>& motions,
                                        model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  std::vector<double> factors;
  if (motions.size() != spec.excitations.size())
    throw std::invalid_argument("build: one ground motion per excitation is needed");
  const double gravity = spec.units.gravity();
  for (std::size_t k = 0; k < motions.size(); ++k) {
    const ExcitationSpec& e = spec.excitations[k];
    model::GroundMotion motion = motions[k];
    const std::string path = fmt::format("/excitations/{}/scale", k);
    if (!(motion.peak() > 0.0) && (e.target_pga || e.target_sa))
      throw InputError(spec.source, path,
                       fmt::format("record '{}' is all zeros: it cannot be scaled "
                                   "to a target",
                                   motion.name));
    double factor = e.scale_factor.value_or(1.0);
    if (e.target_pga) factor = model::scale_to_peak(motion, *e.target_pga * gravity);
    if (e.target_sa) try {
        factor = model::scale_to_spectral_acceleration(motion, *e.target_sa * gravity, e.sa_period,
                                                       e.sa_damping);
      } catch (const std::invalid_argument& error) {
        throw InputError(spec.source, path, error.what());
      }
    model::scale(motion, factor * e.extra_factor);
    factors.push_back(factor * e.extra_factor);
    model::Coordinates direction{};
    std::copy_n(e.direction.begin(), std::min(e.direction.size(), direction.size()),
                direction.begin());
    if (e.supports.empty()) {
      model.excitations.push_back({std::move(motion), direction});
      continue;
    }
    model::SupportExcitation moving{std::move(motion), direction, {}};
    for (std::size_t s = 0; s < e.supports.size(); ++s) {
      const std::string where = fmt::format("/excitations/{}/supports/{}", k, s);
      const Index node = resolver.node(e.supports[s], where);
      // Only a support can be moved: every direction the record acts in must be fixed there.
      bool held = false;
      for (const model::Support& support : model.supports)
        if (support.node == node)
          held = std::ranges::all_of(std::views::iota(std::size_t{0}, direction.size()),
                                     [&](std::size_t axis) {
                                       // A translation's direction index is its axis.
                                       return direction[axis] == 0.0 || support.fixed[axis];
                                     });
      if (!held)
        throw InputError(
            spec.source, where,
            fmt::format("node '{}' is not a support fixed along the excitation's direction",
                        e.supports[s]));
      const double x = model.nodes[static_cast<std::size_t>(node)].position[0];
      const double delay =
          e.apparent_velocity ? std::abs(x - e.wave_origin) / *e.apparent_velocity : 0.0;
      moving.supports.emplace_back(node, delay);
    }
    model.support_excitations.push_back(std::move(moving));
  }
  return factors;
}

void fit_analysis_to_records(AnalysisSpec& analysis, const model::Model& model) {
  if (analysis.duration == 0.0)
    for (const model::UniformExcitation& excitation : model.excitations)
      analysis.duration = std::max(analysis.duration, excitation.motion.duration());
  if (analysis.duration == 0.0)
    for (const model::SupportExcitation& excitation : model.support_excitations)
      for (const auto& [node, delay] : excitation.supports)
        analysis.duration = std::max(analysis.duration, excitation.motion.duration() + delay);
  // Adaptive steps no longer than the records' sampling, so no peak of a record is stepped over.
  if (analysis.adaptive && analysis.adaptive->max_time_step == 0.0) {
    double sampling = INFINITY;
    for (const model::UniformExcitation& excitation : model.excitations)
      sampling = std::min(sampling, excitation.motion.time_step);
    for (const model::SupportExcitation& excitation : model.support_excitations)
      sampling = std::min(sampling, excitation.motion.time_step);
    if (std::isfinite(sampling))
      analysis.adaptive->max_time_step = std::max(sampling, analysis.time_step);
  }
}

}  // namespace pound::builder
