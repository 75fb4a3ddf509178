#include "verification/rod_impact.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "builder/generators.hpp"
#include "core/stopwatch.hpp"
#include "integrators/newmark.hpp"
#include "integrators/transient_analysis.hpp"
#include "verification/transient_run.hpp"

namespace pound::verification {
namespace {

ExactRod exact_rod(const builder::RodSpec& rod) {
  return {rod.youngs_modulus, rod.density,          rod.area,
          rod.length,         rod.initial_velocity, rod.far_end_fixed};
}

double travel_time(const builder::RodSpec& rod) {
  return rod.length / std::sqrt(rod.youngs_modulus / rod.density);
}

// Time where a linearly interpolated history crosses zero between samples k and k + 1.
double crossing(const std::vector<double>& time, const std::vector<double>& value, std::size_t k) {
  const double span = value[k] - value[k + 1];
  if (span == 0.0) return time[k];
  return time[k] + (time[k + 1] - time[k]) * value[k] / span;
}

// The pair the exact solution solves: a rigid wall is a mirror plane, so a rod striking it across
// a gap g moves exactly as against its mirror image (velocity reversed) across 2g, with the same
// contact force.
builder::RodPairSpec exact_pair(const builder::RodPairSpec& pair) {
  if (!pair.right_wall) return pair;
  builder::RodPairSpec mirrored = pair;
  mirrored.right = pair.left;
  mirrored.right.initial_velocity = -pair.left.initial_velocity;
  mirrored.right_wall = false;
  mirrored.gap = 2.0 * pair.gap;
  return mirrored;
}

}  // namespace

ExactRodImpact exact_solution(const builder::RodPairSpec& pair, double t_end) {
  const builder::RodPairSpec exact = exact_pair(pair);
  return ExactRodImpact(exact_rod(exact.left), exact_rod(exact.right), exact.gap, t_end);
}

double exact_separation_velocity(const builder::RodPairSpec& pair, const ExactRodImpact& exact,
                                 double time) {
  const double left = exact.centre_of_mass_velocity(0, time);
  return pair.right_wall ? -left : exact.centre_of_mass_velocity(1, time) - left;
}

std::pair<double, double> exact_contact_window(const builder::RodPairSpec& given) {
  const builder::RodPairSpec pair = exact_pair(given);
  // Long enough for the approach across the gap and many wave transits.
  const double closing = pair.left.initial_velocity - pair.right.initial_velocity;
  const double approach = closing > 0.0 ? pair.gap / closing : 0.0;
  const double horizon =
      approach + 20.0 * std::max(travel_time(pair.left), travel_time(pair.right));
  const ExactRodImpact exact = exact_solution(pair, horizon);
  if (exact.contacts().empty()) return {approach, 0.0};
  return {exact.contacts().front().start,
          exact.contacts().back().end - exact.contacts().front().start};
}

builder::RodPairSpec kawashima_rod_pair(int elements, double stiffness_ratio) {
  builder::RodPairSpec pair;
  pair.id = "rods";
  pair.left = {.youngs_modulus = 100.0,
               .density = 0.1,
               .area = 1.0,
               .length = 10.0,
               .elements = elements,
               .initial_velocity = 0.1,
               .far_end_fixed = false};
  pair.right = pair.left;
  pair.right.initial_velocity = -0.1;
  pair.law.type = "gap_spring";
  pair.law.parameters["stiffness_ratio"] = stiffness_ratio;
  return pair;
}

RodImpactMetrics compare_with_exact(const ExactRodImpact& exact, double first_contact,
                                    double exact_duration, const std::vector<double>& time,
                                    const std::vector<double>& force,
                                    const std::vector<double>& penetration,
                                    double separation_velocity, double exact_separation_velocity,
                                    std::vector<double>* exact_force) {
  RodImpactMetrics m;
  m.exact_duration = exact_duration;
  const double window_end = first_contact + 1.5 * exact_duration;
  double error_squares = 0.0, exact_squares = 0.0;
  double start = -1.0, end = -1.0;
  bool in_contact = false;
  // Penetration that is more than round-off: a hard contact's is +-1e-20 about zero, whose sign
  // says nothing (a crossing of such values extrapolates anywhere).
  double largest_penetration = 0.0;
  for (const double p : penetration)
    largest_penetration = std::max(largest_penetration, std::abs(p));
  const double penetration_floor = 1e-9 * largest_penetration;
  m.min_force = force.empty() ? 0.0 : force.front();
  if (exact_force) exact_force->clear();
  for (std::size_t k = 0; k < time.size(); ++k) {
    const double reference = exact.contact_force(time[k]);
    if (exact_force) exact_force->push_back(reference);
    if (time[k] > window_end + 1e-12 * window_end) continue;
    error_squares += (force[k] - reference) * (force[k] - reference);
    exact_squares += reference * reference;
    m.exact_peak_force = std::max(m.exact_peak_force, reference);
    m.peak_force_ratio = std::max(m.peak_force_ratio, force[k]);
    m.max_penetration = std::max(m.max_penetration, penetration[k]);
    m.min_force = std::min(m.min_force, force[k]);
    const bool contact = force[k] > 0.0;
    // A penalty contact begins and ends where the penetration crosses zero. A hard contact has
    // no such crossing (round-off about zero explicitly, an overlap held until it parts
    // implicitly): its force at a sample acts from half a step before to half a step after it
    // (the velocities at the half steps of central difference, the step's impulse of an
    // implicit step), the first from t_0.
    if (contact && !in_contact) {
      ++m.contact_episodes;
      if (start < 0.0)
        start = k == 0 ? time[0]
                : penetration[k] > penetration_floor && penetration[k - 1] <= 0.0
                    ? crossing(time, penetration, k - 1)
                    : 0.5 * (time[k - 1] + time[k]);
    }
    if (!contact && in_contact)
      end = penetration[k - 1] > penetration_floor && penetration[k] <= 0.0
                ? crossing(time, penetration, k - 1)
                : 0.5 * (time[k - 1] + time[k]);
    in_contact = contact;
  }
  if (in_contact) end = std::min(window_end, time.back());
  m.force_l2_error = exact_squares > 0.0 ? std::sqrt(error_squares / exact_squares) : 0.0;
  m.peak_force_ratio = m.exact_peak_force > 0.0 ? m.peak_force_ratio / m.exact_peak_force : 0.0;
  m.duration = start >= 0.0 ? end - start : 0.0;
  m.duration_error = exact_duration > 0.0 ? (m.duration - exact_duration) / exact_duration : 0.0;
  for (const ContactInterval& interval : exact.contacts())
    if (interval.start <= window_end) ++m.exact_contact_episodes;
  m.separation_velocity = separation_velocity;
  m.exact_separation_velocity = exact_separation_velocity;
  const double scale = std::abs(m.exact_separation_velocity);
  m.separation_velocity_error =
      (separation_velocity - m.exact_separation_velocity) / (scale > 0.0 ? scale : 1.0);
  return m;
}

RodPairNodes::RodPairNodes(const builder::RodPairSpec& pair, const builder::BuiltModel& built,
                           const model::DofMap& dofs)
    : rigid_wall_(pair.right_wall) {
  for (int r = 0; r < rods(); ++r) {
    const builder::RodSpec& rod = r == 0 ? pair.left : pair.right;
    Rod& out = rods_[r];
    out.element_length = rod.length / rod.elements;
    out.node_mass = rod.density * rod.area * out.element_length;
    out.mass = rod.density * rod.area * rod.length;
    out.element_stiffness = rod.youngs_modulus * rod.area / out.element_length;
    out.initial_velocity = rod.initial_velocity;
    for (int i = 0; i <= rod.elements; ++i) {
      out.equation.push_back(
          dofs.own_equation(built.node_index.at(builder::rod_node_id(pair, r, i)), 0));
      out.x.push_back(r == 0 ? -rod.length + i * out.element_length
                             : pair.gap + i * out.element_length);
    }
  }
}

double RodPairNodes::centre_velocity(const integrators::State& state, int rod) const {
  const Rod& r = rods_[rod];
  double momentum = 0.0;
  for (std::size_t i = 0; i < r.equation.size(); ++i) {
    const bool end = i == 0 || i + 1 == r.equation.size();
    if (r.equation[i] >= 0)
      momentum += (end ? 0.5 : 1.0) * r.node_mass * state.velocity[r.equation[i]];
  }
  return momentum / r.mass;
}

double RodPairNodes::separation_velocity(const integrators::State& state) const {
  const double left = centre_velocity(state, 0);
  return rigid_wall_ ? -left : centre_velocity(state, 1) - left;
}

double RodPairNodes::energy(const integrators::State& state) const {
  double energy = 0.0;
  auto value = [](const Vector& v, Index eq) { return eq < 0 ? 0.0 : v[eq]; };
  for (int r = 0; r < rods(); ++r) {
    const Rod& rod = rods_[r];
    for (std::size_t i = 0; i < rod.equation.size(); ++i) {
      const bool end = i == 0 || i + 1 == rod.equation.size();
      const double velocity = value(state.velocity, rod.equation[i]);
      energy += 0.5 * (end ? 0.5 : 1.0) * rod.node_mass * velocity * velocity;
      if (i == 0) continue;
      const double stretch = value(state.displacement, rod.equation[i]) -
                             value(state.displacement, rod.equation[i - 1]);
      energy += 0.5 * rod.element_stiffness * stretch * stretch;
    }
  }
  return energy;
}

double RodPairNodes::initial_energy() const {
  double energy = 0.0;
  for (int r = 0; r < rods(); ++r)
    energy += 0.5 * rods_[r].mass * rods_[r].initial_velocity * rods_[r].initial_velocity;
  return energy;
}

RodImpactMetrics rod_pair_metrics(const builder::RodPairSpec& pair, const RodPairNodes& nodes,
                                  const std::vector<double>& time, const std::vector<double>& force,
                                  const std::vector<double>& penetration,
                                  const integrators::State& final_state,
                                  std::vector<double>* exact_force) {
  const auto [first_contact, exact_duration] = exact_contact_window(pair);
  const ExactRodImpact exact = exact_solution(pair, final_state.time * (1.0 + 1e-9));
  RodImpactMetrics metrics =
      compare_with_exact(exact, first_contact, exact_duration, time, force, penetration,
                         nodes.separation_velocity(final_state),
                         exact_separation_velocity(pair, exact, final_state.time), exact_force);
  const double initial = nodes.initial_energy();
  metrics.energy_ratio = initial > 0.0 ? nodes.energy(final_state) / initial : 1.0;
  return metrics;
}

RodImpactTimes rod_impact_times(const RodImpactOptions& options) {
  const builder::RodPairSpec& pair = options.pair;
  RodImpactTimes times;
  std::tie(times.first_contact, times.contact_duration) = exact_contact_window(pair);
  const double h_left = pair.left.length / pair.left.elements;
  times.time_step = options.courant ? *options.courant * h_left /
                                          std::sqrt(pair.left.youngs_modulus / pair.left.density)
                                    : options.dt_ratio * times.contact_duration;
  times.duration = times.first_contact + options.duration_ratio * times.contact_duration;
  return times;
}

struct RodPairSimulation::Impl {
  explicit Impl(const RodImpactOptions& opts) : options(opts) {
    const builder::RodPairSpec& pair = options.pair;
    const RodImpactTimes times = rod_impact_times(options);
    first_contact = times.first_contact;
    exact_duration = times.contact_duration;
    time_step = times.time_step;
    builder::ModelSpec spec;
    spec.source = "rod-impact";
    spec.rod_pairs = {pair};
    spec.rod_pair_generator_index = {0};
    spec.analysis.time_step = time_step;
    spec.analysis.duration = times.duration;
    spec.analysis.relative_tolerance = options.relative_tolerance;
    spec.analysis.integrator = options.integrator;
    if (options.stable_fraction) {
      spec.analysis.time_step_auto = true;
      spec.analysis.safety_factor = *options.stable_fraction;
    }
    built = builder::build(spec);
    system = std::make_unique<assembly::StructuralSystem>(built.model);
    builder::settle_time_step(built.analysis, built.model, *system, "rod-impact");
    time_step = built.analysis.time_step;
    nodes = std::make_unique<RodPairNodes>(pair, built, system->dofs());
  }

