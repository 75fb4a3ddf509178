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
#include <Eigen/LU>
#include <vector>

#include "integrators/integrator.hpp"
#include "integrators/integrator_catalog.hpp"

namespace pound::integrators {

class CentralDifference final : public Integrator {
 public:
  std::string name() const override { return "central_difference"; }
  // Its catalog entry (integrators/integrator_catalog.hpp).
  static const IntegratorEntry& entry();
  void initialize(SecondOrderSystem& system, State& state) override;
  StepResult advance(SecondOrderSystem& system, const State& from, double dt, State& to) override;

 private:
  // The steps of advance().
  // u_{n+1}, and a_{n+1}, v_{n+1} without the link forces; returns whether they are finite.
  bool advance_without_links(SecondOrderSystem& system, const State& from, double dt, State& to);
  // G, B by columns and the link groups, for the links of the system.
  void prepare_links(const LinkSet& links);
  // delta_{n+1}, the link rates at the half step and the link accelerations without link forces.
  void link_kinematics(SecondOrderSystem& system, const State& from, double half_dt, State& to);
  // F_{n+1}; false, with result.failure, when it is not finite or does not settle.
  bool solve_link_forces(LinkSet& links, State& to, StepResult& result);
  // correction_ from residual_ and tangent_, group by group.
  void solve_newton_correction();
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
};

// The largest stable step of central difference, 2/omega_max (reduced for damping at omega_max),
// with omega_max^2 the largest eigenvalue of (M + B^T m_l B)^-1 (K + B^T k_l B) found by power
// iteration; and no more than each link's own relative mode allows when it has a dashpot. With
// `contacts_active`, every link counts with its tangent at first touch (contact stiffness and
// penalty mass); without, with its tangent at rest (open contacts: none). Throws std::domain_error
// when M has a zero on its diagonal (explicit needs lumped mass on every DOF).
double stable_time_step(SecondOrderSystem& system, bool contacts_active);

}  // namespace pound::integrators
