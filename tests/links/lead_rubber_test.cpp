// The lead-rubber isolator and the elastic-perfectly-plastic spring, made from their registry
// entries: the closed-form cycle of an isolator (energy dissipated per cycle and effective
// stiffness, the two numbers an isolation design rests on) and the EPP loop.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "links/bilinear_spring.hpp"
#include "links/law_registry.hpp"

namespace pound::links {
namespace {

std::unique_ptr<LinkLaw> make(const std::string& type,
                              const std::map<std::string, double>& numbers) {
  return make_law({type, numbers}, {"test.json", "/links/0/law"})(LinkContext{});
}

LinkKinematics at(double penetration) { return {penetration, 0.0, 0.0}; }

// A loop that starts at the peak +D and goes to -D and back, through every point of `path` (the
// ends of the loop's straight pieces) in `per_piece` committed steps each; the trapezoidal sum of
// F d(delta), exact when the force is linear between the points of `path`.
double loop_energy(LinkLaw& law, const std::vector<double>& path, int per_piece) {
  double energy = 0.0, previous = path.front();
  double previous_force = law.set_trial(at(previous)).force;
  law.commit();
  for (std::size_t piece = 1; piece < path.size(); ++piece)
    for (int i = 1; i <= per_piece; ++i) {
      const double delta = path[piece - 1] + (path[piece] - path[piece - 1]) * i / per_piece;
      const double force = law.set_trial(at(delta)).force;
      law.commit();
      energy += 0.5 * (force + previous_force) * (delta - previous);
      previous = delta;
      previous_force = force;
    }
  return energy;
}

// Loads from 0 to +D in steps (through the yield point) and returns the force there.
double load_to(LinkLaw& law, double yield, double peak) {
  for (double delta : {0.5 * yield, yield, 0.5 * (yield + peak), peak}) {
    law.set_trial(at(delta));
    law.commit();
  }
  return law.set_trial(at(peak)).force;
}

// Q_d = 150 kN, k_d = 1.2 kN/mm, k_u = 11 kN/mm: delta_y = Q_d / (k_u - k_d).
constexpr double kStrength = 1.5e5, kPostYield = 1.2e6, kElastic = 1.1e7;

TEST(LeadRubber, CycleDissipatesFourQdTimesDMinusDyWithSecantStiffnessKdPlusQdOverD) {
  // The elastic line k_u delta meets the post-yield line k_d delta + Q_d at delta_y; after a
  // reversal at D the bearing is elastic until the force has dropped by 2 (Q_d + k_d delta_y),
  // i.e. until D - 2 delta_y.
  const double yield = kStrength / (kElastic - kPostYield);
  for (double ductility : {1.5, 4.0, 20.0}) {
    const double peak = ductility * yield;
    auto law = make("lead_rubber", {{"characteristic_strength", kStrength},
                                    {"post_yield_stiffness", kPostYield},
                                    {"elastic_stiffness", kElastic}});
    const double force = load_to(*law, yield, peak);
    const double secant = force / peak, secant_exact = kPostYield + kStrength / peak;
    const std::vector<double> path = {peak, peak - 2 * yield, -peak, -peak + 2 * yield, peak};
    const double energy = loop_energy(*law, path, 7);
    const double energy_exact = 4.0 * kStrength * (peak - yield);
    const double energy_error = std::abs(energy / energy_exact - 1.0);
    const double secant_error = std::abs(secant / secant_exact - 1.0);
    std::cout << "D = " << ductility << " D_y: EDC " << energy << " (exact " << energy_exact
              << ", relative error " << energy_error << "), k_eff " << secant << " (exact "
              << secant_exact << ", relative error " << secant_error << ")\n";
    EXPECT_LT(energy_error, 1e-9);
    EXPECT_LT(secant_error, 1e-9);
    // Back at +D the loop has closed.
    EXPECT_NEAR(law->set_trial(at(peak)).force, force, 1e-9 * force);
  }
}

// Pushed to D and held, a bearing has dissipated Q_d (D - delta_y), its lead's slip; the rest of
// the work, k_d D^2 / 2 in its rubber and the lead's elastic part, it holds (stored_energy):
// F^2 / 2k_u alone called 3.65 times the lead's work dissipated at D = 0.3 m.
TEST(LeadRubber, HeldAtItsPeakItHasDissipatedOnlyTheLeadsSlip) {
  for (const double peak : {0.05, 0.3}) {
    const std::unique_ptr<LinkLaw> law =
        make("lead_rubber", {{"characteristic_strength", kStrength},
                             {"post_yield_stiffness", kPostYield},
                             {"elastic_stiffness", kElastic}});
    const double yield = kStrength / (kElastic - kPostYield);
    const double work = loop_energy(*law, {0.0, yield, peak}, 200);
    const double force = law->set_trial(at(peak)).force;
    const double dissipated = work - *law->stored_energy(force, peak);
    std::printf("D = %g: work %.9g, dissipated %.9g, Q_d (D - d_y) %.9g\n", peak, work, dissipated,
                kStrength * (peak - yield));
    EXPECT_NEAR(dissipated, kStrength * (peak - yield), 1e-9 * work);
  }
}

TEST(LeadRubber, ElasticStiffnessDefaultsToTenTimesThePostYieldOne) {
  auto law = make("lead_rubber",
                  {{"characteristic_strength", kStrength}, {"post_yield_stiffness", kPostYield}});
  EXPECT_EQ(law->name(), "lead_rubber");
  EXPECT_DOUBLE_EQ(law->set_trial(at(1e-6)).stiffness, 10.0 * kPostYield);
  EXPECT_DOUBLE_EQ(*law->yield_deformation(), kStrength / (9.0 * kPostYield));
  // Far past yield the force is on k_d delta + Q_d.
  EXPECT_NEAR(law->set_trial(at(0.3)).force, kPostYield * 0.3 + kStrength, 1e-9 * kStrength);
}

TEST(LeadRubber, RefusesAnElasticStiffnessNotAboveThePostYieldOne) {
  for (double elastic : {kPostYield, 0.5 * kPostYield}) {
    std::optional<InputError> error;
    try {
      (void)make("lead_rubber", {{"characteristic_strength", kStrength},
                                 {"post_yield_stiffness", kPostYield},
                                 {"elastic_stiffness", elastic}});
    } catch (const InputError& caught) {
      error = caught;
    }
    ASSERT_TRUE(error.has_value());
    std::cout << error->where() << ": " << error->reason() << "\n";
    EXPECT_EQ(error->where(), "/links/0/law/elastic_stiffness");
  }
}

TEST(LeadRubber, ElasticPerfectlyPlasticLoopDissipatesFourFyTimesDMinusDy) {
  constexpr double kStiffness = 2e7, kYieldForce = 1e5, yield = kYieldForce / kStiffness;
  for (double ductility : {2.0, 8.0}) {
    const double peak = ductility * yield;
    auto law = make("elastic_perfectly_plastic",
                    {{"stiffness", kStiffness}, {"yield_force", kYieldForce}});
    EXPECT_EQ(law->name(), "elastic_perfectly_plastic");
    const double force = load_to(*law, yield, peak);
    EXPECT_DOUBLE_EQ(force, kYieldForce);
    const std::vector<double> path = {peak, peak - 2 * yield, -peak, -peak + 2 * yield, peak};
    const double energy = loop_energy(*law, path, 5);
    const double exact = 4.0 * kYieldForce * (peak - yield);
    const double error = std::abs(energy / exact - 1.0);
    std::cout << "EPP, D = " << ductility << " D_y: loop energy " << energy << " (exact " << exact
              << ", relative error " << error << ")\n";
    EXPECT_LT(error, 1e-9);
    // The permanent deformation after the loop: the spring unloads elastically from +F_y.
    EXPECT_NEAR(dynamic_cast<const BilinearSpring&>(*law).plastic_deformation(), peak - yield,
                1e-12 * peak);
  }
}

}  // namespace
}  // namespace pound::links
