#include "integrators/newmark.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <Eigen/QR>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"
#include "links/hard_contact.hpp"

namespace pound::integrators {
namespace {

// A residual that Newton cannot reduce (its correction at round-off) is accepted only within
// this fraction of the step's forces (the larger of the loads' and the laws'): the round-off of
// stiff penalties and of HHT's history is 1e-8 of them at most on the verification grids.
constexpr double kRoundOffResidual = 1e-6;

// The fused vector passes of a step, as functions so the restrict qualifiers on their
// parameters let the compiler vectorise them.
void predict(Index n, double dt, double displacement_factor, double velocity_factor, double c_m,
             const double* __restrict__ u, const double* __restrict__ v,
             const double* __restrict__ a, const double* __restrict__ mass,
             double* __restrict__ predicted_u, double* __restrict__ predicted_v,
             double* __restrict__ rhs) {
  for (Index i = 0; i < n; ++i) {
    predicted_u[i] = u[i] + dt * v[i] + displacement_factor * a[i];
    predicted_v[i] = v[i] + velocity_factor * a[i];
    rhs[i] = c_m * mass[i] * predicted_u[i];
  }
}

// The predictors, x = c_c u~ - v~ and M (inertia u~ + a0 x) + f over [first, last), a0 by DOF.
struct DampedPrediction {
  double dt, displacement_factor, velocity_factor, c_c, inertia;
};
void predict_damped(Index first, Index last, const DampedPrediction& p,
                    const double* __restrict__ u, const double* __restrict__ v,
                    const double* __restrict__ a, const double* __restrict__ mass,
                    const double* __restrict__ mass_coefficient, const double* __restrict__ force,
                    double* __restrict__ predicted_u, double* __restrict__ predicted_v,
                    double* __restrict__ x, double* __restrict__ rhs) {
  for (Index i = first; i < last; ++i) {
    predicted_u[i] = u[i] + p.dt * v[i] + p.displacement_factor * a[i];
    predicted_v[i] = v[i] + p.velocity_factor * a[i];
    x[i] = p.c_c * predicted_u[i] - predicted_v[i];
    rhs[i] = mass[i] * (p.inertia * predicted_u[i] + mass_coefficient[i] * x[i]) + force[i];
  }
}

// The same with the stiffness-proportional damping by the shift (Newmark::predict_lumped):
// rhs = c_m M u~ + w x + f and S x, w and S by DOF.
void predict_shifted(Index n, const DampedPrediction& p, const double* __restrict__ u,
                     const double* __restrict__ v, const double* __restrict__ a,
                     const double* __restrict__ mass, const double* __restrict__ weight,
                     const double* __restrict__ shift_coefficient, const double* __restrict__ force,
                     double* __restrict__ predicted_u, double* __restrict__ predicted_v,
                     double* __restrict__ x, double* __restrict__ shift, double* __restrict__ rhs) {
  for (Index i = 0; i < n; ++i) {
    predicted_u[i] = u[i] + p.dt * v[i] + p.displacement_factor * a[i];
    predicted_v[i] = v[i] + p.velocity_factor * a[i];
    x[i] = p.c_c * predicted_u[i] - predicted_v[i];
    shift[i] = shift_coefficient[i] * x[i];
    rhs[i] = p.inertia * mass[i] * predicted_u[i] + weight[i] * x[i] + force[i];
  }
}

// rhs -= L S x = B^T K_f B S x over the folded rows' terms (Newmark::Factorization).
void subtract_folded_shift(const std::vector<Index>& starts, const std::vector<Index>& dofs,
                           const std::vector<double>& gather, const std::vector<double>& scatter,
                           const double* __restrict__ x, double* __restrict__ rhs) {
  for (std::size_t k = 0; k + 1 < starts.size(); ++k) {
    const auto first = static_cast<std::size_t>(starts[k]);
    const auto last = static_cast<std::size_t>(starts[k + 1]);
    double projection = 0.0;
    for (std::size_t j = first; j < last; ++j) projection += gather[j] * x[dofs[j]];
    for (std::size_t j = first; j < last; ++j) rhs[dofs[j]] -= scatter[j] * projection;
  }
}

void correct(Index n, double c_m, double velocity_gain, const double* __restrict__ u,
             const double* __restrict__ predicted_u, const double* __restrict__ predicted_v,
             double* __restrict__ a, double* __restrict__ v) {
  for (Index i = 0; i < n; ++i) {
    a[i] = c_m * (u[i] - predicted_u[i]);
    v[i] = predicted_v[i] + velocity_gain * a[i];
  }
}

}  // namespace

Newmark::Newmark(double beta, double gamma, ConvergenceTest test)
    : beta_(beta), gamma_(gamma), test_(test) {
  if (!(beta > 0.0) || !(gamma >= 0.5))
    throw std::invalid_argument("Newmark needs beta > 0 and gamma >= 1/2");
}

Newmark::Newmark(double beta, double gamma, double alpha_m, double alpha_f, std::string name,
                 ConvergenceTest test)
    : Newmark(beta, gamma, test) {
  alpha_m_ = alpha_m;
  alpha_f_ = alpha_f;
  name_ = std::move(name);
}

Newmark Newmark::average_acceleration(ConvergenceTest test) { return {0.25, 0.5, test}; }
Newmark Newmark::linear_acceleration(ConvergenceTest test) { return {1.0 / 6.0, 0.5, test}; }

Newmark Newmark::hht(double alpha, ConvergenceTest test) {
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
    throw std::invalid_argument("HHT needs alpha in [-1/3, 0]");
  return {0.25 * (1.0 - alpha) * (1.0 - alpha),  0.5 - alpha, 0.0, -alpha,
          fmt::format("hht(alpha={:g})", alpha), test};
}

Newmark Newmark::generalized_alpha(double rho, ConvergenceTest test) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw std::invalid_argument("generalised-alpha needs rho_infinity in [0, 1]");
  const double alpha_m = (2.0 * rho - 1.0) / (rho + 1.0), alpha_f = rho / (rho + 1.0);
  const double gamma = 0.5 - alpha_m + alpha_f;
  return {0.25 * (1.0 - alpha_m + alpha_f) * (1.0 - alpha_m + alpha_f), gamma, alpha_m, alpha_f,
          fmt::format("generalized_alpha(rho_inf={:g})", rho),          test};
}

const IntegratorEntry& Newmark::newmark_entry() {
  static const IntegratorEntry entry{
      .name = "newmark",
      .description =
          "Newmark's method with Newton equilibrium iteration condensed onto the link "
          "rows; unconditionally stable for 2 beta >= gamma >= 1/2; with 2 beta < gamma only for "
          "omega_max dt < 1 / sqrt(gamma / 2 - beta) (linear acceleration: 2 sqrt(3), dt < 0.551 "
          "T_min), and a longer step (omega_max with the links in contact, `pound check` gives "
          "it) is refused where every DOF has a mass (with DOFs without one, check warns against "
          "the shortest period found, and the run stops one that grows)",
      .parameters = {{"beta", 0.25, 0.0, true, std::nullopt, "beta > 0"},
                     {"gamma", 0.5, 0.5, false, std::nullopt, "gamma >= 1/2 (above: damps)"}},
      .presets = {{"newmark_average_acceleration", {{"beta", 0.25}, {"gamma", 0.5}}},
                  {"newmark_linear_acceleration", {{"beta", 1.0 / 6.0}, {"gamma", 0.5}}}},
      .make = [](const std::map<std::string, double>& p,
                 const ConvergenceTest& test) -> std::unique_ptr<Integrator> {
        return std::make_unique<Newmark>(p.at("beta"), p.at("gamma"), test);
      },
      .acceleration_energy =
          [](const std::map<std::string, double>& p) {
            return p.at("gamma") == 0.5 ? 0.5 * (p.at("beta") - 0.25) : 0.0;
          },
      .dissipates = [](const std::map<std::string, double>& p) { return p.at("gamma") > 0.5; },
      // Undamped amplification matrix's spectral radius 1 up to omega dt = 1 / sqrt(gamma / 2 -
      // beta) (Hughes, The Finite Element Method, 1987, section 9.1).
      .stability_limit = [](const std::map<std::string, double>& p) -> std::optional<double> {
        const double margin = 0.5 * p.at("gamma") - p.at("beta");
        if (!(margin > 0.0)) return std::nullopt;
        return 1.0 / std::sqrt(margin);
      }};
  return entry;
}

