#pragma once
// The hard contacts of a static solve, and their friction: constraints on their link rows with
// their forces as multipliers, found by a primal-dual active set (Hintermüller, Ito & Kunisch
// 2002, SIAM J. Optim. 13(3) 865–888; with friction, Hüeber, Stadler & Wohlmuth 2008, SIAM J. Sci.
// Comput. 30(2) 572–596) inside static_equilibrium's Newton iteration.
//   normal row r:  held (delta_r = 0) while lambda_r + c_r delta_r > 0, else free (lambda_r = 0);
//                  a contact touching at the start (delta = 0) is held until its force pulls;
//   friction row t of a held contact: sticks (no further slide, s_t = s_t at the last increment)
//                  while |lambda_t + c_t (s_t - s_0)| <= mu (lambda_n + c_n delta_n), else slips at
//                  lambda_t = sign mu lambda_n, sign that trial's; under a moving belt it slips in
//                  the belt's direction, as penalty friction does in the static solve; in a
//                  contact plane (two tangents) the trial is a vector, the limit a circle, and a
//                  slipping contact's lambda_t = mu lambda_n e along its slide since the last
//                  increment, the direction's turn linearised in each Newton step.
// c_r = sum_j B_rj^2 |K_jj|, the stiffness the row sees (the structure's largest when its DOFs
// have none), so that lambda and c delta are both forces. Forces have a law's sign: F > 0
// presses, and -B^T F is their load on the structure. Units: lambda [F], delta [L], c [F/L].
#include <Eigen/SparseCore>
#include <vector>

#include "assembly/structural_system.hpp"

namespace pound::links {
class HardContact;
class CoulombFriction;
}  // namespace pound::links

namespace pound::assembly {

class StaticHardContacts {
 public:
  // `belt_rate`: the rows' rates from moving surfaces (zero: none); `start_delta`: the rows'
  // delta at u = 0, where sticking rows start.
  StaticHardContacts(StructuralSystem& system, const Vector& belt_rate, const Vector& start_delta);

  bool any() const { return any_; }
  bool constrains(Index row) const;
  // Whether row `row` is a friction row that slips (at mu lambda_n) in the state the last
  // choose() set; false for any other row.
  bool slips(Index row) const { return state_[static_cast<std::size_t>(row)] == Row::kSlip; }
  const Vector& multipliers() const { return multiplier_; }
  void set_multipliers(const Vector& multipliers) { multiplier_ = multipliers; }
  // Zeroes the hard rows of a LinkSet::set_trial force: a hard law returns what was last imposed.
  void leave_out(Vector& force) const;

  // The rows' states at delta and the current multipliers; true when none changed.
  bool choose(const Vector& delta);
  // In force units: c delta of a held or penetrating contact, c times a sticking row's slide.
  double violation(const Vector& delta) const;
  // Newton's step du and the active rows' new multipliers, from
  //   [K_t C; D 0] [du; lambda] = [residual; -g],
  // D the held and sticking rows of B, C their columns (a held row whose friction slips carries
  // it: B_n^T + sign mu B_t^T), g their violation; `residual` without the hard rows' forces.
  // False: the matrix is singular (a mechanism).
  bool solve(const Eigen::SparseMatrix<double>& tangent, const Vector& residual,
             const Vector& delta, Vector& step, Vector& multipliers) const;
  // Whether the last choose() changed no state but a slip's direction.
  bool only_turning() const { return turned_ && !changed_; }
  // Each slipping contact plane's friction mu lambda_n along its slide at delta (a trial of the
  // line search: its true force there, not the linearised one).
  void follow_slides(const Vector& delta);
  // A load increment done: a sticking row holds its slide from here on.
  void commit(const Vector& delta);
  // The hard laws take the forces found (to be committed with the links).
  void impose() const;

 private:
  enum class Row { kFree, kHeld, kStick, kSlip };
  Row friction_state(Index t, const Vector& delta);
  Row friction_state_in_plane(Index t, const Vector& delta);
  Index normal_of(Index t) const;  // a friction row's normal row
  bool in_plane(Index t) const;    // a friction row of a contact plane (two tangents)
  // A slipping contact plane's Newton terms for its slip direction's turn.
  void add_turn_entries(std::vector<Eigen::Triplet<double>>& entries) const;
  void add_turn_forces(const Vector& step, Vector& multipliers) const;
  template <typename Visit>
  void for_each_turning_pair(Visit visit) const;
  double coefficient(Index t) const;
  double target(Index r) const;  // held: delta = 0; sticking: s = s_0

  const integrators::LinkSet::SparseRowMatrix& connectivity_;
  std::vector<links::HardContact*> contacts_;
  std::vector<links::CoulombFriction*> frictions_;
  std::vector<int> tangent_;
  std::vector<char> pair_;
  std::vector<Row> state_;
  Vector multiplier_, scale_, direction_;
  // A slipping contact plane's kappa = mu lambda_n / |s - s_0| on its first row (0: none).
  Vector turn_;
  Vector belt_rate_, anchor_;
  bool any_ = false, started_ = false;
  bool turned_ = false;   // a slipping contact plane's direction changed in choose()
  bool changed_ = false;  // a row's state changed in choose()
};

}  // namespace pound::assembly
