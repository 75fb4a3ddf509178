#pragma once
// The rod-impact benchmark (docs/design.md §3.1): a rod pair solved by the finite element
// model and compared with the exact solution, with the metrics every verification reports.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "builder/build.hpp"
#include "builder/spec.hpp"
#include "integrators/transient_analysis.hpp"
#include "verification/exact_rod_impact.hpp"

namespace pound::verification {

// Metrics against the exact solution. Durations are from first contact to last separation.
struct RodImpactMetrics {
  double force_l2_error = 0.0;  // ||F - F_exact||_2 / ||F_exact||_2 over [0, 1.5 T_exact]
  double duration_error = 0.0;  // (T - T_exact) / T_exact
  double separation_velocity_error = 0.0;  // relative centre-of-mass velocity at the end
  double peak_force_ratio = 0.0;           // max F / max F_exact over the window
  double max_penetration = 0.0;
  double min_force = 0.0;
  double run_time_s = 0.0;  // the solve alone
  long steps = 0;
  long newton_iterations = 0;
  // Context for a reader of the numbers.
  double exact_duration = 0.0;
  double exact_peak_force = 0.0;
  double duration = 0.0;
  int contact_episodes = 0;  // separate contact intervals of the FE solution in the window
  int exact_contact_episodes = 0;
  double separation_velocity = 0.0;  // v_cm(right) - v_cm(left) at the end
  double exact_separation_velocity = 0.0;
  // Kinetic + strain energy of the rods at the end over the initial kinetic energy (1 for an
  // exact elastic collision; above 1 means the integration made energy).
  double energy_ratio = 1.0;
  // What explains a ratio above 1: the step, and for an explicit integrator its stable step with
  // the contact closed (builder::AnalysisSpec::stable_time_step); whether the contact is hard.
  double time_step = 0.0;
  std::optional<double> stable_time_step;
  bool hard_contact = false;
};

// Velocity and stress along both rods at one instant, FE against exact (Kawashima Fig. 6).
struct RodProfile {
  double time = 0.0;   // absolute time of the step used
  double label = 0.0;  // requested time after first contact, in units of T_exact
  struct Point {
    int rod;   // 0 left, 1 right
    double x;  // undeformed coordinate (right rod shifted by the gap, as in the exact solution)
    double velocity, exact_velocity;  // at nodes
    double stress, exact_stress;      // at element midpoints (for the element ending at x)
  };
  std::vector<Point> points;
};

struct RodImpactOptions {
  builder::RodPairSpec pair;
  // Time step: dt_ratio * T_exact, or courant * h / C0 of the left rod when set.
  double dt_ratio = 0.01;
  std::optional<double> courant;
  // Central difference only: this fraction (<= 1) of its computed stable limit instead.
  std::optional<double> stable_fraction;
  double duration_ratio = 3.0;  // run to duration_ratio * T_exact after first contact
  double relative_tolerance = 1e-10;
  builder::IntegratorSpec integrator;  // average acceleration
  std::vector<double> profile_times;   // in units of T_exact after first contact
};

struct RodImpactResult {
  RodImpactMetrics metrics;
  double time_step = 0.0;
  std::vector<double> time, force, exact_force, penetration;
  std::vector<RodProfile> profiles;
};

// The exact solution of a rod pair spec over [0, t_end]; against a rigid wall, that of the rod
// and its mirror image across twice the gap (the same contact force and left rod).
ExactRodImpact exact_solution(const builder::RodPairSpec& pair, double t_end);
// v_cm(right) - v_cm(left) at `time` (the wall's velocity is 0).
double exact_separation_velocity(const builder::RodPairSpec& pair, const ExactRodImpact& exact,
                                 double time);
// Exact first-contact-to-last-separation duration and first contact time, over a horizon long
// enough for the whole collision.
std::pair<double, double> exact_contact_window(const builder::RodPairSpec& pair);
// The run the options ask for: the exact first contact and contact duration, the time step
// (dt_ratio or courant; an explicit method's stable fraction replaces it when built) and the
// run's length, first_contact + duration_ratio * contact_duration.
struct RodImpactTimes {
  double first_contact = 0.0, contact_duration = 0.0, time_step = 0.0, duration = 0.0;
};
RodImpactTimes rod_impact_times(const RodImpactOptions& options);

RodImpactResult run_rod_impact(const RodImpactOptions& options);

// The finite element side alone, built once and solved any number of times (for benchmarks):
// solve() integrates from the initial state and records the link force history.
class RodPairSimulation {
 public:
  explicit RodPairSimulation(const RodImpactOptions& options);
  ~RodPairSimulation();
  double time_step() const;
  double first_contact() const;
  double exact_duration() const;
  // Runs the analysis; returns its statistics. Histories are in the result's vectors.
  integrators::TransientStatistics solve(RodImpactResult& result);
  std::size_t dofs() const;

 private:
  friend RodImpactResult run_rod_impact(const RodImpactOptions& options);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Metrics of a force / penetration history against the exact solution; the velocities are the
// relative centre-of-mass velocities at the last time, FE and exact.
RodImpactMetrics compare_with_exact(const ExactRodImpact& exact, double first_contact,
                                    double exact_duration, const std::vector<double>& time,
                                    const std::vector<double>& force,
                                    const std::vector<double>& penetration,
                                    double separation_velocity, double exact_separation_velocity,
                                    std::vector<double>* exact_force);

// Where the nodes of a generated rod pair sit in a system's equations, in the exact solution's
// x order, and the rods' centre-of-mass velocities (lumped masses, fixed nodes at rest). A rigid
// wall is no rod: rods() is 1.
class RodPairNodes {
 public:
  RodPairNodes(const builder::RodPairSpec& pair, const builder::BuiltModel& built,
               const model::DofMap& dofs);
  double centre_velocity(const integrators::State& state, int rod) const;
  double separation_velocity(const integrators::State& state) const;  // right minus left
  // Kinetic + strain energy of the rods (lumped masses, linear elements): at the start, 1/2 m V0^2
  // of each.
  double energy(const integrators::State& state) const;
  double initial_energy() const;
  int rods() const { return rigid_wall_ ? 1 : 2; }
  const std::vector<Index>& equations(int rod) const { return rods_[rod].equation; }
  const std::vector<double>& positions(int rod) const { return rods_[rod].x; }
  double element_length(int rod) const { return rods_[rod].element_length; }

 private:
  struct Rod {
    std::vector<Index> equation;  // -1 where fixed
    std::vector<double> x;
    double element_length = 0.0;
    double node_mass = 0.0;  // interior node; the ends carry half
    double mass = 0.0;
    double element_stiffness = 0.0;  // E A / h
    double initial_velocity = 0.0;
  } rods_[2];
  bool rigid_wall_ = false;
};

// Metrics of a finished rod-pair run (histories of its contact link, state at the end) against
// the exact solution; shared by `verify rod-impact` and `run` on a rod_pair model.
RodImpactMetrics rod_pair_metrics(const builder::RodPairSpec& pair, const RodPairNodes& nodes,
                                  const std::vector<double>& time, const std::vector<double>& force,
                                  const std::vector<double>& penetration,
                                  const integrators::State& final_state,
                                  std::vector<double>* exact_force = nullptr);

// The rod pair of Kawashima (1980): E = 100, A = 1, rho = 0.1, L = 10, V0 = 0.1 each way.
builder::RodPairSpec kawashima_rod_pair(int elements, double stiffness_ratio);

}  // namespace pound::verification
