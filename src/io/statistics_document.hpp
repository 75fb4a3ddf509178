#pragma once
// batch_stats.json: the statistics of a batch (results/batch_statistics.hpp) as a document.
#include "builder/batch_spec.hpp"
#include "io/document.hpp"
#include "results/batch_statistics.hpp"

namespace pound::io {

Document to_document(const results::BatchStatistics& statistics, const builder::SetSpec& set);

}  // namespace pound::io
