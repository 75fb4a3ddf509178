// Yielding single-degree-of-freedom oscillators, m u'' + c u' + F_s(u) = -m a_g(t), with an
// elastic-perfectly-plastic or bilinear (kinematic hardening) spring made from its registry
// entry, integrated by pound's Newmark average acceleration:
// - under a half-sine ground pulse, against an independent closed-form solution built branch by
//   branch (each elastic or yielding branch is a linear oscillator under a sine force, solved
//   exactly; the switches are located by bracketing and bisection to ~1e-14 s): the peak and the
//   residual (permanent) displacement, and the error at every step falling as dt^2;
// - under a real record (El Centro 1940), against the same run with a 100 times finer step,
//   with the Bouc-Wen spring as well: the observed order of convergence.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "integrators/newmark.hpp"
#include "integrators/transient_analysis.hpp"
#include "links/bilinear_spring.hpp"
#include "links/law_registry.hpp"
#include "support/oscillator.hpp"
#include "support/shared_records.hpp"

namespace pound {
namespace {

constexpr double kPi = std::numbers::pi, kGravity = 9.80665;

// A pier-like SDOF: m = 200 t, T = 0.5 s, F_y = 0.2 m g.
struct Sdof {
  double mass = 2e5;
  double stiffness = 2e5 * (4.0 * kPi) * (4.0 * kPi);  // k = m (2 pi / T)^2
  double yield_force = 0.2 * 2e5 * kGravity;
  double hardening = 0.0;  // b
  double damping_ratio = 0.0;

  double omega() const { return std::sqrt(stiffness / mass); }
  double period() const { return 2.0 * kPi / omega(); }
  double damping() const { return 2.0 * damping_ratio * omega() * mass; }
};

// a_g(t) = amplitude sin(pi t / duration) on [0, duration], 0 after.
struct Pulse {
  double amplitude = 0.4 * kGravity;
  double duration = 0.3;

  double frequency() const { return kPi / duration; }
  double at(double t) const { return t <= duration ? amplitude * std::sin(frequency() * t) : 0.0; }
};

// m u'' + c u' + K u = f0 + f1 sin(W t) from u(t0) = u0, u'(t0) = v0, in closed form, for
// K > 0 underdamped, or K = 0 (a yielding EPP spring) with or without c.
class LinearBranch {
 public:
  struct Motion {
    double u, v;
  };
  LinearBranch(double m, double c, double K, double f0, double f1, double W, double t0, double u0,
               double v0)
      : m_(m), c_(c), K_(K), f0_(f0), W_(W), t0_(t0) {
    // Particular part of the sine: P sin + Q cos (no resonance: K - m W^2 and c W not both 0).
    const double reduced = K - m * W * W, det = reduced * reduced + c * W * c * W;
    P_ = f1 * reduced / det;
    Q_ = -f1 * c * W / det;
    const Motion particular = this->particular(t0);
    a_ = u0 - particular.u;
    b_ = v0 - particular.v;
    if (K_ > 0.0) {
      omega_ = std::sqrt(K / m);
      decay_ = c / (2.0 * m);
      EXPECT_LT(decay_, omega_) << "an overdamped branch: choose other numbers";
      omega_d_ = std::sqrt(omega_ * omega_ - decay_ * decay_);
      b_ = (b_ + decay_ * a_) / omega_d_;  // a cos + b sin, u(0) = a, u'(0) = b omega_d - decay a
    }
  }

  Motion at(double t) const {
    const Motion p = particular(t), h = homogeneous(t - t0_);
    return {p.u + h.u, p.v + h.v};
  }

