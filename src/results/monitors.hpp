#pragma once
// Peak responses an engineer checks after a pounding run: storey and pier drifts (with the
// displacement ductility demand where a yield drift is known), and joints (how far the gap
// opened and closed, how far the girder moved on its seat, and the margin left to unseating).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "integrators/integrator.hpp"
#include "results/ground_acceleration.hpp"
#include "results/observer.hpp"
#include "results/support_motion.hpp"
#include "results/term_sums.hpp"

namespace pound::results {

// A displacement read as the sum of coefficient x displacement over some equations.
using Term = model::DofTerm;

struct DriftPeak {
  double peak_drift = 0.0;      // max |u_top - u_bottom| along its direction (x unless told) [L]
  double time = 0.0;            // when
  double residual_drift = 0.0;  // u_top - u_bottom at the end of the run [L]
  // How far the drift still swings at the end: half its range over the run's last swing window
  // (DriftMonitors::set_swing_window: twice the structure's first period), or without one over
  // its last cycle (its last local maximum and minimum) [L]. A storey still vibrating at the end
  // has no settled residual: its residual_drift is one point of that swing.
  double end_swing = 0.0;
  // The top node's absolute acceleration along the drift (the floor's, the pier top's) [L/T^2]
  double peak_acceleration = 0.0;
  double acceleration_time = 0.0;
  // With corners (3-D floors): the largest drift of a corner along the drift's direction, which
  // corner and when; the storey's twist theta_z,top - theta_z,bottom [rad] at its peak.
  double peak_corner_drift = 0.0;
  std::size_t corner = 0;
  double corner_time = 0.0;
  double peak_twist = 0.0;
  double twist_time = 0.0;
  // With a partner across it (DriftMonitors::set_resultant_pairs: a pier's two drifts bending
  // one biaxial hinge): the peak of sqrt((d / d_y)^2 + (d_p / d_yp)^2), both at the same step.
  double peak_resultant_ratio = 0.0;
};

class DriftMonitors : public Observer {
 public:
  struct Where {
    DofReading bottom, top;  // along the drift's direction, no terms where fixed
    Index top_node;
    int direction = 0;  // of the drift (model/direction.hpp)
    // Along an axis (DriftMonitor::axis): the drift as a sum of terms, and the top's equation
    // and weight for each translation (x, y, z) for its acceleration; empty: along `direction`.
    std::vector<Term> drift = {};
    std::vector<std::pair<DofReading, double>> top_along = {};
    // Each corner's drift along the direction, and the twist, as sums of terms.
    std::vector<std::vector<Term>> corners = {};
    std::vector<Term> twist = {};
  };
  // `support`: the moving supports' motion the drifts add (none: the displacements as they are).
  DriftMonitors(std::vector<Where> storeys, GroundAcceleration& ground,
                SupportMotion* support = nullptr);
  // The end swing is then the drift's half range over the run's last `seconds` (model time), a
  // window long enough that a higher mode's ripple does not hide the first mode's swing; set
  // before the run.
  void set_swing_window(double seconds) {
    swing_window_ = seconds;
    windows_.assign(storeys_.size(), RecentDrifts{});
  }
  // Two monitors whose drifts, each over its yield drift, yield together (a pier's two drifts on
  // one hinge that yields on an ellipse): their resultant ratio's peak is kept for both.
  struct ResultantPair {
    std::size_t first = 0, second = 0;
    double first_yield = 0.0, second_yield = 0.0;
  };
  void set_resultant_pairs(std::vector<ResultantPair> pairs) { pairs_ = std::move(pairs); }
  void record(const integrators::State& state) override;
  // With each storey's largest corner drift, its corner and time, and its twist, from the peaks
  // of the plan sums.
  const std::vector<DriftPeak>& peaks() const;

 private:
  // Where a storey's sums are among the tables' values.
  struct Places {
    std::size_t top = 0, bottom = 0, drift = 0, corners = 0, twist = 0;  // displacement sums
    std::size_t top_acceleration = 0;                                    // acceleration sums
    std::array<std::size_t, 3> along_acceleration{};
  };
  double absolute_acceleration(const Where& w, const Places& at, const integrators::State& state);
  double fixed_or_along_axis(const Where& w, const Places& at, const integrators::State& state);
  void record_plan(const Where& w, const Places& at, DriftPeak& p) const;

