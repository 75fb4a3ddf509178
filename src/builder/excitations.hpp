#pragma once
// The model's ground motion from the records of spec.excitations (read and converted to model
// units by io/): each scaled as its excitation says (a factor, a target PGA or Sa in g, times a
// batch's IDA factor), uniform along its direction or moving the supports it names, each after
// its wave-passage delay.
#include <optional>
#include <string>
#include <vector>

#include "builder/resolver.hpp"
#include "model/model.hpp"

namespace pound::builder {

// The largest |a| of an excitation's scaled record (a pair's stronger component), in g.
struct ScaledPeak {
  std::string record;  // its name (a pair's stronger component's)
  double in_g = 0.0;
};

// Per excitation of the spec: the factor its record was multiplied by (a pair's two components by
// the same one), and its scaled peak.
struct ExcitationScaling {
  std::vector<double> factors;
  std::vector<ScaledPeak> peaks;
  // For each uniform excitation of the model (a pair gives two), the spec's excitation it came
  // from: where a message about it points (/excitations/k).
  std::vector<std::size_t> uniform_sources;
};

// Adds the excitations to `model` (its supports already there). A support that does not hold
// the record's direction is an InputError; so are a pair's components on different time grids.
// `second_motions`: per excitation, a pair's second component (may be empty: none).
ExcitationScaling resolve_excitations(
    const Resolver& resolver, const std::vector<model::GroundMotion>& motions,
    const std::vector<std::optional<model::GroundMotion>>& second_motions, model::Model& model);

// The direction of a pair's `component` (0: the first, 1: the second) in the x-y plane.
model::Coordinates pair_direction(const PairSpec& pair, int component);

// What the records decide of the analysis: its duration when the file gives none (the longest
// record, delays included), and adaptive stepping's longest step (the records' sampling).
void fit_analysis_to_records(AnalysisSpec& analysis, const model::Model& model);

}  // namespace pound::builder
