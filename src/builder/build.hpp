#pragma once
// Spec -> model: expands generators, resolves every id reference and checks what the reader
// cannot see alone (dangling or duplicate ids across generated parts, zero-length elements,
// links joining a node to itself, links without an axis). Errors are InputErrors with the
// file and the JSON path of the offending entry.
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "assembly/structural_system.hpp"
#include "builder/excitations.hpp"
#include "builder/outputs.hpp"
#include "builder/spec.hpp"
#include "integrators/integrator.hpp"
#include "integrators/transient_analysis.hpp"
#include "model/model.hpp"

namespace pound::builder {

struct BuiltModel {
  model::Model model;
  std::map<std::string, Index> node_index;
  // The JSON path of each node: its own entry, or the generator that made it.
  std::vector<std::string> node_origins;
  std::map<std::string, Index> link_index;
  std::vector<std::string> link_origins;  // the JSON path of each link, as node_origins
  AnalysisSpec analysis;
  std::vector<ResolvedRecorder> recorders;
  std::vector<DriftMonitor> drift_monitors;
  std::vector<JointMonitor> joint_monitors;
  // The rod pairs the model was generated from, when it is exactly one rod pair and nothing else
  // (then the exact solution applies and `run` reports the verification metrics).
  std::optional<RodPairSpec> sole_rod_pair;
  // The factor each record of spec.excitations was multiplied by (its scale times extra_factor).
  std::vector<double> excitation_factors;
  std::vector<ScaledPeak> excitation_peaks;  // per excitation, in g
  // Per uniform excitation of the model, the spec's excitation it came from (a pair gives two).
  std::vector<std::size_t> uniform_excitation_sources;
  UnitNames units;  // of spec.units, for the outputs' headers
};

// The size of the model a spec makes, generators included, known before anything is built (a
// generator asked for 10^9 elements must be refused, not allocated): nodes and an upper bound on
// the DOFs, and the entry that makes the most nodes, for the message.
struct ModelSize {
  std::size_t nodes = 0;
  std::size_t dofs = 0;  // nodes x DOFs per node of the scene (1 in 1-D, at most 3 in 2-D)
  std::string largest_path = "/nodes";
  std::size_t largest_nodes = 0;
};
ModelSize model_size(const ModelSpec& spec);

// `motions`: the records of spec.excitations, read and converted to model units (io/); the
// builder scales them as the spec says. `second_motions`: per excitation, a pair's second
// component (empty: none has one).
BuiltModel build(const ModelSpec& spec, const std::vector<model::GroundMotion>& motions = {},
                 const std::vector<std::optional<model::GroundMotion>>& second_motions = {});

// A sliding bearing seated under the weight: friction, no gap, a static start under loads or
// gravity with a part along the link's axis (a horizontal push alone seats nothing). It carries the
// weight from the start and strikes nothing unless it lifts off, so it is no pounding contact (no
// impact warnings before the run; not counted in a case's impacts and pounding force).
bool seated_under_weight(const model::Link& link, const BuiltModel& built);

std::unique_ptr<integrators::Integrator> make_integrator(const AnalysisSpec& analysis);
// The longest stable step of an implicit method stable only below a limit of omega dt
// (IntegratorEntry::stability_limit: linear acceleration), omega_max with the links in contact;
// none for the others, or where a DOF has no lumped mass (the method condenses such DOFs, so
// the eigenproblem is another) or omega_max overflows.
std::optional<double> conditional_stable_step(const integrators::IntegratorChoice& integrator,
                                              assembly::StructuralSystem& system);
integrators::TransientSettings make_transient_settings(const AnalysisSpec& analysis);
// For central difference: sets an "auto" step from the stable limit (links in contact), or
// refuses one above it with the limit in the message, before any step is taken. A free DOF
// without lumped mass is refused naming its node. An implicit method stable only below a limit
// (linear acceleration) has a step above it refused the same way.
void settle_time_step(AnalysisSpec& analysis, const model::Model& model,
                      assembly::StructuralSystem& system, const std::string& source);

}  // namespace pound::builder
