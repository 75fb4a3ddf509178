#pragma once
// The nonlinear part of a system: m link elements, each with one deformation coordinate
//   delta_k = b_k . u - gap_k         (penetration, DESIGN.md section 2)
// and a force F_k(delta, delta_dot, delta_ddot) from its contact law, entering the equations of
// motion as f_links = B^T F. B is constant (small displacements), so the integrators can condense
// the nonlinearity onto these m coordinates while the linear part stays factored once.
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "contact/contact_law.hpp"
#include "core/types.hpp"

namespace pound {

class LinkSet {
 public:
  using SparseRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  struct Term {
    Index dof;
    double coefficient;
  };

  // Rebuilds B from rows; `dofs` is the number of equations of the system.
  LinkSet(Index dofs, const std::vector<std::vector<Term>>& rows, std::vector<double> gaps,
          std::vector<std::unique_ptr<contact::ContactLaw>> laws);
  LinkSet(Index dofs = 0) : LinkSet(dofs, {}, {}, {}) {}

  Index size() const { return static_cast<Index>(laws_.size()); }
  const SparseRowMatrix& connectivity() const { return connectivity_; }  // B (m x n)
  const Vector& gaps() const { return gaps_; }

  // delta = B u - gap
  void penetration(const Vector& displacement, Vector& delta) const;
  // B x (rates and accelerations of delta)
  void project(const Vector& x, Vector& projected) const;
  // ||B^T s||_2 without forming B^T s (B B^T is kept).
  double nodal_norm(const Vector& link_values) const;

  // Sets every law's trial state; returns the forces and the total tangents
  // dF/d(delta) + dF/d(delta_dot) * rate_factor + dF/d(delta_ddot) * acceleration_factor.
  void set_trial(const Vector& delta, const Vector& rate, const Vector& acceleration,
                 double rate_factor, double acceleration_factor, Vector& force,
                 Vector& total_tangent);
  void commit();
  void revert();

  const contact::ContactLaw& law(Index k) const { return *laws_[k]; }

 private:
  SparseRowMatrix connectivity_;
  Matrix gram_;  // B B^T
  Vector gaps_;
  std::vector<std::unique_ptr<contact::ContactLaw>> laws_;
};

}  // namespace pound
