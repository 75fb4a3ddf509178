#pragma once
// Statistics of a batch over ground-motion records: per model and scale, the median, 84th
// percentile and maximum of each response quantity; for each limit the fraction of records
// exceeding it at each scale, and a lognormal fragility fitted to every case of a model.
#include <optional>
#include <string>
#include <vector>

#include "builder/batch_spec.hpp"
#include "results/batch_quantities.hpp"
#include "results/case_summary.hpp"

namespace pound::results {

// Empirical quantile with linear interpolation between order statistics (Hyndman & Fan type 7,
// numpy's and R's default): the p-quantile of x(1) <= ... <= x(n) is at position (n - 1) p.
double quantile(std::vector<double> values, double probability);

struct ResponseStatistics {
  std::string quantity;
  std::size_t count = 0;  // completed cases that have the quantity
  double median = 0.0, p84 = 0.0, max = 0.0;
};

struct Exceedance {
  std::string quantity;
  double limit = 0.0;
  std::size_t count = 0;     // completed cases that have the quantity
  std::size_t exceeded = 0;  // of them, how many exceed the limit (value > limit)
  double fraction = 0.0;
};

struct ScaleGroup {
  std::string model;
  double scale = 1.0;
  std::size_t cases = 0, completed = 0;
  std::vector<ResponseStatistics> responses;
  std::vector<Exceedance> exceedances;
};

// P(exceed | IM = x) = Phi(ln(x / median) / dispersion), fitted by maximum likelihood to the
// (IM, exceeded?) of every case: a probit regression on ln IM, the maximum-likelihood fit Baker
// (2015, "Efficient analytical fragility function fitting using dynamic structural analysis",
// Earthquake Spectra 31(1)) recommends for multiple-stripe data, which scaled records give.
struct FragilityFit {
  std::string model, quantity;
  double limit = 0.0;
  std::size_t observations = 0, exceeded = 0;
  // The model's cases that gave no observation: failed or refused (but for a failure past the
  // limit), or without a positive intensity (a record of zeros).
  std::size_t left_out = 0;
  bool fitted = false;
  std::string reason;       // why there is no fit (no exceedance, all exceed, separated data, ...)
  double median = 0.0;      // [IM units]
  double dispersion = 0.0;  // beta, of ln IM
  double log_likelihood = 0.0;
};

struct FragilityObservation {
  double intensity = 0.0;  // > 0
  bool exceeded = false;
};

FragilityFit fit_lognormal_fragility(const std::vector<FragilityObservation>& observations);

struct BatchStatistics {
  std::size_t cases = 0, completed = 0, failed = 0, input_errors = 0;
  std::vector<ScaleGroup> groups;  // model by model, in the set's scale order
  std::vector<FragilityFit> fragilities;
};

BatchStatistics batch_statistics(const builder::SetSpec& set,
                                 const std::vector<CaseSummary>& cases);

}  // namespace pound::results
