#include "builder/batch_spec.hpp"

#include <fmt/format.h>

namespace pound::builder {

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

const std::vector<std::string>& batch_quantities() {
  static const std::vector<std::string> names = {
      "impacts",           "max_pounding_force", "max_restrainer_force", "max_joint_opening",
      "max_seat_movement", "max_drift_ratio",    "max_ductility",        "energy_balance_error"};
  return names;
}

}  // namespace pound::builder
