#include "integrators/link_set.hpp"

#include <array>
#include <cassert>
#include <cmath>
#include <span>
#include <stdexcept>
#include <utility>

#include "core/sparse_rows.hpp"

namespace pound::integrators {
namespace {

std::vector<LinkSet::Link> scalar_links(const std::vector<std::vector<LinkSet::Term>>& rows,
                                        const std::vector<double>& gaps,
                                        std::vector<std::unique_ptr<links::LinkLaw>> laws) {
  assert(rows.size() == laws.size() && gaps.size() == laws.size());
  std::vector<LinkSet::Link> links(rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    links[k].normal_row = rows[k];
    links[k].gap = gaps[k];
    links[k].law = std::move(laws[k]);
  }
  return links;
}

}  // namespace

LinkSet::LinkSet(Index dofs, const std::vector<std::vector<Term>>& rows, std::vector<double> gaps,
                 std::vector<std::unique_ptr<links::LinkLaw>> laws)
    : LinkSet(dofs, scalar_links(rows, gaps, std::move(laws))) {}

LinkSet::LinkSet(Index dofs, std::vector<Link> links) : links_(std::move(links)) {
  std::vector<Eigen::Triplet<double>> triplets;
  std::vector<double> gaps;
  Index rows = 0;
  auto add_row = [&](const std::vector<Term>& terms, double gap) {
    for (const Term& term : terms) triplets.emplace_back(rows, term.dof, term.coefficient);
    gaps.push_back(gap);
    ++rows;
  };
  for (const Link& link : links_) {
    first_row_.push_back(rows);
    add_row(link.normal_row, link.gap);
    const int tangents = link.friction ? link.friction->tangents()
                         : link.shear  ? link.shear->tangents()
                                       : 0;
    if (static_cast<int>(link.tangential_rows.size()) != tangents || (link.friction && link.shear))
      throw std::invalid_argument(
          "a friction or shear link needs one tangential row per tangent of its law");
    for (const std::vector<Term>& tangential : link.tangential_rows) add_row(tangential, 0.0);
  }
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (links_[k].friction || links_[k].shear)
      block_links_.push_back(k);
    else
      scalar_links_.push_back({links_[k].law.get(), first_row_[k]});
  }
  connectivity_.resize(rows, dofs);
  connectivity_.setFromTriplets(triplets.begin(), triplets.end());
  const Index scatter_cost = dofs + 2 * connectivity_.nonZeros();
  if (rows * rows < scatter_cost) gram_ = Matrix(connectivity_ * connectivity_.transpose());
  gaps_ = Eigen::Map<const Vector>(gaps.data(), rows);
}

void LinkSet::project_rows(const Vector& x, Vector& projected, const Vector* gaps) const {
  multiply_rows(connectivity_, x, projected);
  if (gaps) projected -= *gaps;
}

void LinkSet::penetration(const Vector& displacement, Vector& delta) const {
  project_rows(displacement, delta, &gaps_);
}

// Each sum as project_rows forms it, so the bits are the separate passes' (tested).
template <bool WithSolution>
void LinkSet::project_step(const Vector* u_1, const Vector& u_2, const Vector& v, Vector* delta_1,
                           Vector& delta_2, Vector& rate) const {
  const Index rows = connectivity_.rows();
  if constexpr (WithSolution) delta_1->resize(rows);
  delta_2.resize(rows);
  rate.resize(rows);
  const double* __restrict__ values = connectivity_.valuePtr();
  const auto* __restrict__ columns = connectivity_.innerIndexPtr();
  const auto* __restrict__ starts = connectivity_.outerIndexPtr();
  for (Index row = 0; row < rows; ++row) {
    double sum_1 = 0.0, sum_2 = 0.0, sum_v = 0.0;
    for (auto k = starts[row]; k < starts[row + 1]; ++k) {
      const double value = values[k];
      if constexpr (WithSolution) sum_1 += value * (*u_1)[columns[k]];
      sum_2 += value * u_2[columns[k]];
      sum_v += value * v[columns[k]];
    }
    if constexpr (WithSolution) (*delta_1)[row] = (0.0 + sum_1) - gaps_[row];
    delta_2[row] = (0.0 + sum_2) - gaps_[row];
    rate[row] = 0.0 + sum_v;
  }
}

void LinkSet::penetration_and_rate(const Vector& u, const Vector& v, Vector& delta,
                                   Vector& rate) const {
  project_step<false>(nullptr, u, v, nullptr, delta, rate);
}

void LinkSet::penetrations_and_rate(const Vector& u_1, const Vector& u_2, const Vector& v,
                                    Vector& delta_1, Vector& delta_2, Vector& rate) const {
  project_step<true>(&u_1, u_2, v, &delta_1, delta_2, rate);
}

