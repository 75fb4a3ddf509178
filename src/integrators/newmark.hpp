#pragma once
// Newmark's method with Newton equilibrium iteration condensed onto the link coordinates.
//
//   u_{n+1} = u~ + beta dt^2 a_{n+1},   u~ = u_n + dt v_n + (1/2 - beta) dt^2 a_n
//   v_{n+1} = v~ + gamma dt a_{n+1},    v~ = v_n + (1 - gamma) dt a_n
//   M a_{n+1} + C v_{n+1} + K u_{n+1} + B^T F_{n+1} = f_{n+1}
//
// With A = M/(beta dt^2) + gamma/(beta dt) C + K factored once per dt, u_{n+1} = u_lin - Z F
// where u_lin = A^{-1}(linear right-hand side) and Z = A^{-1} B^T. The remaining equations are
// m scalar ones, F - F_law(delta_lin - G F) = 0 with G = B Z, solved by Newton with the laws'
// consistent tangents. The iteration's start F_start goes into the linear solve,
// u_start = A^{-1}(r - B^T F_start), so that only its corrections F - F_start go through Z and G:
// a step that converges at its start (no link leaves its branch) does no n x m work. This is the
// full Newton method on the whole system, only cheaper: the unbalanced force of the whole system is
// exactly B^T (F - F_law).
//
// A hard contact (links/hard_contact.hpp) has no F_law. Its row is a constraint with the impact
// law at velocity level, as in Moreau-Jean time stepping (Jean 1999, "The non-smooth contact
// dynamics method", CMAME 177 235-257): a contact that would penetrate by t_{n+1} may leave the
// step at a normal rate no more than w+ = -e w- (w- its approach rate at t_n), which Newmark's
// update makes a bound on delta_{n+1}, delta~ + (beta dt / gamma) (w+ - w~); a held contact may
// not close further, delta_{n+1} <= delta_n. F >= 0 with complementarity, solved in the same
// Newton iteration as a semismooth (primal-dual active-set) step on min(F, s (bound - delta)) = 0
// with s = 1 / G(r, r) (Hintermueller, Ito & Kunisch 2002, SIAM J. Optim. 13(3) 865-888): a
// pressing row (F + s (delta - bound) > 0) gets delta = bound, its Jacobian row s G(r, :) with no
// identity; the others F = 0. The force is an impulse of its own step: the acceleration carried
// to the next step leaves it out (release_constraint_acceleration), so an impact's impulse is not
// applied again by the next step's predictor, nor does a held contact's force alternate from step
// to step as under the trapezoidal rule with a bound on the position alone. A rigid pair then
// parts at exactly -e times its approach rate, losing (1 - e^2) of its approach energy; the price
// is an overlap or gap of at most w- dt / 2 left at each impact. The impulse needs mass to act on:
// every DOF of a hard contact's row must carry one (the builder refuses the others). Coulomb
// friction on a hard contact is a constraint on its tangential row in the same iteration
// (Alart & Curnier's semismooth form, evaluate_hard_friction): sticking, no slide over the step
// (a zero slide rate at t_{n+1} when the contact slipped or was open before); slipping,
// F_t = mu F_n against the slide; its force is an impulse of its step like the normal one. In a
// contact plane (two tangents) the trial is a vector and the limit a circle: slipping,
// F_t = mu F_n tau / |tau| (Alart & Curnier's projection on the disc, with one scale s for both
// tangents so that the force at the fixed point is along the slide;
// evaluate_hard_friction_in_plane).
//
// Link rows that carry a force from the start on a linear branch (bearings, springs, hinges:
// stiffness K_r = dF/d(delta) + c_c dF/d(delta_dot) + c_m dF/d(delta_ddot) at the initial state)
// are folded into the factored matrix, A + B^T K B, whose unknown on such a row is then
// F - K_r (B u)_r: constant while the law stays on that branch, so the row has no tangent and a
// step in which no link leaves its branch (and no contact is closed) converges with no Newton
// iteration, from the last step's value. Newton's method is invariant under this affine change
// of the unknowns: the iterates are those of the unfolded iteration but for the start. Not with
// hard contacts (their active set depends on the iterates).
#include <Eigen/LU>
#include <array>
#include <map>
#include <vector>

