#include "links/plane_bouc_wen.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace pound::links {

namespace {

// Loading along a line saturates: the part of z along the move grows at A until |z| nears
// z_max, and the rest dies at about A / z_max per unit of travel (faster for n <= 2), so past
// 64 z_max / A of loading travel z is z_max d, d = D / |D|, to rounding (e^-60), whatever it
// started from. A longer move takes that limit, and its sensitivity z_max / |D| (I - d d^T) (only
// d turns z), instead of sub-steps: a move of any length costs a bounded number of them.
constexpr double kSaturatedTravel = 64.0;

using State = PlaneBoucWen::State;

double dot(const Tangential& a, const Tangential& b) { return a[0] * b[0] + a[1] * b[1]; }

State combine(const State& state, double h, const State& rate) {
  State out = state;
  for (std::size_t a = 0; a < kMaxTangents; ++a) {
    out.z[a] += h * rate.z[a];
    for (std::size_t b = 0; b < kMaxTangents; ++b)
      out.sensitivity[a][b] += h * rate.sensitivity[a][b];
  }
  return out;
}

}  // namespace

PlaneBoucWen::PlaneBoucWen(const ShearNumbers& numbers, int tangents)
    : stiffness_(numbers.stiffness),
      hardening_ratio_(numbers.hardening_ratio),
      amplitude_(numbers.smooth->amplitude),
      sharpness_(numbers.smooth->sharpness),
      saturation_(
          std::pow(amplitude_ / (numbers.smooth->beta + numbers.smooth->gamma), 1.0 / sharpness_)),
      substeps_(saturation_, sharpness_, amplitude_, numbers.smooth->beta, numbers.smooth->gamma),
      tangents_(tangents) {
  const SmoothShape& shape = *numbers.smooth;
  const double sum = shape.beta + shape.gamma;
  // |z|^(n-2) (beta sigma + gamma) = (|z| / z_max)^(n-2) times these: no power of a small
  // deformation underflows.
  const double scale = amplitude_ / (sum * saturation_ * saturation_);
  loading_ = scale * sum;
  unloading_ = scale * (shape.gamma - shape.beta);
}

std::unique_ptr<PlaneHysteresis> PlaneBoucWen::clone() const {
  auto copy = std::make_unique<PlaneBoucWen>(*this);
  copy->revert();
  return copy;
}

// f = A D - c w q z (q = z . D, w = (|z| / z_max)^(n-2)), its derivatives
// df/dz = -c (w q I + q (n - 2) w / |z|^2 z z^T + w z D^T) and df/dD = A I - c w z z^T.
State PlaneBoucWen::rate(const State& state, const Tangential& move, double sign) const {
  const double c = sign > 0.0 ? loading_ : unloading_;
  const double length = std::hypot(state.z[0], state.z[1]);
  const double q = dot(state.z, move);
  const double w = length > 0.0 ? std::pow(length / saturation_, sharpness_ - 2.0) : 0.0;
  const double radial = length > 0.0 ? q * (sharpness_ - 2.0) * w / (length * length) : 0.0;
  Matrix along_z{}, along_move{};  // df/dz, df/dD
  for (std::size_t a = 0; a < kMaxTangents; ++a)
    for (std::size_t b = 0; b < kMaxTangents; ++b) {
      const double identity = a == b ? 1.0 : 0.0;
      along_z[a][b] =
          -c * (w * q * identity + radial * state.z[a] * state.z[b] + w * state.z[a] * move[b]);
      along_move[a][b] = amplitude_ * identity - c * w * state.z[a] * state.z[b];
    }
  State out;
  for (std::size_t a = 0; a < kMaxTangents; ++a) {
    out.z[a] = amplitude_ * move[a] - c * w * q * state.z[a];
    for (std::size_t b = 0; b < kMaxTangents; ++b) {
      out.sensitivity[a][b] = along_move[a][b];
      for (std::size_t m = 0; m < kMaxTangents; ++m)
        out.sensitivity[a][b] += along_z[a][m] * state.sensitivity[m][b];
    }
  }
  return out;
}

