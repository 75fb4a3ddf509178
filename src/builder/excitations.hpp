#pragma once
// The model's ground motion from the records of spec.excitations (read and converted to model
// units by io/): each scaled as its excitation says (a factor, a target PGA or Sa in g, times a
// batch's IDA factor), uniform along its direction or moving the supports it names, each after
// its wave-passage delay.
#include <vector>

#include "builder/resolver.hpp"
#include "model/model.hpp"

namespace pound::builder {

// Adds the excitations to `model` (its supports already there); returns the factor each record
// was multiplied by. A support that does not hold the record's direction is an InputError.
std::vector<double> resolve_excitations(const Resolver& resolver,
                                        const std::vector<model::GroundMotion>& motions,
                                        model::Model& model);

// What the records decide of the analysis: its duration when the file gives none (the longest
// record, delays included), and adaptive stepping's longest step (the records' sampling).
void fit_analysis_to_records(AnalysisSpec& analysis, const model::Model& model);

}  // namespace pound::builder