const IntegratorEntry& Newmark::hht_entry() {
  static const IntegratorEntry entry{
      .name = "hht",
      .description = "Hilber-Hughes-Taylor alpha: second order, damps the high modes",
      .parameters = {{"alpha", -0.1, -1.0 / 3.0, false, 0.0, "alpha in [-1/3, 0]"}},
      .presets = {{"hht", {}}},
      .make = [](const std::map<std::string, double>& p,
                 const ConvergenceTest& test) -> std::unique_ptr<Integrator> {
        return std::make_unique<Newmark>(Newmark::hht(p.at("alpha"), test));
      },
      .dissipates = [](const std::map<std::string, double>& p) { return p.at("alpha") < 0.0; }};
  return entry;
}

const IntegratorEntry& Newmark::generalized_alpha_entry() {
  static const IntegratorEntry entry{
      .name = "generalized_alpha",
      .description =
          "generalised-alpha (Chung & Hulbert 1993): second order, high-frequency "
          "damping set by the spectral radius at infinite frequency",
      .parameters = {{"rho_infinity", 0.8, 0.0, false, 1.0,
                      "spectral radius at infinite frequency, in [0, 1]"}},
      .presets = {{"generalized_alpha", {}}},
      .study_parameters = {{"rho_infinity", 0.5}},
      .make = [](const std::map<std::string, double>& p,
                 const ConvergenceTest& test) -> std::unique_ptr<Integrator> {
        return std::make_unique<Newmark>(Newmark::generalized_alpha(p.at("rho_infinity"), test));
      },
      .dissipates =
          [](const std::map<std::string, double>& p) { return p.at("rho_infinity") < 1.0; }};
  return entry;
}

std::string Newmark::name() const {
  if (!name_.empty()) return name_;
  if (beta_ == 0.25 && gamma_ == 0.5) return "newmark_average_acceleration";
  if (beta_ == 1.0 / 6.0 && gamma_ == 0.5) return "newmark_linear_acceleration";
  return fmt::format("newmark(beta={:g}, gamma={:g})", beta_, gamma_);
}

void Newmark::initialize(SecondOrderSystem& system, State& state, double /*first_step*/) {
  factorizations_.by_step.clear();
  factorizations_.last = nullptr;
  external_.resize(0);  // zeroed at the first step of a system without loads
  mass_solver_.solver.reset();
  factorizations_.uses.clear();
  const Index n = system.size();
  LinkSet& links = system.links();
  if (state.displacement.size() != n) state.displacement = Vector::Zero(n);
  if (state.velocity.size() != n) state.velocity = Vector::Zero(n);
  Vector rate, zero = Vector::Zero(links.size());
  Matrix tangent;
  links.penetration(state.displacement, state.link_penetration);
  links.project(state.velocity, rate);
  if (system.has_link_motion()) {
    Vector offset, offset_rate, offset_acceleration;
    system.link_motion(state.time, offset, offset_rate, offset_acceleration);
    state.link_penetration += offset;
    rate += offset_rate;
  }
  gaps_ = &links.gaps();
  link_rows_.assign(static_cast<std::size_t>(links.size()), {});
  link_blocks_ = false;
  for (Index k = 0; k < links.count(); ++k) {
    link_blocks_ = link_blocks_ || links.rows(k) > 1;
    for (Index r = links.row(k); r < links.row(k) + links.rows(k); ++r)
      link_rows_[static_cast<std::size_t>(r)] = {links.row(k), links.row(k) + links.rows(k)};
  }
  LinkSet::HardRows hard_rows = links.hard_rows();
  hard_laws_ = std::move(hard_rows.contacts);
  hard_frictions_ = std::move(hard_rows.frictions);
  hard_tangent_ = std::move(hard_rows.tangent);
  hard_pair_ = std::move(hard_rows.pair);
  has_hard_contacts_ = false;
  for (std::size_t r = 0; r < hard_laws_.size(); ++r) {
    if (hard_laws_[r]) {
      hard_laws_[r]->impose(0.0);
      has_hard_contacts_ = true;
    }
    if (hard_frictions_[r]) hard_frictions_[r]->impose_tangential(hard_tangent_[r], 0.0, false);
  }
  hard_pressing_.assign(static_cast<std::size_t>(links.size()), 0);
  hard_slipping_.assign(static_cast<std::size_t>(links.size()), 0);
  hard_entries_.assign(static_cast<std::size_t>(links.size()), HardEntries{});
  if (has_hard_contacts_) {
    const std::vector<char> impulsive = links.impulsive_hard_contact_rows(system.lumped_mass());
    for (std::size_t r = 0; r < hard_laws_.size(); ++r)
      if (hard_laws_[r] && !impulsive[r])
        throw SolveError(state.time,
                         "a hard contact pushes a massless DOF, to which an implicit step cannot "
                         "give its impulse");
  }
  unconnected_rows_.clear();
  for (Index r = 0; r < links.size(); ++r) {
    bool moves_a_dof = false;
    for (LinkSet::SparseRowMatrix::InnerIterator it(links.connectivity(), r); it; ++it)
      moves_a_dof = moves_a_dof || it.value() != 0.0;
    if (!moves_a_dof && !hard_laws_[static_cast<std::size_t>(r)] &&
        !hard_frictions_[static_cast<std::size_t>(r)])
      unconnected_rows_.push_back(r);
  }
  set_folding_references(links, state.link_penetration, rate);
  links.set_trial(state.link_penetration, rate, zero, 0.0, 0.0, state.link_force, tangent);
  links.commit();

  // M a0 = f(t0) - C v0 - K u0 - B^T F0
  Vector rhs = Vector::Zero(n), work(n);
  if (system.has_external_force()) system.external_force(state.time, rhs);
  if (system.has_damping()) {
    system.multiply_damping(state.velocity, work);
    rhs -= work;
  }
  system.multiply_stiffness(state.displacement, work);
  rhs -= work;
  rhs.noalias() -= links.connectivity().transpose() * state.link_force;
  state.acceleration.resize(n);
  if (const Vector* mass = system.lumped_mass()) {
    // Massless DOFs (rotations without rotary inertia) have static equations: no acceleration.
    for (Index i = 0; i < n; ++i)
      state.acceleration[i] = (*mass)[i] > 0.0 ? rhs[i] / (*mass)[i] : 0.0;
  } else {
    system.factor(1.0, 0.0, 0.0)->solve(rhs, state.acceleration);
  }
}

void Newmark::set_folding_references(LinkSet& links, const Vector& delta, const Vector& rate) {
  LinkSet::RowDerivatives reference =
      links.row_derivatives(delta, rate, Vector::Zero(links.size()));
  for (Index k = 0; k < links.count(); ++k) {
    const Index row = links.row(k);
    // A contact's force is a constraint's, a friction link's tangent a 2 x 2 or 3 x 3 block.
    if (hard_laws_[static_cast<std::size_t>(row)] || links.has_friction(k)) {
      for (Index r = row; r < row + links.rows(k); ++r)
        reference.stiffness[r] = reference.damping[r] = reference.mass[r] = 0.0;
    }
  }
  reference_stiffness_ = std::move(reference.stiffness);
  reference_damping_ = std::move(reference.damping);
  reference_mass_ = std::move(reference.mass);
}

Vector Newmark::folded_stiffness(double dt) const {
  // The factors evaluate_links gives the laws, so a linear row's tangent is K_r to the bit.
  const double c_m = 1.0 / (beta_ * dt * dt), c_c = gamma_ / (beta_ * dt);
  Vector stiffness = Vector::Zero(reference_stiffness_.size());
  bool any = false;
  for (Index r = 0; r < stiffness.size(); ++r) {
    const double k =
        reference_stiffness_[r] + reference_damping_[r] * c_c + reference_mass_[r] * c_m;
    if (k > 0.0 && std::isfinite(k)) {
      stiffness[r] = k;
      any = true;
    }
  }
  return any ? stiffness : Vector();
}

