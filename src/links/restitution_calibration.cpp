#include "links/restitution_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

#include "links/restitution.hpp"

namespace pound::links {
namespace {

// Contact force of the nondimensional impact (compression positive, never tensile when clipped).
double force(DampedImpact law, double damping, double x, double v) {
  if (x <= 0.0) return 0.0;
  switch (law) {
    case DampedImpact::kelvin_voigt:
      return x + 2.0 * damping * v;
    case DampedImpact::kelvin_voigt_clipped:
      return std::max(0.0, x + 2.0 * damping * v);
    case DampedImpact::hertz_damp:
      return std::max(0.0, x * std::sqrt(x) * (1.0 + damping * v));
    case DampedImpact::jankowski:
      return x * std::sqrt(x) + (v > 0.0 ? 2.0 * damping * std::sqrt(std::sqrt(x)) * v : 0.0);
  }
  return 0.0;
}

}  // namespace

double impact_restitution(DampedImpact law, double damping) {
  const double h = 1e-4;
  double x = 0.0, v = 1.0;
  const bool tension_allowed = law == DampedImpact::kelvin_voigt;
  // Over-damped impacts creep back without separating: after 200 units (an elastic impact lasts
  // about 3) there is no rebound to speak of.
  for (long step = 0; step < static_cast<long>(200.0 / h); ++step) {
    auto a = [&](double position, double velocity) {
      return -force(law, damping, position, velocity);
    };
    const double k1x = v, k1v = a(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = a(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = a(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = a(x + h * k3x, v + h * k3v);
    const double next_x = x + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double next_v = v + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (next_x <= 0.0) return -(v + (next_v - v) * x / (x - next_x));  // back at x = 0
    // Clipped laws: once separating with zero force the bodies fly apart at constant speed.
    if (!tension_allowed && next_v < 0.0 && force(law, damping, next_x, next_v) == 0.0)
      return -next_v;
    x = next_x;
    v = next_v;
  }
  return std::max(0.0, -v);
}

double damping_for_restitution(DampedImpact law, double restitution) {
  static std::mutex mutex;
  static std::map<std::pair<int, double>, double> cache;
  const std::lock_guard lock(mutex);
  const auto key = std::make_pair(static_cast<int>(law), restitution);
  if (auto found = cache.find(key); found != cache.end()) return found->second;
  if (restitution >= 1.0) return cache[key] = 0.0;
  // With tension allowed the linear impact has a closed form (Anagnostopoulos' formula).
  if (law == DampedImpact::kelvin_voigt)
    return cache[key] = kelvin_voigt_damping_ratio(restitution);
  double low = 0.0, high = 1.0;
  while (impact_restitution(law, high) > restitution) {
    low = high;
    high *= 2.0;
    if (high > 1e4)
      throw std::domain_error(
          fmt::format("restitution {} cannot be reached by this law", restitution));
  }
  for (int iteration = 0; iteration < 60 && high - low > 1e-12 * high; ++iteration) {
    const double middle = 0.5 * (low + high);
    const double reached = impact_restitution(law, middle);
    if (std::abs(reached - restitution) < 1e-9) return cache[key] = middle;
    (reached > restitution ? low : high) = middle;
  }
  return cache[key] = 0.5 * (low + high);
}

}  // namespace pound::links
