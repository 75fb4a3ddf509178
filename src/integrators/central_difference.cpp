#include "integrators/central_difference.hpp"

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <Eigen/QR>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "links/hard_contact.hpp"

namespace pound::integrators {
namespace {

const Vector& diagonal_mass(const SecondOrderSystem& system) {
  const Vector* mass = system.lumped_mass();
  if (!mass || !((mass->array() > 0.0).all()))
    throw std::domain_error("central difference needs a lumped mass on every DOF");
  return *mass;
}

// a = (M + B^T diag(m) B)^-1 r for diagonal M, by Woodbury over the rows with m != 0; the small
// matrix is factored once, as the power iteration solves with it every iteration.
class LinkMassSolver {
 public:
  LinkMassSolver(const Vector& inverse_mass, const LinkSet::SparseRowMatrix& b,
                 const Vector& link_mass)
      : inverse_mass_(inverse_mass) {
    std::vector<Index> rows;
    for (Index r = 0; r < link_mass.size(); ++r)
      if (link_mass[r] != 0.0) rows.push_back(r);
    if (rows.empty()) return;
    const auto k = static_cast<Index>(rows.size());
    active_.resize(k, b.cols());
    for (Index i = 0; i < k; ++i) active_.row(i) = b.row(rows[static_cast<std::size_t>(i)]);
    Matrix small = active_ * inverse_mass.asDiagonal() * active_.transpose();
    for (Index i = 0; i < k; ++i) small(i, i) += 1.0 / link_mass[rows[static_cast<std::size_t>(i)]];
    small_lu_.compute(small);
  }
  void solve(const Vector& rhs, Vector& solution) const {
    solution = inverse_mass_.cwiseProduct(rhs);
    if (active_.rows() == 0) return;
    const Vector correction = small_lu_.solve(active_ * solution);
    solution.noalias() -= inverse_mass_.asDiagonal() * (active_.transpose() * correction);
  }

 private:
  const Vector& inverse_mass_;
  Matrix active_;  // the rows of B with a link mass
  Eigen::PartialPivLU<Matrix> small_lu_;
};

// Bit 63 set when x is an infinity or NaN (every exponent bit set: adding one to the exponent
// carries out of it). OR-ed over a pass, it vectorises as integer operations; a sum of the
// values (the other way to test them) would add a serial floating-point reduction to the pass.
inline std::uint64_t not_finite(double x) {
  constexpr std::uint64_t exponent = 0x7ff0000000000000, one = 0x0010000000000000;
  return (std::bit_cast<std::uint64_t>(x) & exponent) + one;
}
inline bool all_finite(std::uint64_t flags) { return (flags >> 63) == 0; }

// u_{n+1} = u_n + dt v_n + dt^2/2 a_n over [first, last), and v* = v_n + dt a_n when damping
// needs it. Returns whether every u_{n+1} is finite.
bool predict(Index first, Index last, double dt, const double* __restrict__ u,
             const double* __restrict__ v, const double* __restrict__ a,
             double* __restrict__ next_u, double* __restrict__ predicted_v) {
  const double displacement_factor = 0.5 * dt * dt;
  std::uint64_t flags = 0;
  for (Index i = first; i < last; ++i) {
    next_u[i] = u[i] + dt * v[i] + displacement_factor * a[i];
    flags |= not_finite(next_u[i]);
  }
  if (predicted_v)
    for (Index i = first; i < last; ++i) predicted_v[i] = v[i] + dt * a[i];
  return all_finite(flags);
}

// a_{n+1} = M^-1 (f - r) (f: nullptr for none) and v_{n+1} = v_n + dt/2 (a_n + a_{n+1}) over
// [first, last), in one pass. Returns whether every v_{n+1} is finite.
bool accelerate(Index first, Index last, double half_dt, const double* __restrict__ inverse_mass,
                const double* __restrict__ r, const double* __restrict__ f,
                const double* __restrict__ v, const double* __restrict__ a,
                double* __restrict__ next_a, double* __restrict__ next_v) {
  std::uint64_t flags = 0;
  if (f) {
    for (Index i = first; i < last; ++i) {
      next_a[i] = inverse_mass[i] * (-r[i] + f[i]);
      next_v[i] = v[i] + half_dt * (a[i] + next_a[i]);
      flags |= not_finite(next_v[i]);
    }
    return all_finite(flags);
  }
  for (Index i = first; i < last; ++i) {
    next_a[i] = inverse_mass[i] * -r[i];
    next_v[i] = v[i] + half_dt * (a[i] + next_a[i]);
    flags |= not_finite(next_v[i]);
  }
  return all_finite(flags);
}

// Union-find over the link rows.
class RowUnion {
 public:
  explicit RowUnion(Index rows) : parent_(static_cast<std::size_t>(rows)) {
    for (Index r = 0; r < rows; ++r) parent_[static_cast<std::size_t>(r)] = r;
  }
  Index root(Index r) {
    while (parent_[static_cast<std::size_t>(r)] != r)
      r = parent_[static_cast<std::size_t>(r)] =
          parent_[static_cast<std::size_t>(parent_[static_cast<std::size_t>(r)])];
    return r;
  }
  void join(Index first, Index second) {
    parent_[static_cast<std::size_t>(root(first))] = root(second);
  }