const Newmark::Factorization& Newmark::factorization(SecondOrderSystem& system, double dt) {
  // A fixed step asks for the same factors at every step: no search; its uses are counted when
  // another step is asked for.
  FactorCache& cache = factorizations_;
  if (dt == cache.last_step && cache.last) {
    ++cache.last_repeats;
    return *cache.last;
  }
  if (cache.last) cache.uses[cache.last_step] += cache.last_repeats;
  cache.last_repeats = 0;
  ++cache.uses[dt];
  const auto found = cache.by_step.find(dt);
  cache.last = found != cache.by_step.end() ? &found->second : &new_factorization(system, dt);
  cache.last_step = dt;
  return *cache.last;
}

Newmark::Factorization& Newmark::new_factorization(SecondOrderSystem& system, double dt) {
  // Adaptive stepping and step cuts ask for a few step sizes over and over, contact location
  // for one-off ones: keep a handful, dropping the least used.
  FactorCache& cache = factorizations_;
  if (cache.by_step.size() >= 8) {
    auto least = cache.by_step.begin();
    for (auto it = cache.by_step.begin(); it != cache.by_step.end(); ++it)
      if (cache.uses[it->first] < cache.uses[least->first]) least = it;
    cache.uses.erase(least->first);
    cache.by_step.erase(least);
  }
  // With alpha_m, alpha_f the mass term weighs (1 - a_m) / (1 - a_f).
  const double c_m = (1.0 - alpha_m_) / (1.0 - alpha_f_) / (beta_ * dt * dt);
  const double c_c = gamma_ / (beta_ * dt);
  Factorization f;
  f.id = ++factorization_count_;
  const double damping_factor = system.has_damping() ? c_c : 0.0;
  // Not with hard contacts: a contact is constrained for the step from the first iterate on which
  // it penetrates, so its result would depend on where the iteration starts.
  if (!general_correction_ && !has_hard_contacts_) f.folded_stiffness = folded_stiffness(dt);
  if (f.folded_stiffness.size() > 0) {
    f.solver = system.factor_with_links(c_m, damping_factor, 1.0, f.folded_stiffness);
  }
  if (f.solver) {
    for (Index r = 0; r < f.folded_stiffness.size(); ++r) {
      if (f.folded_stiffness[r] == 0.0) continue;
      f.folded_rows.push_back(r);
      f.folded_rates = f.folded_rates || reference_damping_[r] != 0.0 || reference_mass_[r] != 0.0;
    }
  } else {
    f.folded_stiffness.resize(0);
    f.solver = system.factor(c_m, damping_factor, 1.0);
  }
  if (!general_correction_) set_rayleigh_shift(system, c_m, damping_factor, f);
  const LinkSet& links = system.links();
  const Index n = system.size(), m = links.size();
  f.influence.resize(n, m);
  Vector column(n), solution(n);
  for (Index k = 0; k < m; ++k) {
    column = links.connectivity().row(k).transpose();
    f.solver->solve(column, solution);
    f.influence.col(k) = solution;
  }
  f.coupling = links.connectivity() * f.influence;
  return cache.by_step.emplace(dt, std::move(f)).first->second;
}

void Newmark::set_rayleigh_shift(const SecondOrderSystem& system, double c_m, double c_c,
                                 Factorization& f) {
  const Vector* mass = system.lumped_mass();
  const SecondOrderSystem::Rayleigh* rayleigh = system.has_damping() ? system.rayleigh() : nullptr;
  if (!mass || !rayleigh || !rayleigh->stiffness) return;
  const Vector& a0 = rayleigh->mass_coefficient;
  const Vector& a1 = rayleigh->stiffness_coefficient;
  f.rayleigh_shift = a1.array() / (1.0 + c_c * a1.array());
  f.rayleigh_weight =
      mass->array() * (a0.array() - f.rayleigh_shift.array() * (c_m + c_c * a0.array()));
  const LinkSet::SparseRowMatrix& connectivity = system.links().connectivity();
  for (const Index r : f.folded_rows) {
    f.shift_starts.push_back(static_cast<Index>(f.shift_dofs.size()));
    for (LinkSet::SparseRowMatrix::InnerIterator term(connectivity, r); term; ++term) {
      f.shift_dofs.push_back(term.col());
      f.shift_gather.push_back(term.value() * f.rayleigh_shift[term.col()]);
      f.shift_scatter.push_back(term.value() * f.folded_stiffness[r]);
    }
  }
  f.shift_starts.push_back(static_cast<Index>(f.shift_dofs.size()));
}

StepResult Newmark::advance(SecondOrderSystem& system, const State& from, double dt, double end,
                            State& to) {
  const Factorization& f = factorization(system, dt);
  const Index n = system.size();
  const double c_m = 1.0 / (beta_ * dt * dt);
  const double c_c = gamma_ / (beta_ * dt);
  to.time = end;
  double external_norm = 0.0;
  bool shifted = false;  // the solution is that of u - S x (predict_lumped)
  if (const Vector* mass = system.lumped_mass();
      mass && (!system.has_damping() || system.rayleigh()) && !general_correction_) {
    external_norm = predict_lumped(system, f, from, end, *mass, dt, c_m, c_c);
    shifted = f.rayleigh_shift.size() > 0;
    if (alpha_m_ != 0.0 || alpha_f_ != 0.0) add_alpha_history(system, from);
  } else {
    predict_step(system, from, dt, c_m);
    if (alpha_m_ != 0.0 || alpha_f_ != 0.0) add_alpha_history(system, from);
    external_norm = add_loads_and_damping(system, to.time, c_c);
  }
  // Folded rows start from their predicted unknowns, F_start, which go into the linear solve:
  // only the iteration's corrections then go through Z. Without them F_start = 0, and the
  // predicted link state is taken in the same pass as the solution's.
  const bool links = system.links().size() > 0;
  started_loaded_ = links && !f.folded_rows.empty();
  if (started_loaded_) {
    predict_links(system, to, false);
    start_folded_rows(system, f, from);
    start_force_ = assumed_force_;
    system.links().subtract_transpose(start_force_, rhs_);
  }
  to.displacement.resize(n);
  f.solver->solve(rhs_, to.displacement);  // u at F_start
  if (shifted) to.displacement += shift_;

  StepResult result;
  if (links) {
    if (started_loaded_) {
      system.links().penetration(to.displacement, delta_start_);
      if (links_move_) delta_start_ += link_offset_;
    } else {
      predict_links(system, to, true);
      if (has_hard_contacts_) bound_hard_contacts(system, from, c_c);
      start_folded_rows(system, f, from);
    }
    if (!solve_link_forces(system, f, c_m, c_c, external_norm, result)) return result;
    apply_link_forces(f, to);
  } else {
    to.link_penetration.resize(0);
    to.link_force.resize(0);
  }

  // a = c_m (u - u~), v = v~ + gamma dt a, in one pass.
  to.acceleration.resize(n);
  to.velocity.resize(n);
  correct(n, c_m, gamma_ * dt, to.displacement.data(), predicted_displacement_.data(),
          predicted_velocity_.data(), to.acceleration.data(), to.velocity.data());
  if (has_hard_contacts_) release_constraint_acceleration(system, to);
  // A NaN or Inf anywhere makes the sum non-finite; Eigen's packet sum is not one serial chain.
  if (!std::isfinite(to.velocity.sum())) {
    result.failure = "the state is not finite";
    return result;
  }
  result.converged = true;
  return result;
}

