#pragma once
// Explicit central difference with lumped mass (Newmark beta = 0, gamma = 1/2; Suzuki & Toi's
// choice):
//   u_{n+1} = u_n + dt v_n + dt^2/2 a_n
//   M a_{n+1} = f_{n+1} - C v* - K u_{n+1} - B^T F,  F = F_law(delta_{n+1}, rate*, B a_{n+1})
//   v_{n+1} = v_n + dt/2 (a_n + a_{n+1})
// with damping forces at v* = v_n + dt a_n (O(dt^2) from v_{n+1}: second order) and link
// rates at the half step v_n + dt/2 a_n (stable with the extended penalty's stiff dashpot). A law's
// mass term (the extended penalty's alpha2) depends on the unknown acceleration: F is found from
// the small system over the link rows (F = F_law(.., free - B M^-1 B^T F)), exactly, by Newton;
// laws without a mass term take one evaluation. A step is refused when the state is not finite.
// Stable only below 2 / omega_max, which depends on the links in contact (alpha0 raises it, alpha2
// lowers it): see stable_time_step.
//
// Hard contacts (links/hard_contact.hpp) are constraints on the next positions, after Carpenter,
// Taylor & Katona (1991): F_{n+1} changes u_{n+2} = u_{n+1} + dt (v_{n+1/2} + dt a_{n+1}) by
// -dt^2 M^-1 B^T F, so the contacts' forces solve, group by group, the small complementarity
// problem  F >= 0,  delta_{n+2} = delta~_{n+2} - dt^2 G F <= bound,  F (bound - delta_{n+2}) = 0
// (an active set: G is positive definite). The bound makes the impact law exact at velocity
// level (Moreau-Jean): a contact that closes in this step (open, delta~_{n+2} > 0) has
// bound = min(0, delta_{n+1}) - e dt w-, w- = (delta~_{n+2} - delta_{n+1}) / dt, so its
// half-step approach rate w- becomes -e w- (it rebounds short of touch, by less than dt w-);
// with e = 0 bound = 0, Carpenter's: the gap closes exactly and the approach stops. A contact
// already carrying a force has bound = min(0, delta_{n+1}): it approaches no further, and lets
// go when held only by tension. No contact ever penetrates. With Coulomb friction its tangential
// row joins the same problem: sticking, s_{n+2} = s_{n+1} (no slide over the step) while
// |F_t| <= mu F_n; slipping, F_t = mu F_n against the slide; the active set changes one row's
// state at a time, the worst first. In a contact plane (two tangents) the limit is a circle:
// slipping, F_t = mu F_n e along the step's slide e = s / |s|, found by Newton's method on e within
// the same active set (slip_in_plane_row).
#include <Eigen/LU>
#include <span>
#include <vector>

#include "integrators/integrator.hpp"
#include "integrators/integrator_catalog.hpp"

namespace pound::integrators {

class CentralDifference final : public Integrator {
 public:
  std::string name() const override { return "central_difference"; }
  // Its catalog entry (integrators/integrator_catalog.hpp).
  static const IntegratorEntry& entry();
  void initialize(SecondOrderSystem& system, State& state, double first_step) override;
  StepResult advance(SecondOrderSystem& system, const State& from, double dt, double end,
                     State& to) override;

 private:
  // The steps of advance().
  // u_{n+1}, and a_{n+1}, v_{n+1} without the link forces; returns whether they are finite.
  bool advance_without_links(SecondOrderSystem& system, const State& from, double dt, State& to);
  // G, B by columns and the link groups, for the links of the system.
  void prepare_links(LinkSet& links);
  // delta_{n+1}, the link rates at the half step and the link accelerations without link forces.
  void link_kinematics(SecondOrderSystem& system, const State& from, double half_dt, State& to);
  // F_{n+1}; false, with result.failure, when it is not finite or does not settle.
  bool solve_link_forces(LinkSet& links, State& to, StepResult& result);
  // correction_ from residual_ and tangent_, group by group.
  void solve_newton_correction();
  // The hard contacts' forces, after the force laws': none penetrates at t_{n+2}; false, with
  // result.failure, when their complementarity problem does not settle.
  bool solve_hard_contacts(const LinkSet& links, State& to, double dt, StepResult& result);
  // One group's forces, delta~_{n+2} = delta + dt rate + scale acceleration and the forces'
  // effect -scale G F; into `force` (and imposed on the laws).
  bool solve_hard_group(const std::vector<Index>& rows, double dt, double scale,
                        const Vector& penetration, const Vector& rate, const Vector& acceleration,
                        Vector& force);
  // delta~_{n+2} and the bound of each of the group's rows, and the first active set.
  void prepare_hard_group(const std::vector<Index>& rows, double dt, double scale,
                          const Vector& penetration, const Vector& rate,
                          const Vector& acceleration);
  // Whether a group row (local index) is in the active set: a friction row with its normal row.
  bool hard_row_active(const std::vector<Index>& rows, std::size_t i) const;
  // A friction row's normal row (local indices).
  std::size_t normal_of(const std::vector<Index>& rows, std::size_t i) const;
  // Whether a group row is a contact plane's friction row (two tangents).
  bool in_plane(const std::vector<Index>& rows, std::size_t i) const;
  int tangent_of(const std::vector<Index>& rows, std::size_t i) const;
  // A contact plane's friction (local rows first, first + 1) starts slipping along `along`.
  void start_slip_in_plane(std::size_t first, const Eigen::Vector2d& along);
  // Row a of the active matrix for a slipping contact plane's friction row.
  void slip_in_plane_row(const std::vector<Index>& rows, const std::vector<Index>& unknowns,
                         Index a, double scale);
  // s_{n+2} - bound of a contact plane's two rows (local i, i + 1) under the forces found.
  Eigen::Vector2d slide_in_plane(const std::vector<Index>& rows, Index i, double scale) const;
  // s~_{n+2} - bound of a contact plane's two rows (local i, i + 1): the slide without forces.
  Eigen::Vector2d free_slide(Index i) const;
  double in_plane_friction_excess(const std::vector<Index>& rows, Index i, double scale) const;
  double slide_round_off(const std::vector<Index>& rows, Index i, double length) const;
  double hard_value_round_off(const std::vector<Index>& rows, Index i, double scale) const;
  bool turn_slip_directions(const std::vector<Index>& rows, double scale);
  // The active rows' forces for the current active set, into group_force_.
  void solve_active_hard_rows(const std::vector<Index>& rows, double scale);
  // delta_{n+2} (or s_{n+2}) of group row i under the forces found.
  double next_hard_value(const std::vector<Index>& rows, Index i, double scale) const;
  // One change of the active set (or of a friction row's stick / slip); false when none is due.
  bool update_hard_active_set(const std::vector<Index>& rows, double scale);
  bool update_hard_friction(const std::vector<Index>& rows, double scale);
  // Every combination of the group's contact states, when one change at a time cycles; false
  // when none is consistent (or the group has more than 6 contacts).
  bool enumerate_hard_states(const std::vector<Index>& rows, double scale);
  // Every hard row's force to zero (the force laws' solve comes first).
  void release_hard_forces();
  // Contacts already closing at t_0 get their force into F_0 and a_0, so that u_1 does not
  // penetrate (u_1 = u_0 + dt v_0 + dt^2/2 a_0).
  void initial_hard_contacts(SecondOrderSystem& system, State& state, double dt);
  // (B^T F) at one DOF the links touch.
  double nodal_link_force(Index dof, const Vector& link_force) const;
  // The link forces' share of a_{n+1} and v_{n+1}; returns whether those v_{n+1} are finite.
  bool apply_link_forces(const State& from, double half_dt, State& to) const;

