#pragma once
// The block on a moving belt (Suzuki & Toi 1987, section 3.2; docs/design.md §3.4): an
// elastic block of quads pressed on a belt by a pressure on its top, held back by springs on
// its trailing face, with Coulomb friction of equal static and kinetic mu at the belt. At t = 0
// the springs pull mu P (the most static friction can hold) and every node moves with the
// belt. The run is swept over the non-dimensional belt speed
//   Pi = V0 sqrt(m k_s) / (mu P)   (m the block's mass, k_s the springs' total stiffness),
// the ratio of a rigid block's oscillation amplitude V0 / omega to the static elongation
// mu P / k_s. A rigid block keeps mu_dynamic / mu_static = 1 at every speed; the elastic block
// does not once it vibrates normal to the belt.
#include <string>
#include <vector>

#include "builder/spec.hpp"
#include "core/table.hpp"
#include "io/document.hpp"

namespace pound::verification {

// What the study reads off a block-on-belt model: one "block" generator with a top pressure,
// one surface with friction (the belt, moving along +x), and the springs: links with an
// elastic_spring law, their pre-tension given as loads along -x on the nodes they hold.
struct BlockBeltScene {
  double mass = 0.0;                  // m = rho W H t [M]
  double spring_stiffness = 0.0;      // k_s [F/L]
  double friction_coefficient = 0.0;  // mu
  double pressing_force = 0.0;        // P = p W t [F]
  double pretension = 0.0;            // the springs' force at t = 0 [F] (mu P in the paper)
  double static_elongation() const {
    return friction_coefficient * pressing_force / spring_stiffness;
  }
  double spring_period() const;                         // 2 pi sqrt(m / k_s)
  double belt_speed(double dimensionless_speed) const;  // V0 for Pi
};
// Throws InputError naming what the model lacks.
BlockBeltScene block_belt_scene(const builder::ModelSpec& spec);

// The longest run the study takes, in spring periods: its steady state settles within the default
// 4, and each period is about 10^4 steps, so 1,000 are some 10^7 steps per speed (minutes), where
// 5e9 would run for years.
inline constexpr double kMostBlockBeltPeriods = 1000.0;

struct BlockBeltOptions {
  double periods = 4.0;  // run for this many spring periods 2 pi sqrt(m / k_s)
  // The steady part: the last whole spring periods in this fraction of the run (at least one).
  double steady_from = 0.5;
  std::size_t samples = 2000;  // history points kept (evenly spaced), for plots
};

struct BlockBeltPoint {
  double dimensionless_speed = 0.0;  // Pi
  double belt_speed = 0.0;           // V0 [L/T]
  // Mean spring force over mu P in the steady part: mu_dynamic / mu_static (1 for a rigid block).
  double friction_ratio = 0.0;
  // Mean fraction of the closed belt contacts that stick, over the steady part, and how often a
  // contact goes from sticking to slipping: switches per contact per spring period.
  double stick_share = 0.0;
  double stick_slip_rate = 0.0;
  // The block sticks when 90 % of its closed belt contacts do. Fraction of the steady part, and
  // stick phases of at least 1 % of the spring period that end in slip (stick-slip cycles).
  double stick_fraction = 0.0;
  int stick_slip_cycles = 0;
  bool stick_slip = false;  // two or more cycles in the steady part
  // Fraction of the steady part with some belt contact open, and whether the block ever left
  // the belt entirely (tumbling: no contact closed at some instant).
  double lift_fraction = 0.0;
  bool tumbling = false;
  double peak_lift = 0.0;  // largest clear distance of a contact node above the belt [L]
  long steps = 0;
  double time_step = 0.0;
  double run_time_s = 0.0;  // the solve alone
  // Histories (Figs. 13-15): time over the spring period; spring elongation and centroid
  // displacements over the static elongation mu P / k_s.
  std::vector<double> time, elongation, centroid_x, centroid_y;
};

// One point of the sweep: `spec` with its belt and block moving at belt_speed(Pi).
BlockBeltPoint run_block_belt(const builder::ModelSpec& spec, double dimensionless_speed,
                              const BlockBeltOptions& options = {});

// The default sweep: decades from 1e-3 to 1e8, finer from 0.003 to 3 where the curve turns.
std::vector<double> block_belt_speeds();

// The table `pound verify block-belt` prints, and what it writes for tools/plot_block_belt.py.
std::string format_block_belt(const BlockBeltScene& scene,
                              const std::vector<BlockBeltPoint>& points);
Table block_belt_sweep_table(const std::vector<BlockBeltPoint>& points);
Table block_belt_history_table(const std::vector<BlockBeltPoint>& points);  // long format
io::Document to_document(const BlockBeltScene& scene, const std::vector<BlockBeltPoint>& points);

}  // namespace pound::verification