// With a lumped mass and Rayleigh damping (C = a0 M + a1 K) or none, the right-hand side is
// M (c_m u~ + a0 x) + f + a1 K x with x = c_c u~ - v~. Its K x needs no product: the factored
// matrix is A = M'' + (I + c_c D1) K + L, with M'' = (c_m + c_c D0) M diagonal, D0 and D1 the
// coefficients by DOF and L = B^T K_f B the folded link rows; K couples no DOFs of different
// coefficients, so S = D1 (I + c_c D1)^-1 commutes with K and M'', and S A = A S + S L - L S.
// Then A^-1 D1 K x = A^-1 S (A - M'' - L) x = S x - A^-1 (S M'' x + L S x): u is the solution
// for the right-hand side M c_m u~ + w x + f - L S x, with w = M D0 - S M'', plus S x (shift_).
// In the low modes the two parts cancel to ~ (omega dt)^2 of S x, which costs round-off of u's
// size only (S x is about u~, as c_c S < 1).
double Newmark::predict_lumped(SecondOrderSystem& system, const Factorization& f, const State& from,
                               double end, const Vector& mass, double dt, double c_m, double c_c) {
  const Index n = system.size();
  const double mass_weight = (1.0 - alpha_m_) / (1.0 - alpha_f_);
  const DampedPrediction p{dt, (0.5 - beta_) * dt * dt, (1.0 - gamma_) * dt, c_c,
                           mass_weight * c_m};
  predicted_displacement_.resize(n);
  predicted_velocity_.resize(n);
  rhs_.resize(n);
  double external_norm = 0.0;
  const bool loaded = system.has_external_force();
  if (loaded) {
    system.external_force(end, external_);
    external_norm = external_.norm();
  } else if (external_.size() != n) {
    external_.setZero(n);  // once: nothing writes it without loads
  }
  const SecondOrderSystem::Rayleigh* rayleigh = system.has_damping() ? system.rayleigh() : nullptr;
  if (f.rayleigh_shift.size() > 0) {
    shift_.resize(n);
    x_.resize(n);
    predict_shifted(n, p, from.displacement.data(), from.velocity.data(), from.acceleration.data(),
                    mass.data(), f.rayleigh_weight.data(), f.rayleigh_shift.data(),
                    external_.data(), predicted_displacement_.data(), predicted_velocity_.data(),
                    x_.data(), shift_.data(), rhs_.data());
    subtract_folded_shift(f.shift_starts, f.shift_dofs, f.shift_gather, f.shift_scatter, x_.data(),
                          rhs_.data());
    return external_norm;
  }
  if (!rayleigh) {
    predict(n, dt, p.displacement_factor, p.velocity_factor, p.inertia, from.displacement.data(),
            from.velocity.data(), from.acceleration.data(), mass.data(),
            predicted_displacement_.data(), predicted_velocity_.data(), rhs_.data());
    if (loaded) rhs_ += external_;
    return external_norm;
  }
  // Mass-proportional only (a1 K x is the shift's, above).
  work_.resize(n);
  predict_damped(0, n, p, from.displacement.data(), from.velocity.data(), from.acceleration.data(),
                 mass.data(), rayleigh->mass_coefficient.data(), external_.data(),
                 predicted_displacement_.data(), predicted_velocity_.data(), work_.data(),
                 rhs_.data());
  return external_norm;
}

void Newmark::predict_step(SecondOrderSystem& system, const State& from, double dt, double c_m) {
  // Predictors and the linear right-hand side's inertia part M (c_m u~), in one pass when M is
  // diagonal (c_m weighted for the alpha methods).
  const Index n = system.size();
  const double mass_weight = (1.0 - alpha_m_) / (1.0 - alpha_f_);
  const double displacement_factor = (0.5 - beta_) * dt * dt, velocity_factor = (1.0 - gamma_) * dt;
  predicted_displacement_.resize(n);
  predicted_velocity_.resize(n);
  rhs_.resize(n);
  if (const Vector* mass = system.lumped_mass()) {
    predict(n, dt, displacement_factor, velocity_factor, mass_weight * c_m,
            from.displacement.data(), from.velocity.data(), from.acceleration.data(), mass->data(),
            predicted_displacement_.data(), predicted_velocity_.data(), rhs_.data());
  } else {
    predicted_displacement_ =
        from.displacement + dt * from.velocity + displacement_factor * from.acceleration;
    predicted_velocity_ = from.velocity + velocity_factor * from.acceleration;
    work_ = mass_weight * c_m * predicted_displacement_;
    system.multiply_mass(work_, rhs_);
  }
}

void Newmark::add_alpha_history(SecondOrderSystem& system, const State& from) {
  // History of the alpha methods: [a_f (f_n - C v_n - K u_n - B^T F_n) - a_m M a_n] / (1 - a_f).
  history_ = Vector::Zero(system.size());
  if (system.has_external_force()) {
    system.external_force(from.time, work_);
    history_ += alpha_f_ * work_;
  }
  system.multiply_stiffness(from.displacement, work_);
  history_ -= alpha_f_ * work_;
  if (system.has_damping()) {
    system.multiply_damping(from.velocity, work_);
    history_ -= alpha_f_ * work_;
  }
  if (from.link_force.size() > 0) {
    const Vector* link_force = &from.link_force;
    if (has_hard_contacts_) {
      // A hard contact's force acted in its own step (release_constraint_acceleration).
      link_history_ = from.link_force;
      for (std::size_t r = 0; r < hard_laws_.size(); ++r)
        if (hard_laws_[r] || hard_frictions_[r]) link_history_[static_cast<Index>(r)] = 0.0;
      link_force = &link_history_;
    }
    history_.noalias() -= alpha_f_ * (system.links().connectivity().transpose() * *link_force);
  }
  system.multiply_mass(from.acceleration, work_);
  history_ -= alpha_m_ * work_;
  rhs_ += history_ / (1.0 - alpha_f_);
}

double Newmark::add_loads_and_damping(SecondOrderSystem& system, double time, double c_c) {
  // The rest of the linear right-hand side: f + C (c_c u~ - v~).
  double external_norm = 0.0;
  if (system.has_external_force()) {
    system.external_force(time, external_);
    rhs_ += external_;
    external_norm = external_.norm();
  }
  if (system.has_damping()) {
    work_ = c_c * predicted_displacement_ - predicted_velocity_;
    damping_force_.resize(system.size());
    system.multiply_damping(work_, damping_force_);
    rhs_ += damping_force_;
  }
  return external_norm;
}

void Newmark::predict_links(SecondOrderSystem& system, const State& to, bool solved) {
  const LinkSet& links = system.links();
  if (solved)
    links.penetrations_and_rate(to.displacement, predicted_displacement_, predicted_velocity_,
                                delta_start_, delta_predicted_, rate_predicted_);
  else
    links.penetration_and_rate(predicted_displacement_, predicted_velocity_, delta_predicted_,
                               rate_predicted_);
  // Support motion moves the links' deformation by s(t); B a = c_m (delta - delta~) stays.
  links_move_ = system.has_link_motion();
  if (links_move_) {
    system.link_motion(to.time, link_offset_, link_offset_rate_, link_offset_acceleration_);
    if (solved) delta_start_ += link_offset_;
    delta_predicted_ += link_offset_;
    rate_predicted_ += link_offset_rate_;
  }
}

