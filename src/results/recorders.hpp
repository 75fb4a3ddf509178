#pragma once
// Recorders: what a run keeps of each accepted step, only for what the user asked for.
#include <memory>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "integrators/integrator.hpp"

namespace pound::results {

class Recorder {
 public:
  virtual ~Recorder() = default;
  virtual void record(const State& state) = 0;
  virtual const Table& table() const = 0;
  virtual const std::string& file() const = 0;
};

// Columns time, <id>.force, <id>.penetration per link.
class LinkRecorder final : public Recorder {
 public:
  LinkRecorder(std::string file, std::vector<Index> links, const std::vector<std::string>& ids);
  void record(const State& state) override;
  const Table& table() const override { return table_; }
  const std::string& file() const override { return file_; }

 private:
  std::string file_;
  std::vector<Index> links_;
  Table table_;
};

// Columns time, <id>.u_x, <id>.v_x, <id>.a_x (and _y in 2-D) per node; fixed DOFs record 0.
class NodeRecorder final : public Recorder {
 public:
  // equations[k][d]: equation of node k in direction d, or -1 where fixed.
  NodeRecorder(std::string file, std::vector<std::vector<Index>> equations,
               const std::vector<std::string>& ids);
  void record(const State& state) override;
  const Table& table() const override { return table_; }
  const std::string& file() const override { return file_; }

 private:
  std::string file_;
  std::vector<std::vector<Index>> equations_;
  Table table_;
};

// Pounding summary of one link over the run.
struct LinkSummary {
  int impacts = 0;                  // closings (open -> contact)
  double peak_force = 0.0;          // [F]
  double peak_penetration = 0.0;    // [L]
  double impulse = 0.0;             // integral of F dt [F T]
  double work = 0.0;                // integral of F d(delta) [F L]: energy left in or taken by
                                    // the link; after separation, the energy it dissipated
  double first_contact = -1.0;      // time of the first step in contact, -1 if never
  double last_contact = -1.0;       // time of the last step in contact
};

class LinkSummaries {
 public:
  explicit LinkSummaries(Index links) : summaries_(static_cast<std::size_t>(links)) {}
  void record(const State& state);
  const std::vector<LinkSummary>& summaries() const { return summaries_; }

 private:
  std::vector<LinkSummary> summaries_;
  State previous_;
  bool started_ = false;
};

}  // namespace pound::results
