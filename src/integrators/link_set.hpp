#pragma once
// The nonlinear part of a system: link elements whose deformations are linear in u,
//   delta = b_n . u - gap     (penetration, docs/design.md §2)
//   s     = b_t . u           (tangential slides, only for links with friction)
// and whose forces, F (normal) and R_t (tangential), enter the equations of motion as B^T F.
// Each link has one row of B; with friction one more per tangent (one in a plane, two in 3-D). B is
// constant (small displacements), so the integrators condense the nonlinearity onto these rows
// while the linear part stays factored once.
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "core/types.hpp"
#include "links/coulomb_friction.hpp"
#include "links/coupled_shear.hpp"
#include "links/link_law.hpp"

namespace pound::integrators {

// How far past its bound a hard contact's delta may be, over the size of its terms
// (LinkSet::row_magnitudes): above what their sums accumulate in round-off over a run, so that a
// contact at rest against another (grazing, as after two rods part, or two bodies riding together
// after a plastic impact) stays without force rather than chatter.
inline constexpr double kHardContactRoundOff = 1e-10;

class LinkSet {
 public:
  using SparseRowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;
  struct Term {
    Index dof;
    double coefficient;
  };
  struct Link {
    std::vector<Term> normal_row;
    double gap = 0.0;
    std::unique_ptr<links::LinkLaw> law;  // without friction or a shear
    // With friction or a shear: the tangential rows (one per tangent of the law) and the
    // friction law or the bearing's coupled shear, which owns the normal law.
    std::vector<std::vector<Term>> tangential_rows;
    std::unique_ptr<links::CoulombFriction> friction;
    std::unique_ptr<links::CoupledShear> shear;
  };

  LinkSet(Index dofs, std::vector<Link> links);
  // Links without friction, one row each.
  LinkSet(Index dofs, const std::vector<std::vector<Term>>& rows, std::vector<double> gaps,
          std::vector<std::unique_ptr<links::LinkLaw>> laws);
  explicit LinkSet(Index dofs = 0) : LinkSet(dofs, std::vector<Link>{}) {}

  Index size() const { return connectivity_.rows(); }                // rows
  Index count() const { return static_cast<Index>(links_.size()); }  // links
  Index row(Index link) const { return first_row_[static_cast<std::size_t>(link)]; }
  bool has_friction(Index link) const {
    return links_[static_cast<std::size_t>(link)].friction != nullptr;
  }
  const links::CoupledShear* shear(Index link) const {
    return links_[static_cast<std::size_t>(link)].shear.get();
  }
  // A link's rows: its normal row, then its tangential ones.
  Index rows(Index link) const {
    return 1 + static_cast<Index>(links_[static_cast<std::size_t>(link)].tangential_rows.size());
  }
  const SparseRowMatrix& connectivity() const { return connectivity_; }  // B (rows x n)
  const Vector& gaps() const { return gaps_; }

  // Row deformations B u - gap (penetrations and slides).
  void penetration(const Vector& displacement, Vector& delta) const;
  // penetration(u, delta) and project(v, rate) in one pass over B's rows, to the same bits: a
  // time step's predicted link state.
  void penetration_and_rate(const Vector& u, const Vector& v, Vector& delta, Vector& rate) const;
  // penetration(u_1, delta_1), penetration(u_2, delta_2) and project(v, rate) in one pass, to
  // the same bits: the same with the linear solution's.
  void penetrations_and_rate(const Vector& u_1, const Vector& u_2, const Vector& v, Vector& delta_1,
                             Vector& delta_2, Vector& rate) const;
  // B x (their rates and accelerations).
  void project(const Vector& x, Vector& projected) const;
  // nodal -= B^T F, over the rows whose F is not zero.
  void subtract_transpose(const Vector& row_values, Vector& nodal) const;
  // ||B^T s||_2: as sqrt(s^T (B B^T) s) with B B^T kept where that is the cheaper (few link rows
  // on many DOFs, m^2 < n + 2 nnz(B): the rod), else from B^T s scattered (the bridges).
  double nodal_norm(const Vector& row_values) const;