bool Newmark::solve_link_forces(SecondOrderSystem& system, const Factorization& f, double c_m,
                                double c_c, double external_norm, StepResult& result) {
  LinkSet& links = system.links();
  Backtrack backtrack;
  for (int iteration = 0;; ++iteration) {
    evaluate_links(links, f, c_m, c_c);
    const ResidualKind kind = residual_kind();
    if (kind == ResidualKind::not_finite) {
      result.failure = "link forces are not finite";
      return false;
    }
    // Every residual an exact zero (every row on the branch it started on): converged.
    result.unbalanced_force = kind == ResidualKind::zero ? 0.0 : links.nodal_norm(residual_);
    const auto allowed = [&](double reference) {
      return test_.relative_tolerance * reference + test_.absolute_tolerance;
    };
    // The reference is the larger of ||f|| and ||B^T F_law||: the second is needed only when the
    // first does not already pass the step.
    double reference = external_norm;
    if (result.unbalanced_force <= allowed(reference)) return true;
    reference = std::max(external_norm, links.nodal_norm(law_force_));
    if (result.unbalanced_force <= allowed(reference)) return true;
    if (iteration == test_.max_iterations) {
      result.failure = fmt::format(
          "Newton did not converge in {} iterations (unbalanced force {:.3e}, reference {:.3e})",
          test_.max_iterations, result.unbalanced_force, reference);
      return false;
    }
    if (backtracked(backtrack, iteration, result.unbalanced_force)) continue;
    solve_correction(f);
    assumed_force_ -= correction_;
    mark_changed_rows();
    ++result.iterations;
    // Converged to machine precision: with a very stiff penalty the residual cannot fall below
    // its round-off (stiffness x eps x displacement) while the correction already has. The law's
    // terms may be far larger than its force: an extended penalty's alpha2 c_m (delta - delta~)
    // cancels delta's leading digits (T delta of 6e10 N for a force of 3.4e4 at alpha2 =
    // 0.45 m_eff, dt = 1e-5: Newton then swung by 1e-5 N, its round-off, to the 25th iteration).
    // Only a residual small against the forces (the loads' and the laws'; not the iterate's own
    // unknowns, 1e17 N where a damper's linear_velocity is 1e-300): a tangent of 1e50 makes any
    // correction vanish against its terms while a yielded spring's residual is the whole load,
    // and an extended penalty's release with a residual of 3.8e5 N against no force at all was
    // accepted so.
    if (iteration > 0 && result.unbalanced_force <= kRoundOffResidual * reference &&
        correction_.norm() <= 1e-14 * std::max({assumed_force_.norm(), law_terms_norm(), 1e-300})) {
      deform_links(f);
      return true;
    }
  }
}

double Newmark::law_terms_norm() const {
  double sum = 0.0;
  for (Index r = 0; r < delta_.size(); ++r) {
    const double term = tangent_(r, r) * delta_[r];
    sum += term * term;
  }
  return std::sqrt(sum);
}

// Newton's full steps, kept while they converge (every run that converges in kBacktrackAfter
// iterations is untouched). Past them, a correction that left the residual no smaller is halved
// back from the forces it started at, up to kHalvings times: a row whose force rises from zero
// with an unbounded slope (Jankowski's damping ~ delta^(1/4) delta_dot at a contact's onset)
// otherwise has Newton jump between open (tangent zero) and closed (tangent huge) for ever, at
// any step size. Not with hard contacts, whose semismooth rows keep their active-set logic.
bool Newmark::backtracked(Backtrack& backtrack, int iteration, double unbalanced) {
  constexpr int kBacktrackAfter = 8, kHalvings = 30;
  if (has_hard_contacts_ || iteration < kBacktrackAfter) return false;
  if (backtrack.started && unbalanced >= backtrack.unbalanced && backtrack.halvings < kHalvings) {
    ++backtrack.halvings;
    backtrack.scale *= 0.5;
    assumed_force_ = backtrack.force - backtrack.scale * correction_;
    return true;
  }
  backtrack = {true, unbalanced, assumed_force_, 1.0, 0};
  return false;
}

// More hard constraints than the DOFs they hold (a rigid deck's two corners sticking: four rows on
// three DOFs) make the Jacobian singular; their forces are then not unique, but the motion is:
// the least-norm correction (a complete orthogonal decomposition) finds one set of them.
namespace {
Vector least_norm_correction(const Matrix& jacobian, const Vector& residual) {
  return jacobian.completeOrthogonalDecomposition().solve(residual);
}
}  // namespace

double Newmark::tangent_times_coupling(const double* coupling, const RowCoupling& row,
                                       Index column_start) {
  double entry = row.diagonal * coupling[column_start + row.row];
  for (int k = 0; k < row.count; ++k)
    entry += row.tangents[static_cast<std::size_t>(k)] *
             coupling[column_start + row.rows[static_cast<std::size_t>(k)]];
  return entry;
}

template <typename Visit>
void Newmark::for_each_hard_entry(Index r, Visit visit) const {
  if (!hard_slipping_[static_cast<std::size_t>(r)]) return;
  const LinkRows& rows = link_rows_[static_cast<std::size_t>(r)];
  const HardEntries& entries = hard_entries_[static_cast<std::size_t>(r)];
  for (Index row = rows.first; row < rows.end; ++row)
    if (const double entry = entries[static_cast<std::size_t>(row - rows.first)]; entry != 0.0)
      visit(row, entry);
}

// d(residual)/dF = I + T G, with T block diagonal (a link's row, or its normal and tangential
// rows). A row whose tangent is zero (an open contact, a slack restrainer) is the identity row,
// so its correction is its residual; only the rows with a tangent form the system that is
// factored, at no more than the size of the active links.
void Newmark::solve_correction(const Factorization& f) {
  const Index m = residual_.size();
  if (general_correction_) {
    jacobian_.noalias() = tangent_ * f.coupling;
    for (Index r = 0; r < m; ++r) {
      if (!hard_pressing_[static_cast<std::size_t>(r)]) jacobian_(r, r) += 1.0;
      for_each_hard_entry(r, [&](Index row, double entry) { jacobian_(r, row) += entry; });
    }
    jacobian_lu_.compute(jacobian_);
    jacobian_lu_.solve(residual_, correction_);
    if (!correction_.allFinite()) correction_ = least_norm_correction(jacobian_, residual_);
    factored_id_ = 0;
    return;
  }
  correction_ = residual_;
  active_rows_.clear();
  moved_rows_.clear();
  row_coupling_.resize(static_cast<std::size_t>(m));
  for (Index r = 0; r < m; ++r) {
    // The other rows of r's link (a friction link's or a shear's) whose tangents couple into it.
    RowCoupling& coupled = row_coupling_[static_cast<std::size_t>(r)];
    coupled.row = r;
    coupled.diagonal = tangent_(r, r);
    coupled.count = 0;
    if (link_blocks_) {
      const LinkRows& rows = link_rows_[static_cast<std::size_t>(r)];
      for (Index q = rows.first; q < rows.end; ++q)
        if (const double tangent = tangent_(r, q); q != r && tangent != 0.0) {
          coupled.rows[static_cast<std::size_t>(coupled.count)] = q;
          coupled.tangents[static_cast<std::size_t>(coupled.count++)] = tangent;
        }
    }
    if (coupled.diagonal != 0.0 || coupled.count > 0 || hard_slipping_[static_cast<std::size_t>(r)])
      active_rows_.push_back(r);
    else if (residual_[r] != 0.0)
      moved_rows_.push_back(r);
  }
  const Index size = static_cast<Index>(active_rows_.size());
  if (size == 0) return;
  // Row r of T G: T(r, r) G(r, c) + the sum of T(r, q) G(q, c) over the other rows of its link,
  // G(r, c) at coupling[c m + r]. Each row's tangents are copied out of row_coupling_ before its
  // loop, so they stay in registers (stores to jacobian_ might otherwise alias them).
  const double* const coupling = f.coupling.data();
  column_starts_.clear();
  for (const Index c : moved_rows_) column_starts_.push_back(c * m);
  reduced_residual_.resize(size);
  for (Index i = 0; i < size; ++i) {
    const RowCoupling row =
        row_coupling_[static_cast<std::size_t>(active_rows_[static_cast<std::size_t>(i)])];
    // The identity rows' known corrections move to the right-hand side.
    double rhs = residual_[row.row];
    for (std::size_t k = 0; k < moved_rows_.size(); ++k)
      rhs -= tangent_times_coupling(coupling, row, column_starts_[k]) * residual_[moved_rows_[k]];
    reduced_residual_[i] = rhs;
  }
  // The same rows with the same tangents (linear laws, or branches that did not change): the
  // same matrix, whose factors are kept.
  active_tangents_.clear();
  tangent_offsets_.clear();
  for (const Index r : active_rows_) {
    tangent_offsets_.push_back(static_cast<Index>(active_tangents_.size()));
    active_tangents_.push_back(tangent_(r, r));
    active_tangents_.push_back(hard_slipping_[static_cast<std::size_t>(r)]);
    if (hard_slipping_[static_cast<std::size_t>(r)]) {
      const HardEntries& entries = hard_entries_[static_cast<std::size_t>(r)];
      active_tangents_.insert(active_tangents_.end(), entries.begin(), entries.end());
    }
    if (!link_blocks_) continue;
    const LinkRows& rows = link_rows_[static_cast<std::size_t>(r)];
    for (Index q = rows.first; q < rows.end; ++q)
      if (q != r) active_tangents_.push_back(tangent_(r, q));
  }
  const bool same_rows = f.id == factored_id_ && active_rows_ == factored_rows_;
  const bool same_matrix = same_rows && active_tangents_ == factored_tangents_;
  if (!(same_rows && !same_matrix && solve_by_row_update(coupling, m)))
    solve_with_factors(f, coupling, m, same_matrix);
  for (Index i = 0; i < size; ++i)
    correction_[active_rows_[static_cast<std::size_t>(i)]] = reduced_correction_[i];
}

