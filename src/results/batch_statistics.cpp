#include "results/batch_statistics.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pound::results {

double quantile(std::vector<double> values, double probability) {
  if (values.empty()) throw std::invalid_argument("quantile of no values");
  std::sort(values.begin(), values.end());
  const double position = probability * static_cast<double>(values.size() - 1);
  const auto below = static_cast<std::size_t>(std::floor(position));
  const std::size_t above = std::min(below + 1, values.size() - 1);
  const double weight = position - static_cast<double>(below);
  return values[below] + weight * (values[above] - values[below]);
}

namespace {

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::numbers::sqrt2); }
double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * std::numbers::pi); }

// Log-likelihood of the probit model P(exceed) = Phi(a + b ln x) and its gradient, with the
// ratios phi/Phi taken from erfc, which keeps them accurate far into the tails.
struct Likelihood {
  double value = 0.0;
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();  // expected (Fisher) information
};

Likelihood likelihood(const std::vector<FragilityObservation>& data, double a, double b) {
  Likelihood l;
  for (const FragilityObservation& o : data) {
    const double t = std::log(o.intensity);
    const double eta = a + b * t;
    const double p = normal_cdf(eta), q = normal_cdf(-eta), density = normal_pdf(eta);
    l.value += o.exceeded ? std::log(p) : std::log(q);
    const double score = o.exceeded ? density / p : -density / q;
    const double weight = density * density / (p * q);
    const Eigen::Vector2d x(1.0, t);
    l.gradient += score * x;
    l.information += weight * x * x.transpose();
  }
  return l;
}

// The quantity a limit is on. The set reader accepts no other names, so a stranger is a bug.
const BatchQuantity& limited_quantity(const builder::ResponseLimit& limit) {
  const BatchQuantity* quantity = find_batch_quantity(limit.quantity);
  if (!quantity) throw std::logic_error("a limit on an unknown quantity: " + limit.quantity);
  return *quantity;
}

// Where the intensities lie, overall and on either side of the limit.
struct IntensitySpread {
  std::size_t exceeded = 0;
  double lowest = INFINITY, highest = -INFINITY;
  double highest_safe = -INFINITY, lowest_exceeding = INFINITY;
};

IntensitySpread intensity_spread(const std::vector<FragilityObservation>& observations) {
  IntensitySpread spread;
  for (const FragilityObservation& o : observations) {
    if (!(o.intensity > 0.0) || !std::isfinite(o.intensity))
      throw std::invalid_argument("fragility: intensities must be positive");
    spread.exceeded += o.exceeded;
    spread.lowest = std::min(spread.lowest, o.intensity);
    spread.highest = std::max(spread.highest, o.intensity);
    if (o.exceeded)
      spread.lowest_exceeding = std::min(spread.lowest_exceeding, o.intensity);
    else
      spread.highest_safe = std::max(spread.highest_safe, o.intensity);
  }
  return spread;
}

// Why the data cannot identify a lognormal curve, or empty when they can.
std::string unidentifiable_reason(const IntensitySpread& spread, std::size_t observations) {
  if (spread.exceeded == 0) return "no case exceeds the limit";
  if (spread.exceeded == observations) return "every case exceeds the limit";
  // (To the last digits: records scaled to one target come out an ulp or so apart.)
  if (spread.highest - spread.lowest <= 1e-9 * spread.highest)
    return "every case has the same intensity: the dispersion is not identifiable";
  // Complete separation: the likelihood grows without bound as the dispersion goes to 0.
  if (spread.highest_safe <= spread.lowest_exceeding) {
    const std::string where =
        spread.highest_safe < spread.lowest_exceeding
            ? fmt::format("completely between intensities {:.4g} and {:.4g}", spread.highest_safe,
                          spread.lowest_exceeding)
            : fmt::format(
                  "at intensity {:.4g} (none exceeds below it, all do above it, some "
                  "at it: the median is there)",
                  spread.highest_safe);
    return fmt::format(
        "the cases separate {}: the dispersion is not identifiable (it tends to 0); "
        "run more records or scales around there",
        where);
  }
  return {};
}

// The (a, b) of the largest likelihood of P = Phi(a + b ln IM): Fisher scoring from beta = 0.5
// at the median intensity, halving steps that lower the likelihood (it is concave in (a, b), so
// this converges).
struct ProbitFit {
  double a = 0.0, b = 0.0;
  Likelihood at_fit;
};

ProbitFit maximise_likelihood(const std::vector<FragilityObservation>& observations) {
  std::vector<double> logs;
  for (const FragilityObservation& o : observations) logs.push_back(std::log(o.intensity));
  double b = 2.0, a = -b * quantile(logs, 0.5);
  Likelihood current = likelihood(observations, a, b);
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Eigen::Vector2d step = current.information.ldlt().solve(current.gradient);
    double fraction = 1.0;
    Likelihood trial = likelihood(observations, a + step[0], b + step[1]);
    while (!(trial.value >= current.value) && fraction > 1e-10) {
      fraction *= 0.5;
      trial = likelihood(observations, a + fraction * step[0], b + fraction * step[1]);
    }
    a += fraction * step[0];
    b += fraction * step[1];
    current = trial;
    if (std::abs(fraction * step[0]) + std::abs(fraction * step[1]) <=
        1e-13 * (1.0 + std::abs(a) + std::abs(b)))
      break;
  }
  return {a, b, current};
}

}  // namespace