 private:
  std::vector<Index> parent_;
};

// Groups of link rows: r and s share one when G(r, s) != 0, or when they are rows of one link.
std::vector<std::vector<Index>> coupled_row_groups(const Matrix& coupling, const LinkSet& links) {
  const Index m = links.size();
  RowUnion rows(m);
  for (Index r = 0; r < m; ++r)
    for (Index c = r + 1; c < m; ++c)
      if (coupling(r, c) != 0.0 || coupling(c, r) != 0.0) rows.join(r, c);
  for (Index k = 0; k < links.count(); ++k)
    for (Index r = links.row(k) + 1; r < links.row(k) + links.rows(k); ++r)
      rows.join(links.row(k), r);
  std::vector<Index> group_of(static_cast<std::size_t>(m), -1);
  std::vector<std::vector<Index>> groups;
  for (Index r = 0; r < m; ++r) {
    Index& group = group_of[static_cast<std::size_t>(rows.root(r))];
    if (group < 0) {
      group = static_cast<Index>(groups.size());
      groups.emplace_back();
    }
    groups[static_cast<std::size_t>(group)].push_back(r);
  }
  return groups;
}

// The diagonals of the links' tangents: stiffness, penalty mass and dashpot of each row.
struct LinkTangents {
  Vector stiffness, mass, damping;
};

// Link tangents: at first touch (closing) when contacts count, else at rest.
LinkTangents link_tangents(LinkSet& links, bool contacts_active,
                           std::span<const LinkRowState> at = {}) {
  const Index m = links.size();
  Vector delta = contacts_active ? Vector::Constant(m, 1e-12) : Vector(-links.gaps());
  Vector rate = Vector::Constant(m, contacts_active ? 1e-12 : 0.0);
  for (const LinkRowState& state : at) {
    delta[state.row] = state.penetration;
    rate[state.row] = state.rate;
  }
  Vector force;
  Matrix stiffness_only, with_mass, with_damping;
  links.set_trial(delta, rate, Vector::Zero(m), 0.0, 0.0, force, stiffness_only);
  links.set_trial(delta, rate, Vector::Zero(m), 0.0, 1.0, force, with_mass);
  links.set_trial(delta, rate, Vector::Zero(m), 1.0, 0.0, force, with_damping);
  links.revert();
  LinkTangents tangents{stiffness_only.diagonal(), (with_mass - stiffness_only).diagonal(),
                        (with_damping - stiffness_only).diagonal()};
  // A contact's friction sticks on its stick spring, dashpot and mass, which the touch above
  // (with almost no normal force to hold them) leaves slipping: a friction pendulum's k_t = 1e10
  // N/m bounds its step far below its normal stiffness's, and "auto" took 0.016 s for a 6.3 ms
  // limit.
  if (contacts_active)
    for (Index link = 0; link < links.count(); ++link)
      if (const links::CoulombFriction* friction = links.friction(link))
        for (Index r = links.row(link) + 1; r < links.row(link) + links.rows(link); ++r) {
          const links::StickPenalty& stick = friction->stick();
          tangents.stiffness[r] = std::max(tangents.stiffness[r], stick.stiffness);
          tangents.damping[r] = std::max(tangents.damping[r], stick.damping);
          tangents.mass[r] = std::max(tangents.mass[r], stick.mass);
        }
  return tangents;
}

struct HighestMode {
  double eigenvalue;  // omega_max^2
  Vector shape;
};

// Power iteration on (M + B^T m_l B)^-1 (K + B^T k_l B), from a fixed start (reproducible).
HighestMode highest_mode(SecondOrderSystem& system, const Vector& inverse_mass,
                         const LinkTangents& tangents) {
  const LinkSet& links = system.links();
  Vector x = Vector::LinSpaced(system.size(), 1.0, 2.0), y, kx, projected;
  const LinkMassSolver mass_solver(inverse_mass, links.connectivity(), tangents.mass);
  double lambda = 0.0;
  for (int iteration = 0; iteration < 500; ++iteration) {
    // x /= ||x||, scaled first when ||x||^2 would overflow (omega^2 above ~1e154): plain
    // normalize() would make x zero there and the iteration "settle" at 0.
    if (const double norm = x.norm(); !std::isfinite(norm))
      x.stableNormalize();
    else if (norm > 0.0)
      x /= norm;
    system.multiply_stiffness(x, kx);
    links.project(x, projected);
    kx.noalias() += links.connectivity().transpose() * tangents.stiffness.cwiseProduct(projected);
    mass_solver.solve(kx, y);
    // An overflow would normalise to a zero vector and "settle" at 0: report it as infinite.
    if (!y.allFinite()) return {std::numeric_limits<double>::infinity(), std::move(x)};
    const double next = x.dot(y);
    const bool settled = iteration > 20 && std::abs(next - lambda) <= 1e-10 * std::abs(next);
    lambda = next;
    x = y;
    if (settled) break;
  }
  return {lambda, std::move(x)};
}

// x^T C x / (2 w x^T M x) for the mode x of frequency w, the links' penalty masses in M.
double damping_ratio(SecondOrderSystem& system, Vector shape, const Vector& link_mass,
                     double omega) {
  shape.normalize();
  Vector cx, mx, projected;
  system.multiply_damping(shape, cx);
  system.multiply_mass(shape, mx);
  system.links().project(shape, projected);
  const double modal_mass = shape.dot(mx) + projected.dot(link_mass.cwiseProduct(projected));
  return shape.dot(cx) / (2.0 * omega * modal_mass);
}

// The stable step of the textbook central difference (damping with v_n+1) for a mode of
// frequency w and damping ratio z: (2 / w)(sqrt(1 + z^2) - z). Past z = 1 as
// (2 / w) / (sqrt(1 + z^2) + z), the same number without the cancellation that made it 0 for z
// past 1e8 (a friction pendulum of R = 1e6 m: its tangent N / R is 1 N/m beside its stick
// damping, and central difference was refused as if its step had to be 0).
double damped_stable_step(double omega, double zeta) {
  const double root = std::sqrt(1.0 + zeta * zeta);
  return zeta > 1.0 ? 2.0 / omega / (root + zeta) : 2.0 / omega * (root - zeta);
}

// The highest mode's stable step, of frequency `omega` and shape `shape`. Damping lowers it, with
// z the damping ratio of the mode: x^T C x / (2 w x^T M x). The step damps with C v*,
// v* = v_n + dt a_n, whose amplification has the eigenvalue -1 at w dt = 2 (sqrt(1 + 4 z^2) - 2 z):
// the limit of the textbook scheme, (2 / w)(sqrt(1 + z^2) - z), at twice the damping (0.75 of it
// at z = 0.32, half of it, m / c, far past critical; at the textbook limit a mode damped at 0.32
// grew).
double structural_stable_step(SecondOrderSystem& system, Vector shape, const LinkTangents& tangents,
                              double omega) {
  const double zeta =
      system.has_damping() ? damping_ratio(system, std::move(shape), tangents.mass, omega) : 0.0;
  return damped_stable_step(omega, 2.0 * zeta);
}

// The stable step of link row r's own relative mode: its two end masses,
// m_rel = 1 / (B M^-1 B^T), against its stiffness, penalty mass and dashpot. A dashpot with no
// stiffness (a viscous damper) is stable below 2 m / c (m = m_rel + m_link), but past m / c its
// decay's amplification 1 - h c / m is negative: the velocity changes sign at every step, and
// the damper's response, which is that decay, is wrong (-68 % at 0.8 of 2 m / c). So m / c.
double link_mode_stable_step(const LinkSet& links, const Vector& inverse_mass,
                             const LinkTangents& tangents, Index r) {
  const double relative_mass =
      1.0 / links.connectivity().row(r).cwiseAbs2().dot(inverse_mass.transpose());
  const double modal_mass = relative_mass + tangents.mass[r];
  if (!(tangents.stiffness[r] > 0.0)) return modal_mass / tangents.damping[r];
  const double link_omega = std::sqrt(tangents.stiffness[r] / modal_mass);
  const double link_zeta =
      tangents.damping[r] / (2.0 * std::sqrt(tangents.stiffness[r] * modal_mass));
  return damped_stable_step(link_omega, link_zeta);
}

}  // namespace

const IntegratorEntry& CentralDifference::entry() {
  static const IntegratorEntry entry{
      .name = "central_difference",
      .description =
          "explicit central difference with lumped mass; stable below its computed "
          "step, which \"time_step\": \"auto\" takes",
      .is_explicit = true,
      .presets = {{"central_difference", {}}},
      .make = [](const std::map<std::string, double>&, const ConvergenceTest&)
          -> std::unique_ptr<Integrator> { return std::make_unique<CentralDifference>(); },
      .acceleration_energy = [](const std::map<std::string, double>&) { return -0.125; },
      .stability_limit = [](const std::map<std::string, double>&) -> std::optional<double> {
        return 2.0;
      }};
  return entry;
}

void CentralDifference::initialize(SecondOrderSystem& system, State& state, double first_step) {
  const Index n = system.size();
  inverse_mass_ = diagonal_mass(system).cwiseInverse();
  coupling_.resize(0, 0);  // G = B M^-1 B^T and B by columns, built at the first step with links
  LinkSet& links = system.links();
  if (state.displacement.size() != n) state.displacement = Vector::Zero(n);
  if (state.velocity.size() != n) state.velocity = Vector::Zero(n);
  links.penetration(state.displacement, state.link_penetration);
  links.project(state.velocity, rate_);
  if (system.has_link_motion()) {
    system.link_motion(state.time, offset_, offset_rate_, offset_acceleration_);
    state.link_penetration += offset_;
    rate_ += offset_rate_;
  }
  if (links.size() > 0) {
    prepare_links(links);
    // The hard contacts' forces at the start are found below for this start: none imposed
    // before (a trial of the first step on this system, as the run's check makes) may act in it.
    release_hard_forces();
  }
  links.set_trial(state.link_penetration, rate_, Vector::Zero(links.size()), 0.0, 0.0,
                  state.link_force, tangent_);
  links.commit();
  Vector rhs = Vector::Zero(n);
  if (system.has_external_force()) system.external_force(state.time, rhs);
  if (system.has_damping()) {
    system.multiply_damping(state.velocity, work_);
    rhs -= work_;
  }
  system.multiply_stiffness(state.displacement, work_);
  rhs -= work_;
  rhs.noalias() -= links.connectivity().transpose() * state.link_force;
  state.acceleration = inverse_mass_.cwiseProduct(rhs);
  if (links.size() > 0) initial_hard_contacts(system, state, first_step);
}

StepResult CentralDifference::advance(SecondOrderSystem& system, const State& from, double dt,
                                      double end, State& to) {
  LinkSet& links = system.links();
  const Index n = system.size(), m = links.size();
  if (inverse_mass_.size() != n) inverse_mass_ = diagonal_mass(system).cwiseInverse();
  StepResult result;
  to.time = end;
  const double half_dt = 0.5 * dt;
  to.displacement.resize(n);
  to.acceleration.resize(n);
  to.velocity.resize(n);
  bool finite_state = advance_without_links(system, from, dt, to);
  if (m > 0) {
    if (coupling_.rows() != m) prepare_links(links);
    link_kinematics(system, from, half_dt, to);
    if (!hard_groups_.empty())
      release_hard_forces();  // the force laws' solve sees no constraint force
    if (!solve_link_forces(links, to, result)) return result;
    if (!hard_groups_.empty() && !solve_hard_contacts(links, to, dt, result)) return result;
    finite_state &= apply_link_forces(from, half_dt, to);
  } else {
    to.link_penetration.resize(0);
    to.link_force.resize(0);
  }
  if (!finite_state) {
    result.failure = "the state is not finite (is the time step above the stable limit?)";
    return result;
  }
  result.converged = true;
  return result;
}

bool CentralDifference::advance_without_links(SecondOrderSystem& system, const State& from,
                                              double dt, State& to) {
  const Index n = system.size();
  const double half_dt = 0.5 * dt;
  const bool external = system.has_external_force();
  if (external) system.external_force(to.time, work_);
  // The vector passes (predict, K u, accelerate) go block by block when the system can, each
  // testing the values it writes for the finiteness check.
  bool finite_state = true;
  if (!system.has_damping()) {
    const auto make = [&](Index first, Index last) {
      finite_state &= predict(first, last, dt, from.displacement.data(), from.velocity.data(),
                              from.acceleration.data(), to.displacement.data(), nullptr);
    };
    const auto use = [&](Index first, Index last) {
      finite_state &=
          accelerate(first, last, half_dt, inverse_mass_.data(), rhs_.data(),
                     external ? work_.data() : nullptr, from.velocity.data(),
                     from.acceleration.data(), to.acceleration.data(), to.velocity.data());
    };
    system.multiply_stiffness_by_blocks(to.displacement, rhs_, make, use);
    return finite_state;
  }
  // With damping, C v* with v* = v_n + dt a_n: it differs from v_{n+1} by O(dt^2) and keeps the
  // scheme second order (the half-step velocity would not).
  predicted_velocity_.resize(n);
  finite_state =
      predict(0, n, dt, from.displacement.data(), from.velocity.data(), from.acceleration.data(),
              to.displacement.data(), predicted_velocity_.data());
  // r = (K u - f) + C v*: its negative is the unfused step's (f - K u) - C v*, exactly.
  system.multiply_stiffness(to.displacement, rhs_);
  if (external) rhs_ -= work_;
  system.multiply_damping(predicted_velocity_, damping_force_);
  rhs_ += damping_force_;
  finite_state &=
      accelerate(0, n, half_dt, inverse_mass_.data(), rhs_.data(), nullptr, from.velocity.data(),
                 from.acceleration.data(), to.acceleration.data(), to.velocity.data());
  return finite_state;
}

void CentralDifference::prepare_links(LinkSet& links) {
  const LinkSet::SparseRowMatrix& b = links.connectivity();
  coupling_ = Matrix(b * inverse_mass_.asDiagonal() * b.transpose());
  link_columns_ = b;
  link_dofs_.clear();
  for (Index j = 0; j < link_columns_.outerSize(); ++j)
    if (Eigen::SparseMatrix<double>::InnerIterator(link_columns_, j)) link_dofs_.push_back(j);
  link_groups_ = coupled_row_groups(coupling_, links);
  group_jacobians_.resize(link_groups_.size());
  group_lus_.resize(link_groups_.size());
  LinkSet::HardRows hard_rows = links.hard_rows();
  hard_laws_ = std::move(hard_rows.contacts);
  hard_frictions_ = std::move(hard_rows.frictions);
  hard_tangent_ = std::move(hard_rows.tangent);
  hard_pair_ = std::move(hard_rows.pair);
  hard_groups_.clear();
  for (const std::vector<Index>& group : link_groups_) {
    std::vector<Index> hard;
    for (const Index r : group)
      if (hard_laws_[static_cast<std::size_t>(r)] || hard_frictions_[static_cast<std::size_t>(r)])
        hard.push_back(r);
    if (!hard.empty()) hard_groups_.push_back(std::move(hard));
  }
}

void CentralDifference::release_hard_forces() {
  for (links::HardContact* hard : hard_laws_)
    if (hard) hard->impose(0.0);
  for (std::size_t r = 0; r < hard_frictions_.size(); ++r)
    if (hard_frictions_[r]) hard_frictions_[r]->impose_tangential(hard_tangent_[r], 0.0, false);
}

bool CentralDifference::solve_hard_contacts(const LinkSet& links, State& to, double dt,
                                            StepResult& result) {
  // delta~_{n+2} of every row: delta_{n+1} + dt (w_{n+1/2} + dt B a_{n+1}), with a_{n+1} carrying
  // the force laws' forces already.
  link_acceleration_ = free_acceleration_;
  link_acceleration_.noalias() -= coupling_ * to.link_force;
  links.row_magnitudes(to.displacement, magnitudes_);
  for (const std::vector<Index>& rows : hard_groups_)
    if (!solve_hard_group(rows, dt, dt * dt, to.link_penetration, rate_, link_acceleration_,
                          to.link_force)) {
      result.failure =
          "the hard contacts' forces did not settle (a contact closing and "
          "releasing without end)";
      return false;
    }
  return true;
}

void CentralDifference::initial_hard_contacts(SecondOrderSystem& system, State& state, double dt) {
  LinkSet& links = system.links();
  if (hard_groups_.empty()) return;
  Vector acceleration, force = Vector::Zero(links.size());
  links.project(state.velocity, rate_);
  links.project(state.acceleration, acceleration);
  if (system.has_link_motion()) {
    system.link_motion(state.time, offset_, offset_rate_, offset_acceleration_);
    rate_ += offset_rate_;
    acceleration += offset_acceleration_;
  }
  links.row_magnitudes(state.displacement, magnitudes_);
  for (const std::vector<Index>& rows : hard_groups_)
    if (!solve_hard_group(rows, dt, 0.5 * dt * dt, state.link_penetration, rate_, acceleration,
                          force))
      throw SolveError(state.time, "the hard contacts' forces at the start did not settle");
  links.commit();
  for (const std::vector<Index>& rows : hard_groups_)
    for (const Index r : rows) state.link_force[r] = force[r];
  for (const Index j : link_dofs_)
    state.acceleration[j] -= inverse_mass_[j] * nodal_link_force(j, force);
}

bool CentralDifference::solve_hard_group(const std::vector<Index>& rows, double dt, double scale,
                                         const Vector& penetration, const Vector& rate,
                                         const Vector& acceleration, Vector& forces) {
  prepare_hard_group(rows, dt, scale, penetration, rate, acceleration);
  const auto size = static_cast<int>(rows.size());
  bool settled = false;
  for (int iteration = 0; iteration < 8 * size + 8 && !settled; ++iteration) {
    solve_active_hard_rows(rows, scale);
    settled = !update_hard_active_set(rows, scale);
  }
  if (!settled && !enumerate_hard_states(rows, scale)) return false;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Index r = rows[i];
    const double force = group_force_[static_cast<Index>(i)];
    forces[r] = force;
    if (links::HardContact* law = hard_laws_[static_cast<std::size_t>(r)])
      law->impose(force);
    else
      hard_frictions_[static_cast<std::size_t>(r)]->impose_tangential(
          hard_tangent_[static_cast<std::size_t>(r)], force,
          slip_[i] != 0 && hard_row_active(rows, i));
  }
  return true;
}