  std::vector<Where> storeys_;
  std::vector<ResultantPair> pairs_;
  GroundAcceleration& ground_;
  SupportMotion* support_;
  // The plan fields (corner, twist) and the windowed end swing are folded in when the peaks are
  // read after a record.
  mutable std::vector<DriftPeak> peaks_;
  mutable bool read_current_ = true;
  std::vector<Places> places_;
  // Each storey's drift at the last step, which way it was going, and its last turning points.
  struct Turning {
    double previous = 0.0, maximum = 0.0, minimum = 0.0;
    int slope = 0;
    bool has_maximum = false, has_minimum = false;
  };
  std::vector<Turning> turning_;
  static void track_swing(Turning& turning, double drift, DriftPeak& peak);
  // With a swing window: each storey's (time, drift) of the steps inside it, oldest first, in a
  // ring that doubles when full (no allocation once the window has filled); the swing is taken
  // from them when the peaks are read, so a step only stores its drift (a monotonic queue of the
  // window's extremes cost the bridge's step 2 %).
  double swing_window_ = 0.0;
  class RecentDrifts {
   public:
    // Adds (time, drift) after dropping the steps older than `start`.
    void add(double time, double drift, double start);
    // Half the range of the drifts kept.
    double half_range() const;

   private:
    std::vector<std::pair<double, double>> ring_ = std::vector<std::pair<double, double>>(16);
    std::size_t head_ = 0, size_ = 0;
  };
  std::vector<RecentDrifts> windows_;
  TermSums displacement_sums_, acceleration_sums_;
  std::vector<double> displacements_, accelerations_;  // their values at the step
  // The largest |sum| of every displacement sum and when it first was, kept in one pass over
  // them all (a 3-D building's four corners and twist a storey; record_plan read them one by
  // one, a fifth of the eccentric buildings' step): each storey's plan peaks come from them.
  std::vector<double> sum_peaks_, sum_times_;
};

struct JointPeak {
  double peak_opening = 0.0;        // max -(delta + gap): the joint wider than at the start [L]
  double peak_closing = 0.0;        // max (delta + gap): the joint narrower than at the start [L]
  double peak_seat_movement = 0.0;  // max |u_girder - u_seat| along x [L]
  // The largest movement away from the joint (the way that opens it, toward the girder's own
  // span): what takes the girder end off its seat, which moving toward the joint cannot, as the
  // other girder or the backwall stops it there [L]
  double peak_unseating_movement = 0.0;
  double residual_opening = 0.0;          // -(delta + gap) at the end of the run [L]
  double peak_girder_acceleration = 0.0;  // the girder end's absolute, along x [L/T^2]
  // 3-D, with a direction: the girder end's turn in plan on its seat, theta_z,girder less the
  // seat's [rad]
  double peak_plan_rotation = 0.0;
};

class JointMonitors : public Observer {
 public:
  struct Where {
    Index link_row;  // the pounding link's normal row
    double gap;
    DofReading girder_x, seat_x;  // no terms where fixed
    Index girder;                 // node
    // A point's movement on its seat across the support line (a skewed deck's corner): the sum
    // of coefficient x displacement over these equations; empty: u(girder_x) - u(seat_x).
    using Term = results::Term;
    std::vector<Term> movement = {};
    std::vector<Term> plan_rotation = {};  // theta_z of the girder less the seat's (3-D, z up)
    // +1 or -1: the sign of the movement that opens the joint (the girder moving away from its
    // pounding link); 0 where the link does not move with the girder (then either way counts).
    double opening_sign = 0.0;
  };
  // `support`: the moving supports' motion the movements add (none: the displacements as they
  // are).
  JointMonitors(std::vector<Where> joints, GroundAcceleration& ground,
                SupportMotion* support = nullptr)
      : joints_(std::move(joints)), ground_(ground), support_(support), peaks_(joints_.size()) {}
  void record(const integrators::State& state) override;
  const std::vector<JointPeak>& peaks() const { return peaks_; }

 private:
  std::vector<Where> joints_;
  GroundAcceleration& ground_;
  SupportMotion* support_;
  std::vector<JointPeak> peaks_;
};

}  // namespace pound::results
