#include "verification/rod_impact_2d.hpp"

#include <algorithm>
#include <cmath>

#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "core/stopwatch.hpp"
#include "integrators/transient_analysis.hpp"
#include "verification/rod_impact.hpp"
#include "verification/rod_impact_report.hpp"
#include "verification/transient_run.hpp"

namespace pound::verification {
namespace {

constexpr const char* kStrips[] = {"left", "right"};  // block and material ids of rods 0 and 1

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty()) return 0.0;
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto upper = std::upper_bound(x.begin(), x.end(), at);
  const std::size_t k = static_cast<std::size_t>(upper - x.begin());
  const double w = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return (1 - w) * y[k - 1] + w * y[k];
}

double l2_error(const std::vector<double>& time, const std::vector<double>& force,
                const std::vector<double>& exact, double window_end) {
  double error = 0.0, norm = 0.0;
  for (std::size_t k = 0; k < time.size() && time[k] <= window_end; ++k) {
    error += (force[k] - exact[k]) * (force[k] - exact[k]);
    norm += exact[k] * exact[k];
  }
  return norm > 0.0 ? std::sqrt(error / norm) : 0.0;
}

// The 1-D model, central difference like the strips.
RodImpactResult run_rods(const RodImpact2dOptions& options) {
  RodImpactOptions one_d;
  one_d.pair = options.pair;
  one_d.integrator = integrators::IntegratorChoice::preset("central_difference");
  one_d.stable_fraction = options.stable_fraction;
  one_d.duration_ratio = options.duration_ratio;
  return run_rod_impact(one_d);
}

// Rod r (0 left, 1 right) as a strip: a square section of side sqrt(A), plane stress of
// thickness sqrt(A).
builder::BlockSpec strip(const RodImpact2dOptions& options, int r) {
  const builder::RodSpec& rod = r == 0 ? options.pair.left : options.pair.right;
  const double side = std::sqrt(rod.area);
  builder::BlockSpec block;
  block.id = kStrips[r];
  block.origin = {r == 0 ? -rod.length : options.pair.gap, -side / 2};
  block.width = rod.length;
  block.height = side;
  block.columns = rod.elements;
  block.rows = r == 1 && options.elements_across_struck > 0 ? options.elements_across_struck
                                                            : options.elements_across;
  block.material = kStrips[r];
  block.thickness = side;
  block.initial_velocity = {rod.initial_velocity, 0.0};
  if (rod.far_end_fixed) block.fixed_edges = {r == 0 ? "left" : "right"};
  block.generator_index = r;
  return block;
}

// The strips, in contact at their facing edges, run by central difference to `end_time`.
builder::ModelSpec strips_spec(const RodImpact2dOptions& options, double end_time) {
  builder::ModelSpec spec;
  spec.source = "rod-impact-2d";
  spec.dimension = 2;
  for (int r = 0; r < 2; ++r) {
    const builder::RodSpec& rod = r == 0 ? options.pair.left : options.pair.right;
    spec.materials.push_back({kStrips[r], rod.youngs_modulus, rod.density, options.poisson_ratio});
    spec.blocks.push_back(strip(options, r));
  }
  builder::ContactSpec contact;
  contact.id = "interface";
  contact.nodes = {"left.right"};
  contact.segments = {"right.left"};
  contact.law = options.pair.law;
  contact.friction = builder::FrictionSpec{options.friction, {}, {}, {}, {}};
  spec.contacts.push_back(contact);
  spec.analysis.integrator = integrators::IntegratorChoice::preset("central_difference");
  spec.analysis.time_step_auto = true;
  spec.analysis.safety_factor = options.stable_fraction;
  spec.analysis.duration = end_time;
  spec.recorders_given = true;
  return spec;
}

// Runs the strips: the total normal force of the contact links at each step into `result`.
void run_strips(const builder::ModelSpec& spec, RodImpact2dResult& result) {
  builder::BuiltModel built = builder::build(spec);
  assembly::StructuralSystem system(built.model);
  builder::settle_time_step(built.analysis, built.model, system, spec.source);
  std::vector<Index> normal_rows;
  for (Index k = 0; k < system.links().count(); ++k) normal_rows.push_back(system.links().row(k));
  result.contact_links = static_cast<int>(normal_rows.size());

  integrators::State state = initial_state(built, system);
  const Stopwatch stopwatch;
  const integrators::TransientStatistics stats = run_analysis(
      built, system, state, [&](const integrators::State& s, const integrators::StepResult&) {
        double force = 0.0;
        for (Index row : normal_rows) force += s.link_force[row];
        result.time.push_back(s.time);
        result.force_2d.push_back(force);
      });
  result.run_time_2d_s = stopwatch.seconds();
  result.steps_2d = stats.steps;
}

// The exact force and the 1-D one at the strips' steps, the errors and the peaks.
void compare_forces(const RodImpact2dOptions& options, const RodImpactResult& rods,
                    double first_contact, double end_time, RodImpact2dResult& result) {
  const ExactRodImpact exact = exact_solution(options.pair, end_time);
  for (double t : result.time) {
    result.exact_force.push_back(exact.contact_force(t));
    result.force_1d.push_back(interpolate(rods.time, rods.force, t));
  }
  const double window_end = first_contact + 1.5 * result.exact_duration;
  result.force_l2_error_2d = l2_error(result.time, result.force_2d, result.exact_force, window_end);
  // The 1-D error on its own steps, as `verify rod-impact` reports it.
  result.force_l2_error_1d = rods.metrics.force_l2_error;
  for (std::size_t k = 0; k < result.time.size(); ++k) {
    result.peak_force_2d = std::max(result.peak_force_2d, result.force_2d[k]);
    result.exact_peak_force = std::max(result.exact_peak_force, result.exact_force[k]);
  }
  for (double f : rods.force) result.peak_force_1d = std::max(result.peak_force_1d, f);
}

}  // namespace

RodImpact2dOptions suzuki_toi_rods_2d() {
  RodImpact2dOptions options;
  options.pair = rod_impact_case("fixed-end", 50, 1.0, "extended_penalty", 1.0);
  return options;
}

RodImpact2dResult run_rod_impact_2d(const RodImpact2dOptions& options) {
  RodImpact2dResult result;
  const auto [first_contact, exact_duration] = exact_contact_window(options.pair);
  result.exact_duration = exact_duration;
  const double end_time = first_contact + options.duration_ratio * exact_duration;
  const RodImpactResult rods = run_rods(options);
  result.steps_1d = rods.metrics.steps;
  run_strips(strips_spec(options, end_time), result);
  compare_forces(options, rods, first_contact, end_time, result);
  return result;
}

Table rod_impact_2d_table(const RodImpact2dResult& result) {
  return {{"time", "force_2d", "force_1d", "exact_force"},
          {result.time, result.force_2d, result.force_1d, result.exact_force}};
}

}  // namespace pound::verification
