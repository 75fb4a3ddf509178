#pragma once
// The two horizontal components of one station's record, and the intensity measures engineers
// take of a pair: the geometric mean of the components' spectra and the orientation-independent
// RotD50 and RotD100 (Boore, D. M. (2010), "Orientation-independent, nongeometric-mean measures
// of seismic intensity from two horizontal components of motion", BSSA 100(4), 1830-1835).
//
// RotDnn at period T: the oscillator's displacement under each component, u_1(t) and u_2(t), is
// projected on every horizontal direction theta = 0, 1, ..., 179 degrees,
//   u(theta, t) = u_1(t) cos(theta) + u_2(t) sin(theta)
// (a linear oscillator's response to the rotated record is the rotated response); nn is the
// percentile over theta of the peaks max_t |u(theta, t)|, times w^2. RotD100 is the largest, in
// the direction it names; RotD50 the median (the mean of the 90th and 91st of the 180 sorted
// peaks), which a rotation of the pair by a whole number of degrees leaves unchanged. Period 0
// (or an oscillator that follows the ground rigidly) takes the ground accelerations themselves.
#include <string>

#include "model/ground_motion.hpp"

namespace pound::model {

struct GroundMotionPair {
  GroundMotion first, second;  // orthogonal horizontal components, `second` 90 degrees from `first`
};

// Throws std::invalid_argument naming both components unless they are on one time grid: the
// same time step (to 1e-9 of it) and the same number of samples.
void require_one_grid(const GroundMotion& first, const GroundMotion& second);
// The pair, once checked to be on one time grid (rotated and pair_spectral_acceleration check a
// pair put together otherwise).
GroundMotionPair make_component_pair(GroundMotion first, GroundMotion second);

// The pair's axes turned by `angle` [rad], counter-clockwise from `first` towards `second`:
// first' = first cos + second sin, second' = second cos - first sin.
GroundMotionPair rotated(const GroundMotionPair& pair, double angle);

// Spectral accelerations of a pair at one period, in the records' units.
struct PairSpectralAcceleration {
  double first = 0.0, second = 0.0;  // each component's Sa
  double geometric_mean = 0.0;       // sqrt(first * second)
  double rot_d50 = 0.0, rot_d100 = 0.0;
  double rot_d100_angle = 0.0;  // [degrees] from `first` towards `second`, in [0, 180)
};
PairSpectralAcceleration pair_spectral_acceleration(const GroundMotionPair& pair, double period,
                                                    double damping_ratio);

}  // namespace pound::model
