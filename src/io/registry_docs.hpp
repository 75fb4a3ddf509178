#pragma once
// Generated docs from the registries: the law table of docs/laws.md (from each law's entry:
// formula, role and traits, parameters with units, source), the integrator table of
// docs/model_format.md (from the integrator catalog), and the vocabulary of the model fuzzer's
// dictionary (every key and name a model file may hold).
#include <vector>

#include "io/generated_docs.hpp"

namespace pound::io {

// "laws" (one row per law) and "law_parameters" (a table per law), for docs/laws.md.
std::vector<GeneratedSection> law_sections();
// "integrators", for docs/model_format.md.
GeneratedSection integrator_section();
// "model_vocabulary", for fuzz/model.dict: one quoted token a line.
GeneratedSection vocabulary_section();

}  // namespace pound::io