// One change at a time can cycle when several frictional contacts strike together (a skewed
// deck's two corners, one about to stick as the other slips): a small group then tries every
// combination of states, each contact lifted or pressing, and then sticking or slipping either
// way, and keeps the first that asks for no change (the enumeration of Pfeiffer & Glocker,
// "Multibody Dynamics with Unilateral Contacts", 1996, ch. 7, for small contact problems).
bool CentralDifference::enumerate_hard_states(const std::vector<Index>& rows, double scale) {
  std::vector<std::size_t> contacts;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (hard_laws_[static_cast<std::size_t>(rows[i])]) contacts.push_back(i);
  if (contacts.size() > 6) return false;
  // Contact i with friction: lifted, sticking, or slipping either way (in a contact plane, its
  // direction iterated by Newton from the free slide's or the opposite).
  const auto rubs = [&](std::size_t i) {
    return i + 1 < rows.size() && hard_frictions_[static_cast<std::size_t>(rows[i + 1])];
  };
  long combinations = 1;
  for (const std::size_t i : contacts) combinations *= rubs(i) ? 4 : 2;
  const std::vector<char> candidates = candidate_;
  const Vector bounds = bound_;
  for (long combination = 0; combination < combinations; ++combination) {
    candidate_ = candidates;
    bound_ = bounds;
    active_.assign(rows.size(), 0);
    slip_.assign(rows.size(), 0);
    long code = combination;
    for (const std::size_t i : contacts) {
      const long states = rubs(i) ? 4 : 2, state = code % states;  // 0 lifted, 1 stick, 2-3 slip
      code /= states;
      if (state == 0) continue;
      active_[i] = 1;
      if (!candidate_[i]) {
        candidate_[i] = 1;
        bound_[static_cast<Index>(i)] = 0.0;
      }
      if (state < 2) continue;
      const double way = state == 2 ? 1.0 : -1.0;
      if (!in_plane(rows, i + 1)) {
        slip_[i + 1] = static_cast<signed char>(way);
      } else {
        start_slip_in_plane(i + 1, way * free_slide(static_cast<Index>(i) + 1));
      }
    }
    solve_active_hard_rows(rows, scale);
    for (int turn = 0; turn < 50 && group_force_.allFinite() && turn_slip_directions(rows, scale);
         ++turn)
      solve_active_hard_rows(rows, scale);
    if (group_force_.allFinite() && !update_hard_active_set(rows, scale)) return true;
  }
  return false;
}

