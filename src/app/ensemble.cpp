#include "app/ensemble.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "builder/batch_spec.hpp"
#include "results/batch_quantities.hpp"
#include "results/batch_statistics.hpp"

namespace pound::app {
namespace {

// 1 + eps, 1 - eps, 1 + 2 eps, 1 - 2 eps, ...
std::vector<double> record_factors(const EnsembleOptions& options) {
  std::vector<double> factors;
  for (int k = 0; k < options.copies; ++k) {
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    factors.push_back(1.0 + sign * (k / 2 + 1) * options.perturbation);
  }
  return factors;
}

// The run's own statistics (steps, iterations, run time, balance errors), also as a rod
// benchmark's verification repeats them, and its records are not responses.
bool is_response(const std::string& path) {
  static const std::vector<std::string> statistics{
      "/time_step", "/duration",          "/end_time",  "/dofs",
      "/steps",     "/newton_iterations", "/step_cuts", "/max_unbalanced_force",
      "/run_time_s"};
  const std::string_view own =
      path.starts_with("/verification/") ? std::string_view(path).substr(13) : path;
  if (std::find(statistics.begin(), statistics.end(), own) != statistics.end()) return false;
  // The records as applied (each copy's own scale): inputs, not responses; an adaptive run's
  // rejected steps, located contacts and tolerance: how it stepped.
  if (path.starts_with("/excitations/") || path.starts_with("/adaptive/")) return false;
  return !path.ends_with("balance_error");
}

// An energy: the balance's terms, and the links' works and energies.
bool is_energy(const std::string& path) {
  const std::string key = path.substr(path.rfind('/') + 1);
  return path.starts_with("/energy/") || key == "work" || key == "hysteretic_energy" ||
         key == "damping_energy" || key == "created_energy";
}

// The numbers damage is judged by, which the report lists; ensemble.json has them all.
bool is_headline(const std::string& path) {
  static const std::vector<std::string> keys{"peak_force",
                                             "peak_tension",
                                             "impacts",
                                             "peak_deformation",
                                             "ductility",
                                             "curvature_ductility",
                                             "resultant_ductility",
                                             "peak_opening",
                                             "peak_seat_movement",
                                             "unseating_margin",
                                             "residual_opening",
                                             "peak_drift",
                                             "residual_drift",
                                             "peak_absolute_acceleration",
                                             "peak_girder_acceleration"};
  const std::string key = path.substr(path.rfind('/') + 1);
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// `scale`: a size the spread is measured against where the quantity's own is smaller.
QuantitySpread spread_of(const std::string& path, double unperturbed,
                         const std::vector<double>& values, double robust_spread, double scale) {
  QuantitySpread q{path, unperturbed};
  q.median = results::quantile(values, 0.5);
  q.p16 = results::quantile(values, 0.16);
  q.p84 = results::quantile(values, 0.84);
  q.min = *std::min_element(values.begin(), values.end());
  q.max = *std::max_element(values.begin(), values.end());
  const double size = std::max({std::abs(unperturbed), std::abs(q.min), std::abs(q.max), scale});
  q.spread = size > 0.0 ? (q.p84 - q.p16) / size : 0.0;
  q.deviation = size > 0.0 ? std::abs(unperturbed - q.median) / size : 0.0;
  q.robust = q.spread <= robust_spread && q.deviation <= 0.5 * robust_spread;
  q.headline = is_headline(path);
  return q;
}

// Every number of the unperturbed summary that each completed copy also has.
std::vector<QuantitySpread> spreads(const RunOutcome& unperturbed,
                                    const std::vector<RunOutcome>& copies, double robust_spread) {
  std::vector<std::map<std::string, double>> numbers;
  for (const RunOutcome& copy : copies)
    if (copy.failure.empty()) {
      std::map<std::string, double> values;
      for (const auto& [path, value] : copy.summary.numbers()) values[path] = value;
      numbers.push_back(std::move(values));
    }
  std::vector<QuantitySpread> result;
  if (numbers.empty()) return result;
  // Energies are judged against the largest energy term, as the balance is: the kinetic energy
  // left at the end of a friction pendulum's run (1e-9 of the input, its stick spring still
  // ringing) or a free vibration's spring work of 3e-18 J is not a result whose spread matters.
  double energy_scale = 0.0;
  for (const auto& [path, value] : unperturbed.summary.numbers())
    if (path.starts_with("/energy/") && is_response(path))
      energy_scale = std::max(energy_scale, std::abs(value));
  for (const auto& [path, value] : unperturbed.summary.numbers()) {
    if (!is_response(path)) continue;
    std::vector<double> values;
    for (const auto& copy : numbers)
      if (const auto found = copy.find(path); found != copy.end()) values.push_back(found->second);
    if (values.size() == numbers.size())
      result.push_back(
          spread_of(path, value, values, robust_spread, is_energy(path) ? energy_scale : 0.0));
  }
  return result;
}

}  // namespace

results::CaseSummary EnsembleResult::row_summary(bool medians) const {
  const bool completed = unperturbed.failure.empty();
  results::CaseSummary summary = medians && completed ? median_summary() : unperturbed.case_summary;
  // Failed copies are counted whether or not the unperturbed run completed (docs/batch_format.md).
  if (failed() > 0) summary.warnings = summary.warnings.value_or(0.0) + failed();
  return summary;
}

int EnsembleResult::failed() const {
  return static_cast<int>(
      std::count_if(failures.begin(), failures.end(), [](const auto& f) { return !f.empty(); }));
}

results::CaseSummary EnsembleResult::median_summary() const {
  results::CaseSummary summary = unperturbed.case_summary;
  const std::size_t completed = copies.size() - static_cast<std::size_t>(failed());
  // The member's median over the completed copies, where the run has it and every copy does.
  const auto take_median = [&](std::optional<double> results::CaseSummary::*member) {
    if (!(summary.*member)) return;
    std::vector<double> values;
    for (std::size_t k = 0; k < copies.size(); ++k)
      if (failures[k].empty() && copies[k].*member) values.push_back(*(copies[k].*member));
    if (!values.empty() && values.size() == completed)
      summary.*member = results::quantile(values, 0.5);
  };
  for (const results::BatchQuantity& quantity : results::batch_quantities())
    if (quantity.response) take_median(quantity.value);
  // The least unseating margin is a response as well (not a batch quantity: limits take the
  // seat movement), and the row's `unseated` follows its median, as the seat movement's does.
  // (A run's own `unseated` is its least margin <= 0, so this leaves an unchanged margin's.)
  take_median(&results::CaseSummary::min_unseating_margin);
  if (summary.min_unseating_margin) summary.unseated = *summary.min_unseating_margin <= 0.0;
  return summary;
}

std::string EnsembleOptionsError::option() const {
  std::string name = "--" + argument;
  std::replace(name.begin(), name.end(), '_', '-');
  return name;
}

std::optional<EnsembleOptionsError> ensemble_options_error(const EnsembleOptions& options) {
  if (const auto error =
          builder::ensemble_error(options.copies, options.perturbation, options.robust_spread)) {
    const char* argument = error->number == builder::EnsembleNumber::copies ? "ensemble"
                           : error->number == builder::EnsembleNumber::perturbation
                               ? "perturbation"
                               : "robust_spread";
    return EnsembleOptionsError{argument, error->why};
  }
  if (options.jobs < 0)
    return EnsembleOptionsError{"jobs", fmt::format("must be >= 0, got {}", options.jobs)};
  return std::nullopt;
}

EnsembleResult run_ensemble(const RunRequest& request, const EnsembleOptions& options,
                            const std::function<void(std::size_t, std::size_t)>& copy_done) {
  EnsembleResult result{run_model(request), record_factors(options)};
  std::vector<RunOutcome> copies(result.factors.size());
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t jobs = std::min<std::size_t>(
      options.jobs > 0 ? static_cast<std::size_t>(options.jobs) : cores, copies.size());
  std::atomic<std::size_t> next{0};
  std::mutex reporting;  // copy_done's calls, one at a time
  std::size_t done = 0;
  // What a copy threw (Ctrl-C's Interrupted, say): the others stop taking copies, and it is
  // thrown again here, after every thread has ended.
  std::vector<std::exception_ptr> thrown(jobs);
  auto work = [&](std::size_t job) {
    try {
      for (std::size_t k = next++; k < copies.size(); k = next++) {
        RunRequest copy = request;
        copy.histories = false;
        copy.before_run = nullptr;    // writes nothing
        copy.before_solve = nullptr;  // the unperturbed run's warnings are the copies'
        copy.progress = nullptr;
        copy.record_factor = result.factors[k];
        copies[k] = run_model(copy);
        if (copy_done) {
          const std::lock_guard lock(reporting);
          copy_done(++done, copies.size());
        }
      }
    } catch (...) {
      thrown[job] = std::current_exception();
      next = copies.size();
    }
  };
  if (copy_done) copy_done(0, copies.size());
  std::vector<std::thread> threads;
  for (std::size_t j = 1; j < jobs; ++j) threads.emplace_back(work, j);
  work(0);
  for (std::thread& thread : threads) thread.join();
  for (const std::exception_ptr& failure : thrown)
    if (failure) std::rethrow_exception(failure);
  for (const RunOutcome& copy : copies) {
    result.failures.push_back(copy.failure);
    result.copies.push_back(copy.case_summary);
    result.copies_setup_s += copy.setup_s;
    result.copies_solve_s += copy.case_summary.run_time_s.value_or(0.0);
  }
  result.quantities = spreads(result.unperturbed, copies, options.robust_spread);
  return result;
}

std::string ensemble_report(const EnsembleResult& result, const EnsembleOptions& options) {
  std::vector<const QuantitySpread*> loose;
  std::size_t other = 0;
  for (const QuantitySpread& q : result.quantities)
    if (!q.robust) (q.headline ? loose.push_back(&q) : void(++other));
  // Peaks and counts before the states left at the end of the record (residual openings and
  // drifts), which end near zero and so spread most relative to their size: a reader looks for
  // the peak forces first. Within each, the least robust first.
  const auto residual = [](const QuantitySpread* q) {
    return q->path.find("/residual_") != std::string::npos;
  };
  std::stable_sort(loose.begin(), loose.end(), [&](const auto* a, const auto* b) {
    if (residual(a) != residual(b)) return residual(b);
    return a->spread > b->spread;
  });
  const std::string copies = fmt::format(
      "ensemble: {} cop{} with {} scaled by 1 +- k {:g} (k up to {}), {} failed",
      result.factors.size(), result.factors.size() == 1 ? "y" : "ies", result.unperturbed.perturbed,
      options.perturbation, (options.copies + 1) / 2, result.failed());
  if (result.quantities.empty())
    return copies + ": no statistics (no copy completed, or none reports the run's numbers)\n";
  std::string text = fmt::format(
      "{}: {} of {} numbers are not robust (16-84 % spread above {:g} of their size, or the "
      "unperturbed run further than half that from the median)\n",
      copies, loose.size() + other, result.quantities.size(), options.robust_spread);
  const std::size_t completed = result.factors.size() - static_cast<std::size_t>(result.failed());
  if (completed < 5)
    text += fmt::format(
        "  {} completed cop{}: their 16-84 % are those of {} sample{}, no measure of the spread; "
        "run 10 or more to judge one\n",
        completed, completed == 1 ? "y" : "ies", completed, completed == 1 ? "" : "s");
  constexpr std::size_t kShown = 16;
  for (std::size_t k = 0; k < std::min(kShown, loose.size()); ++k) {
    const QuantitySpread& q = *loose[k];
    text += fmt::format(
        "  {}: {:.4g}; median {:.4g}, 16-84 % {:.4g} to {:.4g}, range {:.4g} to "
        "{:.4g} (spread {:.0f} %{})\n",
        q.path, q.unperturbed, q.median, q.p16, q.p84, q.min, q.max, 100.0 * q.spread,
        q.deviation > 0.5 * options.robust_spread
            ? fmt::format(", the unperturbed run {:.0f} % from the median", 100.0 * q.deviation)
            : "");
  }
  const std::size_t more_headline = loose.size() - std::min(kShown, loose.size());
  if (more_headline + other > 0)
    text += fmt::format(
        "  ... and {} more in ensemble.json ({} of them headline, {} others: energies, "
        "impulses, contact times...)\n",
        more_headline + other, more_headline, other);
  return text;
}

io::Document ensemble_document(const EnsembleResult& result, const EnsembleOptions& options) {
  io::Document doc;
  doc.set("copies", static_cast<long>(result.factors.size()))
      .set("perturbation", options.perturbation)
      .set("robust_spread", options.robust_spread)
      .set("perturbed", result.unperturbed.perturbed)
      .set("record_factors", result.factors)
      .set("failed", static_cast<long>(result.failed()));
  std::vector<io::Document> failures;
  for (std::size_t k = 0; k < result.failures.size(); ++k)
    if (!result.failures[k].empty())
      failures.push_back(
          io::Document().set("record_factor", result.factors[k]).set("reason", result.failures[k]));
  doc.set("failures", failures);
  doc.set("quantities", io::documents(result.quantities, [](const QuantitySpread& q) {
            return io::Document()
                .set("path", q.path)
                .set("unperturbed", q.unperturbed)
                .set("median", q.median)
                .set("p16", q.p16)
                .set("p84", q.p84)
                .set("min", q.min)
                .set("max", q.max)
                .set("spread", q.spread)
                .set("deviation", q.deviation)
                .set("robust", q.robust)
                .set("headline", q.headline);
          }));
  return doc;
}

}  // namespace pound::app
