#pragma once
// One run of a built model, watched and summed up: the observers every run has (its recorders,
// when histories are kept, the link summaries, the energy balance, the drift and joint monitors)
// and the pounding summary made of them, from which summary.json, the printed report and a batch
// row are written.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "builder/build.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/link_law.hpp"
#include "results/case_summary.hpp"
#include "results/energy_balance.hpp"
#include "results/monitors.hpp"
#include "results/recorders.hpp"

namespace pound::results {

class RunObservers {
 public:
  RunObservers(const builder::BuiltModel& built, const assembly::StructuralSystem& system,
               bool histories);
  // Its recorders and monitors refer to its ground_: it stays where it was made.
  RunObservers(const RunObservers&) = delete;
  RunObservers& operator=(const RunObservers&) = delete;
  // Every observer, then the check that the integration has not created energy: a run holding
  // more than kEnergyGrowthLimit of its largest energy term beyond what was put in stops (a
  // SolveError at the state's time) before it goes on to a NaN.
  void record(const integrators::State& state);
  // Further observers (verifications), told every step after the run's own.
  void add(Observer& observer) { extra_.push_back(&observer); }

  const std::vector<std::unique_ptr<Recorder>>& recorders() const { return recorders_; }
  const LinkSummaries& links() const { return links_; }
  const EnergyBalance& energy() const { return energy_; }
  const DriftMonitors& drifts() const { return drifts_; }
  // The drift monitors' end swing over the run's last `seconds` (DriftMonitors::set_swing_window).
  void set_swing_window(double seconds) { drifts_.set_swing_window(seconds); }
  // The peak |V_i| and |M_i| (none for a truss) of drift monitor k's base element, if it has one
  // (a 3-D beam's: its shear along the drift, its moment about the horizontal axis across it).
  std::optional<double> base_shear(std::size_t monitor) const;
  std::optional<double> base_moment(std::size_t monitor) const;
  const JointMonitors& joints() const { return joints_; }