void CentralDifference::prepare_hard_group(const std::vector<Index>& rows, double dt, double scale,
                                           const Vector& penetration, const Vector& rate,
                                           const Vector& acceleration) {
  const auto size = static_cast<Index>(rows.size());
  free_next_.resize(size);
  bound_.resize(size);
  candidate_.assign(rows.size(), 0);
  active_.assign(rows.size(), 0);
  slip_.assign(rows.size(), 0);
  slip_direction_.setZero(size);
  slip_turn_.setZero(size);
  for (Index i = 0; i < size; ++i) {
    const Index r = rows[static_cast<std::size_t>(i)];
    const double now = penetration[r];
    const double next = now + dt * rate[r] + scale * acceleration[r];
    free_next_[i] = next;
    const links::HardContact* law = hard_laws_[static_cast<std::size_t>(r)];
    if (!law) {
      bound_[i] = now;  // a friction row sticks where it is: no slide over the step
      continue;
    }
    const bool holding = law->in_contact();
    // Holding: no further approach. Closing in this step: the impact law on the approach rate,
    // w+ = -e w- exactly (stopping short of touch by less than dt w-); with e = 0 the gap
    // closes instead, touching exactly, and the approach stops in this step or the next.
    if (holding)
      bound_[i] = std::min(0.0, now);
    else if (law->restitution() == 0.0)
      bound_[i] = 0.0;
    else
      bound_[i] = std::min(0.0, now) - law->restitution() * std::max(0.0, next - now);
    const double tolerance = kHardContactRoundOff * magnitudes_[r];
    candidate_[static_cast<std::size_t>(i)] = holding || next > tolerance;
    active_[static_cast<std::size_t>(i)] =
        candidate_[static_cast<std::size_t>(i)] && next > bound_[i] + tolerance;
  }
}