  // Work vectors and matrices, kept so that a step allocates nothing.
  Vector rate_, offset_, offset_rate_, offset_acceleration_, force_, residual_, work_,
      inverse_mass_;
  Vector rhs_, predicted_velocity_, damping_force_, free_acceleration_, link_acceleration_;
  Vector correction_;
  Matrix tangent_;
  // Constant for the system given to initialize() (B is), built at its first step with links.
  Matrix coupling_;  // G = B M^-1 B^T
  // Rows of B that G or a link's own rows tie together (links sharing a node): the link-force
  // system is block diagonal over these groups, so it is solved group by group.
  std::vector<std::vector<Index>> link_groups_;
  std::vector<Matrix> group_jacobians_;
  std::vector<Eigen::PartialPivLU<Matrix>> group_lus_;
  Vector group_residual_;
  Eigen::SparseMatrix<double> link_columns_;  // B by columns, for B^T F at the DOFs it touches
  std::vector<Index> link_dofs_;              // the columns of B that have entries
  // Hard contacts: their laws by row, and the rows of each link group that are hard.
  std::vector<links::HardContact*> hard_laws_;  // by row; nullptr for a force law's row
  // The friction of a hard contact, on its tangential row; nullptr on every other row.
  std::vector<links::CoulombFriction*> hard_frictions_;
  std::vector<int> hard_tangent_;  // a friction row's tangent (0, or 1 in a contact plane)
  std::vector<char> hard_pair_;    // a friction row of a contact plane whose two tangents move
  std::vector<std::vector<Index>> hard_groups_;
  // Per hard row of a group: delta_{n+2} (s_{n+2}) without its force, its bound, whether it is
  // in the active set, a friction row's slip direction (0: sticking); the active set's matrix,
  // its solution, and the group's forces.
  Vector free_next_, bound_, active_force_, active_right_, magnitudes_, group_force_;
  std::vector<char> candidate_, active_;
  std::vector<signed char> slip_;
  // A slipping contact plane's direction e (on both its rows) and Newton's kappa = mu F_n / |s|
  // (on its first).
  Vector slip_direction_, slip_turn_;
  std::vector<Index> active_rows_;  // the group rows with an unknown force, in order
  Matrix active_matrix_;
};

// The largest stable step of central difference, 2/omega_max (reduced for damping at omega_max),
// with omega_max^2 the largest eigenvalue of (M + B^T m_l B)^-1 (K + B^T k_l B) found by power
// iteration; and no more than each link's own relative mode allows when it has a dashpot. With
// `contacts_active`, every link counts with its tangent at first touch (contact stiffness and
// penalty mass); without, with its tangent at rest (open contacts: none). Throws std::domain_error
// when M has a zero on its diagonal (explicit needs lumped mass on every DOF).
// `at`: link rows whose tangents are taken at a given penetration and rate instead (a Hertz-type
// contact, whose stiffness at first touch is 0, at its estimated peak penetration).
struct LinkRowState {
  Index row;
  double penetration, rate;
};
double stable_time_step(SecondOrderSystem& system, bool contacts_active,
                        std::span<const LinkRowState> at = {});
// omega_max of the same eigenproblem, undamped (for an implicit method stable only below a limit
// of omega dt, IntegratorEntry::stability_limit). The same requirements and errors.
double highest_frequency(SecondOrderSystem& system, bool contacts_active);

}  // namespace pound::integrators