FragilityFit fit_lognormal_fragility(const std::vector<FragilityObservation>& observations) {
  FragilityFit fit;
  fit.observations = observations.size();
  const IntensitySpread spread = intensity_spread(observations);
  fit.exceeded = spread.exceeded;
  fit.reason = unidentifiable_reason(spread, observations.size());
  if (!fit.reason.empty()) return fit;
  const ProbitFit probit = maximise_likelihood(observations);
  const double a = probit.a, b = probit.b;
  if (!(b > 0.0) || !std::isfinite(a) || !std::isfinite(b)) {
    fit.reason = "the fitted probability does not grow with intensity";
    return fit;
  }
  fit.fitted = true;
  fit.dispersion = 1.0 / b;
  fit.median = std::exp(-a / b);
  fit.log_likelihood = probit.at_fit.value;
  return fit;
}

// A failed case whose running peak passed the limit before it stopped: its whole run's peak is
// at least that, so it exceeded the limit (left out, it made a fragility non-conservative where
// the failures were collapses). One below the limit says nothing and stays out.
bool exceeded_before_stopping(const CaseSummary& c, const builder::ResponseLimit& limit) {
  const BatchQuantity& quantity = limited_quantity(limit);
  if (c.status != CaseStatus::failed || !quantity.running_peak) return false;
  const std::optional<double> value = c.*quantity.value;
  return value && *value > limit.value;
}

BatchStatistics batch_statistics(const builder::SetSpec& set,
                                 const std::vector<results::CaseSummary>& cases) {
  BatchStatistics stats;
  stats.cases = cases.size();
  for (const results::CaseSummary& c : cases) {
    stats.completed += c.status == CaseStatus::completed;
    stats.failed += c.status == CaseStatus::failed;
    stats.input_errors += c.status == CaseStatus::input_error;
  }
  for (const builder::BatchModel& model : set.models) {
    for (const double scale : set.scales) {
      ScaleGroup group;
      group.model = model.id;
      group.scale = scale;
      std::vector<const results::CaseSummary*> completed, stopped;
      for (const results::CaseSummary& c : cases)
        if (c.model == model.id && c.scale == scale) {
          ++group.cases;
          if (c.status == CaseStatus::completed) completed.push_back(&c);
          if (c.status == CaseStatus::failed) stopped.push_back(&c);
        }
      group.completed = completed.size();
      for (const BatchQuantity& quantity : batch_quantities()) {
        std::vector<double> values;
        for (const results::CaseSummary* c : completed)
          if (const std::optional<double> value = c->*quantity.value) values.push_back(*value);
        if (values.empty()) continue;
        group.responses.push_back({std::string(quantity.name), values.size(), quantile(values, 0.5),
                                   quantile(values, 0.84),
                                   *std::max_element(values.begin(), values.end())});
      }
      for (const builder::ResponseLimit& limit : set.limits) {
        Exceedance e{limit.quantity, limit.value};
        const auto value_of = limited_quantity(limit).value;
        for (const results::CaseSummary* c : completed)
          if (const std::optional<double> value = c->*value_of) {
            ++e.count;
            e.exceeded += *value > limit.value;
          }
        for (const results::CaseSummary* c : stopped)
          if (exceeded_before_stopping(*c, limit)) {
            ++e.count;
            ++e.exceeded;
          }
        e.fraction = e.count ? static_cast<double>(e.exceeded) / static_cast<double>(e.count) : 0.0;
        group.exceedances.push_back(e);
      }
      stats.groups.push_back(std::move(group));
    }
    for (const builder::ResponseLimit& limit : set.limits) {
      std::vector<FragilityObservation> observations;
      std::size_t of_model = 0;
      const auto value_of = limited_quantity(limit).value;
      for (const results::CaseSummary& c : cases) {
        if (c.model != model.id) continue;
        ++of_model;
        if (!c.intensity || !(*c.intensity > 0.0)) continue;
        if (c.status == CaseStatus::completed) {
          if (const std::optional<double> value = c.*value_of)
            observations.push_back({*c.intensity, *value > limit.value});
        } else if (exceeded_before_stopping(c, limit)) {
          observations.push_back({*c.intensity, true});
        }
      }
      FragilityFit fit;
      if (observations.empty())
        fit.reason = fmt::format("no completed case reports {}", limit.quantity);
      else
        fit = fit_lognormal_fragility(observations);
      fit.left_out = of_model - observations.size();
      fit.model = model.id;
      fit.quantity = limit.quantity;
      fit.limit = limit.value;
      stats.fragilities.push_back(fit);
    }
  }
  return stats;
}

}  // namespace pound::results
