#include "builder/excitations.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "model/record_pair.hpp"

namespace pound::builder {

namespace {

// What resolving excitation k needs besides its records.
struct ExcitationPlace {
  const Resolver& resolver;
  const ExcitationSpec& spec;
  std::size_t k;

  std::string path(const std::string& where) const {
    return fmt::format("/excitations/{}{}", k, where);
  }
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(resolver.spec().source, path(where), what);
  }
};

// An Sa target's period is at most pound spectrum's 1000 s, in the model's unit of time (1000 s
// is 1e6 ms: a millisecond model was held to 1000 ms).
void check_sa_period(const ExcitationPlace& place) {
  const ExcitationSpec& e = place.spec;
  const double second = place.resolver.spec().units.second();
  const double longest = model::kLongestSpectralPeriod * second;
  if (e.target_sa && !(e.sa_period <= longest))
    place.fail("/scale/period",
               fmt::format("must be <= {:g} ({:g} s, pound spectrum's range), got {:g}", longest,
                           model::kLongestSpectralPeriod, e.sa_period));
}

// The factor of a single record: to its target PGA or Sa (in g), or as given.
double record_factor(const ExcitationPlace& place, const model::GroundMotion& motion,
                     double gravity) {
  const ExcitationSpec& e = place.spec;
  check_sa_period(place);
  if (!(motion.peak() > 0.0) && (e.target_pga || e.target_sa))
    place.fail("/scale", fmt::format("record '{}' is all zeros: it cannot be scaled to a target",
                                     motion.name));
  if (e.target_pga) return model::scale_to_peak(motion, *e.target_pga * gravity);
  if (e.target_sa) try {
      return model::scale_to_spectral_acceleration(motion, *e.target_sa * gravity, e.sa_period,
                                                   e.sa_damping);
    } catch (const std::invalid_argument& error) {
      place.fail("/scale", error.what());
    }
  return e.scale_factor.value_or(1.0);
}

// The one factor of a pair: its RotD50 (of the accelerations for a PGA, of Sa(T) for an Sa) to
// the target, as design codes scale a pair (Boore 2010), or as given.
double pair_factor(const ExcitationPlace& place, const model::GroundMotionPair& pair,
                   double gravity) {
  const ExcitationSpec& e = place.spec;
  check_sa_period(place);
  if (!e.target_pga && !e.target_sa) return e.scale_factor.value_or(1.0);
  const double target = (e.target_pga ? *e.target_pga : *e.target_sa) * gravity;
  const double rot_d50 =
      model::pair_spectral_acceleration(pair, e.target_pga ? 0.0 : e.sa_period, e.sa_damping)
          .rot_d50;
  if (!(rot_d50 > 0.0) || !std::isfinite(target / rot_d50))
    place.fail("/scale", fmt::format("the pair '{}', '{}' has no motion at that period: it "
                                     "cannot be scaled to a target",
                                     pair.first.name, pair.second.name));
  return target / rot_d50;
}

// A factor that makes a record overflow (a PGA of 1e308 g) leaves no motion to analyse: the run
// would only fail at its first step with a state that is not finite.
void check_scaled(const ExcitationPlace& place, const model::GroundMotion& motion, double factor) {
  if (!std::isfinite(factor) || !std::isfinite(motion.peak()))
    place.fail("/scale", fmt::format("record '{}' scaled by {:.3g} overflows the number range (a "
                                     "factor far beyond any ground motion)",
                                     motion.name, factor));
}

// Adds a record (already scaled) along `direction`: uniform, or moving the supports the
// excitation names, each after its wave-passage delay.
void add_component(const ExcitationPlace& place, model::GroundMotion motion,
                   const model::Coordinates& direction, model::Model& model,
                   ExcitationScaling& scaling) {
  const ExcitationSpec& e = place.spec;
  if (e.supports.empty()) {
    model.excitations.push_back({std::move(motion), direction});
    scaling.uniform_sources.push_back(place.k);
    return;
  }
  model::SupportExcitation moving{std::move(motion), direction, {}};
  for (std::size_t s = 0; s < e.supports.size(); ++s) {
    const std::string where = fmt::format("/supports/{}", s);
    const Index node = place.resolver.node(e.supports[s], place.path(where));
    // Only a support can be moved: every direction the record acts in must be fixed there.
    bool held = false;
    for (const model::Support& support : model.supports)
      if (support.node == node) {
        held = true;
        // A translation's direction index is its axis.
        for (std::size_t axis = 0; axis < direction.size(); ++axis)
          held = held && (direction[axis] == 0.0 || support.fixed[axis]);
      }
    if (!held)
      place.fail(where, fmt::format("node '{}' is not a support fixed along the excitation's "
                                    "direction",
                                    e.supports[s]));
    const double x = model.nodes[static_cast<std::size_t>(node)].position[0];
    const double delay =
        e.apparent_velocity ? std::abs(x - e.wave_origin) / *e.apparent_velocity : 0.0;
    moving.supports.emplace_back(node, delay);
  }
  model.support_excitations.push_back(std::move(moving));
}

}  // namespace

