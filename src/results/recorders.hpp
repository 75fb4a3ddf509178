#pragma once
// Recorders: what a run keeps of each accepted step, only for what the user asked for.
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "builder/spec.hpp"
#include "core/table.hpp"
#include "core/units.hpp"
#include "integrators/integrator.hpp"
#include "model/element.hpp"
#include "results/ground_acceleration.hpp"
#include "results/observer.hpp"
#include "results/support_motion.hpp"
#include "results/term_sums.hpp"

namespace pound::results {

class Recorder : public Observer {
 public:
  virtual ~Recorder() = default;
  virtual Table table() const = 0;  // what is written
  // The table, moved out once the run is over (no copy of a history for its writer).
  virtual Table take_table() { return table(); }
  virtual const std::string& file() const = 0;
  // The values it holds after `steps` steps over `duration` [T], for the memory check; 0 for a
  // recorder of constant size.
  virtual double held_values(double steps, double duration) const = 0;
  // Room for the values it will hold after `steps` steps over `duration` [T], before the run:
  // a history that grows by doubling copies itself and faults in fresh pages as it goes.
  virtual void reserve(double /*steps*/, double /*duration*/) {}
};

// The quantities a recorder takes from each state, with their column names and what each
// measures.
class Quantities {
 public:
  virtual ~Quantities() = default;
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<Dimension>& dimensions() const { return dimensions_; }
  // values: one per name, in order.
  virtual void take(const integrators::State& state, double* values) const = 0;

 protected:
  void add(std::string name, Dimension dimension) {
    names_.push_back(std::move(name));
    dimensions_.push_back(dimension);
  }

 private:
  std::vector<std::string> names_;
  std::vector<Dimension> dimensions_;
};

// The units of these dimensions, in order.
std::vector<std::string> unit_names(const UnitNames& units,
                                    const std::vector<Dimension>& dimensions);

// Where a link's values sit in the state's link vectors: its normal row, and its tangential
// rows right after it when the link has friction (one in a plane, two in 3-D).
struct LinkRows {
  Index row = 0;
  Index tangents = 0;
  bool rotational = false;  // a hinge: a moment and a rotation
};

// <id>.force, <id>.penetration per link (a moment and a rotation, in their units, for a
// rotational link), and <id>.tangential_force, <id>.slide for a link with
// friction in a plane (<id>.tangential_force_1, <id>.slide_1, <id>.tangential_force_2,
// <id>.slide_2 along t_1 and t_2 in 3-D).
class LinkQuantities final : public Quantities {
 public:
  LinkQuantities(std::vector<LinkRows> links, const std::vector<std::string>& ids);
  void take(const integrators::State& state, double* values) const override;

 private:
  std::vector<LinkRows> links_;
};

// <id>.u_x, <id>.v_x, <id>.a_rel_x, <id>.a_abs_x (and _y, _rz as the scene has them) per node.
// u, v and a_rel are relative to the ground (fixed DOFs give 0); a_abs is a_rel plus the
// ground's acceleration (a fixed DOF's is the ground's).
class NodeQuantities final : public Quantities {
 public:
  // readings[k][i]: node k in direction directions[k][i] (model::direction of a scene of
  // `dimension`), no terms where fixed; nodes[k] its index.
  NodeQuantities(std::vector<std::vector<DofReading>> readings,
                 std::vector<std::vector<int>> directions, int dimension, std::vector<Index> nodes,
                 const std::vector<std::string>& ids, builder::AccelerationFrame accelerations,
                 GroundAcceleration& ground);
  void take(const integrators::State& state, double* values) const override;

