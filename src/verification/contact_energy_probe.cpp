#include "verification/contact_energy_probe.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "builder/build.hpp"
#include "core/errors.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/restitution.hpp"
#include "results/recorders.hpp"

namespace pound::verification {
namespace {

// M = diag(masses), no stiffness or damping: the free ends of one link.
class FreeMasses final : public integrators::SecondOrderSystem {
 public:
  FreeMasses(Vector masses, integrators::LinkSet links)
      : masses_(std::move(masses)), links_(std::move(links)) {}
  Index size() const override { return masses_.size(); }
  void multiply_mass(const Vector& x, Vector& y) const override { y = masses_.cwiseProduct(x); }
  const Vector* lumped_mass() const override { return &masses_; }
  bool has_damping() const override { return false; }
  void multiply_damping(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  void multiply_stiffness(const Vector& x, Vector& y) const override { y.setZero(x.size()); }
  bool has_external_force() const override { return false; }
  void external_force(double, Vector& force) const override { force.setZero(size()); }
  std::unique_ptr<integrators::LinearSolver> factor(double c_m, double, double) const override {
    return std::make_unique<Diagonal>(c_m * masses_);
  }
  integrators::LinkSet& links() override { return links_; }

 private:
  class Diagonal final : public integrators::LinearSolver {
   public:
    explicit Diagonal(Vector diagonal) : diagonal_(std::move(diagonal)) {}
    void solve(const Vector& rhs, Vector& solution) const override {
      solution = rhs.cwiseQuotient(diagonal_);
    }

   private:
    Vector diagonal_;
  };
  Vector masses_;
  integrators::LinkSet links_;
};

// The contact duration of the bare masses: half a period on the stiffness at touch, or the
// closed form of an elastic Hertz impact; 0 when the law has neither.
double bare_contact_duration(const links::LinkLaw& law, double effective_mass, double velocity) {
  const double touch = law.clone()->set_trial({1e-9, 1e-9, 0.0}).stiffness;
  if (touch > 0.0) return std::numbers::pi * std::sqrt(effective_mass / touch);
  constexpr double kDepth = 1e-4;
  const double shallow = law.clone()->set_trial({kDepth, 0.0, 0.0}).force;
  if (!(shallow > 0.0)) return 0.0;
  return links::hertz_impact(shallow / std::pow(kDepth, 1.5), effective_mass, velocity).duration;
}

// The created energy of one impact with first touch at `phase` of a step.
double created_at_phase(const links::LinkLaw& law, const links::LinkContext& context,
                        const builder::AnalysisSpec& analysis, double velocity, double duration,
                        double phase) {
  Vector masses(2);
  std::vector<integrators::LinkSet::Term> row;
  Index free = 0;
  if (!context.fixed_i) {
    masses[free] = context.mass_i;
    row.push_back({free++, 1.0});
  }
  if (!context.fixed_j) {
    masses[free] = context.mass_j;
    row.push_back({free++, -1.0});
  }
  masses.conservativeResize(free);
  const double dt = analysis.time_step, gap = velocity * dt * (2.0 + phase);
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(law.clone());
  FreeMasses system(masses, integrators::LinkSet(free, {row}, {gap}, std::move(laws)));
  // The closing velocity shared in inverse proportion to the masses (momentum zero).
  integrators::State state;
  state.displacement = Vector::Zero(free);
  state.velocity.resize(free);
  const double m_eff = context.effective_mass();
  for (Index k = 0; k < free; ++k)
    state.velocity[k] = row[k].coefficient * velocity * m_eff / masses[k];
  std::unique_ptr<integrators::Integrator> integrator = builder::make_integrator(analysis);
  integrators::TransientSettings settings = builder::make_transient_settings(analysis);
  settings.end_time = gap / velocity + 3.0 * duration + 2.0 * dt;
  settings.time_limit = 0.0;
  settings.max_steps = 0;
  results::LinkSummaries summaries({0});
  if (!analysis.integrator.is_explicit())
    summaries.set_step_forces(system.links().impulsive_hard_contact_rows(system.lumped_mass()));
  integrators::TransientAnalysis run(system, *integrator, settings);
  run.run(state, [&](const integrators::State& s, const integrators::StepResult&) {
    summaries.record(s);
  });
  return summaries.summaries()[0].created_energy() / (0.5 * m_eff * velocity * velocity);
}

}  // namespace

std::optional<ContactEnergyProbe> probe_contact_energy(const links::LinkLaw& law,
                                                       const links::LinkContext& context,
                                                       const builder::AnalysisSpec& analysis,
                                                       double approach_velocity) {
  constexpr double kMostSteps = 20000.0;
  if (!(approach_velocity > 0.0) || !(analysis.time_step > 0.0)) return std::nullopt;
  if ((context.fixed_i && context.fixed_j) || (!context.fixed_i && !(context.mass_i > 0.0)) ||
      (!context.fixed_j && !(context.mass_j > 0.0)))
    return std::nullopt;
  ContactEnergyProbe probe;
  probe.contact_duration = bare_contact_duration(law, context.effective_mass(), approach_velocity);
  if (!(probe.contact_duration > 0.0) ||
      probe.contact_duration / analysis.time_step > kMostSteps / 4.0)
    return std::nullopt;
  try {
    for (const double phase : {0.125, 0.375, 0.625, 0.875})
      probe.created_fraction = std::max(probe.created_fraction,
                                        created_at_phase(law, context, analysis, approach_velocity,
                                                         probe.contact_duration, phase));
  } catch (const SolveError&) {
    return std::nullopt;  // the run itself will say why the step fails
  }
  return probe;
}

}  // namespace pound::verification
