// Suzuki & Toi's rods as 2-D strips (Fig. 11) against the 1-D model and the exact 1-D solution.
#include "verification/rod_impact_2d.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <iostream>

namespace pound::verification {
namespace {

void print(const std::string& label, const RodImpact2dResult& r) {
  std::cout << fmt::format(
      "{}: force_l2_error 2-D {:.4f}, 1-D {:.4f}; peak/exact 2-D {:.3f}, 1-D {:.3f}; {} links\n",
      label, r.force_l2_error_2d, r.force_l2_error_1d, r.peak_force_2d / r.exact_peak_force,
      r.peak_force_1d / r.exact_peak_force, r.contact_links);
}

// Without Poisson's ratio the strips have no lateral motion: each row of quads is a 1-D rod,
// so the strips' force follows the 1-D model's. The only differences are the time steps
// (the explicit stable step of each mesh) and the penalty numbers, which come from the
// diagonal of the 2-D K and M.
TEST(RodImpact2d, WithoutPoissonsRatioTheStripsAreThe1DRods) {
  RodImpact2dOptions options = suzuki_toi_rods_2d();
  options.poisson_ratio = 0.0;
  const RodImpact2dResult r = run_rod_impact_2d(options);
  print("nu = 0", r);
  EXPECT_EQ(r.contact_links, options.elements_across + 1);
  EXPECT_LT(r.force_l2_error_1d, 0.1);
  EXPECT_NEAR(r.force_l2_error_2d, r.force_l2_error_1d, 0.005);
}

// With nu = 0.3 the strips bulge at the wave front: the lateral inertia Suzuki & Toi saw as a
// lower mode mixed into the force. The 2-D force departs further from the 1-D theory than the
// 1-D model does, yet the contact lasts as long and carries the same mean force.
TEST(RodImpact2d, LateralInertiaAddsToTheErrorAgainstThe1DTheory) {
  RodImpact2dOptions options = suzuki_toi_rods_2d();
  const RodImpact2dResult with = run_rod_impact_2d(options);
  options.poisson_ratio = 0.0;
  const RodImpact2dResult without = run_rod_impact_2d(options);
  print("nu = 0.3", with);
  EXPECT_GT(with.force_l2_error_2d, without.force_l2_error_2d + 0.01);
  EXPECT_LT(with.force_l2_error_2d, 0.2);
  // Impulse over the exact contact window: within 3 % of rho C0 V0 A * T.
  double impulse = 0.0, exact_impulse = 0.0;
  for (std::size_t k = 1; k < with.time.size(); ++k) {
    const double dt = with.time[k] - with.time[k - 1];
    impulse += 0.5 * (with.force_2d[k] + with.force_2d[k - 1]) * dt;
    exact_impulse += 0.5 * (with.exact_force[k] + with.exact_force[k - 1]) * dt;
  }
  std::cout << fmt::format("impulse 2-D / exact = {:.4f}\n", impulse / exact_impulse);
  EXPECT_NEAR(impulse / exact_impulse, 1.0, 0.03);
}

// Non-matching meshes: the striking strip's 5 interface nodes (4 elements across) meet a struck
// strip of 3 elements across, so 3 of them land inside its segments (node-to-segment, the
// segment's ends sharing the force by their weights) and 2 on its corners (node-to-node). With
// nu = 0 the 1-D physics holds exactly, so the force must match the matching-mesh run's.
TEST(RodImpact2d, NodeToSegmentContactCarriesTheSameForceAsMatchingMeshes) {
  RodImpact2dOptions options = suzuki_toi_rods_2d();
  options.poisson_ratio = 0.0;
  const RodImpact2dResult matching = run_rod_impact_2d(options);
  options.elements_across_struck = 3;
  const RodImpact2dResult segments = run_rod_impact_2d(options);
  print("node-to-segment, nu = 0", segments);
  EXPECT_EQ(segments.contact_links, 5);
  std::cout << fmt::format("force_l2_error: matching {:.4f}, node-to-segment {:.4f}\n",
                           matching.force_l2_error_2d, segments.force_l2_error_2d);
  EXPECT_NEAR(segments.force_l2_error_2d, matching.force_l2_error_2d, 0.02);
  EXPECT_NEAR(segments.peak_force_2d / segments.exact_peak_force,
              matching.peak_force_2d / matching.exact_peak_force, 0.15);
}

}  // namespace
}  // namespace pound::verification