// A friction row (local index i) follows its normal row: just before it, or before its pair's
// first row. (A tangent whose DOFs are all held is no hard row: the group leaves it out.)
std::size_t CentralDifference::normal_of(const std::vector<Index>& rows, std::size_t i) const {
  return i - 1 - (in_plane(rows, i) ? static_cast<std::size_t>(tangent_of(rows, i)) : 0);
}

int CentralDifference::tangent_of(const std::vector<Index>& rows, std::size_t i) const {
  return hard_tangent_[static_cast<std::size_t>(rows[i])];
}

bool CentralDifference::hard_row_active(const std::vector<Index>& rows, std::size_t i) const {
  return hard_laws_[static_cast<std::size_t>(rows[i])] ? active_[i] != 0
                                                       : active_[normal_of(rows, i)] != 0;
}

bool CentralDifference::in_plane(const std::vector<Index>& rows, std::size_t i) const {
  return hard_pair_[static_cast<std::size_t>(rows[i])] != 0;
}

void CentralDifference::start_slip_in_plane(std::size_t first, const Eigen::Vector2d& along) {
  const double length = along.norm();
  const auto i = static_cast<Index>(first);
  // No slide to follow: along the first tangent, the way `along` points if it has a sign.
  slip_direction_.segment<2>(i) = length > 0.0
                                      ? Eigen::Vector2d(along / length)
                                      : Eigen::Vector2d(std::signbit(along[0]) ? -1.0 : 1.0, 0.0);
  slip_turn_[i] = 0.0;
  slip_[first] = slip_[first + 1] = 1;
}

void CentralDifference::solve_active_hard_rows(const std::vector<Index>& rows, double scale) {
  // Active normal and sticking rows: scale G F = delta~ - bound (their next value on the bound);
  // slipping rows: F_t = sign mu F_n.
  std::vector<Index>& unknowns = active_rows_;
  unknowns.clear();
  bool friction = false;
  for (std::size_t i = 0; i < rows.size(); ++i)
    if (hard_row_active(rows, i)) {
      unknowns.push_back(static_cast<Index>(i));
      friction = friction || !hard_laws_[static_cast<std::size_t>(rows[i])];
    }
  const auto count = static_cast<Index>(unknowns.size());
  group_force_.setZero(static_cast<Index>(rows.size()));
  if (count == 0) return;
  active_matrix_.resize(count, count);
  active_force_.resize(count);
  for (Index a = 0; a < count; ++a) {
    const auto i = static_cast<std::size_t>(unknowns[static_cast<std::size_t>(a)]);
    if (slip_[i] != 0 && in_plane(rows, i)) {
      slip_in_plane_row(rows, unknowns, a, scale);
      continue;
    }
    if (slip_[i] != 0) {
      active_matrix_.row(a).setZero();
      active_matrix_(a, a) = 1.0;
      active_matrix_(a, a - 1) =
          -slip_[i] * hard_frictions_[static_cast<std::size_t>(rows[i])]->coefficient();
      active_force_[a] = 0.0;
      continue;
    }
    active_force_[a] = free_next_[static_cast<Index>(i)] - bound_[static_cast<Index>(i)];
    for (Index b = 0; b < count; ++b)
      active_matrix_(a, b) =
          scale *
          coupling_(rows[i], rows[static_cast<std::size_t>(unknowns[static_cast<std::size_t>(b)])]);
  }
  // Without friction the matrix is G's, positive definite; a slipping row makes it unsymmetric.
  active_right_ = active_force_;
  if (friction)
    active_force_ = active_matrix_.partialPivLu().solve(active_right_);
  else
    active_force_ = active_matrix_.llt().solve(active_right_);
  // More constraints than the DOFs they hold (a block sticking on its floor and pressed against
  // its wall): the forces are not unique, the motion is; the least-norm forces (a complete
  // orthogonal decomposition), as Newmark takes.
  if (!active_force_.allFinite())
    active_force_ = active_matrix_.completeOrthogonalDecomposition().solve(active_right_);
  for (Index a = 0; a < count; ++a)
    group_force_[unknowns[static_cast<std::size_t>(a)]] = active_force_[a];
}

