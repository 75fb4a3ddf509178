#pragma once
// The response quantities of `pound batch`, in one table: the numeric columns of
// batch_summary.csv that batch_stats.json summarises per model and scale, that a set's limits
// may name, and that tools/plot_batch.py draws (it reads the table from batch_stats.json).
// A new quantity is a member of CaseSummary and a row here.
#include <optional>
#include <span>
#include <string_view>

#include "core/units.hpp"
#include "results/case_summary.hpp"

namespace pound::results {

struct BatchQuantity {
  std::string_view name;                      // its column and its key in batch_stats.json
  std::optional<double> CaseSummary::*value;  // where a case keeps it (absent: no such part)
  std::string_view meaning;                   // what it is, with its units
  std::string_view axis_label;                // for figures
  // false for a check of the analysis rather than a response of the structure (not plotted
  // unless asked for).
  bool response = true;
  // A running peak (largest so far): a run that stopped early has at least the value it
  // reached, so past a limit it exceeded it. Not so a value at the record's end (residual drift).
  bool running_peak = true;
  // What it measures, in each model's units (none: a count or a ratio).
  Dimension dimension = Dimension::none;
};

// In the order of their columns.
std::span<const BatchQuantity> batch_quantities();

// The quantity of that name, or nullptr.
const BatchQuantity* find_batch_quantity(std::string_view name);

}  // namespace pound::results
