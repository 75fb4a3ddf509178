#include "builder/batch_spec.hpp"

#include <fmt/format.h>

namespace pound::builder {

const char* intensity_name(IntensityKind kind) { return kind == IntensityKind::sa ? "sa" : "pga"; }

const char* pair_measure_name(PairMeasure measure) {
  return measure == PairMeasure::rot_d50 ? "rotd50" : "geometric_mean";
}

std::optional<EnsembleError> ensemble_error(int copies, double perturbation, double robust_spread) {
  constexpr int kMostCopies = 1000;  // each copy is a whole run
  if (copies < 1 || copies > kMostCopies)
    return EnsembleError{
        EnsembleNumber::copies,
        fmt::format("the number of copies must be 1 to {}, got {}", kMostCopies, copies)};
  if (!(perturbation > 0.0 && perturbation < 1e-2))
    return EnsembleError{EnsembleNumber::perturbation,
                         fmt::format("a relative change of the records at the level of numerical "
                                     "noise is in (0, 0.01), got {}",
                                     perturbation)};
  // Below the double spacing above 1 (2.2e-16), 1 + k eps rounds alike for two k (at 1.2e-16,
  // 1 + eps and 1 + 2 eps are both 1 + 2.2e-16), or to 1: two copies, or a copy and the
  // unperturbed run, would be the same run and narrow the quantiles.
  double above = 1.0, below = 1.0;
  for (int k = 1; k <= copies / 2 + 1; ++k) {
    const double up = 1.0 + k * perturbation, down = 1.0 - k * perturbation;
    if (!(up > above && down < below))
      return EnsembleError{
          EnsembleNumber::perturbation,
          k == 1 ? fmt::format("{} leaves the records unchanged: 1 + it is 1 in double precision "
                               "(it must be at least 2.3e-16)",
                               perturbation)
                 : fmt::format("{} gives copies that are the same run: 1 +- {} times it rounds as "
                               "1 +- {} times it does in double precision (it must be at least "
                               "2.3e-16)",
                               perturbation, k, k - 1)};
    above = up;
    below = down;
  }
  // The copies' factors reach 1 +- (copies / 2 + 1) eps at most.
  if (!(perturbation * (copies / 2 + 1) < 0.5))
    return EnsembleError{EnsembleNumber::perturbation,
                         fmt::format("(copies / 2 + 1) times the perturbation must stay below 0.5, "
                                     "or the records change sign; got {} copies of {}",
                                     copies, perturbation)};
  if (!(robust_spread > 0.0 && robust_spread < 1.0))
    return EnsembleError{EnsembleNumber::robust_spread,
                         fmt::format("must be in (0, 1), got {}", robust_spread)};
  return std::nullopt;
}

std::vector<BatchCase> plan_cases(const SetSpec& set) {
  std::vector<BatchCase> cases;
  cases.reserve(set.models.size() * set.records.size() * set.scales.size());
  for (std::size_t m = 0; m < set.models.size(); ++m)
    for (std::size_t r = 0; r < set.records.size(); ++r)
      for (const double scale : set.scales)
        cases.push_back(
            {.index = cases.size(),
             .model = m,
             .record = r,
             .scale = scale,
             .name = fmt::format("{}/{}/x{}", set.models[m].id, set.records[r].id, scale)});
  return cases;
}

}  // namespace pound::builder