 private:
  GroundAcceleration ground_;  // shared by the recorders and monitors below
  SupportMotion support_;      // shared by the monitors below
  std::vector<std::unique_ptr<Recorder>> recorders_;
  LinkSummaries links_;
  EnergyBalance energy_;
  int steps_creating_ = 0;  // consecutive steps above kEnergyGrowthLimit
  // Links are passive unless supports move under them (multi-support input, a moving belt),
  // which then feed energy in through them.
  bool passive_links_;
  DriftMonitors drifts_;
  // The drift monitors' base elements' end forces at each step, and where monitor k's are in
  // them (none without a base element): only their peak shear and moment are kept.
  // Its base element's shear and moment at end i, each one component (V_i, M_i of a plane beam)
  // or two (Vy_i, Vz_i and My_i, Mz_i of a 3-D one: along the drift's direction, and about the
  // horizontal axis across it); a truss has neither.
  struct BaseRows {
    std::vector<std::size_t> shear, moment;  // in base_row_
    // A 3-D beam's: each component's share of the shear along the drift and of the moment about
    // the horizontal axis across it (its local axis' global component); empty: the resultant.
    std::vector<double> shear_weights, moment_weights;
    // The elements above the base (builder::DriftMonitor::upper_elements): their shears, whose
    // largest the peak shear takes too.
    struct Shear {
      std::vector<std::size_t> components;
      std::vector<double> weights;
    };
    std::vector<Shear> upper;
    double peak_shear = 0.0, peak_moment = 0.0;
  };
  std::vector<std::optional<BaseRows>> base_rows_;
  std::unique_ptr<Quantities> base_forces_;
  std::vector<double> base_row_;
  void set_up_base_forces(const builder::BuiltModel& built,
                          const assembly::StructuralSystem& system);
  void record_base_forces(const integrators::State& state);
  JointMonitors joints_;
  std::vector<Observer*> extra_;
};

// The histories of `recorders` held until the run ends need 8 bytes per value and their text up to
// 24 more (every table is formatted before any is written), counted with a margin as 40: refuse
// a run whose histories would not fit in `available` bytes, before it starts.
void check_histories_fit(const std::vector<std::unique_ptr<Recorder>>& recorders,
                         const builder::AnalysisSpec& analysis,
                         std::optional<std::size_t> available, const std::string& model_path);
// Room in each history for the whole run (Recorder::reserve), once it fits.
void reserve_histories(const std::vector<std::unique_ptr<Recorder>>& recorders,
                       const builder::AnalysisSpec& analysis);

// How the run ended.
struct RunStatus {
  std::string failure;    // empty when completed
  double end_time = 0.0;  // the last time reached (the failure's time when failed)
  bool completed() const { return failure.empty(); }
};

// A friction pendulum's numbers (a friction link with a radius): mu, R and the stick spring k_t.
struct PendulumNumbers {
  double coefficient = 0.0, radius = 0.0, stick_stiffness = 0.0;
};

struct LinkResult {
  std::string id, law;
  bool hard_contact() const { return law == "hard_contact"; }  // a constraint, its impacts impulses
  links::LinkRole role = links::LinkRole::contact;
  LinkSummary summary;
  bool rotational = false;  // a hinge: deformations are rotations
  std::optional<PendulumNumbers> pendulum;
  // A sliding bearing seated under the weight (builder::seated_under_weight): a contact by its
  // law, but no pounding one.
  bool seated = false;
  // A contact or restrainer whose engagements' negative work is energy created (not a spring,
  // not a law with an inertia term).
  bool passive_engagements = false;
  // A yielding law's delta_y and its stiffness at rest (LinkLaw::yield_deformation).
  std::optional<double> yield_deformation, initial_stiffness;
  // What the law keeps at zero force at the end (LinkLaw::permanent_deformation): a yielded
  // restrainer's plastic elongation, the backfill soil's permanent deformation.
  double permanent_deformation = 0.0;
  double slack = 0.0;  // a restrainer's (LinkLaw::slack)
  double peak_deformation() const {
    return std::max(summary.peak_penetration, summary.peak_opening);
  }
  // What its ductility is measured in: peak |delta|, or a restrainer's peak elongation beyond
  // its slack (Caltrans SDC, DesRoches & Fenves 2000).
  double peak_demand() const {
    return role == links::LinkRole::tension ? std::max(0.0, summary.peak_opening - slack)
                                            : peak_deformation();
  }
  // peak_demand / delta_y; none for a hinge, whose elastic rotation is the numerical stiffness's
  // (the member's ductility is its drift monitor's).
  std::optional<double> ductility() const;
  // peak_demand - delta_y of a yielding law: a hinge's plastic rotation theta_p, the measure of
  // ASCE 41's hinge acceptance criteria and of the curvature ductility 1 + theta_p / (phi_y L_p).
  std::optional<double> peak_plastic_deformation() const;
  // What its added stiffness-proportional damping did (LinkLaw::viscous_part): part of
  // summary.work and of summary's forces, never of the hysteretic energy.
  links::ViscousPart viscous;
  // The elastic energy a yielding law held at the end and at the start (LinkLaw::stored_energy,
  // without the viscous part's force; F^2 / (2 k_0) where the law gives none).
  double final_stored_energy = 0.0, initial_stored_energy = 0.0;
  // Energy the law dissipated: its work less the change of the elastic energy it holds, both
  // without the viscous part. 0 for a restrainer that never yielded: an elastic cable dissipates
  // nothing, and its work's rest is the created energy of engagements inside a step.
  std::optional<double> hysteretic_energy() const;
  // A bearing's coupled shear (model::LinkShear) and, when it yields, its resultant's peak in
  // units of delta_y = F_y / k (of each direction's: the ellipse's; none for a hinge, as
  // ductility()), each direction's peak
  // plastic deformation (a hinge's theta_p about that tangent) and the energy it dissipated (its
  // work less sum_a F_a^2 / (2 k_a)).
  std::optional<model::LinkShear> shear;
  links::ShearViscousPart shear_viscous;  // what the shear's `rayleigh` did
  bool shear_yields() const;
  std::optional<double> shear_ductility() const;
  std::optional<double> shear_peak_plastic_deformation(std::size_t along) const;
  std::optional<double> shear_hysteretic_energy() const;
  // Friction on its tangential rows: summary.shear is then its slide (a resultant in a contact
  // plane), the tangential force and their work (friction's and a pendulum's restoring part).
  bool friction = false;
};

struct DriftResult {
  builder::DriftMonitor monitor;
  DriftPeak peak;
  double ratio() const { return peak.peak_drift / monitor.height; }
  double residual_ratio() const { return peak.residual_drift / monitor.height; }
  // With corners: the largest corner drift over the height, and over the centre's peak drift
  // (how much the twist adds at the floor's edge).
  std::optional<double> corner_ratio() const;
  std::optional<double> corner_amplification() const;
  // The largest drift ratio anywhere on the floor: the corners' where there are any.
  double largest_ratio() const { return std::max(ratio(), corner_ratio().value_or(0.0)); }
  // peak drift / yield drift where the model yields there (DriftMonitor::yields), along the
  // monitor's own direction (as codes check each principal direction)
  std::optional<double> ductility() const;
  // Where the two directions yield together on an ellipse: the peak of
  // sqrt((d_1 / d_y1)^2 + (d_2 / d_y2)^2) of its two drifts at each step (DriftMonitor::
  // yields_with: a storey's coupled link, a pier's biaxial hinge), which passes 1 when the
  // member yields, where each direction's ductility along a diagonal is 1/sqrt(2) of it.
  std::optional<double> resultant_ductility;
  // The larger of the two: what a member's yielding is judged by.
  std::optional<double> largest_ductility() const {
    if (!resultant_ductility) return ductility();
    return std::max(ductility().value_or(0.0), *resultant_ductility);
  }
  // the same ratio for an elastic member given a yield drift: a demand, not a ductility
  std::optional<double> elastic_demand_ratio() const;
  // 1 + theta_p / (phi_y L_p) of the member's hinge (DriftMonitor::curvature)
  std::optional<double> curvature_ductility;
  // Peak |shear| at the base of the storey or pier and, for a beam, |moment| there [F], [F L]
  // (DriftMonitor::base_element, shear_link).
  std::optional<double> peak_shear, peak_base_moment;
  // The top has no lumped mass along the drift (a pier of density 0): a static DOF, whose Newmark
  // acceleration is the step's double difference of its displacement, not an acceleration (a
  // massless pier top read 3x the massive one's). peak.peak_acceleration is then not reported.
  bool top_without_mass = false;
  std::optional<double> top_acceleration() const {
    return top_without_mass ? std::nullopt : std::optional<double>(peak.peak_acceleration);
  }
};

struct JointResult {
  builder::JointMonitor monitor;
  std::string link;  // id
  JointPeak peak;
  // A 3-D monitor with a direction (z up, as girder_bridge makes them): its girder end's turn in
  // plan is reported.
  bool in_space = false;
  std::optional<double> margin() const;  // to unseating, with a seat width
  bool unseated() const {
    return monitor.seat_width > 0.0 && peak.peak_unseating_movement >= monitor.seat_width;
  }
};

// What a run found, quantity by quantity.
// How an explicit run's step was chosen: its stable step, and whether the step is a fraction of
// it ("auto", or no step given).
struct StepChoice {
  std::optional<double> stable_time_step;  // central difference, links in contact
  bool automatic = false;                  // safety_factor x stable_time_step
  bool defaulted = false;                  // automatic because the model gave no step
  double safety_factor = 0.0;
  bool record_step = false;    // automatic, and the shortest record step was the shorter
  const char* rule = "given";  // builder::AnalysisSpec::time_step_rule
};

struct RunSummary {
  RunStatus status;
  std::string integrator;
  bool integrator_dissipates = false;  // damps the high modes by design (IntegratorEntry)
  double time_step = 0.0, duration = 0.0, run_time_s = 0.0;
  StepChoice step_choice;
  Index dofs = 0;
  integrators::TransientStatistics statistics;
  std::optional<integrators::AdaptiveStepping> adaptive;
  std::vector<LinkResult> links;
  std::vector<DriftResult> drifts;
  std::vector<JointResult> joints;
  EnergyTerms energy;
  double worst_balance_error = 0.0;
  std::vector<std::string> warnings;  // for results an engineer should not trust as they are
  bool p_delta = false;               // gravity's P-Delta acts (a yielded pier can run away)
  // The part of energy.links that yielding links dissipated (their hysteretic energy); none
  // when no link yields.
  std::optional<double> hysteretic_energy() const;
  // The energy contacts and restrainers gave the structure beyond what they took
  // (LinkSummary::created_energy, summed), and that over the energy put in: the input work, or
  // the initial energy when the run starts moving instead.
  double contact_created_energy() const;
  double contact_created_fraction() const;
};

// Above this fraction of the input the energy contacts created is a warning (issue: a gap
// spring whose contact starts inside a step gives back about 1 % on a record).
inline constexpr double kContactCreatedWarning = 0.01;

RunSummary summarise_run(const builder::BuiltModel& built, const assembly::StructuralSystem& system,
                         const RunObservers& observers, RunStatus status,
                         const integrators::TransientStatistics& statistics,
                         const std::string& integrator, double run_time);

// A batch row's responses (the case's name, record and intensity are the caller's).
void summarise_case(const RunSummary& run, CaseSummary& row);

}  // namespace pound::results