State PlaneBoucWen::rk4_step(const State& state, double h, const Tangential& move,
                             double sign) const {
  const State k1 = rate(state, move, sign);
  const State k2 = rate(combine(state, 0.5 * h, k1), move, sign);
  const State k3 = rate(combine(state, 0.5 * h, k2), move, sign);
  const State k4 = rate(combine(state, h, k3), move, sign);
  State out = state;
  for (std::size_t a = 0; a < kMaxTangents; ++a) {
    out.z[a] += h / 6.0 * (k1.z[a] + 2.0 * k2.z[a] + 2.0 * k3.z[a] + k4.z[a]);
    for (std::size_t b = 0; b < kMaxTangents; ++b)
      out.sensitivity[a][b] += h / 6.0 *
                               (k1.sensitivity[a][b] + 2.0 * k2.sensitivity[a][b] +
                                2.0 * k3.sensitivity[a][b] + k4.sensitivity[a][b]);
  }
  return out;
}

// Sub-steps from `start`, graded near z = 0 (|z|^n is not smooth there), each at most
// max_substep of travel: the grid of a move does not depend on where its trial ends.
double PlaneBoucWen::advance_branch(State& state, double start, const Tangential& move,
                                    double sign) const {
  const double travel = std::hypot(move[0], move[1]);
  while (start < 1.0) {
    const double length = std::hypot(state.z[0], state.z[1]);
    const double h = std::min(substeps_.at(length) / travel, 1.0 - start);
    const State next = rk4_step(state, h, move, sign);
    if (sign < 0.0 && dot(next.z, move) >= 0.0) {
      // z . D reaches 0 inside this sub-step: bisect its length.
      double inside = 0.0, beyond = h;
      for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (inside + beyond);
        if (middle <= inside || middle >= beyond) break;
        (dot(rk4_step(state, middle, move, sign).z, move) < 0.0 ? inside : beyond) = middle;
      }
      state = rk4_step(state, beyond, move, sign);
      return start + beyond;
    }
    if (next.z == state.z && next.sensitivity == state.sensitivity) return 1.0;
    state = next;
    start += h;
  }
  return 1.0;
}

State PlaneBoucWen::advance(const Tangential& move) const {
  State state{committed_z_, {}};
  if (!std::isfinite(move[0] + move[1])) {
    state.z.fill(std::numeric_limits<double>::quiet_NaN());
    return state;
  }
  double start = 0.0;
  if (dot(state.z, move) < 0.0) start = advance_branch(state, 0.0, move, -1.0);
  const double travel = std::hypot(move[0], move[1]);
  if ((1.0 - start) * travel > kSaturatedTravel * saturation_ / amplitude_) {
    for (std::size_t a = 0; a < kMaxTangents; ++a) {
      state.z[a] = saturation_ * move[a] / travel;
      for (std::size_t b = 0; b < kMaxTangents; ++b)
        state.sensitivity[a][b] =
            saturation_ / travel * ((a == b ? 1.0 : 0.0) - move[a] * move[b] / (travel * travel));
    }
    return state;
  }
  if (start < 1.0) advance_branch(state, start, move, 1.0);
  return state;
}

PlaneBoucWen::Matrix PlaneBoucWen::slope(const Tangential& z, const Tangential& direction) const {
  return rate({z, {}}, direction, dot(z, direction) < 0.0 ? -1.0 : 1.0).sensitivity;
}

PlaneResponse PlaneBoucWen::set_trial(const Tangential& deformation) {
  trial_s_ = deformation;
  Tangential move{};
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
    move[a] = deformation[a] - committed_s_[a];
  const bool moved = move != Tangential{};
  const State state =
      moved ? advance(move) : State{committed_z_, slope(committed_z_, committed_direction_)};
  trial_z_ = state.z;
  const double elastic = hardening_ratio_ * stiffness_;
  const double hysteretic = (1.0 - hardening_ratio_) * stiffness_;
  PlaneResponse out;
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a) {
    out.force[a] = elastic * trial_s_[a] + hysteretic * trial_z_[a];
    for (std::size_t b = 0; b < static_cast<std::size_t>(tangents_); ++b)
      out.tangent[a][b] = (a == b ? elastic : 0.0) + hysteretic * state.sensitivity[a][b];
  }
  return out;
}

void PlaneBoucWen::commit() {
  if (trial_s_ != committed_s_)
    for (std::size_t a = 0; a < kMaxTangents; ++a)
      committed_direction_[a] = trial_s_[a] - committed_s_[a];
  committed_s_ = trial_s_;
  committed_z_ = trial_z_;
}

void PlaneBoucWen::revert() {
  trial_s_ = committed_s_;
  trial_z_ = committed_z_;
}

Tangential PlaneBoucWen::plastic_deformation() const {
  Tangential plastic{};
  for (std::size_t a = 0; a < static_cast<std::size_t>(tangents_); ++a)
    plastic[a] = committed_s_[a] - committed_z_[a] / amplitude_;
  return plastic;
}

}  // namespace pound::links