// A slipping contact plane's row a (tangent k of its contact): F_t = mu F_n e + kappa P s(F),
// P = I - e e^T, kappa = mu F_n / |s| at the last iterate, s(F) = s~ - bound - scale G_t F:
// Newton's linearisation of F_t = mu F_n s / |s| about the last slide (kappa = 0 on the first
// solve, with e from the stick force or the free slide). At its fixed point P s = 0: the force is
// mu F_n along the slide.
void CentralDifference::slip_in_plane_row(const std::vector<Index>& rows,
                                          const std::vector<Index>& unknowns, Index a,
                                          double scale) {
  const auto i = static_cast<std::size_t>(unknowns[static_cast<std::size_t>(a)]);
  const auto tangent = static_cast<Index>(tangent_of(rows, i));
  const Index first = static_cast<Index>(i) - tangent;  // local index of tangent 0
  const Eigen::Vector2d e = slip_direction_.segment<2>(first);
  const double kappa = slip_turn_[first];
  const double coefficient = hard_frictions_[static_cast<std::size_t>(rows[i])]->coefficient();
  Eigen::Vector2d projection = -e[tangent] * e;
  projection[tangent] += 1.0;  // row `tangent` of I - e e^T
  active_force_[a] = 0.0;
  for (Index b = 0; b < 2; ++b)
    active_force_[a] += kappa * projection[b] * (free_next_[first + b] - bound_[first + b]);
  const auto count = static_cast<Index>(unknowns.size());
  for (Index c = 0; c < count; ++c) {
    const Index column = rows[static_cast<std::size_t>(unknowns[static_cast<std::size_t>(c)])];
    double entry = 0.0;
    for (Index b = 0; b < 2; ++b)
      entry += projection[b] * coupling_(rows[static_cast<std::size_t>(first + b)], column);
    active_matrix_(a, c) = kappa * scale * entry;
  }
  active_matrix_(a, a) += 1.0;
  active_matrix_(a, a - tangent - 1) -= coefficient * e[tangent];  // the normal row's unknown
}

double CentralDifference::next_hard_value(const std::vector<Index>& rows, Index i,
                                          double scale) const {
  double next = free_next_[i];
  for (const Index j : active_rows_)
    next -= scale *
            coupling_(rows[static_cast<std::size_t>(i)], rows[static_cast<std::size_t>(j)]) *
            group_force_[j];
  return next;
}

bool CentralDifference::update_hard_active_set(const std::vector<Index>& rows, double scale) {
  // One change at a time, the worst first: the most tensile active row leaves; a sticking row
  // past mu F_n slips; a slipping row whose slide turned back sticks; a row past its bound joins.
  const auto size = static_cast<Index>(rows.size());
  Index worst = -1;
  double worst_value = 0.0;
  for (const Index i : active_rows_)
    if (hard_laws_[static_cast<std::size_t>(rows[static_cast<std::size_t>(i)])] &&
        group_force_[i] < worst_value) {
      worst = i;
      worst_value = group_force_[i];
    }
  if (worst >= 0) {
    active_[static_cast<std::size_t>(worst)] = 0;
    for (Index t = worst + 1;
         t < size && hard_frictions_[static_cast<std::size_t>(rows[static_cast<std::size_t>(t)])];
         ++t)
      slip_[static_cast<std::size_t>(t)] = 0;
    return true;
  }
  if (update_hard_friction(rows, scale)) return true;
  if (turn_slip_directions(rows, scale)) return true;
  double worst_excess = 0.0;
  for (Index i = 0; i < size; ++i) {
    const Index r = rows[static_cast<std::size_t>(i)];
    if (active_[static_cast<std::size_t>(i)] || !hard_laws_[static_cast<std::size_t>(r)]) continue;
    // A row that was no candidate is bound only by not penetrating.
    const double bound = candidate_[static_cast<std::size_t>(i)] ? bound_[i] : 0.0;
    const double excess =
        next_hard_value(rows, i, scale) - bound - hard_value_round_off(rows, i, scale);
    if (excess > worst_excess) {
      worst = i;
      worst_excess = excess;
    }
  }
  if (worst < 0) return false;
  if (!candidate_[static_cast<std::size_t>(worst)]) {
    candidate_[static_cast<std::size_t>(worst)] = 1;
    bound_[worst] = 0.0;
  }
  active_[static_cast<std::size_t>(worst)] = 1;
  return true;
}