 private:
  Motion particular(double t) const {
    const double s = std::sin(W_ * t), co = std::cos(W_ * t), tau = t - t0_;
    Motion sine{P_ * s + Q_ * co, W_ * (P_ * co - Q_ * s)};
    if (K_ > 0.0) return {sine.u + f0_ / K_, sine.v};
    if (c_ > 0.0) return {sine.u + f0_ / c_ * tau, sine.v + f0_ / c_};
    return {sine.u + 0.5 * f0_ / m_ * tau * tau, sine.v + f0_ / m_ * tau};
  }
  // With (a_, b_) fitted to the initial state.
  Motion homogeneous(double tau) const {
    if (K_ > 0.0) {
      const double e = std::exp(-decay_ * tau), co = std::cos(omega_d_ * tau),
                   s = std::sin(omega_d_ * tau);
      return {e * (a_ * co + b_ * s),
              e * ((b_ * omega_d_ - decay_ * a_) * co - (a_ * omega_d_ + decay_ * b_) * s)};
    }
    if (c_ > 0.0) {  // C1 + C2 e^(-r tau) with r = c / m, C2 = -v0 / r
      const double r = c_ / m_, e = std::exp(-r * tau);
      return {a_ + b_ / r * (1.0 - e), b_ * e};
    }
    return {a_ + b_ * tau, b_};
  }

  double m_, c_, K_, f0_, W_, t0_;
  double P_ = 0.0, Q_ = 0.0, a_ = 0.0, b_ = 0.0;
  double omega_ = 0.0, decay_ = 0.0, omega_d_ = 0.0;
};

// The first t in (from, to] where g turns >= 0, scanning with `scan` and bisecting to the last
// representable bracket.
std::optional<double> first_crossing(const std::function<double(double)>& g, double from, double to,
                                     double scan) {
  for (double lo = from; lo < to; lo += scan) {
    const double hi = std::min(lo + scan, to);
    if (g(hi) < 0.0) continue;
    double inside = lo, beyond = hi;
    while (true) {
      const double middle = 0.5 * (inside + beyond);
      if (middle <= inside || middle >= beyond) break;
      (g(middle) < 0.0 ? inside : beyond) = middle;
    }
    return beyond;
  }
  return std::nullopt;
}

// The exact response, branch by branch: elastic (F = k (u - p)), yielding up or down
// (F = b k u +- (1 - b) F_y, the yield lines of kinematic hardening), pulse on or over.
class ExactResponse {
 public:
  ExactResponse(const Sdof& s, const Pulse& pulse, double end) {
    const double hardening_modulus = s.hardening * s.stiffness / (1.0 - s.hardening);  // H
    const double scan = s.period() / 4000.0;
    double t = 0.0, plastic = 0.0;
    LinearBranch::Motion motion{0.0, 0.0};
    Mode mode = Mode::elastic;
    while (t < end) {
      const bool pulsing = t < pulse.duration;
      const double limit = pulsing ? pulse.duration : end;
      const LinearBranch branch = make_branch(s, pulse, mode, plastic, pulsing, t, motion);
      // Elastic between u_- and u_+, where |k (u - p) - H p| = F_y; yielding until u' = 0.
      const double up = plastic + (hardening_modulus * plastic + s.yield_force) / s.stiffness;
      const double down = plastic + (hardening_modulus * plastic - s.yield_force) / s.stiffness;
      const std::function<double(double)> leaves = [&](double time) {
        const LinearBranch::Motion m = branch.at(time);
        if (mode == Mode::elastic) return std::max(m.u - up, down - m.u);
        return mode == Mode::yielding_up ? -m.v : m.v;
      };
      const std::optional<double> event = first_crossing(leaves, t, limit, scan);
      const double next = event.value_or(limit);
      pieces_.push_back({t, next, branch, mode});
      motion = branch.at(next);
      if (event) {
        ++switches_;
        if (mode == Mode::elastic) {
          mode = motion.u > 0.5 * (up + down) ? Mode::yielding_up : Mode::yielding_down;
        } else {  // back on the elastic line through the point reached: k (u - p) - H p = +-F_y
          const double sign = mode == Mode::yielding_up ? 1.0 : -1.0;
          plastic =
              (s.stiffness * motion.u - sign * s.yield_force) / (s.stiffness + hardening_modulus);
          mode = Mode::elastic;
        }
      }
      t = next;
    }
    plastic_ = plastic;
    find_peak(scan);
  }

  double displacement(double t) const { return piece_at(t).branch.at(t).u; }
  double peak() const { return peak_; }        // max |u|
  double plastic() const { return plastic_; }  // p at the end: the permanent displacement
  int switches() const { return switches_; }

 private:
  enum class Mode { elastic, yielding_up, yielding_down };
  struct Piece {
    double start, end;
    LinearBranch branch;
    Mode mode;
  };

