#include "links/restitution_calibration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>

#include "core/errors.hpp"

namespace pound::links {
namespace {

// The cache key of a law's knob for e: its name and choices (its numbers do not matter in unit
// form).
std::string calibration_key(const LawEntry& entry, const LawSpec& law, double restitution) {
  std::string key = entry.name;
  for (const auto& [name, value] : law.choices) key += fmt::format(";{}={}", name, value);
  return key + fmt::format(";e={}", restitution);
}

// x and x' of the unit impact.
struct Phase {
  double position, velocity;
};

// One classical Runge-Kutta step of x'' = -F(x, x') with the law's trial forces.
Phase runge_kutta_step(LinkLaw& law, const Phase& s, double h) {
  const auto acceleration = [&law](double x, double v) {
    return -law.set_trial({x, v, 0.0}).force;
  };
  const double k1x = s.velocity, k1v = acceleration(s.position, s.velocity);
  const double k2x = s.velocity + 0.5 * h * k1v,
               k2v = acceleration(s.position + 0.5 * h * k1x, s.velocity + 0.5 * h * k1v);
  const double k3x = s.velocity + 0.5 * h * k2v,
               k3v = acceleration(s.position + 0.5 * h * k2x, s.velocity + 0.5 * h * k2v);
  const double k4x = s.velocity + h * k3v,
               k4v = acceleration(s.position + h * k3x, s.velocity + h * k3v);
  return {s.position + h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x),
          s.velocity + h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)};
}

}  // namespace

double impact_restitution(LinkLaw& law) {
  // The committed state just before contact, approaching at 1 (the approach velocity at first
  // contact is then 1 whatever the law interpolates), and the start just inside contact, so that
  // a force that jumps at contact (a dashpot's) acts from the first stage on.
  law.set_trial({-std::numeric_limits<double>::min(), 1.0, 0.0});
  law.commit();
  Phase state{std::numeric_limits<double>::min(), 1.0};
  // RK4 at h = 1e-3 of the ~3 units an impact lasts: 1e-13 in e where the force is smooth. Where
  // it is not, the step is small: it starts at 1e-12 and grows by 10 % a step (forces like
  // x^(1/4) x' at first touch), and halves down to 1e-12 to close in on the turn, x' = 0, where
  // laws switch their damping, and on the release, x = 0, or the let-go of a clipped law.
  constexpr double kStep = 1e-3, kSmallest = 1e-12, kGrowth = 1.1;
  double step = kSmallest, time = 0.0;
  // Over-damped impacts creep back without separating: after 200 units (an elastic impact lasts
  // about 3) there is no rebound to speak of.
  while (time < 200.0) {
    const Phase next = runge_kutta_step(law, state, step);
    const bool turns = state.velocity > 0.0 && next.velocity <= 0.0;
    if (turns && step > kSmallest) {
      step *= 0.5;
      continue;
    }
    if (next.position <= 0.0) {
      // Back at x = 0 within this step. Stages past x = 0 would see no force where the law still
      // acts (a dashpot's tension as it lets go): close in on x = 0 with halved steps instead,
      // and interpolate the last, tiny one.
      if (step > kSmallest) {
        step *= 0.5;
        continue;
      }
      return -(state.velocity + (next.velocity - state.velocity) * state.position /
                                    (state.position - next.position));
    }
    // A law that lets go while separating (its force clipped at 0) stays let go: the bodies fly
    // apart at constant speed.
    const double force = law.set_trial({next.position, next.velocity, 0.0}).force;
    if (next.velocity < 0.0 && force == 0.0) {
      // Let go inside this step, where the force has a kink: closed in on like the release.
      if (step > kSmallest) {
        step *= 0.5;
        continue;
      }
      return -next.velocity;
    }
    law.commit();
    state = next;
    time += step;
    step = std::min(kStep, kGrowth * step);
  }
  return std::max(0.0, -state.velocity);
}

double damping_for_restitution(const LawEntry& entry, const LawSpec& law, double restitution) {
  static std::mutex mutex;
  static std::map<std::string, double> cache;
  const std::lock_guard lock(mutex);
  const std::string key = calibration_key(entry, law, restitution);
  if (auto found = cache.find(key); found != cache.end()) return found->second;
  if (restitution >= 1.0) return cache[key] = 0.0;
  const auto reached = [&](double damping) {
    return impact_restitution(*entry.calibration->unit_law(damping, law));
  };
  // e falls monotonically with the knob: bracket the target by doubling, then close in with
  // TOMS 748 (Alefeld, Potra & Shi 1995; Boost.Math), about a quarter of bisection's impact
  // integrations for the same knob to 1e-12.
  double low = 0.0, high = 1.0;
  double high_excess = reached(high) - restitution;
  while (high_excess > 0.0) {
    low = high;
    high *= 2.0;
    if (high > 1e4)
      throw std::domain_error(
          fmt::format("restitution {} cannot be reached by {}", restitution, entry.name));
    high_excess = reached(high) - restitution;
  }
  if (high_excess == 0.0) return cache[key] = high;
  const double low_excess = low == 0.0 ? 1.0 - restitution : reached(low) - restitution;
  std::uintmax_t evaluations = 60;
  const auto [from, to] = boost::math::tools::toms748_solve(
      [&](double knob) { return reached(knob) - restitution; }, low, high, low_excess, high_excess,
      [](double a, double b) { return b - a <= 1e-12 * b; }, evaluations);
  return cache[key] = 0.5 * (from + to);
}

double calibrated_damping(const LawEntry& entry, const LawSpec& law, const LawSource& where) {
  const double e = *law.number("restitution");
  if (law.choice("calibration", "exact") != "exact") return entry.calibration->published(e);
  try {
    return damping_for_restitution(entry, law, e);
  } catch (const std::domain_error& error) {
    throw InputError(where.file, where.path + "/restitution", error.what());
  }
}

}  // namespace pound::links
