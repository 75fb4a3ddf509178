#pragma once
// Suzuki & Toi's rod impact in 2-D (1987, Fig. 11): the rods of the 1-D benchmark as plane-stress
// strips of quads (square section, h t = A), node-to-node contact with the extended penalty and
// Coulomb friction at the interface. Its contact force is compared side by side with the 1-D
// model and the exact 1-D solution: the difference is the strips' lateral inertia (Poisson
// expansion), which the 1-D theory leaves out.
#include <vector>

#include "builder/spec.hpp"
#include "core/table.hpp"

namespace pound::verification {

struct RodImpact2dOptions {
  builder::RodPairSpec pair;  // the 1-D pair; its element counts are the strips' along the axis
  int elements_across = 4;
  // Elements across the struck (right) strip; 0: as many as the striking one (matching meshes,
  // node-to-node contact). Otherwise the striking strip's interface nodes meet the struck
  // strip's segments between its nodes: node-to-segment contact.
  int elements_across_struck = 0;
  double poisson_ratio = 0.3;
  double friction = 0.6;
  double stable_fraction = 0.5;  // central difference at this fraction of its stable step (both)
  double duration_ratio = 2.0;   // run to duration_ratio * T_exact after first contact
};

struct RodImpact2dResult {
  std::vector<double> time, force_2d, force_1d, exact_force;  // force_1d interpolated
  double force_l2_error_2d = 0.0, force_l2_error_1d = 0.0;    // over [0, 1.5 T_exact]
  double peak_force_2d = 0.0, peak_force_1d = 0.0, exact_peak_force = 0.0;
  double exact_duration = 0.0;
  long steps_2d = 0, steps_1d = 0;
  double run_time_2d_s = 0.0;
  int contact_links = 0;
};

// Kawashima's rods in Suzuki & Toi's fixed-end arrangement, 50 elements, extended penalty.
RodImpact2dOptions suzuki_toi_rods_2d();
RodImpact2dResult run_rod_impact_2d(const RodImpact2dOptions& options);
Table rod_impact_2d_table(const RodImpact2dResult& result);

}  // namespace pound::verification
