#pragma once
// `pound run --ensemble N`: the model's run and N copies of it with every record scaled by
// 1 + s k eps (s = +-1, k = 1, 2, ...: 1 + eps, 1 - eps, 1 + 2 eps, ...), perturbations at the
// level of numerical noise. After the first impacts pounding is chaotic (issue 20: a 1e-4 change
// of the record moved the bundled bridge's abutment peak force 6.7-10.6 MN), so a single run's
// late peak is one sample of a spread. For every number of summary.json the ensemble gives the
// unperturbed value, the median, the 16 and 84 % quantiles (type 7) and the range of the copies,
// and calls it robust when its 16-84 % spread is within `robust_spread` of its size (the
// largest |value| over the runs). In a linear model every response scales with the record, so
// its spread is the perturbations' own (2 k_max eps), far inside any threshold.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/model_run.hpp"

namespace pound::app {

struct EnsembleOptions {
  int copies = 0;               // N >= 1
  double perturbation = 1e-4;   // eps, in (0, 1e-2)
  double robust_spread = 0.05;  // relative 16-84 % spread of a robust quantity, in (0, 1)
  int jobs = 0;                 // threads; 0: every core
};

struct QuantitySpread {
  std::string path;  // in summary.json, array items by id ("/links/bridge.a1.backfill/peak_force")
  double unperturbed = 0.0;
  double median = 0.0, p16 = 0.0, p84 = 0.0, min = 0.0, max = 0.0;  // over the completed copies
  double spread = 0.0;  // (p84 - p16) / the largest |value| over the runs (0 when all are 0)
  // |unperturbed - median| over the same size: how far the single run lies from the copies.
  double deviation = 0.0;
  // spread within the threshold and the unperturbed run within half of it of the median: with
  // one or two copies the band alone is narrow by construction (a rattling block's 28 impacts
  // against copies of 19 and 20 had a spread of 0.024).
  bool robust = true;
  // One of the numbers damage is judged by (peak forces, impacts, drifts, ductilities, joint
  // openings and seat movements), which the report and ensemble.png show.
  bool headline = false;
};

struct EnsembleResult {
  RunOutcome unperturbed;
  std::vector<double> factors;        // the copies' record factors, in order
  std::vector<std::string> failures;  // per copy: empty when it completed
  std::vector<QuantitySpread> quantities;
  std::vector<results::CaseSummary> copies;           // each copy's case summary, in order
  double copies_setup_s = 0.0, copies_solve_s = 0.0;  // summed over the copies (RunOutcome's)
  int failed() const;
  // The unperturbed case summary with each response (results/batch_quantities.hpp) replaced by
  // its median over the completed copies (left as it is where a copy lacks it, or none
  // completed): a batch row that a chaotic peak does not decide alone.
  results::CaseSummary median_summary() const;
  // A batch row: the medians (`medians`, where the run completed) or the unperturbed run's
  // numbers, with each copy that failed counted among its warnings: a failed copy is left out of
  // the medians, and its case must be read before them (a collapse there biases them low).
  results::CaseSummary row_summary(bool medians) const;
};

// What is wrong with the options: the number as Python's pound.run names it ("ensemble",
// "perturbation", "robust_spread", "jobs") and why; option() is the command line's name for it.
struct EnsembleOptionsError {
  std::string argument;
  std::string why;
  std::string option() const;  // "--robust-spread"
};
std::optional<EnsembleOptionsError> ensemble_options_error(const EnsembleOptions& options);

// Runs the model as `request` asks (its histories included) and the copies (histories off) on
// `jobs` threads; the numbers do not depend on the thread count. InputErrors throw as run_model's.
// `copy_done` (if any) is called with 0 as the copies start and after each copy with the copies
// done, and their number, one call at a time; the copies report no progress of their own
// (request.progress is the unperturbed run's).
EnsembleResult run_ensemble(
    const RunRequest& request, const EnsembleOptions& options,
    const std::function<void(std::size_t done, std::size_t total)>& copy_done = {});

// The lines `pound run` prints: the perturbations, and the quantities that are not robust.
std::string ensemble_report(const EnsembleResult& result, const EnsembleOptions& options);

// ensemble.json: the options, the factors, the failures and every quantity's spread.
io::Document ensemble_document(const EnsembleResult& result, const EnsembleOptions& options);

}  // namespace pound::app