  // Sets every law's trial state; returns the row forces and the total tangent
  // dF/d(delta) + dF/d(delta_dot) * rate_factor + dF/d(delta_ddot) * acceleration_factor,
  // block diagonal (a 2 x 2 or 3 x 3 block, not symmetric, for a link with friction). Only the
  // blocks' entries are written: a tangent already of this size keeps its zeros outside them
  // (callers may change entries inside the blocks only), as zeroing all m x m cost more than the
  // laws.
  void set_trial(const Vector& delta, const Vector& rate, const Vector& acceleration,
                 double rate_factor, double acceleration_factor, Vector& force, Matrix& tangent);
  // The same with dF/d(delta_ddot) alone (the laws' mass terms, exactly), for an explicit step:
  // its forces depend on the accelerations only through them.
  void set_trial_mass(const Vector& delta, const Vector& rate, const Vector& acceleration,
                      Vector& force, Matrix& mass_tangent);
  // Each row's derivatives of its own force (the diagonal of set_trial's tangent, by kind) at a
  // trial state, which it sets.
  struct RowDerivatives {
    Vector stiffness, damping, mass;
  };
  RowDerivatives row_derivatives(const Vector& delta, const Vector& rate,
                                 const Vector& acceleration);
  void commit();
  void revert();
  // Friction links: CoulombFriction::anchor_at_rest with their committed tangential forces.
  void anchor_friction_at_rest(const Vector& force);

  // Each row's own stiffness at rest, on copies of the laws: a normal row's law at delta = -gap,
  // a shear's k; 0 on friction's tangential rows (whose stick needs a contact).
  Vector rest_stiffness() const;

  // The normal law of a link (for a link with friction or a shear, the one inside it).
  const links::LinkLaw& law(Index link) const;
  // The hard contact of a link (with friction, its normal law); none for a force law.
  links::HardContact* hard_contact(Index link) {
    const Link& entry = links_[static_cast<std::size_t>(link)];
    if (entry.shear) return nullptr;  // the builder gives a shear a force law
    return entry.friction ? entry.friction->hard_contact() : entry.law->hard_contact();
  }
  // The constraints by row, for the integrators that find their forces: a hard contact on its
  // normal row, its friction (whose tangential force is a constraint's too) on each of its
  // tangential rows that moves (a row whose DOFs are all held has no slide and no force to find);
  // nullptr elsewhere. `tangent`: a friction row's tangent (0, or 1 for the second of a contact
  // plane), so its normal row is row - 1 - tangent; `pair`: both tangents of a contact plane
  // move (its friction limit is a circle; otherwise the one row's, a segment).
  struct HardRows {
    std::vector<links::HardContact*> contacts;
    std::vector<links::CoulombFriction*> frictions;
    std::vector<int> tangent;
    std::vector<char> pair;
  };
  HardRows hard_rows();
  // sum_j |B_rj u_j| of each row: the size of delta's terms, and so of its round-off.
  void row_magnitudes(const Vector& u, Vector& magnitudes) const;
  // 1 on the rows of hard contacts between masses (with friction, every row of the link), by
  // row: every DOF of the link's rows carries mass
  // (`lumped_mass`; none: a consistent mass, which every DOF carries). Such a contact's force is
  // an impulse in an implicit step; against a massless point (a column between floors) it is the
  // point's static reaction.
  std::vector<char> impulsive_hard_contact_rows(const Vector* lumped_mass) const;
  const links::CoulombFriction* friction(Index link) const {
    return links_[static_cast<std::size_t>(link)].friction.get();
  }

 private:
  // A step's predicted link state in one pass over B's rows: B u_2 - gap and B v, and with
  // WithSolution B u_1 - gap too.
  template <bool WithSolution>
  void project_step(const Vector* u_1, const Vector& u_2, const Vector& v, Vector* delta_1,
                    Vector& delta_2, Vector& rate) const;
  // B x (core/sparse_rows.hpp), less the gaps when given.
  void project_rows(const Vector& x, Vector& projected, const Vector* gaps) const;
  // Evaluates every law once; `total` makes the tangent entries of a LawResponse.
  template <typename Total>
  void evaluate(const Vector& delta, const Vector& rate, const Vector& acceleration, Total total,
                Vector& force, Matrix& tangent);

  std::vector<Link> links_;
  std::vector<Index> first_row_;
  // The links of one row (a law alone) and their rows; the others (friction, a shear) by index.
  struct ScalarLink {
    links::LinkLaw* law;
    Index row;
  };
  std::vector<ScalarLink> scalar_links_;
  std::vector<std::size_t> block_links_;
  SparseRowMatrix connectivity_;
  Matrix gram_;                   // B B^T, or empty
  mutable Vector nodal_scratch_;  // of nodal_norm
  Vector gaps_;
};

}  // namespace pound::integrators