void LinkSet::project(const Vector& x, Vector& projected) const {
  project_rows(x, projected, nullptr);
}

void LinkSet::subtract_transpose(const Vector& row_values, Vector& nodal) const {
  const double* __restrict__ values = connectivity_.valuePtr();
  const auto* __restrict__ columns = connectivity_.innerIndexPtr();
  const auto* __restrict__ starts = connectivity_.outerIndexPtr();
  double* __restrict__ out = nodal.data();
  for (Index row = 0; row < connectivity_.rows(); ++row) {
    const double value = row_values[row];
    if (value == 0.0) continue;
    for (auto k = starts[row]; k < starts[row + 1]; ++k) out[columns[k]] -= values[k] * value;
  }
}

double LinkSet::nodal_norm(const Vector& row_values) const {
  // Into kept storage: no allocation per call.
  if (gram_.size() == 0) {
    nodal_scratch_.setZero(connectivity_.cols());
    const double* __restrict__ values = connectivity_.valuePtr();
    const auto* __restrict__ columns = connectivity_.innerIndexPtr();
    const auto* __restrict__ starts = connectivity_.outerIndexPtr();
    double* __restrict__ nodal = nodal_scratch_.data();
    for (Index row = 0; row < connectivity_.rows(); ++row) {
      const double value = row_values[row];
      if (value == 0.0) continue;  // an open contact's row
      for (auto k = starts[row]; k < starts[row + 1]; ++k) nodal[columns[k]] += values[k] * value;
    }
    return nodal_scratch_.norm();
  }
  nodal_scratch_.noalias() = gram_ * row_values;
  return std::sqrt(std::max(0.0, row_values.dot(nodal_scratch_)));
}

void LinkSet::set_trial(const Vector& delta, const Vector& rate, const Vector& acceleration,
                        double rate_factor, double acceleration_factor, Vector& force,
                        Matrix& tangent) {
  evaluate(
      delta, rate, acceleration,
      [rate_factor, acceleration_factor](const links::LawResponse& r) {
        return r.stiffness + r.damping * rate_factor + r.mass * acceleration_factor;
      },
      force, tangent);
}

void LinkSet::set_trial_mass(const Vector& delta, const Vector& rate, const Vector& acceleration,
                             Vector& force, Matrix& mass_tangent) {
  evaluate(
      delta, rate, acceleration, [](const links::LawResponse& r) { return r.mass; }, force,
      mass_tangent);
}

LinkSet::RowDerivatives LinkSet::row_derivatives(const Vector& delta, const Vector& rate,
                                                 const Vector& acceleration) {
  RowDerivatives derivatives;
  Vector force;
  Matrix tangent;
  using Kind = double links::LawResponse::*;
  for (const auto& entry :
       {std::pair<Kind, Vector*>{&links::LawResponse::stiffness, &derivatives.stiffness},
        {&links::LawResponse::damping, &derivatives.damping},
        {&links::LawResponse::mass, &derivatives.mass}}) {
    // A named member, not a structured binding: clang 14 cannot capture a binding.
    const Kind kind = entry.first;
    evaluate(
        delta, rate, acceleration, [kind](const links::LawResponse& r) { return r.*kind; }, force,
        tangent);
    *entry.second = tangent.diagonal();
  }
  return derivatives;
}

template <typename Total>
void LinkSet::evaluate(const Vector& delta, const Vector& rate, const Vector& acceleration,
                       Total total, Vector& force, Matrix& tangent) {
  const Index rows = size();
  force.resize(rows);
  if (tangent.rows() != rows || tangent.cols() != rows) tangent.setZero(rows, rows);
  // The links of one row, from flat arrays: a law call and two stores each.
  double* __restrict__ forces = force.data();
  double* __restrict__ diagonal = tangent.data();
  for (const ScalarLink& link : scalar_links_) {
    const Index n = link.row;
    const links::LawResponse response = link.law->set_trial({delta[n], rate[n], acceleration[n]});
    forces[n] = response.force;
    diagonal[n * (rows + 1)] = total(response);
  }
  for (const std::size_t k : block_links_) {
    const Index n = first_row_[k];
    const links::LinkKinematics normal{delta[n], rate[n], acceleration[n]};
    const Link& link = links_[k];
    const auto tangents = link.tangential_rows.size();
    std::array<links::LinkKinematics, links::kMaxTangents> slide;
    for (std::size_t a = 0; a < tangents; ++a) {
      const Index t = n + 1 + static_cast<Index>(a);
      slide[a] = {delta[t], rate[t], acceleration[t]};
    }
    const std::span<const links::LinkKinematics> slides(slide.data(), tangents);
    const links::FrictionResponse response = link.friction
                                                 ? link.friction->set_trial(normal, slides)
                                                 : link.shear->set_trial(normal, slides);
    force[n] = response.normal.force;
    tangent(n, n) = total(response.normal);
    for (std::size_t a = 0; a < tangents; ++a) {
      const Index t = n + 1 + static_cast<Index>(a);
      force[t] = response.tangential_force[a];
      tangent(t, n) = total(response.tangential_on_normal[a]);
      for (std::size_t b = 0; b < tangents; ++b)
        tangent(t, n + 1 + static_cast<Index>(b)) = total(response.tangential_on_slip[a][b]);
    }
  }
}