  static LinearBranch make_branch(const Sdof& s, const Pulse& pulse, Mode mode, double plastic,
                                  bool pulsing, double t, LinearBranch::Motion motion) {
    const double force = pulsing ? -s.mass * pulse.amplitude : 0.0;
    if (mode == Mode::elastic)  // m u'' + c u' + k u = -m a_g + k p
      return {s.mass, s.damping(), s.stiffness, s.stiffness * plastic, force, pulse.frequency(),
              t,      motion.u,    motion.v};
    // m u'' + c u' + b k u = -m a_g -+ (1 - b) F_y
    const double offset =
        (mode == Mode::yielding_up ? -1.0 : 1.0) * (1.0 - s.hardening) * s.yield_force;
    return {s.mass,   s.damping(), s.hardening * s.stiffness, offset, force, pulse.frequency(), t,
            motion.u, motion.v};
  }

  const Piece& piece_at(double t) const {
    const auto after = std::upper_bound(pieces_.begin(), pieces_.end(), t,
                                        [](double time, const Piece& p) { return time < p.start; });
    return *(after == pieces_.begin() ? after : after - 1);
  }

  // |u| is largest at a piece's end or where u' = 0 inside one.
  void find_peak(double scan) {
    for (const Piece& p : pieces_) {
      peak_ = std::max({peak_, std::abs(p.branch.at(p.start).u), std::abs(p.branch.at(p.end).u)});
      double from = p.start;
      while (from < p.end) {
        const double sign = p.branch.at(std::min(from + 0.5 * scan, p.end)).v > 0.0 ? 1.0 : -1.0;
        const std::optional<double> turn = first_crossing(
            [&](double time) { return -sign * p.branch.at(time).v; }, from, p.end, scan);
        if (!turn) break;
        peak_ = std::max(peak_, std::abs(p.branch.at(*turn).u));
        from = *turn;
      }
    }
  }

  std::vector<Piece> pieces_;
  double plastic_ = 0.0, peak_ = 0.0;
  int switches_ = 0;
};

// The link law of the SDOF's spring, from the registry.
std::unique_ptr<links::LinkLaw> spring_law(const links::LawSpec& spec) {
  return links::make_law(spec, {"test.json", "/links/0/law"})(links::LinkContext{});
}

links::LawSpec bilinear_spec(const Sdof& s) {
  if (s.hardening == 0.0)
    return {"elastic_perfectly_plastic",
            {{"stiffness", s.stiffness}, {"yield_force", s.yield_force}}};
  return {"bilinear_spring",
          {{"stiffness", s.stiffness},
           {"yield_force", s.yield_force},
           {"hardening_ratio", s.hardening}}};
}

struct Response {
  std::vector<double> time, displacement;
  double plastic = 0.0;  // the spring's permanent deformation at the end (bilinear laws)
};

// Newmark average acceleration on the SDOF with the spring `spec` under a_g.
Response newmark_run(const Sdof& s, const links::LawSpec& spec,
                     const std::function<double(double)>& ground, double dt, double end) {
  std::vector<std::unique_ptr<links::LinkLaw>> laws;
  laws.push_back(spring_law(spec));
  integrators::LinkSet links(1, {{{0, 1.0}}}, {0.0}, std::move(laws));
  testing::Oscillator system(s.mass, s.damping(), 0.0, std::move(links),
                             [&](double t) { return -s.mass * ground(t); });
  integrators::Newmark newmark = integrators::Newmark::average_acceleration();
  integrators::TransientAnalysis analysis(system, newmark, {.time_step = dt, .end_time = end});
  integrators::State state;
  state.displacement = Vector::Zero(1);
  state.velocity = Vector::Zero(1);
  Response run;
  analysis.run(state, [&](const integrators::State& at, const integrators::StepResult&) {
    run.time.push_back(at.time);
    run.displacement.push_back(at.displacement[0]);
  });
  if (const auto* bilinear = dynamic_cast<const links::BilinearSpring*>(&system.links().law(0)))
    run.plastic = bilinear->plastic_deformation();
  return run;
}

struct PulseErrors {
  double nodal, peak, plastic, end;  // relative to the exact peak
};

PulseErrors pulse_errors(const Sdof& s, const Pulse& pulse, const ExactResponse& exact, double dt,
                         double end) {
  const Response run = newmark_run(
      s, bilinear_spec(s), [&](double t) { return pulse.at(t); }, dt, end);
  double nodal = 0.0, peak = 0.0;
  for (std::size_t n = 0; n < run.time.size(); ++n) {
    nodal = std::max(nodal, std::abs(run.displacement[n] - exact.displacement(run.time[n])));
    peak = std::max(peak, std::abs(run.displacement[n]));
  }
  EXPECT_NEAR(run.time.back(), end, 1e-9);
  const double scale = exact.peak();
  return {nodal / scale, std::abs(peak - scale) / scale,
          std::abs(run.plastic - exact.plastic()) / scale,
          std::abs(run.displacement.back() - exact.displacement(end)) / scale};
}

// The slope of log(error) against log(dt), least squares: the observed order over several steps
// (a yield onset inside a step adds an error that depends on where in the step it falls, so one
// pair of steps alone gives a noisy order).
double fitted_order(const std::vector<double>& steps, const std::vector<double>& errors) {
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    mx += std::log(steps[i]) / static_cast<double>(steps.size());
    my += std::log(errors[i]) / static_cast<double>(steps.size());
  }
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    sxy += (std::log(steps[i]) - mx) * (std::log(errors[i]) - my);
    sxx += (std::log(steps[i]) - mx) * (std::log(steps[i]) - mx);
  }
  return sxy / sxx;
}

