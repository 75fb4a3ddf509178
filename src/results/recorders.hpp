#pragma once
// Recorders: what a run keeps of each accepted step, only for what the user asked for.
#include <memory>
#include <string>
#include <vector>

#include "builder/spec.hpp"
#include "core/table.hpp"
#include "integrators/integrator.hpp"
#include "results/ground_acceleration.hpp"
#include "results/observer.hpp"

namespace pound::results {

class Recorder : public Observer {
 public:
  virtual ~Recorder() = default;
  virtual const Table& table() const = 0;
  virtual const std::string& file() const = 0;
};

// Where a link's values sit in the state's link vectors: its normal row, and the tangential
// row right after it when the link has friction.
struct LinkRows {
  Index row = 0;
  bool friction = false;
};

// Columns time, <id>.force, <id>.penetration per link, and <id>.tangential_force, <id>.slide
// for a link with friction.
class LinkRecorder final : public Recorder {
 public:
  LinkRecorder(std::string file, std::vector<LinkRows> links, const std::vector<std::string>& ids);
  void record(const integrators::State& state) override;
  const Table& table() const override { return table_; }
  const std::string& file() const override { return file_; }

 private:
  std::string file_;
  std::vector<LinkRows> links_;
  Table table_;
};

// Columns time, <id>.u_x, <id>.v_x, <id>.a_rel_x, <id>.a_abs_x (and _y, _rz as the scene has
// them) per node. u, v and a_rel are relative to the ground (fixed DOFs record 0); a_abs is
// a_rel plus the ground's acceleration (a fixed DOF's is the ground's).
class NodeRecorder final : public Recorder {
 public:
  // equations[k][d]: equation of node k in direction d, or -1 where fixed; nodes[k] its index.
  NodeRecorder(std::string file, std::vector<std::vector<Index>> equations,
               std::vector<Index> nodes, const std::vector<std::string>& ids,
               builder::AccelerationFrame accelerations, GroundAcceleration& ground);
  void record(const integrators::State& state) override;
  const Table& table() const override { return table_; }
  const std::string& file() const override { return file_; }

 private:
  std::string file_;
  std::vector<std::vector<Index>> equations_;
  std::vector<Index> nodes_;
  bool relative_, absolute_;
  GroundAcceleration& ground_;
  Table table_;
};

// Pounding summary of one link over the run.
struct LinkSummary {
  int impacts = 0;                 // engagements: open -> force (contact, or a taut restrainer)
  double peak_force = 0.0;         // largest compression [F]
  double peak_tension = 0.0;       // largest tension (restrainers, hooks) [F]
  double peak_penetration = 0.0;   // [L]
  double peak_opening = 0.0;       // largest -delta: how far the joint opened [L]
  double impulse = 0.0;            // integral of F dt [F T]
  double work = 0.0;               // integral of F d(delta) [F L]: energy left in or taken by
                                   // the link; after separation, the energy it dissipated
  double first_contact = -1.0;     // time of the first step in contact, -1 if never
  double last_contact = -1.0;      // time of the last step in contact
  double final_force = 0.0;        // at the end of the run [F]
  double final_deformation = 0.0;  // delta at the end of the run (residual) [L]
};

class LinkSummaries : public Observer {
 public:
  explicit LinkSummaries(std::vector<Index> normal_rows)
      : rows_(std::move(normal_rows)), summaries_(rows_.size()) {}
  void record(const integrators::State& state) override;
  const std::vector<LinkSummary>& summaries() const { return summaries_; }

 private:
  std::vector<Index> rows_;
  std::vector<LinkSummary> summaries_;
  integrators::State previous_;
  bool started_ = false;
};

}  // namespace pound::results
