#include "results/batch_quantities.hpp"

#include <algorithm>
#include <array>

namespace pound::results {
namespace {

const std::array<BatchQuantity, 11> kQuantities = {{
    {"impacts", &CaseSummary::impacts,
     "engagements of the contact links (every law but springs, restrainers and hooks), summed "
     "over the links [-]",
     "number of impacts [-]"},
    {"max_pounding_force", &CaseSummary::max_pounding_force,
     "largest compression of a contact link [model force units]",
     "peak pounding force [model force units]", true, true, Dimension::force},
    {"max_restrainer_force", &CaseSummary::max_restrainer_force,
     "largest tension of a restrainer or hook [model force units]",
     "peak restrainer force [model force units]", true, true, Dimension::force},
    {"max_joint_opening", &CaseSummary::max_joint_opening,
     "largest widening of a joint beyond its initial gap, over the joint monitors [model length "
     "units]",
     "peak joint opening [model length units]", true, true, Dimension::length},
    {"max_seat_movement", &CaseSummary::max_seat_movement,
     "largest movement of a girder on its seat, over the joint monitors [model length units]",
     "peak seat movement [model length units]", true, true, Dimension::length},
    {"max_drift_ratio", &CaseSummary::max_drift_ratio,
     "largest drift over height of the storey and pier monitors (at a 3-D floor's corners too) [-]",
     "peak drift ratio [-]"},
    {"max_ductility", &CaseSummary::max_ductility,
     "largest drift over yield drift of the storey and pier monitors that have one [-]",
     "peak displacement ductility [-]"},
    {"max_residual_drift_ratio", &CaseSummary::max_residual_drift_ratio,
     "largest |residual drift| over height at the end of the record, over the storey and pier "
     "monitors [-]",
     "residual drift ratio [-]", true, false},
    {"energy_balance_error", &CaseSummary::energy_balance_error,
     "worst energy balance error over the run, as a fraction of the largest energy term [-]",
     "energy balance error [-]", false},
    {"max_top_acceleration", &CaseSummary::max_top_acceleration,
     "largest absolute acceleration along x at the top of a storey or pier monitor (a floor, a "
     "pier top) [model acceleration units]",
     "peak floor / pier top acceleration [model acceleration units]", true, true,
     Dimension::acceleration},
    {"max_deck_acceleration", &CaseSummary::max_deck_acceleration,
     "largest absolute acceleration along x of a girder end at a joint monitor [model "
     "acceleration units]",
     "peak deck acceleration [model acceleration units]", true, true, Dimension::acceleration},
}};

}  // namespace

std::span<const BatchQuantity> batch_quantities() { return kQuantities; }

const BatchQuantity* find_batch_quantity(std::string_view name) {
  const auto found = std::find_if(kQuantities.begin(), kQuantities.end(),
                                  [&](const BatchQuantity& q) { return q.name == name; });
  return found == kQuantities.end() ? nullptr : &*found;
}

}  // namespace pound::results