#include "core/pivoted_lu.hpp"
#include "integrators/integrator.hpp"
#include "integrators/integrator_catalog.hpp"

namespace pound::integrators {

//
// With alpha_m, alpha_f the same step is the generalised-alpha family (Chung & Hulbert 1993):
// the equation holds at the intermediate instants, inertia at n+1-alpha_m, the rest (damping,
// stiffness, link forces, loads) at n+1-alpha_f, with the forces interpolated between n and n+1:
//   (1-a_m) M a_{n+1} + a_m M a_n + (1-a_f)(C v + K u + B^T F + ...)_{n+1} + a_f (...)_n = ...
// Dividing by (1-a_f) leaves the structure above with c_m scaled by (1-a_m)/(1-a_f) and a history
// term, so the condensed Newton on the link forces is unchanged. HHT-alpha is a_m = 0.
class Newmark final : public Integrator {
 public:
  Newmark(double beta, double gamma, ConvergenceTest test = {});
  // Trapezoidal rule: unconditionally stable, no numerical damping.
  static Newmark average_acceleration(ConvergenceTest test = {});
  // Conditionally stable (dt < 0.551 T_min), third-order period error.
  static Newmark linear_acceleration(ConvergenceTest test = {});
  // Hilber-Hughes-Taylor, alpha in [-1/3, 0]: gamma = 1/2 - alpha, beta = (1 - alpha)^2 / 4;
  // damps the high modes, second order.
  static Newmark hht(double alpha, ConvergenceTest test = {});
  // Generalised-alpha with the spectral radius rho_inf in [0, 1] at infinite frequency:
  // a_m = (2 rho - 1)/(rho + 1), a_f = rho/(rho + 1), gamma = 1/2 - a_m + a_f,
  // beta = (1 - a_m + a_f)^2 / 4. rho_inf = 1: no damping; 0: the high modes die in one step.
  static Newmark generalized_alpha(double rho_infinity, ConvergenceTest test = {});

  // The catalog entries of the three variants (integrators/integrator_catalog.hpp).
  static const IntegratorEntry& newmark_entry();
  static const IntegratorEntry& hht_entry();
  static const IntegratorEntry& generalized_alpha_entry();

  std::string name() const override;
  void initialize(SecondOrderSystem& system, State& state, double first_step) override;
  StepResult advance(SecondOrderSystem& system, const State& from, double dt, double end,
                     State& to) override;

  // The general path: the Newton correction I + T G over every link row, factored at every
  // iteration, no link row folded into the linear part, and the right-hand side by products with
  // M and C (no lumped mass's fused pass, no Rayleigh shift). Off by default (linear rows folded,
  // the active rows only, factors kept while their tangents stay, a1 K x by the shift); on, to
  // verify that the fast path gives the same results.
  void set_general_correction(bool general) { general_correction_ = general; }
  // Corrections solved with the kept factors updated by rows (large link systems, one or two
  // rows changed), for the tests that compare that path with the general one.
  long row_updates() const { return row_update_count_; }
  void set_row_updates(bool allowed) { row_updates_allowed_ = allowed; }

  double beta() const { return beta_; }
  double gamma() const { return gamma_; }
  double alpha_m() const { return alpha_m_; }
  double alpha_f() const { return alpha_f_; }

