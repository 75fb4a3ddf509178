#include "integrators/link_set.hpp"

#include <cassert>
#include <cmath>

namespace pound {

LinkSet::LinkSet(Index dofs, const std::vector<std::vector<Term>>& rows, std::vector<double> gaps,
                 std::vector<std::unique_ptr<contact::ContactLaw>> laws)
    : connectivity_(static_cast<Index>(rows.size()), dofs),
      gaps_(Eigen::Map<const Vector>(gaps.data(), static_cast<Index>(gaps.size()))),
      laws_(std::move(laws)) {
  assert(rows.size() == laws_.size() && gaps.size() == laws_.size());
  std::vector<Eigen::Triplet<double>> triplets;
  for (std::size_t k = 0; k < rows.size(); ++k)
    for (const Term& term : rows[k])
      triplets.emplace_back(static_cast<Index>(k), term.dof, term.coefficient);
  connectivity_.setFromTriplets(triplets.begin(), triplets.end());
  gram_ = Matrix(connectivity_ * connectivity_.transpose());
}

void LinkSet::penetration(const Vector& displacement, Vector& delta) const {
  delta.noalias() = connectivity_ * displacement;
  delta -= gaps_;
}

void LinkSet::project(const Vector& x, Vector& projected) const {
  projected.noalias() = connectivity_ * x;
}

double LinkSet::nodal_norm(const Vector& link_values) const {
  return std::sqrt(std::max(0.0, link_values.dot(gram_ * link_values)));
}

void LinkSet::set_trial(const Vector& delta, const Vector& rate, const Vector& acceleration,
                        double rate_factor, double acceleration_factor, Vector& force,
                        Vector& total_tangent) {
  force.resize(size());
  total_tangent.resize(size());
  for (Index k = 0; k < size(); ++k) {
    const contact::LawResponse response =
        laws_[k]->set_trial({delta[k], rate[k], acceleration[k]});
    force[k] = response.force;
    total_tangent[k] = response.stiffness + response.damping * rate_factor +
                       response.mass * acceleration_factor;
  }
}

void LinkSet::commit() {
  for (auto& law : laws_) law->commit();
}

void LinkSet::revert() {
  for (auto& law : laws_) law->revert();
}

}  // namespace pound