// reduced_correction_ with jacobian_lu_, factored anew first unless `same_matrix`.
void Newmark::solve_with_factors(const Factorization& f, const double* coupling, Index m,
                                 bool same_matrix) {
  const Index size = static_cast<Index>(active_rows_.size());
  if (!same_matrix) {
    jacobian_.resize(size, size);
    column_starts_.clear();
    for (const Index c : active_rows_) column_starts_.push_back(c * m);
    for (Index i = 0; i < size; ++i) {
      const Index r = active_rows_[static_cast<std::size_t>(i)];
      const RowCoupling coupled = row_coupling_[static_cast<std::size_t>(r)];
      for (Index j = 0; j < size; ++j)
        jacobian_(i, j) =
            tangent_times_coupling(coupling, coupled, column_starts_[static_cast<std::size_t>(j)]);
      // A pressing hard contact's row is s G(r, :) alone: its F_law moves with F. A slipping
      // friction row's adds its entries on its link's rows, which are active too and come in
      // order just around it (the normal row, the tangents), at i - (r - row).
      if (!hard_pressing_[static_cast<std::size_t>(r)]) jacobian_(i, i) += 1.0;
      for_each_hard_entry(r, [&](Index row, double entry) {
        // Within two places of i: the link's rows that move are active and in order.
        Index j = std::max<Index>(0, i - 2);
        while (active_rows_[static_cast<std::size_t>(j)] != row) ++j;
        jacobian_(i, j) += entry;
      });
    }
    jacobian_lu_.compute(jacobian_);
    factored_id_ = f.id;
    factored_rows_ = active_rows_;
    factored_tangents_ = active_tangents_;
    factored_offsets_ = tangent_offsets_;
    update_places_.clear();
  }
  jacobian_lu_.solve(reduced_residual_, reduced_correction_);
  if (!reduced_correction_.allFinite())
    reduced_correction_ = least_norm_correction(jacobian_, reduced_residual_);
}

// The active rows whose tangents differ from the factored ones: with one or two of them in a
// large system (a storey spring changing branch, one contact pressing, among a building's 35
// rows), the Jacobian is the factored J0 plus those rows' changes, J = J0 + E D (E their unit
// columns, D the changes), solved with J0's factors by the Woodbury identity:
// x = y - Z (I + D Z)^-1 D y, y = J0^-1 b, Z = J0^-1 E (kept while the changed rows are the same).
// That is 2 n^2 + O(k n) operations against 2/3 n^3 for new factors; it differs from them by
// round-off, which the Newton iteration's residual test sees like any other. Not with hard
// contacts (their rows' Jacobian entries depend on more than their tangents), and refused (new
// factors instead) where I + D Z is near singular or the result is not finite.
bool Newmark::solve_by_row_update(const double* coupling, Index m) {
  const Index size = static_cast<Index>(active_rows_.size());
  if (!row_updates_allowed_ || size < kRowUpdateSize || has_hard_contacts_ ||
      tangent_offsets_ != factored_offsets_)
    return false;
  changed_places_.clear();
  for (Index i = 0; i < size; ++i) {
    const auto first = static_cast<std::size_t>(tangent_offsets_[static_cast<std::size_t>(i)]);
    const std::size_t end =
        i + 1 < size ? static_cast<std::size_t>(tangent_offsets_[static_cast<std::size_t>(i + 1)])
                     : active_tangents_.size();
    if (std::equal(active_tangents_.begin() + static_cast<std::ptrdiff_t>(first),
                   active_tangents_.begin() + static_cast<std::ptrdiff_t>(end),
                   factored_tangents_.begin() + static_cast<std::ptrdiff_t>(first)))
      continue;
    if (changed_places_.size() == static_cast<std::size_t>(kMaxRowUpdates)) return false;
    changed_places_.push_back(i);
  }
  const Index k = static_cast<Index>(changed_places_.size());
  if (k == 0) return false;
  // D: the changed rows' entries of I + T G less J0's (jacobian_ keeps J0).
  column_starts_.clear();
  for (const Index c : active_rows_) column_starts_.push_back(c * m);
  // D and Z at their largest row and column count, so a change of k allocates nothing.
  row_changes_.resize(kMaxRowUpdates, size);
  for (Index a = 0; a < k; ++a) {
    const Index i = changed_places_[static_cast<std::size_t>(a)];
    const RowCoupling& row =
        row_coupling_[static_cast<std::size_t>(active_rows_[static_cast<std::size_t>(i)])];
    for (Index j = 0; j < size; ++j)
      row_changes_(a, j) =
          tangent_times_coupling(coupling, row, column_starts_[static_cast<std::size_t>(j)]) +
          (i == j ? 1.0 : 0.0) - jacobian_(i, j);
  }
  if (changed_places_ != update_places_) {
    update_columns_.resize(size, kMaxRowUpdates);
    for (Index a = 0; a < k; ++a) {
      unit_.setZero(size);
      unit_[changed_places_[static_cast<std::size_t>(a)]] = 1.0;
      jacobian_lu_.solve(unit_, update_column_);
      update_columns_.col(a) = update_column_;
    }
    update_places_ = changed_places_;
  }
  jacobian_lu_.solve(reduced_residual_, reduced_correction_);
  // C = I + D Z and D y, one or two of each. det J = det J0 det C: C near singular (against the
  // size of its terms, or its own) means the updated Jacobian is, and new factors decide.
  double capacitance[2][2] = {}, projected[2] = {}, largest_term = 1.0;
  for (Index a = 0; a < k; ++a) {
    projected[a] = row_changes_.row(a).dot(reduced_correction_);
    for (Index b = 0; b < k; ++b) {
      capacitance[a][b] = (a == b ? 1.0 : 0.0) + row_changes_.row(a).dot(update_columns_.col(b));
      largest_term = std::max(
          largest_term, row_changes_.row(a).cwiseAbs().dot(update_columns_.col(b).cwiseAbs()));
    }
  }
  constexpr double kTrusted = 1e-8;  // at most ~1e8 ulps lost to cancellation
  double weights[2] = {};
  if (k == 1) {
    if (!(std::abs(capacitance[0][0]) > kTrusted * largest_term)) return false;
    weights[0] = projected[0] / capacitance[0][0];
  } else {
    const double determinant =
        capacitance[0][0] * capacitance[1][1] - capacitance[0][1] * capacitance[1][0];
    const double size_squared =
        capacitance[0][0] * capacitance[0][0] + capacitance[0][1] * capacitance[0][1] +
        capacitance[1][0] * capacitance[1][0] + capacitance[1][1] * capacitance[1][1];
    if (!(std::abs(determinant) > kTrusted * size_squared) ||
        !(size_squared > kTrusted * kTrusted * largest_term * largest_term))
      return false;
    weights[0] =
        (capacitance[1][1] * projected[0] - capacitance[0][1] * projected[1]) / determinant;
    weights[1] =
        (capacitance[0][0] * projected[1] - capacitance[1][0] * projected[0]) / determinant;
  }
  for (Index a = 0; a < k; ++a) reduced_correction_ -= weights[a] * update_columns_.col(a);
  if (!reduced_correction_.allFinite()) return false;
  ++row_update_count_;
  return true;
}