 private:
  Newmark(double beta, double gamma, double alpha_m, double alpha_f, std::string name,
          ConvergenceTest test);
  struct Factorization {
    std::unique_ptr<LinearSolver> solver;
    Matrix influence;  // Z = A^{-1} B^T (n x m)
    Matrix coupling;   // G = B Z (m x m)
    long id = 0;       // serial number, for the link system factored with it
    // K_r of the rows folded into the factored matrix (none: empty), and those rows.
    Vector folded_stiffness;
    std::vector<Index> folded_rows;
    bool folded_rates = false;  // some folded row has a dashpot or a mass term
    // With a lumped mass and Rayleigh damping with a1: the stiffness-proportional damping's
    // right-hand side without a product by K (predict_lumped): S = a1 / (1 + c_c a1) and
    // w = m (a0 - S (c_m + c_c a0)) by DOF; empty otherwise.
    Vector rayleigh_shift, rayleigh_weight;
    // The folded rows' L S x = B^T K_f B S x over their terms alone: row k's p = sum of
    // gather * x over its terms [starts[k], starts[k + 1]), then scatter * p off each term's DOF.
    std::vector<Index> shift_starts, shift_dofs;
    std::vector<double> shift_gather, shift_scatter;
  };
  // rayleigh_shift and rayleigh_weight of f for these coefficients, when they apply.
  static void set_rayleigh_shift(const SecondOrderSystem& system, double c_m, double c_c,
                                 Factorization& f);
  // K_r of every row for this step (zero where the row is not folded), from the references.
  Vector folded_stiffness(double dt) const;
  // The factors for dt: the last ones, or those kept for dt, or new ones.
  const Factorization& factorization(SecondOrderSystem& system, double dt);
  // Factors dt's matrix into the cache, dropping the least used beyond a handful.
  Factorization& new_factorization(SecondOrderSystem& system, double dt);

  // The steps of advance(), c_m = 1 / (beta dt^2) and c_c = gamma / (beta dt).
  // u~, v~ and the right-hand side's inertia part.
  void predict_step(SecondOrderSystem& system, const State& from, double dt, double c_m);
  // The same and the right-hand side but the alpha history, with a lumped mass and Rayleigh
  // damping or none, f_{n+1} taken at `end`; returns ||f_{n+1}||. With f's rayleigh_shift, the
  // right-hand side is that of u - S x, and shift_ holds S x (added to the solution).
  double predict_lumped(SecondOrderSystem& system, const Factorization& f, const State& from,
                        double end, const Vector& mass, double dt, double c_m, double c_c);
  // The alpha methods' history term, added to the right-hand side.
  void add_alpha_history(SecondOrderSystem& system, const State& from);
  // f_{n+1} and the damping term, added to the right-hand side; returns ||f_{n+1}||.
  double add_loads_and_damping(SecondOrderSystem& system, double time, double c_c);
  // The link deformations of u~ and the rates of v~, with the supports' motion; `solved`: and
  // those of u at F_start (to.displacement, solved), in the same pass.
  void predict_links(SecondOrderSystem& system, const State& to, bool solved);
  // F_{n+1} by the condensed Newton iteration; false, with result.failure, when it fails.
  bool solve_link_forces(SecondOrderSystem& system, const Factorization& f, double c_m, double c_c,
                         double external_norm, StepResult& result);
  // The Newton correction of the link forces from residual_ and tangent_, in correction_.
  void solve_correction(const Factorization& f);
  bool solve_by_row_update(const double* coupling, Index m);  // the kept factors, Woodbury
  void solve_with_factors(const Factorization& f, const double* coupling, Index m,
                          bool same_matrix);
  long row_update_count_ = 0;
  bool row_updates_allowed_ = true;
  // delta, rate and acceleration of the links at the assumed F, the laws' forces and tangent
  // there, and the residual F - F_law.
  void deform_links(const Factorization& f);
  void evaluate_links(LinkSet& links, const Factorization& f, double c_m, double c_c);
  enum class ResidualKind { zero, some, not_finite };
  ResidualKind residual_kind() const;
  // u_{n+1} = u_start - Z (F - F_start) and the link state of `to`.
  void apply_link_forces(const Factorization& f, State& to) const;
  // (B u)_r of a folded row from its deformation and the supports' offset, or at the current
  // iterate.
  double folded_projection(Index row, double delta, double offset) const;
  double folded_projection(Index row) const;
  // The folded rows' unknowns for t_{n+1}, predicted from t_n on their branch: the start of the
  // iteration.
  void start_folded_rows(SecondOrderSystem& system, const Factorization& f, const State& from);
  // The hard contacts' rows of the iteration: law force F + s (delta - bound) and tangent s
  // (pressing), or 0.
  void evaluate_hard_contacts(const Factorization& f);
  // A hard contact's friction row t (its normal row t - 1): stick or slip, law force, tangent.
  void evaluate_hard_friction(const Factorization& f, Index t);
  // The same for a contact plane's two tangential rows t, t + 1 (normal row t - 1).
  void evaluate_hard_friction_in_plane(const Factorization& f, Index t);
  // Zeroes row r's hard-friction Jacobian entries (before its state is chosen again).
  void clear_hard_friction_row(Index r);
  // visit(row, entry) for each nonzero entry of a slipping friction row r outside T G.
  template <typename Visit>
  void for_each_hard_entry(Index r, Visit visit) const;
  // The rows' derivatives at the initial state, zero on the rows that are not folded.
  void set_folding_references(LinkSet& links, const Vector& delta, const Vector& rate);
  // Each hard contact's bound for this step, from its state at t_n.
  void bound_hard_contacts(SecondOrderSystem& system, const State& from, double c_c);
  // a_{n+1} without the hard contacts' forces, their state force the step's impulse / dt.
  void release_constraint_acceleration(SecondOrderSystem& system, State& to);