 private:
  std::vector<std::vector<DofReading>> readings_;
  std::vector<Index> nodes_;
  bool relative_, absolute_;
  GroundAcceleration& ground_;
  std::vector<std::vector<int>> directions_;
};

// <id>.<force> per element, Element::end_force_names (beams N_i, V_i, M_i, N_j, V_j, M_j;
// trusses N), from the displacements of its DOFs (fixed ones 0): the elastic forces K_e u_e in
// the element's axes, as the nodes act on it, without damping or second-order terms.
class ElementQuantities final : public Quantities {
 public:
  // readings[k]: each of elements[k]'s dofs(), no terms where fixed. wanted[k]: the end forces
  // taken of elements[k] (places in its end_force_names()), in that order; empty: all of every
  // element's.
  ElementQuantities(std::vector<std::shared_ptr<const model::Element>> elements,
                    std::vector<std::vector<DofReading>> readings,
                    std::vector<std::vector<std::size_t>> wanted = {});
  void take(const integrators::State& state, double* values) const override;
  // Read from the supports' total motion (the readings then name its entries): the forces of
  // members on moving supports.
  void read_total_motion(SupportMotion* support) { support_ = support; }

 private:
  // Each end force as one sum over the equations: its row of the element's end force map
  // (model::end_force_map) times the DOFs' readings, formed once.
  TermSums forces_;
  SupportMotion* support_ = nullptr;
};

// A time history: columns time and the quantities, a row per sampled step; `units` name the
// columns' units.
class HistoryRecorder final : public Recorder {
 public:
  HistoryRecorder(std::string file, std::unique_ptr<Quantities> quantities,
                  builder::OutputSampling sampling = {}, const UnitNames& units = {});
  void record(const integrators::State& state) override;
  Table table() const override { return table_; }
  Table take_table() override { return std::move(table_); }
  const Table& history() const { return table_; }
  const std::string& file() const override { return file_; }
  double held_values(double steps, double duration) const override;
  void reserve(double steps, double duration) override;

 private:
  bool due(double time);
  double rows_after(double steps, double duration) const;

  std::string file_;
  std::unique_ptr<Quantities> quantities_;
  builder::OutputSampling sampling_;
  long step_ = 0;            // states seen
  double next_time_ = 0.0;   // with an interval: the next multiple due
  std::vector<double> row_;  // scratch
  Table table_;
};

// The envelope of the quantities over every step: a row per quantity (text columns "quantity"
// and its "unit") with max, time_of_max, min, time_of_min and abs_max (the larger of |max|,
// |min|). The first time a value is reached counts.
class EnvelopeRecorder final : public Recorder {
 public:
  EnvelopeRecorder(std::string file, std::unique_ptr<Quantities> quantities,
                   const UnitNames& units = {});
  void record(const integrators::State& state) override;
  Table table() const override;
  const std::string& file() const override { return file_; }
  double held_values(double, double) const override { return 0.0; }
  // The larger of |max| and |min| of quantity q so far.
  double abs_max(std::size_t q) const { return std::max(std::abs(max_[q]), std::abs(min_[q])); }