bool CentralDifference::update_hard_friction(const std::vector<Index>& rows, double scale) {
  Index worst = -1;
  double worst_excess = 0.0;
  int worst_slip = 0;
  for (const Index i : active_rows_) {
    const Index r = rows[static_cast<std::size_t>(i)];
    const links::CoulombFriction* friction = hard_frictions_[static_cast<std::size_t>(r)];
    if (!friction) continue;
    double excess = 0.0;
    int slip = 0;
    if (in_plane(rows, static_cast<std::size_t>(i))) {
      if (tangent_of(rows, static_cast<std::size_t>(i)) != 0) continue;
      excess = in_plane_friction_excess(rows, i, scale);
      slip = 1;
    } else if (slip_[static_cast<std::size_t>(i)] == 0) {
      const double force = group_force_[i], limit = friction->coefficient() * group_force_[i - 1];
      // Relative to R_n: a sticking row at mu = 0 with a round-off force stays sticking.
      excess = (std::abs(force) - limit) / std::max(group_force_[i - 1], 1e-300) - 1e-12;
      slip = force > 0.0 ? 1 : -1;
    } else {
      // Slipping at F_t = sign mu F_n resists a slide of that sign; one the other way sticks.
      const double slide = next_hard_value(rows, i, scale) - bound_[i];
      excess = -slip_[static_cast<std::size_t>(i)] * slide - hard_value_round_off(rows, i, scale);
      excess /= std::max(magnitudes_[r], 1e-300);
    }
    if (excess > worst_excess) {
      worst = i;
      worst_excess = excess;
      worst_slip = slip;
    }
  }
  if (worst < 0) return false;
  const auto row = static_cast<std::size_t>(worst);
  if (!in_plane(rows, row)) {
    slip_[row] = static_cast<signed char>(worst_slip);
  } else if (slip_[row] != 0) {
    slip_[row] = slip_[row + 1] = 0;  // its slide turned back: it sticks
  } else {
    start_slip_in_plane(row, group_force_.segment<2>(worst));
  }
  return true;
}

// What round-off leaves in a row's next value delta~ - scale G F - bound: a share of its terms'
// size plus the margin of the row's own (its displacement's terms, kHardContactRoundOff). At rest,
// as at the start, the displacement is zero and only the terms count: there a corner whose partner
// sticks slides by round-off alone, and without them stick and slip would be round-off's choice.
double CentralDifference::hard_value_round_off(const std::vector<Index>& rows, Index i,
                                               double scale) const {
  const Index r = rows[static_cast<std::size_t>(i)];
  double terms = std::abs(free_next_[i]) + std::abs(bound_[i]);
  for (const Index j : active_rows_)
    terms += std::abs(scale * coupling_(r, rows[static_cast<std::size_t>(j)]) * group_force_[j]);
  return 1e-12 * terms + kHardContactRoundOff * magnitudes_[r];
}

// A contact plane's friction (local rows i, i + 1) asking to change, relative: sticking, by how
// much |F_t| passes mu F_n; slipping, by how much its slide runs against its force.
double CentralDifference::in_plane_friction_excess(const std::vector<Index>& rows, Index i,
                                                   double scale) const {
  const auto row = static_cast<std::size_t>(i);
  const double normal = group_force_[static_cast<Index>(normal_of(rows, row))];
  const double coefficient = hard_frictions_[static_cast<std::size_t>(rows[row])]->coefficient();
  if (slip_[row] == 0)
    return (group_force_.segment<2>(i).norm() - coefficient * normal) / std::max(normal, 1e-300) -
           1e-12;
  const Eigen::Vector2d slide = slide_in_plane(rows, i, scale);
  const double round_off = slide_round_off(rows, i, slide.norm());
  return (-slide.dot(slip_direction_.segment<2>(i)) - round_off) / std::max(round_off, 1e-300);
}

// What round-off leaves in a contact plane's slide s = s~ - bound - scale G F: of the free
// slide's size or the rows' own (the deck's displacement), whichever is larger.
double CentralDifference::slide_round_off(const std::vector<Index>& rows, Index i,
                                          double length) const {
  const auto row = static_cast<std::size_t>(i);
  const double magnitude = std::max(magnitudes_[rows[row]], magnitudes_[rows[row + 1]]);
  return 1e-12 * (free_slide(i).norm() + length) + kHardContactRoundOff * magnitude;
}

Eigen::Vector2d CentralDifference::free_slide(Index i) const {
  return free_next_.segment<2>(i) - bound_.segment<2>(i);
}

Eigen::Vector2d CentralDifference::slide_in_plane(const std::vector<Index>& rows, Index i,
                                                  double scale) const {
  return {next_hard_value(rows, i, scale) - bound_[i],
          next_hard_value(rows, i + 1, scale) - bound_[i + 1]};
}

// Newton's step on the slip directions of the slipping contact planes: e = s / |s| at the slide
// found, kappa = mu F_n / |s|; true when one turned by more than round-off.
bool CentralDifference::turn_slip_directions(const std::vector<Index>& rows, double scale) {
  bool turned = false;
  for (const Index i : active_rows_) {
    const auto row = static_cast<std::size_t>(i);
    if (!in_plane(rows, row) || slip_[row] == 0 || tangent_of(rows, row) != 0) continue;
    const Eigen::Vector2d slide = slide_in_plane(rows, i, scale);
    const Eigen::Vector2d e = slip_direction_.segment<2>(i);
    const double length = slide.norm();
    const double round_off = slide_round_off(rows, i, length);
    if (length <= round_off) continue;
    const Eigen::Vector2d across = slide - slide.dot(e) * e;
    if (across.norm() <= round_off && slip_turn_[i] > 0.0) continue;
    const double normal = group_force_[static_cast<Index>(normal_of(rows, row))];
    slip_direction_.segment<2>(i) = slide / length;
    slip_turn_[i] = hard_frictions_[static_cast<std::size_t>(rows[row])]->coefficient() *
                    std::max(0.0, normal) / length;
    turned = true;
  }
  return turned;
}

void CentralDifference::link_kinematics(SecondOrderSystem& system, const State& from,
                                        double half_dt, State& to) {
  const LinkSet& links = system.links();
  const LinkSet::SparseRowMatrix& b = links.connectivity();
  links.penetration(to.displacement, to.link_penetration);
  // Link rates at the half step B (v_n + dt/2 a_n): the extended penalty's critical dashpot on
  // its stiff relative mode is stable there at the Courant limit, not with the forward-predicted
  // velocity. Only the DOFs in B are visited.
  rate_.resize(b.rows());
  for (Index r = 0; r < b.rows(); ++r) {
    double sum = 0.0;
    for (LinkSet::SparseRowMatrix::InnerIterator it(b, r); it; ++it)
      sum += it.value() * (from.velocity[it.col()] + half_dt * from.acceleration[it.col()]);
    rate_[r] = sum;
  }
  links.project(to.acceleration, free_acceleration_);
  if (system.has_link_motion()) {
    system.link_motion(to.time, offset_, offset_rate_, offset_acceleration_);
    to.link_penetration += offset_;
    rate_ += offset_rate_;
    free_acceleration_ += offset_acceleration_;
  }
}

