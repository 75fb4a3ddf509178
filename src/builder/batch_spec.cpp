#include "builder/batch_spec.hpp"

#include <fmt/format.h>

namespace pound::builder {

const char* intensity_name(IntensityKind kind) { return kind == IntensityKind::sa ? "sa" : "pga"; }

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
