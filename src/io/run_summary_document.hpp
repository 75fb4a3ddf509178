#pragma once
// summary.json of a run (results/run_summary.hpp) as a document: the status and statistics, every
// link's pounding summary, the drift and joint monitors, the energy balance and the warnings.
#include <string>

#include "io/document.hpp"
#include "results/run_summary.hpp"

namespace pound::io {

Document to_document(const results::RunSummary& run, const std::string& model_path,
                     const std::string& title);

}  // namespace pound::io
