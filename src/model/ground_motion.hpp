#pragma once
// A ground-acceleration record, uniformly sampled, in the model's units of acceleration (the
// io/ readers convert from g, cm/s^2 or m/s^2), with the scaling engineers apply to records.
#include <string>
#include <vector>

namespace pound::model {

struct GroundMotion {
  std::string name;                  // where it came from (file name), for outputs
  double time_step = 0.0;            // [T], > 0
  std::vector<double> acceleration;  // [L/T^2], acceleration[k] at t = k * time_step

  double duration() const;  // (n - 1) * time_step
  // Linear interpolation between samples; 0 before 0 and after the last sample (the ground is
  // at rest once the record ends).
  double at(double time) const;
  double peak() const;          // max |a|
  double time_of_peak() const;  // when max |a| comes first, from the record's start [T]
};

// Ground acceleration, velocity and displacement of a record, possibly delayed (a support that
// the wave reaches later), for multi-support excitation. Velocity and displacement are the exact
// integrals of the linearly interpolated acceleration from rest at t = 0 (no baseline correction:
// a record whose velocity does not end at zero keeps drifting after its end).
struct GroundState {
  double acceleration = 0.0, velocity = 0.0, displacement = 0.0;
};
class GroundKinematics {
 public:
  GroundKinematics(const GroundMotion& motion, double delay);
  GroundState at(double time) const;
  double peak_velocity() const;  // max |velocity| over the samples

 private:
  GroundMotion motion_;
  double delay_;
  std::vector<double> velocity_, displacement_;  // at the samples
};

// The longest period a spectrum is asked at [s]: spectra stop at 10 to 20 s, and far beyond
// w^2 underflows (S_a 0, S_d = S_a / w^2 undefined).
inline constexpr double kLongestSpectralPeriod = 1000.0;

// Pseudo-spectral acceleration S_a = w^2 max|u| of a linear SDOF (period, damping ratio) under
// the record, computed with the exact piecewise-linear recurrence (Nigam & Jennings 1969), so
// it is exact for the linearly interpolated record, and over the free vibration after its last
// sample: the record is zero after it, as a run takes it, and an oscillator of a period longer
// than the record peaks there (T = 1 s on 3 s of a record: 0.42 g, against 0.25 g over the
// samples alone). Period 0 gives the peak acceleration.
double spectral_acceleration(const GroundMotion& motion, double period, double damping_ratio);

// The largest |u| of a linear oscillator's free vibration from (u, v) (omega, damping ratio in
// [0, 1)): |u| itself, or its first extremum (the later ones decay).
double free_vibration_peak(double u, double v, double omega, double damping_ratio);

// Whether the oscillator's pseudo-acceleration is the ground acceleration itself: period 0, or a
// valid damping ratio and a period a thousand times shorter than the time step, which follows
// the base rigidly (Sa the peak to (T / dt)^2; integrating it would overflow w^2 for periods near
// 1e-300). When it is, checks that the motion has samples.
bool moves_with_ground(const GroundMotion& motion, double period, double damping_ratio);

// 40 periods log-spaced from 0.02 s to 10 s: the default of spectra [s].
std::vector<double> default_spectrum_periods();

// The coefficients of one step of the exact recurrence below (ground_motion.cpp derives them).
struct OscillatorStep {
  double a11, a12, a21, a22;
  double step_u, ramp_u, step_v, ramp_v;  // b11 + b12, b12, b21 + b22, b22
};

// A linear SDOF (period, damping ratio) from rest on a base whose acceleration is linear within
// each step, advanced step by step (steps of any length) with Nigam & Jennings' exact
// recurrence: the spectrum of a signal known only as it is computed (a floor's acceleration).
// Period 0 follows the base rigidly: its Sa is the peak base acceleration. The peak is taken at
// the step ends, so shorter steps can only find a larger one.
class ResponseOscillator {
 public:
  ResponseOscillator(double period, double damping_ratio);
  void advance(double base_start, double base_end, double dt);
  // S_a = w^2 max|u| so far; the peak |base| for period 0 or periods far below the step.
  double pseudo_acceleration() const;

 private:
  double period_, damping_ratio_, omega_ = 0.0;
  double u_ = 0.0, v_ = 0.0, peak_displacement_ = 0.0, peak_base_ = 0.0;
  OscillatorStep map_{};
  double map_dt_ = 0.0;  // the step map_ is for
};

// Relative displacement, velocity and absolute acceleration history of a linear SDOF under the
// record at the record's own samples (Nigam & Jennings); used for spectra and as an exact
// reference for the time integrators.
struct SdofResponse {
  std::vector<double> displacement, velocity, absolute_acceleration;
};
SdofResponse sdof_response(const GroundMotion& motion, double period, double damping_ratio);

// Scale factors that bring a record to a target: a peak ground acceleration, or a spectral
// acceleration at a period (damping ratio usually 0.05). Targets in the record's own units.
double scale_to_peak(const GroundMotion& motion, double target_peak);
double scale_to_spectral_acceleration(const GroundMotion& motion, double target, double period,
                                      double damping_ratio);
void scale(GroundMotion& motion, double factor);

}  // namespace pound::model
