#pragma once
// The moving supports' quasi-static motion, which a run under multi-support excitation takes out
// of the displacements it carries (u = u_dyn + R u_s, docs/model_format.md): the monitors that
// judge damage by displacement (a girder's movement on its seat, a pier's drift) add it back, and
// read a moving support's own displacement, so that they give total deformations as the links
// do. Without moving supports they read u itself.
#include <functional>
#include <limits>
#include <vector>

#include "core/types.hpp"
#include "integrators/integrator.hpp"

namespace pound::results {

class SupportMotion {
 public:
  // Each moving support's displacement u_s,k at a time, in the influences' order.
  using Displacements = std::function<void(double time, std::vector<double>& displacements)>;

  SupportMotion() = default;  // no moving supports
  SupportMotion(std::vector<Vector> influences, Displacements displacements)
      : influences_(std::move(influences)), displacements_(std::move(displacements)) {}

  bool moving() const { return !influences_.empty(); }
  // Where a term reads moving support k's displacement in total()'s vector (after the free DOFs).
  Index support_entry(Index free_dofs, std::size_t k) const {
    return free_dofs + static_cast<Index>(k);
  }
  // u without moving supports; else the free DOFs' u + sum r_k u_s,k followed by each u_s,k (the
  // entries support_entry names), formed once per time.
  const Vector& total(const integrators::State& state) {
    if (!moving()) return state.displacement;
    if (!(time_ == state.time)) {
      displacements_(state.time, support_now_);
      const Index n = state.displacement.size();
      total_.resize(n + static_cast<Index>(influences_.size()));
      total_.head(n) = state.displacement;
      for (std::size_t k = 0; k < influences_.size(); ++k) {
        total_.head(n) += support_now_[k] * influences_[k];
        total_[n + static_cast<Index>(k)] = support_now_[k];
      }
      time_ = state.time;
    }
    return total_;
  }

 private:
  std::vector<Vector> influences_;
  Displacements displacements_;
  std::vector<double> support_now_;
  double time_ = std::numeric_limits<double>::quiet_NaN();  // of total_
  Vector total_;
};

}  // namespace pound::results
