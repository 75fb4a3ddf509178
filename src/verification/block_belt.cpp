#include "verification/block_belt.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "assembly/static_equilibrium.hpp"
#include "assembly/structural_system.hpp"
#include "builder/build.hpp"
#include "builder/generators.hpp"
#include "core/errors.hpp"
#include "core/stopwatch.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/law_registry.hpp"
#include "results/energy_balance.hpp"
#include "verification/transient_run.hpp"

namespace pound::verification {
namespace {

bool is_spring(const builder::LinkSpec& link) {
  const links::LawEntry* law = links::find_law(link.law.type);
  return law && law->traits.role == links::LinkRole::spring;
}

}  // namespace

double BlockBeltScene::spring_period() const {
  return 2.0 * std::numbers::pi * std::sqrt(mass / spring_stiffness);
}

double BlockBeltScene::belt_speed(double dimensionless_speed) const {
  return dimensionless_speed * friction_coefficient * pressing_force /
         std::sqrt(mass * spring_stiffness);
}

BlockBeltScene block_belt_scene(const builder::ModelSpec& spec) {
  auto fail = [&spec](const std::string& path, const std::string& what) {
    throw InputError(spec.source, path, "block on a belt: " + what);
  };
  if (spec.blocks.size() != 1) fail("/generators", "needs exactly one \"block\" generator");
  if (spec.surfaces.size() != 1 || !spec.surfaces[0].friction)
    fail("/surfaces", "needs exactly one surface with friction (the belt)");
  const builder::BlockSpec& block = spec.blocks[0];
  BlockBeltScene scene;
  const builder::MaterialSpec* material = nullptr;
  for (const builder::MaterialSpec& m : spec.materials)
    if (m.id == block.material) material = &m;
  if (!material) fail("/generators", fmt::format("material '{}' does not exist", block.material));
  scene.mass = material->density * block.width * block.height * block.thickness;
  scene.pressing_force = block.pressure[2] * block.width * block.thickness;
  scene.friction_coefficient = spec.surfaces[0].friction->coefficient;
  std::vector<std::string> held;
  for (const builder::LinkSpec& link : spec.links)
    if (is_spring(link)) {
      scene.spring_stiffness += link.law.number("stiffness").value_or(0.0);
      held.push_back(link.node_j);
    }
  for (const builder::LoadSpec& load : spec.loads)
    if (std::find(held.begin(), held.end(), load.node) != held.end()) scene.pretension -= load.x;
  if (!(scene.mass > 0.0)) fail("/generators", "the block needs a density");
  if (!(scene.pressing_force > 0.0)) fail("/generators", "the block needs a pressure on its top");
  if (!(scene.friction_coefficient > 0.0)) fail("/surfaces/0/friction", "mu must be > 0");
  if (!(scene.spring_stiffness > 0.0))
    fail("/links", "needs springs (links with an elastic_spring law) holding the block");
  return scene;
}

std::vector<double> block_belt_speeds() {
  return {1e-3, 3e-3, 1e-2,  3e-2, 5e-2, 0.1, 0.2, 0.3, 0.5, 1.0,
          3.0,  10.0, 100.0, 1e3,  1e4,  1e5, 1e6, 1e7, 1e8};
}

BlockBeltPoint run_block_belt(const builder::ModelSpec& base, double dimensionless_speed,
                              const BlockBeltOptions& options) {
  const BlockBeltScene scene = block_belt_scene(base);
  BlockBeltPoint point;
  point.dimensionless_speed = dimensionless_speed;
  point.belt_speed = scene.belt_speed(dimensionless_speed);
  builder::ModelSpec spec = base;
  spec.surfaces[0].velocity = {point.belt_speed, 0.0};
  spec.blocks[0].initial_velocity = {point.belt_speed, 0.0};
  const double period = scene.spring_period();
  spec.analysis.duration = options.periods * period;
  spec.analysis.static_initial_state = true;
  spec.recorders.clear();
  spec.recorders_given = true;

  builder::BuiltModel built = builder::build(spec);
  assembly::StructuralSystem system(built.model);
  builder::settle_time_step(built.analysis, built.model, system, spec.source);
  point.time_step = built.analysis.time_step;

  // Where the study looks: spring and belt link rows, the block's x and y equations.
  const integrators::LinkSet& links = system.links();
  std::vector<Index> spring_rows, belt_links;
  for (Index k = 0; k < static_cast<Index>(built.model.links.size()); ++k) {
    const model::Link& link = built.model.links[static_cast<std::size_t>(k)];
    if (link.id.starts_with(spec.surfaces[0].id + "."))
      belt_links.push_back(k);
    else
      for (const builder::LinkSpec& s : spec.links)
        if (s.id == link.id && is_spring(s)) spring_rows.push_back(links.row(k));
  }
  const Vector mass = system.mass_matrix().diagonal();
  std::vector<std::pair<Index, Index>> block_equations;  // (x, y)
  double block_mass = 0.0;
  const builder::BlockSpec& block = spec.blocks[0];
  for (int i = 0; i <= block.columns; ++i)
    for (int j = 0; j <= block.rows; ++j) {
      const Index node = built.node_index.at(builder::block_node_id(block, i, j));
      const Index x = system.dofs().own_equation(node, 0), y = system.dofs().own_equation(node, 1);
      block_equations.emplace_back(x, y);
      if (x >= 0) block_mass += mass[x];
    }

  const double unit = scene.static_elongation();
  const double force_unit = scene.friction_coefficient * scene.pressing_force;
  // Whole spring periods, so that a rigid block's oscillation averages out.
  const double steady_periods =
      std::max(1.0, std::floor((1.0 - options.steady_from) * options.periods));
  const double steady_from = std::max(0.0, spec.analysis.duration - steady_periods * period);
  const long expected = static_cast<long>(spec.analysis.duration / point.time_step) + 1;
  const long stride =
      std::max<long>(1, expected / static_cast<long>(std::max<std::size_t>(options.samples, 1)));
  double force_sum = 0.0, steady_time = 0.0, stick_time = 0.0, lift_time = 0.0;
  double stick_share_sum = 0.0;
  std::vector<char> was_sticking(belt_links.size(), 0);
  long switches = 0;
  double previous_time = 0.0, stick_began = -1.0;
  bool stuck = false;
  long step = 0;
  // A sweep point must not report numbers from a diverging run: the energy the integration
  // makes is watched as in `pound run`, and the point fails with the time and the reason.
  results::EnergyBalance energy(system, built.analysis.integrator.acceleration_energy(),
                                built.analysis.integrator.is_explicit());
  // As in RunObservers: an implicit step's hard-contact force is its step's impulse / dt.
  if (!built.analysis.integrator.is_explicit())
    energy.set_step_forces(system.links().impulsive_hard_contact_rows(system.lumped_mass()));
  auto observe = [&](const integrators::State& s, const integrators::StepResult&) {
    energy.record(s);
    if (const double created = energy.terms().created_fraction();
        created > results::kEnergyGrowthLimit || !std::isfinite(created))
      throw SolveError(s.time, std::isfinite(created)
                                   ? fmt::format("block on a belt at Pi = {:g}: the structure "
                                                 "holds {:.1f} % more energy than was put in: "
                                                 "the integration diverged",
                                                 dimensionless_speed, 100.0 * created)
                                   : fmt::format("block on a belt at Pi = {:g}: the energy is "
                                                 "no longer finite: the integration diverged",
                                                 dimensionless_speed));
    double spring_force = scene.pretension;
    for (Index row : spring_rows) spring_force -= s.link_force[row];
    int closed = 0, sticking = 0;
    for (std::size_t c = 0; c < belt_links.size(); ++c) {
      const Index k = belt_links[c];
      const Index row = links.row(k);
      const bool contact = links.law(k).in_contact();
      const bool sticks = contact && !links.friction(k)->slipping();
      closed += contact;
      sticking += sticks;
      if (contact && !sticks && was_sticking[c] && s.time > steady_from) ++switches;
      was_sticking[c] = sticks;
      point.peak_lift = std::max(point.peak_lift, -s.link_penetration[row]);
    }
    // Not at t = 0, where the block rests on the belt by construction: an implicit integrator
    // finds a hard contact's force from the first step on, so none is in contact there yet.
    if (closed == 0 && step > 0) point.tumbling = true;
    // The block sticks when (nearly) all of it does: 90 % of its closed contacts, so that a
    // corner slipping alone does not hide a stick phase.
    const bool whole_stick = closed > 0 && sticking >= 0.9 * closed;
    const double dt = s.time - previous_time;
    previous_time = s.time;
    if (s.time > steady_from && dt > 0.0) {
      steady_time += dt;
      force_sum += spring_force * dt;
      if (whole_stick) stick_time += dt;
      if (closed > 0) stick_share_sum += dt * sticking / closed;
      if (closed < static_cast<int>(belt_links.size())) lift_time += dt;
    }
    if (whole_stick && !stuck) stick_began = s.time;
    if (!whole_stick && stuck && s.time > steady_from && s.time - stick_began >= 0.01 * period)
      ++point.stick_slip_cycles;
    stuck = whole_stick;
    if (step++ % stride == 0) {
      double cx = 0.0, cy = 0.0;
      for (const auto& [x, y] : block_equations) {
        if (x >= 0) cx += mass[x] * s.displacement[x];
        if (y >= 0) cy += mass[y] * s.displacement[y];
      }
      point.time.push_back(s.time / period);
      point.elongation.push_back(spring_force / force_unit);
      point.centroid_x.push_back(cx / block_mass / unit);
      point.centroid_y.push_back(cy / block_mass / unit);
    }
  };

  integrators::State state = initial_state(built, system);
  const Stopwatch stopwatch;
  state.displacement = assembly::static_equilibrium(system, 0.0).displacement;
  const integrators::TransientStatistics stats = run_analysis(built, system, state, observe);
  point.run_time_s = stopwatch.seconds();
  point.steps = stats.steps;
  point.friction_ratio = steady_time > 0.0 ? force_sum / steady_time / force_unit : 0.0;
  point.stick_fraction = steady_time > 0.0 ? stick_time / steady_time : 0.0;
  point.stick_share = steady_time > 0.0 ? stick_share_sum / steady_time : 0.0;
  point.stick_slip_rate = steady_time > 0.0
                              ? static_cast<double>(switches) /
                                    static_cast<double>(belt_links.size()) / (steady_time / period)
                              : 0.0;
  point.lift_fraction = steady_time > 0.0 ? lift_time / steady_time : 0.0;
  point.stick_slip = point.stick_slip_cycles >= 2;
  return point;
}

std::string format_block_belt(const BlockBeltScene& scene,
                              const std::vector<BlockBeltPoint>& points) {
  std::string text = fmt::format(
      "block on a moving belt (Suzuki & Toi 1987, 3.2): m = {:.4g}, k_s = {:.4g}, mu = {:g}, "
      "P = {:.4g}, springs at t = 0: {:.4g} (mu P = {:.4g}), spring period {:.4g}\n"
      "mu_dyn/mu_st: mean spring force / (mu P) over the whole spring periods of the second half; "
      "share: mean fraction of the closed "
      "contacts sticking; switches: stick-to-slip switches per contact per spring period; stick: "
      "fraction of the time the block sticks (90 % of its closed "
      "contacts); cycles: such stick phases >= 1 % of the spring period ending in slip\n\n",
      scene.mass, scene.spring_stiffness, scene.friction_coefficient, scene.pressing_force,
      scene.pretension, scene.friction_coefficient * scene.pressing_force, scene.spring_period());
  text += fmt::format(
      "{:>10} {:>11} {:>12} {:>7} {:>8} {:>7} {:>7} {:>11} {:>6} {:>9} {:>10} {:>7} {:>8}\n", "Pi",
      "V0", "mu_dyn/mu_st", "share", "switches", "stick", "cycles", "stick-slip", "lift",
      "tumbling", "peak_lift", "steps", "run_s");
  for (const BlockBeltPoint& p : points)
    text += fmt::format(
        "{:>10.3g} {:>11.4g} {:>12.4f} {:>7.3f} {:>8.3g} {:>7.3f} {:>7} {:>11} {:>6.3f} {:>9} "
        "{:>10.3g} {:>7} {:>8.2f}\n",
        p.dimensionless_speed, p.belt_speed, p.friction_ratio, p.stick_share, p.stick_slip_rate,
        p.stick_fraction, p.stick_slip_cycles, p.stick_slip ? "yes" : "no", p.lift_fraction,
        p.tumbling ? "yes" : "no", p.peak_lift, p.steps, p.run_time_s);
  return text;
}

Table block_belt_sweep_table(const std::vector<BlockBeltPoint>& points) {
  Table table = table_with_columns({"dimensionless_speed", "belt_speed", "friction_ratio",
                                    "stick_share", "stick_slip_rate", "stick_fraction",
                                    "stick_slip_cycles", "stick_slip", "lift_fraction", "tumbling",
                                    "peak_lift", "steps", "time_step", "run_time_s"});
  for (const BlockBeltPoint& p : points)
    append_row(table,
               {p.dimensionless_speed, p.belt_speed, p.friction_ratio, p.stick_share,
                p.stick_slip_rate, p.stick_fraction, static_cast<double>(p.stick_slip_cycles),
                p.stick_slip ? 1.0 : 0.0, p.lift_fraction, p.tumbling ? 1.0 : 0.0, p.peak_lift,
                static_cast<double>(p.steps), p.time_step, p.run_time_s});
  return table;
}

Table block_belt_history_table(const std::vector<BlockBeltPoint>& points) {
  Table table = table_with_columns(
      {"dimensionless_speed", "time_over_period", "elongation", "centroid_x", "centroid_y"});
  for (const BlockBeltPoint& p : points)
    for (std::size_t k = 0; k < p.time.size(); ++k)
      append_row(table, {p.dimensionless_speed, p.time[k], p.elongation[k], p.centroid_x[k],
                         p.centroid_y[k]});
  return table;
}

io::Document to_document(const BlockBeltScene& scene, const std::vector<BlockBeltPoint>& points) {
  io::Document document;
  document.set("mass", scene.mass)
      .set("spring_stiffness", scene.spring_stiffness)
      .set("friction_coefficient", scene.friction_coefficient)
      .set("pressing_force", scene.pressing_force)
      .set("pretension", scene.pretension)
      .set("spring_period", scene.spring_period());
  auto row = [](const BlockBeltPoint& p) {
    return io::Document()
        .set("dimensionless_speed", p.dimensionless_speed)
        .set("belt_speed", p.belt_speed)
        .set("friction_ratio", p.friction_ratio)
        .set("stick_share", p.stick_share)
        .set("stick_slip_rate", p.stick_slip_rate)
        .set("stick_fraction", p.stick_fraction)
        .set("stick_slip_cycles", p.stick_slip_cycles)
        .set("stick_slip", p.stick_slip)
        .set("lift_fraction", p.lift_fraction)
        .set("tumbling", p.tumbling)
        .set("peak_lift", p.peak_lift)
        .set("steps", p.steps)
        .set("run_time_s", p.run_time_s);
  };
  document.set("points", io::documents(points, row));
  return document;
}

}  // namespace pound::verification