void Newmark::mark_changed_rows() {
  for (Index r = 0; r < correction_.size(); ++r)
    if (correction_[r] != 0.0 && !changed_mark_[static_cast<std::size_t>(r)]) {
      changed_mark_[static_cast<std::size_t>(r)] = 1;
      changed_rows_.push_back(r);
    }
}

// delta = delta_start - G (F - F_start) over the rows the iteration has corrected (none at its
// first evaluation, few after it); a dense product when most are.
void Newmark::deform_links(const Factorization& f) {
  const Index m = assumed_force_.size();
  if (2 * static_cast<Index>(changed_rows_.size()) > m) {
    force_change_.resize(m);
    for (Index k = 0; k < m; ++k) force_change_[k] = force_change(k);
    delta_.noalias() = delta_start_ - f.coupling * force_change_;
    return;
  }
  delta_ = delta_start_;
  for (const Index k : changed_rows_)
    if (const double change = force_change(k); change != 0.0)
      delta_.noalias() -= change * f.coupling.col(k);
}

void Newmark::evaluate_links(LinkSet& links, const Factorization& f, double c_m, double c_c) {
  deform_links(f);
  const Index m = delta_.size();
  rate_.resize(m);
  acceleration_.resize(m);
  for (Index r = 0; r < m; ++r) {
    const double change = delta_[r] - delta_predicted_[r];
    rate_[r] = rate_predicted_[r] + c_c * change;
    acceleration_[r] = c_m * change;
  }
  if (links_move_) acceleration_ += link_offset_acceleration_;
  links.set_trial(delta_, rate_, acceleration_, c_c, c_m, law_force_, tangent_);
  if (has_hard_contacts_) evaluate_hard_contacts(f);
  // law_force_ stays the whole law forces (the convergence test's reference); a folded row's
  // residual is against its law force less K_r (B u)_r.
  residual_.resize(m);
  for (Index r = 0; r < m; ++r) residual_[r] = assumed_force_[r] - law_force_[r];
  for (const Index r : f.folded_rows) {
    const double folded_force = law_force_[r] - f.folded_stiffness[r] * folded_projection(r);
    residual_[r] = assumed_force_[r] - folded_force;
    tangent_(r, r) -= f.folded_stiffness[r];
  }
  for (const Index r : unconnected_rows_) {  // their force moves nothing: taken as it is
    assumed_force_[r] -= residual_[r];
    residual_[r] = 0.0;
  }
}

// Whether every residual is finite (a law force that is not makes its row's residual not
// finite), and whether every one is an exact zero, in one pass.
Newmark::ResidualKind Newmark::residual_kind() const {
  int not_finite = 0, nonzero = 0;
  for (Index r = 0; r < residual_.size(); ++r) {
    const double value = residual_[r];
    not_finite |= static_cast<int>(!(value - value == 0.0));
    nonzero |= static_cast<int>(value != 0.0);
  }
  return not_finite ? ResidualKind::not_finite : nonzero ? ResidualKind::some : ResidualKind::zero;
}

double Newmark::folded_projection(Index row, double delta, double offset) const {
  return delta + gaps_->coeff(row) - offset;  // (B u)_r = delta_r + gap_r - s_r(t)
}

double Newmark::folded_projection(Index row) const {
  return folded_projection(row, delta_[row], links_move_ ? link_offset_[row] : 0.0);
}

// On its branch a folded row's force is F_n + k (delta - delta_n) + c (rate - rate_n)
// + m (accel - accel_n), with its reference derivatives k, c, m; its unknown F - K_r (B u)_r is the
// same at any delta of the step. Taken at the predictor (delta~, rate~, the supports'
// acceleration), that is F_n - K_r (B u_n)_r plus what the terms below add: a row that stays on
// its branch starts converged, dashpot and moving support included. Each term is an exact zero
// for a spring (k = K_r, no rate, no motion), whose unknown then stays exactly what it was.
void Newmark::start_folded_rows(SecondOrderSystem& system, const Factorization& f,
                                const State& from) {
  const Index m = system.links().size();
  assumed_force_.setZero(m);
  for (const Index r : changed_rows_) changed_mark_[static_cast<std::size_t>(r)] = 0;
  changed_rows_.clear();
  changed_mark_.resize(static_cast<std::size_t>(m), 0);
  if (f.folded_rows.empty()) return;
  if (links_move_)
    system.link_motion(from.time, start_offset_, start_offset_rate_, start_offset_acceleration_);
  if (f.folded_rates) {
    system.links().project(from.velocity, start_rate_);
    system.links().project(from.acceleration, start_acceleration_);
    if (links_move_) {
      start_rate_ += start_offset_rate_;
      start_acceleration_ += start_offset_acceleration_;
    }
  }
  for (const Index r : f.folded_rows) {
    const double stiffness = f.folded_stiffness[r];
    const double offset = links_move_ ? start_offset_[r] : 0.0;
    double unknown =
        from.link_force[r] - stiffness * folded_projection(r, from.link_penetration[r], offset);
    unknown +=
        (reference_stiffness_[r] - stiffness) * (delta_predicted_[r] - from.link_penetration[r]);
    if (links_move_) unknown += stiffness * (link_offset_[r] - offset);
    if (f.folded_rates) {
      const double acceleration = links_move_ ? link_offset_acceleration_[r] : 0.0;
      unknown += reference_damping_[r] * (rate_predicted_[r] - start_rate_[r]) +
                 reference_mass_[r] * (acceleration - start_acceleration_[r]);
    }
    assumed_force_[r] = unknown;
  }
}

void Newmark::bound_hard_contacts(SecondOrderSystem& system, const State& from, double c_c) {
  const LinkSet& links = system.links();
  links.project(from.velocity, hard_rate_);
  if (links_move_) {
    system.link_motion(from.time, hard_offset_, hard_offset_rate_, hard_offset_acceleration_);
    hard_rate_ += hard_offset_rate_;
  }
  hard_bound_.resize(links.size());
  hard_candidate_.assign(hard_laws_.size(), 0);
  links.row_magnitudes(from.displacement, hard_magnitudes_);
  for (std::size_t r = 0; r < hard_laws_.size(); ++r) {
    const auto row = static_cast<Index>(r);
    if (const links::CoulombFriction* friction = hard_frictions_[r]) {
      // A contact that stuck over the last step slides no further; any other sticks with a zero
      // slide rate at t_{n+1} (a bound on s alone would reverse the slide rate, as the
      // trapezoidal rule reverses a rate held at zero displacement).
      const std::size_t normal = r - 1 - static_cast<std::size_t>(hard_tangent_[r]);
      const bool sticking = hard_laws_[normal]->in_contact() && !friction->slipping();
      hard_bound_[row] = sticking ? from.link_penetration[row]
                                  : delta_predicted_[row] - rate_predicted_[row] / c_c;
      continue;
    }
    const links::HardContact* law = hard_laws_[r];
    if (!law) continue;
    const bool holding = law->in_contact();
    hard_candidate_[r] = holding;
    if (holding) {
      // No further approach. (A zero rate at t_{n+1} instead lets delta creep by
      // dt^2 (1/2 - beta - beta (1 - gamma) / gamma) B a_n a step when gamma != 1/2, opening a
      // pressed contact, whose force then does negative work.)
      hard_bound_[row] = from.link_penetration[row];
      continue;
    }
    // The impact law: w_{n+1} = -e w-, by Newmark's w_{n+1} = w~ + (gamma / (beta dt))
    // (delta_{n+1} - delta~).
    const double after = -law->restitution() * std::max(0.0, hard_rate_[row]);
    hard_bound_[row] = delta_predicted_[row] + (after - rate_predicted_[row]) / c_c;
  }
}