  integrators::TransientStatistics solve(RodImpactResult& result,
                                         std::vector<integrators::State>* snapshots,
                                         integrators::State& final_state) {
    std::vector<double> targets;
    for (double label : options.profile_times)
      targets.push_back(first_contact + label * exact_duration);
    if (snapshots) snapshots->assign(targets.size(), integrators::State{});
    const std::size_t expected = static_cast<std::size_t>(built.analysis.duration / time_step) + 2;
    result.time.clear();
    result.force.clear();
    result.penetration.clear();
    result.time.reserve(expected);
    result.force.reserve(expected);
    result.penetration.reserve(expected);
    final_state = initial_state(built, *system);
    return run_analysis(
        built, *system, final_state,
        [&](const integrators::State& s, const integrators::StepResult&) {
          result.time.push_back(s.time);
          result.force.push_back(s.link_force[0]);
          result.penetration.push_back(s.link_penetration[0]);
          if (!snapshots) return;
          for (std::size_t p = 0; p < targets.size(); ++p)
            if ((*snapshots)[p].displacement.size() == 0 && s.time >= targets[p] - 0.5 * time_step)
              (*snapshots)[p] = s;
        });
  }

  RodProfile profile(const ExactRodImpact& exact, const integrators::State& s, double label) const {
    RodProfile profile{s.time, label, {}};
    auto value_at = [](const Vector& v, Index eq) { return eq < 0 ? 0.0 : v[eq]; };
    for (int r = 0; r < nodes->rods(); ++r) {
      const builder::RodSpec& rod = r == 0 ? options.pair.left : options.pair.right;
      const std::vector<Index>& equation = nodes->equations(r);
      const double h = nodes->element_length(r);
      for (std::size_t i = 0; i < equation.size(); ++i) {
        RodProfile::Point point{
            r, nodes->positions(r)[i], value_at(s.velocity, equation[i]), 0.0, 0.0, 0.0};
        point.exact_velocity = exact.state(r, point.x, s.time).velocity;
        if (i > 0) {
          // Stress of the element ending at this node, compared at its midpoint.
          const double strain =
              (value_at(s.displacement, equation[i]) - value_at(s.displacement, equation[i - 1])) /
              h;
          point.stress = rod.youngs_modulus * strain;
          point.exact_stress = exact.state(r, point.x - 0.5 * h, s.time).stress;
        }
        profile.points.push_back(point);
      }
    }
    return profile;
  }