TEST(YieldingOscillator, HalfSinePulseMatchesTheBranchByBranchClosedFormAtSecondOrder) {
  struct Case {
    std::string label;
    double hardening, damping_ratio;
  };
  for (const Case& c : {Case{"EPP, undamped", 0.0, 0.0}, Case{"EPP, 5% damping", 0.0, 0.05},
                        Case{"bilinear b = 0.1, 2% damping", 0.1, 0.02}}) {
    Sdof s;
    s.hardening = c.hardening;
    s.damping_ratio = c.damping_ratio;
    const Pulse pulse;
    const double end = 6.0 * s.period();  // the pulse, then free vibration
    const ExactResponse exact(s, pulse, end);
    const double yield = s.yield_force / s.stiffness;
    std::cout << c.label << ": exact peak " << exact.peak() << " m (ductility "
              << exact.peak() / yield << "), permanent displacement " << exact.plastic()
              << " m, u(end) " << exact.displacement(end) << " m, " << exact.switches()
              << " switches\n";
    EXPECT_GT(exact.peak(), 3.0 * yield);  // it does yield
    EXPECT_GE(exact.switches(), 2);
    std::vector<double> steps, nodal, permanent;
    std::vector<PulseErrors> errors;
    for (int per_period : {500, 1000, 2000}) {
      steps.push_back(s.period() / per_period);
      errors.push_back(pulse_errors(s, pulse, exact, steps.back(), end));
      const PulseErrors& e = errors.back();
      nodal.push_back(e.nodal);
      permanent.push_back(e.plastic);
      std::cout << "  dt = T/" << per_period << ": max |u - u_exact| " << e.nodal << ", peak "
                << e.peak << ", permanent displacement " << e.plastic << ", u(end) " << e.end
                << " (each / exact peak)\n";
    }
    const double order = fitted_order(steps, nodal);
    const double permanent_order = fitted_order(steps, permanent);
    std::cout << "  observed order " << order << " (permanent displacement: " << permanent_order
              << ")\n";
    EXPECT_NEAR(order, 2.0, 0.3) << c.label;
    EXPECT_NEAR(permanent_order, 2.0, 0.4) << c.label;
    const PulseErrors& finest = errors.back();
    EXPECT_LT(finest.nodal, 1e-4) << c.label;
    EXPECT_LT(finest.peak, 1e-4) << c.label;
    EXPECT_LT(finest.plastic, 1e-4) << c.label;
    EXPECT_LT(finest.end, 1e-4) << c.label;
  }
}

// The record's samples common to every run: max |u - u_reference| over them, and at the end.
struct RecordErrors {
  double nodal, end;
};