 private:
  std::string file_;
  std::unique_ptr<Quantities> quantities_;
  UnitNames units_;
  std::vector<double> row_, max_, min_, time_of_max_, time_of_min_;
  bool started_ = false;
};

// A bearing's shear over the run (a link with a coupled shear; a hinge's bending across its
// axis): the resultant of its tangential rows, |F_t| and |s|, and each row's.
struct ShearSummary {
  double peak_force = 0.0;         // [F]
  double peak_deformation = 0.0;   // [L]
  double work = 0.0;               // integral of F_t . ds [F L]
  double final_force = 0.0;        // [F]
  double final_deformation = 0.0;  // residual [L]
  // Along each tangent: the largest |s_a| [L] and |F_a| [F], and F_a at the end [F].
  std::array<double, 2> peak_deformations{}, peak_forces{}, final_forces{};
  std::array<double, 2> final_deformations{};  // s_a at the end [L]
  // F_a at the start of a run begun at rest (a static initial state's), else 0: the spring's own
  // force there, what it held before the run did any work [F].
  std::array<double, 2> initial_forces{};
  std::array<double, 2> initial_deformations{};  // s_a with them [L]
  // The largest |(s_1 / delta_y1, s_2 / delta_y2)|: the resultant's ductility on an elliptic
  // surface (0 while the law has no yield).
  double peak_ductility = 0.0;
};

// A link's shear rows: how many follow its normal row, and each one's yield deformation
// (infinite: elastic).
struct ShearRows {
  Index count = 0;
  std::array<double, 2> yield_deformation{};
};

// Pounding summary of one link over the run.
struct LinkSummary {
  int impacts = 0;                 // engagements: open -> force (contact, or a taut restrainer)
  double peak_force = 0.0;         // largest compression [F]
  double peak_tension = 0.0;       // largest tension (restrainers, hooks) [F]
  double peak_penetration = 0.0;   // [L]
  double peak_opening = 0.0;       // largest -delta: a contact's clear distance, gap included [L]
  double impulse = 0.0;            // integral of F dt [F T]
  double work = 0.0;               // integral of F d(delta) [F L]: energy left in or taken by
                                   // the link; after separation, the energy it dissipated
  double first_contact = -1.0;     // time of the first step in contact, -1 if never
  double last_contact = -1.0;      // time of the last step in contact
  double final_force = 0.0;        // at the end of the run [F]
  double final_deformation = 0.0;  // delta at the end of the run (residual) [L]
  // The force at the start of a run begun at rest (under a static initial state's loads), else
  // 0: with no velocity anywhere it is the law's own, held before the run did any work [F].
  double initial_force = 0.0;
  double initial_deformation = 0.0;  // delta with it [L]
  // Work done on the link in its current engagement (0 while open) [F L].
  double engagement_work = 0.0;
  // Energy the link gave the structure beyond what it had taken, summed over its engagements:
  // a passive contact or restrainer stores nothing once open, so an engagement that ends with
  // negative work has created that much (a penalty contact starting or ending inside a step).
  // Before its end an engagement counts when its work is negative, since what a law holds is
  // never negative. An engagement under way at the start (a preloaded contact under a static
  // initial state) held energy this run did not give it, so it does not count [F L].
  double finished_created_energy = 0.0;
  bool engaged_at_start = false;  // the current engagement began before the run
  double created_energy() const {
    return finished_created_energy + (engaged_at_start ? 0.0 : std::max(0.0, -engagement_work));
  }
  std::optional<ShearSummary> shear;  // a bearing's shear, on the rows after the normal one
};

class LinkSummaries : public Observer {
 public:
  // shear_rows[k]: the tangential rows after link k's normal row that are a bearing's shear
  // (count 0: none).
  explicit LinkSummaries(std::vector<Index> normal_rows,
                         const std::vector<ShearRows>& shear_rows = {});
  // By row of B: 1 where the state's force is its step's average (an implicit integrator's hard
  // contact: its impulse acts in the step that found it), so impulse and work take the rectangle
  // rule there, F_{n+1} dt and F_{n+1} d(delta), instead of the trapezoidal one.
  void set_step_forces(const std::vector<char>& by_row);
  void record(const integrators::State& state) override;
  // Work beyond what record() took, by row of B (EnergyBalance::extra_link_work): added to each
  // link's work, its shear's, and its engagement's.
  void add_work(const Vector& by_row);
  // Gathered from the running columns below at each call: take it once, not per link.
  const std::vector<LinkSummary>& summaries() const;

 private:
  // What every step updates, one array per quantity over the links (index k), so that one pass
  // vectorises: the bridge's 20 links cost 1,500 instructions a step as rows of LinkSummary.
  struct Running {
    std::vector<double> force, penetration, previous_force, previous_penetration;
    std::vector<double> peak_force, peak_tension, peak_penetration, peak_opening;
    std::vector<double> impulse, work, engagement_work, last_contact;
  };
  // The shear's resultant |x| over its rows.
  double resultant(const Vector& values, std::size_t k) const;
  void record_shear(const integrators::State& state, std::size_t k);
  // Engagements begun or ended this step (force from or to 0): counts and created energy.
  void record_engagements(double time);
  void record_initial_forces(const integrators::State& state);

  std::vector<Index> rows_;
  std::vector<ShearRows> shear_rows_;
  mutable std::vector<LinkSummary> summaries_;  // the rarely written fields live here
  std::vector<char> step_forces_;               // by summary
  Running running_;
  bool any_shear_ = false;
  integrators::State previous_;  // kept only for the shear rows
  double previous_time_ = 0.0;
  bool started_ = false;
};

}  // namespace pound::results
