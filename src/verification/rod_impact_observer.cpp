#include "verification/rod_impact_observer.hpp"

namespace pound::verification {

RodImpactObserver::RodImpactObserver(builder::RodPairSpec pair, RodPairNodes nodes,
                                     Index contact_row)
    : pair_(std::move(pair)), nodes_(std::move(nodes)), contact_row_(contact_row) {}

std::unique_ptr<RodImpactObserver> RodImpactObserver::attach(const builder::BuiltModel& built,
                                                             const model::DofMap& dofs,
                                                             const integrators::LinkSet& links) {
  if (!built.sole_rod_pair || links.count() != 1) return nullptr;
  return std::unique_ptr<RodImpactObserver>(new RodImpactObserver(
      *built.sole_rod_pair, RodPairNodes(*built.sole_rod_pair, built, dofs), links.row(0)));
}

void RodImpactObserver::record(const integrators::State& state) {
  time_.push_back(state.time);
  force_.push_back(state.link_force[contact_row_]);
  penetration_.push_back(state.link_penetration[contact_row_]);
}

RodImpactMetrics RodImpactObserver::metrics(const integrators::State& final_state) const {
  return rod_pair_metrics(pair_, nodes_, time_, force_, penetration_, final_state);
}

}  // namespace pound::verification