  RodImpactOptions options;
  double first_contact = 0.0;
  double exact_duration = 0.0;
  double time_step = 0.0;
  builder::BuiltModel built;
  std::unique_ptr<assembly::StructuralSystem> system;
  std::unique_ptr<RodPairNodes> nodes;
};

RodPairSimulation::RodPairSimulation(const RodImpactOptions& options)
    : impl_(std::make_unique<Impl>(options)) {}
RodPairSimulation::~RodPairSimulation() = default;
double RodPairSimulation::time_step() const { return impl_->time_step; }
double RodPairSimulation::first_contact() const { return impl_->first_contact; }
double RodPairSimulation::exact_duration() const { return impl_->exact_duration; }
std::size_t RodPairSimulation::dofs() const {
  return static_cast<std::size_t>(impl_->system->size());
}
integrators::TransientStatistics RodPairSimulation::solve(RodImpactResult& result) {
  integrators::State final_state;
  return impl_->solve(result, nullptr, final_state);
}

RodImpactResult run_rod_impact(const RodImpactOptions& options) {
  RodPairSimulation::Impl simulation(options);
  RodImpactResult result;
  result.time_step = simulation.time_step;
  std::vector<integrators::State> snapshots;
  integrators::State final_state;
  const Stopwatch stopwatch;
  const integrators::TransientStatistics stats = simulation.solve(result, &snapshots, final_state);
  const double run_time = stopwatch.seconds();

  result.metrics = rod_pair_metrics(options.pair, *simulation.nodes, result.time, result.force,
                                    result.penetration, final_state, &result.exact_force);
  result.metrics.run_time_s = run_time;
  result.metrics.steps = stats.steps;
  result.metrics.newton_iterations = stats.newton_iterations;
  result.metrics.time_step = simulation.time_step;
  result.metrics.stable_time_step = simulation.built.analysis.stable_time_step;
  result.metrics.hard_contact = options.pair.law.type == "hard_contact";
  const ExactRodImpact exact = exact_solution(options.pair, final_state.time * (1.0 + 1e-9));
  for (std::size_t p = 0; p < snapshots.size(); ++p)
    if (snapshots[p].displacement.size() > 0)
      result.profiles.push_back(simulation.profile(exact, snapshots[p], options.profile_times[p]));
  return result;
}

}  // namespace pound::verification