model::Coordinates pair_direction(const PairSpec& pair, int component) {
  const double angle = pair.angle * M_PI / 180.0;
  const double c = std::cos(angle), s = std::sin(angle);
  return component == 0 ? model::Coordinates{c, s, 0.0} : model::Coordinates{-s, c, 0.0};
}

// The records, scaled as the spec says (targets in g), along their directions.
ExcitationScaling resolve_excitations(
    const Resolver& resolver, const std::vector<model::GroundMotion>& motions,
    const std::vector<std::optional<model::GroundMotion>>& second_motions, model::Model& model) {
  const ModelSpec& spec = resolver.spec();
  ExcitationScaling scaling;
  if (motions.size() != spec.excitations.size())
    throw std::invalid_argument("build: one ground motion per excitation is needed");
  const double gravity = spec.units.gravity();
  for (std::size_t k = 0; k < motions.size(); ++k) {
    const ExcitationSpec& e = spec.excitations[k];
    const ExcitationPlace place{resolver, e, k};
    const bool paired = e.pair && k < second_motions.size() && second_motions[k];
    if (e.pair && !paired) throw std::invalid_argument("build: a pair needs its second record");
    if (paired && model.dimension != 3)
      place.fail("/pair", fmt::format("a pair of horizontal components needs a 3-D scene "
                                      "(\"dimension\": 3); this one is {}-D",
                                      model.dimension));
    if (!paired) {
      const double factor = record_factor(place, motions[k], gravity) * e.extra_factor;
      model::GroundMotion motion = motions[k];
      model::scale(motion, factor);
      check_scaled(place, motion, factor);
      scaling.factors.push_back(factor);
      scaling.peaks.push_back({motion.name, motion.peak() / gravity});
      add_component(place, std::move(motion), model::to_coordinates(e.direction), model, scaling);
      continue;
    }
    model::GroundMotionPair pair;
    try {
      pair = model::make_component_pair(motions[k], *second_motions[k]);
    } catch (const std::invalid_argument& error) {
      place.fail("/pair", error.what());
    }
    const double factor = pair_factor(place, pair, gravity) * e.extra_factor;
    model::scale(pair.first, factor);
    model::scale(pair.second, factor);
    check_scaled(place, pair.first, factor);
    check_scaled(place, pair.second, factor);
    scaling.factors.push_back(factor);
    const model::GroundMotion& stronger =
        pair.first.peak() >= pair.second.peak() ? pair.first : pair.second;
    scaling.peaks.push_back({stronger.name, stronger.peak() / gravity});
    add_component(place, std::move(pair.first), pair_direction(*e.pair, 0), model, scaling);
    add_component(place, std::move(pair.second), pair_direction(*e.pair, 1), model, scaling);
  }
  return scaling;
}

void fit_analysis_to_records(AnalysisSpec& analysis, const model::Model& model) {
  analysis.duration_from_records = analysis.duration == 0.0;
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
