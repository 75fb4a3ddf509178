#include "model/record_pair.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace pound::model {
namespace {

constexpr int kAngles = 180;  // 0, 1, ..., 179 degrees: the non-redundant directions

// cos(theta) and sin(theta) of each whole degree, exact at the axes, so that theta = 0 and 90
// give the components' own values.
struct Directions {
  std::array<double, kAngles> cosines{}, sines{};
  Directions() {
    for (int angle = 0; angle < kAngles; ++angle) {
      const double radians = angle * std::numbers::pi / 180.0;
      cosines[angle] = angle == 90 ? 0.0 : std::cos(radians);
      sines[angle] = angle == 0 ? 0.0 : std::sin(radians);
    }
  }
};

// max_t |x_1(t) cos(theta) + x_2(t) sin(theta)| for each whole degree theta.
std::array<double, kAngles> rotated_peaks(const Directions& d, const std::vector<double>& first,
                                          const std::vector<double>& second) {
  std::array<double, kAngles> peaks{};
  for (std::size_t k = 0; k < first.size(); ++k)
    for (int angle = 0; angle < kAngles; ++angle)
      peaks[angle] = std::max(peaks[angle],
                              std::abs(first[k] * d.cosines[angle] + second[k] * d.sines[angle]));
  return peaks;
}

// Each component's response to project: the oscillator's displacement times w^2 and its state
// at the last sample, or the ground accelerations (period 0, or an oscillator that follows the
// ground rigidly; no free vibration after), as spectral_acceleration takes them, so that the
// projections at 0 and 90 degrees are the components' Sa to the bit.
struct PseudoAcceleration {
  std::vector<double> history;
  bool oscillates = false;
  double last_u = 0.0, last_v = 0.0;
};

PseudoAcceleration pseudo_acceleration_history(const GroundMotion& motion, double period,
                                               double damping_ratio) {
  if (moves_with_ground(motion, period, damping_ratio)) return {motion.acceleration};
  SdofResponse response = sdof_response(motion, period, damping_ratio);
  const double omega = 2.0 * std::numbers::pi / period;
  PseudoAcceleration result{std::move(response.displacement), true};
  result.last_u = result.history.back();
  result.last_v = response.velocity.back();
  for (double& u : result.history) u *= omega * omega;
  return result;
}

// The projections' peaks over the free vibration after the last sample: the projection of two
// oscillators of one period and damping is one such oscillator, from the projected state.
void add_free_vibration(const Directions& d, const PseudoAcceleration& first,
                        const PseudoAcceleration& second, double period, double damping_ratio,
                        std::array<double, kAngles>& peaks) {
  if (!first.oscillates || !second.oscillates) return;
  const double omega = 2.0 * std::numbers::pi / period;
  for (int angle = 0; angle < kAngles; ++angle) {
    const double c = d.cosines[angle], s = d.sines[angle];
    const double u = first.last_u * c + second.last_u * s, v = first.last_v * c + second.last_v * s;
    peaks[angle] =
        std::max(peaks[angle], omega * omega * free_vibration_peak(u, v, omega, damping_ratio));
  }
}

}  // namespace

void require_one_grid(const GroundMotion& first, const GroundMotion& second) {
  const std::string names = fmt::format("the components '{}' and '{}'", first.name, second.name);
  if (first.acceleration.size() != second.acceleration.size())
    throw std::invalid_argument(fmt::format("{} of a pair must have as many samples ({} and {})",
                                            names, first.acceleration.size(),
                                            second.acceleration.size()));
  if (!(std::abs(first.time_step - second.time_step) <= 1e-9 * first.time_step))
    throw std::invalid_argument(fmt::format("{} of a pair must have one time step ({:g} and {:g})",
                                            names, first.time_step, second.time_step));
}

GroundMotionPair make_component_pair(GroundMotion first, GroundMotion second) {
  require_one_grid(first, second);
  return {std::move(first), std::move(second)};
}

GroundMotionPair rotated(const GroundMotionPair& pair, double angle) {
  require_one_grid(pair.first, pair.second);  // a pair put together by hand
  GroundMotionPair turned = pair;
  const double c = std::cos(angle), s = std::sin(angle);
  for (std::size_t k = 0; k < pair.first.acceleration.size(); ++k) {
    const double a1 = pair.first.acceleration[k], a2 = pair.second.acceleration[k];
    turned.first.acceleration[k] = c * a1 + s * a2;
    turned.second.acceleration[k] = c * a2 - s * a1;
  }
  return turned;
}

PairSpectralAcceleration pair_spectral_acceleration(const GroundMotionPair& pair, double period,
                                                    double damping_ratio) {
  require_one_grid(pair.first, pair.second);
  // One oscillator run per component (sdof_response checks the period and damping); the
  // projections at 0 and 90 degrees are the components' own Sa.
  const PseudoAcceleration first = pseudo_acceleration_history(pair.first, period, damping_ratio);
  const PseudoAcceleration second = pseudo_acceleration_history(pair.second, period, damping_ratio);
  const Directions directions;
  std::array<double, kAngles> peaks = rotated_peaks(directions, first.history, second.history);
  add_free_vibration(directions, first, second, period, damping_ratio, peaks);
  PairSpectralAcceleration result;
  result.first = peaks[0];
  result.second = peaks[90];
  result.geometric_mean = std::sqrt(result.first * result.second);
  const auto largest = std::max_element(peaks.begin(), peaks.end());
  result.rot_d100 = *largest;
  result.rot_d100_angle = static_cast<double>(largest - peaks.begin());
  std::array<double, kAngles> sorted = peaks;
  std::nth_element(sorted.begin(), sorted.begin() + kAngles / 2, sorted.end());
  const double upper = sorted[kAngles / 2];
  const double lower = *std::max_element(sorted.begin(), sorted.begin() + kAngles / 2);
  result.rot_d50 = 0.5 * (lower + upper);
  if (!std::isfinite(result.rot_d100))
    throw std::invalid_argument("the spectral acceleration of the pair '" + pair.first.name +
                                "' at that period overflows the number range");
  return result;
}

}  // namespace pound::model