RecordErrors record_errors(const Response& run, const Response& reference, double sample) {
  std::map<long, double> at_samples;
  for (std::size_t n = 0; n < reference.time.size(); ++n)
    if (const long k = std::lround(reference.time[n] / sample);
        std::abs(reference.time[n] - static_cast<double>(k) * sample) < 1e-9)
      at_samples[k] = reference.displacement[n];
  double nodal = 0.0;
  for (std::size_t n = 0; n < run.time.size(); ++n) {
    const long k = std::lround(run.time[n] / sample);
    if (std::abs(run.time[n] - static_cast<double>(k) * sample) < 1e-9 && at_samples.count(k))
      nodal = std::max(nodal, std::abs(run.displacement[n] - at_samples.at(k)));
  }
  return {nodal, std::abs(run.displacement.back() - reference.displacement.back())};
}

TEST(YieldingOscillator, ElCentroConvergesAtSecondOrderAgainstAHundredTimesFinerStep) {
  POUND_SKIP_WITHOUT_SHARED_RECORDS();
  model::GroundMotion motion = testing::el_centro(1000);  // the strong part, 10 s
  // The ground is at rest after the record: its last sample set to 0 makes that continuous (a
  // jump there would cost the trapezoidal rule an O(dt) impulse error). Then 5 s (10 periods)
  // at rest: u(end) is near the residual displacement.
  motion.acceleration.back() = 0.0;
  const double end = motion.duration() + 5.0;
  Sdof s;
  s.damping_ratio = 0.05;
  s.yield_force = 0.15 * s.mass * kGravity;
  const double z_max = s.yield_force / s.stiffness;
  Sdof hardening = s;
  hardening.hardening = 0.05;
  // A Bouc-Wen spring with the same k, F_y ~ k z_max and b: n = 2, beta = gamma.
  const links::LawSpec bouc_wen{"bouc_wen",
                                {{"stiffness", s.stiffness},
                                 {"hardening_ratio", 0.05},
                                 {"sharpness", 2.0},
                                 {"beta", 0.5 / (z_max * z_max)},
                                 {"gamma", 0.5 / (z_max * z_max)}}};
  struct Case {
    std::string label;
    links::LawSpec spec;
  };
  const auto ground = [&](double t) { return motion.at(t); };
  const std::vector<double> steps = {motion.time_step / 4.0, motion.time_step / 8.0,
                                     motion.time_step / 16.0};
  for (const Case& c :
       {Case{"EPP", bilinear_spec(s)}, Case{"bilinear b = 0.05", bilinear_spec(hardening)},
        Case{"Bouc-Wen n = 2", bouc_wen}}) {
    const Response reference = newmark_run(s, c.spec, ground, steps.front() / 100.0, end);
    double peak = 0.0;
    for (double u : reference.displacement) peak = std::max(peak, std::abs(u));
    std::cout << c.label << ": peak " << peak << " m (" << peak / z_max
              << " yield displacements), residual u(end) " << reference.displacement.back()
              << " m\n";
    EXPECT_GT(peak, 2.0 * z_max);
    std::vector<double> nodal, residual;
    for (double dt : steps) {
      const RecordErrors e =
          record_errors(newmark_run(s, c.spec, ground, dt, end), reference, motion.time_step);
      nodal.push_back(e.nodal / peak);
      residual.push_back(e.end / peak);
      std::cout << "  dt = " << dt << ": max |u - u_ref| / peak " << nodal.back()
                << ", |residual - residual_ref| / peak " << residual.back() << "\n";
    }
    const double order = fitted_order(steps, nodal);
    std::cout << "  observed order " << order
              << " (residual displacement, not monotone: " << fitted_order(steps, residual)
              << ")\n";
    // The residual's error is a sum of signed contributions of the yield events, each O(dt^2)
    // with a factor that depends on where the event falls in its step: bounded, not monotone.
    EXPECT_NEAR(order, 2.0, 0.3) << c.label;
    EXPECT_LT(nodal.back(), 1e-4) << c.label;
    EXPECT_LT(residual.back(), 1e-4) << c.label;
  }
}

}  // namespace
}  // namespace pound