void LinkSet::anchor_friction_at_rest(const Vector& force) {
  for (std::size_t k = 0; k < links_.size(); ++k)
    if (links_[k].friction)
      links_[k].friction->anchor_at_rest(
          std::span(force.data() + first_row_[k] + 1, links_[k].tangential_rows.size()));
}

void LinkSet::commit() {
  for (const ScalarLink& link : scalar_links_) link.law->commit();
  for (const std::size_t k : block_links_) {
    Link& link = links_[k];
    if (link.friction)
      link.friction->commit();
    else
      link.shear->commit();
  }
}

void LinkSet::revert() {
  for (const ScalarLink& link : scalar_links_) link.law->revert();
  for (const std::size_t k : block_links_) {
    Link& link = links_[k];
    if (link.friction)
      link.friction->revert();
    else
      link.shear->revert();
  }
}

std::vector<char> LinkSet::impulsive_hard_contact_rows(const Vector* lumped_mass) const {
  std::vector<char> rows(static_cast<std::size_t>(size()), 0);
  for (std::size_t k = 0; k < links_.size(); ++k) {
    if (!law(static_cast<Index>(k)).is_hard_contact()) continue;
    const Index first = first_row_[k], last = first + LinkSet::rows(static_cast<Index>(k));
    bool massive = true;
    if (lumped_mass)
      for (Index row = first; row < last; ++row)
        for (SparseRowMatrix::InnerIterator term(connectivity_, row); term; ++term)
          massive = massive && (*lumped_mass)[term.col()] > 0.0;
    for (Index row = first; row < last; ++row) rows[static_cast<std::size_t>(row)] = massive;
  }
  return rows;
}

LinkSet::HardRows LinkSet::hard_rows() {
  const auto m = static_cast<std::size_t>(size());
  HardRows hard{std::vector<links::HardContact*>(m, nullptr),
                std::vector<links::CoulombFriction*>(m, nullptr), std::vector<int>(m, 0),
                std::vector<char>(m, 0)};
  const auto moves = [&](Index row) {
    for (SparseRowMatrix::InnerIterator term(connectivity_, row); term; ++term)
      if (term.value() != 0.0) return true;
    return false;
  };
  for (Index k = 0; k < count(); ++k) {
    const Index first = first_row_[static_cast<std::size_t>(k)];
    hard.contacts[static_cast<std::size_t>(first)] = hard_contact(k);
    const Link& link = links_[static_cast<std::size_t>(k)];
    if (!link.friction || !link.friction->hard_contact()) continue;
    int moving = 0;
    for (int a = 0; a < link.friction->tangents(); ++a) {
      const auto row = static_cast<std::size_t>(first + 1 + a);
      if (!moves(static_cast<Index>(row))) continue;
      hard.frictions[row] = link.friction.get();
      hard.tangent[row] = a;
      ++moving;
    }
    if (moving == 2)
      hard.pair[static_cast<std::size_t>(first + 1)] =
          hard.pair[static_cast<std::size_t>(first + 2)] = 1;
  }
  return hard;
}

const links::LinkLaw& LinkSet::law(Index link) const {
  const Link& entry = links_[static_cast<std::size_t>(link)];
  if (entry.shear) return entry.shear->normal_law();
  return entry.friction ? entry.friction->normal_law() : *entry.law;
}

Vector LinkSet::rest_stiffness() const {
  Vector stiffness = Vector::Zero(size());
  for (Index k = 0; k < count(); ++k) {
    const Index row = LinkSet::row(k);
    stiffness[row] = law(k).clone()->set_trial({-gaps_[row], 0.0, 0.0}).stiffness;
    if (const links::CoupledShear* bearing = shear(k))
      for (int a = 0; a < bearing->tangents(); ++a)
        stiffness[row + 1 + a] =
            bearing->numbers()[static_cast<std::size_t>(a)].initial_stiffness();
  }
  return stiffness;
}

void LinkSet::row_magnitudes(const Vector& u, Vector& magnitudes) const {
  magnitudes.resize(connectivity_.rows());
  for (Index r = 0; r < connectivity_.rows(); ++r) {
    double sum = 0.0;
    for (SparseRowMatrix::InnerIterator it(connectivity_, r); it; ++it)
      sum += std::abs(it.value() * u[it.col()]);
    magnitudes[r] = sum;
  }
}

}  // namespace pound::integrators
