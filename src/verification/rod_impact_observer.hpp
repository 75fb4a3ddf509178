#pragma once
// The rod-impact verification of a run: when a model is one rod pair and nothing else (its
// generator says so: BuiltModel::sole_rod_pair), the exact wave solution applies, and `pound run`
// compares its contact force with it as `pound verify rod-impact` does.
#include <memory>
#include <vector>

#include "builder/build.hpp"
#include "results/observer.hpp"
#include "verification/rod_impact.hpp"

namespace pound::verification {

class RodImpactObserver final : public results::Observer {
 public:
  // An observer for `built` when it is one rod pair; none otherwise.
  static std::unique_ptr<RodImpactObserver> attach(const builder::BuiltModel& built,
                                                   const model::DofMap& dofs,
                                                   const integrators::LinkSet& links);
  // The contact link's force and penetration at every step.
  void record(const integrators::State& state) override;
  // The metrics of the run that ended in `final_state` against the exact solution.
  RodImpactMetrics metrics(const integrators::State& final_state) const;

 private:
  RodImpactObserver(builder::RodPairSpec pair, RodPairNodes nodes, Index contact_row);

  builder::RodPairSpec pair_;
  RodPairNodes nodes_;
  Index contact_row_;
  std::vector<double> time_, force_, penetration_;
};

}  // namespace pound::verification