void Newmark::evaluate_hard_contacts(const Factorization& f) {
  for (std::size_t r = 0; r < hard_laws_.size(); ++r) {
    if (!hard_laws_[r]) continue;
    const auto row = static_cast<Index>(r);
    // Constrained from the iterate on which it first penetrates, for the rest of the step.
    if (!hard_candidate_[r] && delta_[row] > 0.0) hard_candidate_[r] = 1;
    // s = 1 / G(r, r) makes s delta a force, the one that would close delta alone.
    const double scale = 1.0 / f.coupling(row, row);
    const double pressing = assumed_force_[row] + scale * (delta_[row] - hard_bound_[row]);
    // Past the bound by no more than delta's round-off is no force: two bodies riding together
    // after a plastic impact pressed each other by 1e-10 N now and then, 29 "impacts" for 1.
    hard_pressing_[r] =
        hard_candidate_[r] && pressing > scale * kHardContactRoundOff * hard_magnitudes_[row];
    law_force_[row] = hard_pressing_[r] ? pressing : 0.0;
    tangent_(row, row) = hard_pressing_[r] ? scale : 0.0;
  }
  for (std::size_t r = 0; r < hard_frictions_.size(); ++r) {
    if (!hard_frictions_[r]) continue;
    if (!hard_pair_[r])
      evaluate_hard_friction(f, static_cast<Index>(r));
    else if (hard_tangent_[r] == 0)
      evaluate_hard_friction_in_plane(f, static_cast<Index>(r));
  }
}

void Newmark::clear_hard_friction_row(Index r) {
  const auto row = static_cast<std::size_t>(r);
  hard_slipping_[row] = 0;
  hard_entries_[row] = HardEntries{};
  hard_pressing_[row] = 0;
  const LinkRows& rows = link_rows_[row];
  for (Index q = rows.first + 1; q < rows.end; ++q) tangent_(r, q) = 0.0;
}

// Alart & Curnier's (1991) semismooth form of Coulomb's law on a pressing contact's tangential
// row t: with the trial force F_t + s (s_t - bound), s = 1 / G(t, t), the row sticks
// (s_t = bound, a Jacobian row s G(t, :)) while the trial stays within mu F_n, else slips at
// F_t = sign(trial) mu F_n (a Jacobian row e_t - sign mu e_n).
void Newmark::evaluate_hard_friction(const Factorization& f, Index t) {
  const auto r = static_cast<std::size_t>(t);
  const Index normal_row = t - 1 - hard_tangent_[r];
  clear_hard_friction_row(t);
  if (!hard_pressing_[static_cast<std::size_t>(normal_row)]) {
    law_force_[t] = 0.0;
    return;
  }
  const double normal = std::max(0.0, assumed_force_[normal_row]);
  const double coefficient = hard_frictions_[r]->coefficient();
  const double scale = 1.0 / f.coupling(t, t);
  const double trial = assumed_force_[t] + scale * (delta_[t] - hard_bound_[t]);
  if (std::abs(trial) <= coefficient * normal) {
    law_force_[t] = trial;
    tangent_(t, t) = scale;
    hard_pressing_[r] = 1;
    return;
  }
  const double direction = trial > 0.0 ? 1.0 : -1.0;
  law_force_[t] = direction * coefficient * assumed_force_[normal_row];
  hard_slipping_[r] = 1;
  hard_entries_[r][0] = -direction * coefficient;
}

// In a contact plane the trial tau = F_t + s (s_t - bound) is a vector, s = 2 / (G_11 + G_22)
// one scale for both tangents. Sticking while |tau| <= mu F_n (each row as in a plane scene);
// slipping, F_t = mu F_n e, e = tau / |tau|, whose derivative
//   dF_t = mu e dF_n + Q (dF_t - s G_t dF),   Q = mu F_n (I - e e^T) / |tau|,
// makes T(t, t) = s Q and the entries -mu e and -Q outside T G.
void Newmark::evaluate_hard_friction_in_plane(const Factorization& f, Index t) {
  const Index normal = t - 1;
  for (Index a = 0; a < 2; ++a) clear_hard_friction_row(t + a);
  if (!hard_pressing_[static_cast<std::size_t>(normal)]) {
    law_force_.segment(t, 2).setZero();
    return;
  }
  const double coefficient = hard_frictions_[static_cast<std::size_t>(t)]->coefficient();
  const double limit = coefficient * std::max(0.0, assumed_force_[normal]);
  const double scale = 2.0 / (f.coupling(t, t) + f.coupling(t + 1, t + 1));
  const Eigen::Vector2d trial =
      assumed_force_.segment<2>(t) + scale * (delta_.segment<2>(t) - hard_bound_.segment<2>(t));
  const double length = trial.norm();
  if (length <= limit) {
    law_force_.segment<2>(t) = trial;
    for (Index a = 0; a < 2; ++a) {
      tangent_(t + a, t + a) = scale;
      hard_pressing_[static_cast<std::size_t>(t + a)] = 1;
    }
    return;
  }
  const Eigen::Vector2d direction = trial / length;
  law_force_.segment<2>(t) = coefficient * assumed_force_[normal] * direction;
  const Eigen::Matrix2d turn = coefficient * assumed_force_[normal] / length *
                               (Eigen::Matrix2d::Identity() - direction * direction.transpose());
  for (Index a = 0; a < 2; ++a) {
    const auto row = static_cast<std::size_t>(t + a);
    hard_slipping_[row] = 1;
    hard_entries_[row] = {-coefficient * direction[a], -turn(a, 0), -turn(a, 1)};
    for (Index b = 0; b < 2; ++b) tangent_(t + a, t + b) = scale * turn(a, b);
  }
}

// The hard contacts' forces act as this step's impulses: the acceleration kept for the next
// step is the one without them (w M^-1 B^T F_hard added back, w = (1 - a_f) / (1 - a_m) the
// weight F has in a_{n+1}), so the next step's predictor does not apply half of an impact's
// impulse again, and a held contact's force does not alternate from step to step under the
// trapezoidal rule; each step finds the force that holds anew. The state's force of such a row
// is its step's average, the impulse gamma w F dt over dt (what the energy balance and the link
// summaries take as the step's force: LinkSummaries::set_step_forces).
void Newmark::release_constraint_acceleration(SecondOrderSystem& system, State& to) {
  const double weight = (1.0 - alpha_f_) / (1.0 - alpha_m_);
  hard_force_.setZero(system.links().size());
  bool any = false;
  for (std::size_t r = 0; r < hard_laws_.size(); ++r) {
    if (!hard_laws_[r] && !hard_frictions_[r]) continue;
    const auto row = static_cast<Index>(r);
    hard_force_[row] = weight * assumed_force_[row];
    to.link_force[row] = gamma_ * hard_force_[row];
    if (hard_laws_[r])
      hard_laws_[r]->impose(to.link_force[row]);
    else
      hard_frictions_[r]->impose_tangential(hard_tangent_[r], to.link_force[row],
                                            hard_slipping_[r] != 0);
    any = any || hard_force_[row] != 0.0;
  }
  if (!any) return;
  work_.noalias() = system.links().connectivity().transpose() * hard_force_;
  if (const Vector* mass = system.lumped_mass()) {
    for (Index i = 0; i < work_.size(); ++i)
      if ((*mass)[i] > 0.0) to.acceleration[i] += work_[i] / (*mass)[i];
    return;
  }
  if (!mass_solver_.solver) mass_solver_.solver = system.factor(1.0, 0.0, 0.0);
  mass_solver_.solver->solve(work_, hard_acceleration_);
  to.acceleration += hard_acceleration_;
}

void Newmark::apply_link_forces(const Factorization& f, State& to) const {
  // u_{n+1} = u_start - Z (F - F_start)
  for (const Index k : changed_rows_)
    if (const double change = force_change(k); change != 0.0)
      to.displacement -= change * f.influence.col(k);
  to.link_penetration = delta_;
  to.link_force = assumed_force_;
  for (const Index r : f.folded_rows)
    to.link_force[r] += f.folded_stiffness[r] * folded_projection(r);
}

}  // namespace pound::integrators