  double beta_;
  double gamma_;
  double alpha_m_ = 0.0;
  double alpha_f_ = 0.0;
  std::string name_;  // of the preset, when one was used
  ConvergenceTest test_;
  // Factors by dt, so step cuts reuse theirs. Tied to the system given to initialize(), so a
  // copy of the integrator starts without them.
  struct FactorCache {
    FactorCache() = default;
    FactorCache(const FactorCache&) {}
    FactorCache& operator=(const FactorCache&) {
      by_step.clear();
      uses.clear();
      last = nullptr;
      return *this;
    }
    std::map<double, Factorization> by_step;
    std::map<double, long> uses;  // how often each was asked for
    double last_step = 0.0;       // the step last asked for, and its factors (nullptr: none)
    const Factorization* last = nullptr;
    long last_repeats = 0;  // asked for again since, not yet in uses
  } factorizations_;
  // Work vectors, kept to avoid allocation inside the time loop.
  Vector predicted_displacement_, predicted_velocity_, rhs_, work_, external_, damping_force_;
  Vector shift_, x_;  // S x of predict_lumped and its x = c_c u~ - v~
  Vector history_;
  // The iteration starts from F_start (the folded rows' predicted unknowns, 0 elsewhere), which
  // the linear solve takes in its right-hand side: u_start = A^{-1}(r - B^T F_start), whose link
  // deformations are delta_start; F - F_start, the iteration's corrections so far.
  Vector start_force_, delta_start_, force_change_;
  bool started_loaded_ = false;  // F_start has folded rows (else it is zero)
  // The rows this step's iteration has corrected (F may differ from F_start on these only), in
  // the order first corrected, and a mark by row.
  std::vector<Index> changed_rows_;
  // Rows that move no free DOF (a link between two supports, deformed by their motion alone):
  // no residual of theirs reaches the equilibrium test, so their force is the law's outright.
  std::vector<Index> unconnected_rows_;
  std::vector<char> changed_mark_;
  void mark_changed_rows();  // after a correction
  // Where a late Newton step stands: the forces it started from, with their unbalanced force, and
  // how far its correction is cut back.
  struct Backtrack {
    bool started = false;
    double unbalanced = 0.0;
    Vector force;
    double scale = 1.0;
    int halvings = 0;
  };
  // ||diag(T) delta||: the size of the link laws' terms, whose cancellation bounds the residual.
  double law_terms_norm() const;
  // Cuts a late correction that did not lower the unbalanced force back by half (true: the
  // forces changed, evaluate again).
  bool backtracked(Backtrack& backtrack, int iteration, double unbalanced);
  double force_change(Index row) const {
    return started_loaded_ ? assumed_force_[row] - start_force_[row] : assumed_force_[row];
  }
  Vector delta_predicted_, rate_predicted_;
  Vector delta_, rate_, acceleration_, assumed_force_, law_force_, residual_, correction_;
  // dF/d(delta), dF/d(delta_dot), dF/d(delta_ddot) of each row at the initial state, on the rows
  // that may be folded (a force law's, not a contact's nor a friction link's), zero elsewhere.
  Vector reference_stiffness_, reference_damping_, reference_mass_;
  Matrix tangent_, jacobian_;
  PivotedLu jacobian_lu_;
  bool general_correction_ = false;
  // The rows of each row's link, [first, end): a friction link's tangents couple them.
  struct LinkRows {
    Index first = 0, end = 0;
  };
  std::vector<LinkRows> link_rows_;
  bool link_blocks_ = false;        // any link with more than one row
  std::vector<Index> active_rows_;  // link rows with a tangent, in order
  std::vector<Index> moved_rows_;   // the others with a residual
  // The other rows q of a row's link whose tangent T(r, q) couples into row r (a friction link's
  // or a bearing's shear), found once per correction.
  struct RowCoupling {
    Index row = 0;
    double diagonal = 0.0;  // T(r, r)
    std::array<Index, links::kMaxTangents> rows{};
    std::array<double, links::kMaxTangents> tangents{};  // T(r, q) of those rows
    int count = 0;
  };
  std::vector<RowCoupling> row_coupling_;
  // Row (r) of T G at the columns c whose G(:, c) start at column_start = c m.
  static double tangent_times_coupling(const double* coupling, const RowCoupling& row,
                                       Index column_start);
  std::vector<Index> column_starts_;     // c m of the columns c of G a correction reads
  std::vector<double> active_tangents_;  // T(r, r), slip, T(r, q) of each active row
  // What jacobian_lu_ holds: the factorisation's id, the rows and their tangents.
  long factorization_count_ = 0, factored_id_ = 0;
  std::vector<Index> factored_rows_;
  std::vector<double> factored_tangents_;
  // Row updates of the kept factors (solve_by_row_update): from this many active rows, up to
  // this many changed rows.
  static constexpr Index kRowUpdateSize = 24;
  static constexpr int kMaxRowUpdates = 2;  // (its small solve is written for one or two)
  std::vector<Index> tangent_offsets_, factored_offsets_;  // each active row's first tangent
  std::vector<Index> changed_places_, update_places_;      // (places in active_rows_)
  Matrix row_changes_, update_columns_;                    // D, and Z = J0^-1 E of update_places_
  Vector unit_, update_column_;
  Vector reduced_residual_, reduced_correction_;
  Vector link_offset_, link_offset_rate_, link_offset_acceleration_;
  bool links_move_ = false;  // this step's links see the supports' motion (predict_links)
  Vector start_offset_, start_offset_rate_, start_offset_acceleration_;  // the supports' at t_n
  Vector start_rate_, start_acceleration_;  // of the link rows at t_n, for the folded dashpots
  const Vector* gaps_ = nullptr;            // of the system's links
  // Hard contacts: their laws by row (nullptr for a force law's row), found at initialize(), and
  // which of them press (delta = 0 enforced) at the current iterate.
  std::vector<links::HardContact*> hard_laws_;
  std::vector<links::CoulombFriction*> hard_frictions_;  // on a hard contact's friction rows
  std::vector<int> hard_tangent_;                        // a friction row's tangent, 0 or 1
  std::vector<char> hard_pair_;      // a friction row of a contact plane whose two tangents move
  std::vector<char> hard_pressing_;  // (a friction row: sticking)
  std::vector<char> hard_slipping_;  // a friction row slipping
  // A slipping friction row's Jacobian entries d(F - F_law)/dF outside T G on the rows of its link
  // (normal, tangent 1, tangent 2): -sign mu on the normal one in a plane scene; in a contact
  // plane -mu e_a on the normal and -Q(a, b) on the tangents. Zero on every other row.
  using HardEntries = std::array<double, 3>;
  std::vector<HardEntries> hard_entries_;
  std::vector<char> hard_candidate_;  // constrained in this step (held, or penetrated)
  Vector hard_bound_, hard_rate_, hard_force_, hard_acceleration_, link_history_;
  Vector hard_magnitudes_;  // LinkSet::row_magnitudes at the step's start: delta's round-off
  Vector hard_offset_, hard_offset_rate_, hard_offset_acceleration_;  // the supports' at t_n
  // M factored, for a consistent mass; tied to the system like the factors above.
  struct MassSolver {
    MassSolver() = default;
    MassSolver(const MassSolver&) {}
    MassSolver& operator=(const MassSolver&) {
      solver.reset();
      return *this;
    }
    std::unique_ptr<LinearSolver> solver;
  } mass_solver_;
  bool has_hard_contacts_ = false;
};

}  // namespace pound::integrators