bool CentralDifference::solve_link_forces(LinkSet& links, State& to, StepResult& result) {
  // The link forces F change the accelerations by -M^-1 B^T F, so the laws see
  // delta_ddot = free - G F (G = B M^-1 B^T). Solve F = F_law(delta, rate, free - G F): laws with
  // no mass term need one evaluation; the extended penalty's alpha2 makes it a small system.
  to.link_force.setZero(links.size());
  for (int iteration = 0;; ++iteration) {
    link_acceleration_ = free_acceleration_;
    link_acceleration_.noalias() -= coupling_ * to.link_force;
    links.set_trial_mass(to.link_penetration, rate_, link_acceleration_, force_, tangent_);
    // Without a mass term the law's force does not depend on F: it is the answer.
    if (tangent_.cwiseAbs().maxCoeff() == 0.0) {
      to.link_force = force_;
      return true;
    }
    residual_ = to.link_force - force_;
    if (!residual_.allFinite()) {
      result.failure = "link forces are not finite";
      return false;
    }
    if (links.nodal_norm(residual_) <= 1e-12 * std::max(1e-300, links.nodal_norm(force_)))
      return true;
    if (iteration == 25) {
      result.failure = "the link forces of the explicit step did not settle in 25 iterations";
      return false;
    }
    solve_newton_correction();
    to.link_force -= correction_;
    // At machine precision already (a very stiff penalty mass): stop as the implicit step does.
    if (iteration > 0 && correction_.norm() <= 1e-14 * std::max(to.link_force.norm(), 1e-300))
      return true;
  }
}

void CentralDifference::solve_newton_correction() {
  // I + (dF_law / d(delta_ddot)) G, block by block: T and G tie rows only within a group.
  correction_.resize(residual_.size());
  for (std::size_t k = 0; k < link_groups_.size(); ++k) {
    const std::vector<Index>& rows = link_groups_[k];
    const Index size = static_cast<Index>(rows.size());
    Matrix& jacobian = group_jacobians_[k];
    jacobian.resize(size, size);
    group_residual_.resize(size);
    for (Index a = 0; a < size; ++a) {
      const Index r = rows[static_cast<std::size_t>(a)];
      group_residual_[a] = residual_[r];
      for (Index c = 0; c < size; ++c) {
        double sum = a == c ? 1.0 : 0.0;
        for (Index q : rows)
          sum += tangent_(r, q) * coupling_(q, rows[static_cast<std::size_t>(c)]);
        jacobian(a, c) = sum;
      }
    }
    group_lus_[k].compute(jacobian);
    const Vector solved = group_lus_[k].solve(group_residual_);
    for (Index a = 0; a < size; ++a) correction_[rows[static_cast<std::size_t>(a)]] = solved[a];
  }
}

double CentralDifference::nodal_link_force(Index dof, const Vector& link_force) const {
  double force = 0.0;
  for (Eigen::SparseMatrix<double>::InnerIterator it(link_columns_, dof); it; ++it)
    force += it.value() * link_force[it.row()];
  return force;
}

bool CentralDifference::apply_link_forces(const State& from, double half_dt, State& to) const {
  // a -= M^-1 B^T F and v_{n+1} again, at the DOFs the links touch.
  std::uint64_t flags = 0;
  for (const Index j : link_dofs_) {
    to.acceleration[j] -= inverse_mass_[j] * nodal_link_force(j, to.link_force);
    to.velocity[j] = from.velocity[j] + half_dt * (from.acceleration[j] + to.acceleration[j]);
    flags |= not_finite(to.velocity[j]);
  }
  return all_finite(flags);
}

namespace {

void refuse_overflow(const HighestMode& mode, const LinkTangents& tangents) {
  if (!std::isfinite(mode.eigenvalue) || !tangents.stiffness.allFinite() ||
      !tangents.damping.allFinite())
    throw std::domain_error(
        "the highest frequency overflows the number range (a stiffness or damping far beyond "
        "physical ones, or masses near zero), so no explicit step is stable");
}

}  // namespace

double highest_frequency(SecondOrderSystem& system, bool contacts_active) {
  const Vector inverse_mass = diagonal_mass(system).cwiseInverse();
  const LinkTangents tangents = link_tangents(system.links(), contacts_active);
  const HighestMode mode = highest_mode(system, inverse_mass, tangents);
  refuse_overflow(mode, tangents);
  return std::sqrt(std::max(mode.eigenvalue, 0.0));
}

double stable_time_step(SecondOrderSystem& system, bool contacts_active,
                        std::span<const LinkRowState> at) {
  const Vector inverse_mass = diagonal_mass(system).cwiseInverse();
  LinkSet& links = system.links();
  const LinkTangents tangents = link_tangents(links, contacts_active, at);
  HighestMode mode = highest_mode(system, inverse_mass, tangents);
  refuse_overflow(mode, tangents);
  const double omega = std::sqrt(std::max(mode.eigenvalue, 0.0));
  // Nothing stiff (a mass on dampers alone): only the links' own modes bound the step.
  double limit = std::numeric_limits<double>::infinity();
  if (omega > 0.0) limit = structural_stable_step(system, std::move(mode.shape), tangents, omega);
  // A link's own relative mode (its two end masses, m_rel = 1 / (B M^-1 B^T), against its
  // stiffness, penalty mass and dashpot) can be the binding one when its dashpot is stiff: the
  // extended penalty's critical alpha1 allows only 0.414 of 2 / omega there.
  // Where nothing vibrates above round-off (omega 0) a row's stiffness is as negligible: then
  // only a dashpot without one bounds the step.
  for (Index r = 0; r < links.size(); ++r)
    if ((tangents.stiffness[r] > 0.0 && omega > 0.0) ||
        (!(tangents.stiffness[r] > 0.0) && tangents.damping[r] > 0.0))
      limit = std::min(limit, link_mode_stable_step(links, inverse_mass, tangents, r));
  if (std::isnan(limit))
    throw std::domain_error(
        "the stable step is not a number: a mode's damping overflows the number range (a "
        "stiffness or damping far beyond physical ones, or masses near zero)");
  if (!(limit > 0.0))
    throw std::domain_error(fmt::format(
        "the stable step {:g} is not positive (a stiffness or damping far beyond physical ones, "
        "or masses near zero)",
        limit));
  return limit;
}

}  // namespace pound::integrators
