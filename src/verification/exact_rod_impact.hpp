#pragma once
// Exact solution of two elastic rods colliding along their common axis (1-D wave equation in
// each rod, unilateral contact at the facing ends), by characteristics: with uniform initial
// velocity and zero initial stress in each rod the state is piecewise constant in x and t, and
// every discontinuity starts at an end, so the solution is exact to rounding.
//
// Geometry and signs: the left rod occupies [-L1, 0], the right rod [gap, gap + L2] at t = 0.
// Velocities are along +x. The rods approach when v_left > v_right. Stress is positive in
// tension (so a compressive wave has sigma < 0). The contact force is the compressive force
// transmitted across the interface, F >= 0. Far ends are free (sigma = 0) or fixed (v = 0).
// Units: any consistent set (E [F/L^2], rho [M/L^3], A [L^2], L [L], v [L/T]).
//
// References: Kawashima (1980) eqs. 10-14 (T_I = 2L/C0, |sigma| = rho*C0*v); Suzuki & Toi
// (1987) rod examples (fixed far end, A2 = 3*A1).
#include <memory>
#include <vector>

namespace pound::verification {

struct ExactRod {
  double youngs_modulus = 0.0;    // E
  double density = 0.0;           // rho
  double area = 0.0;              // A
  double length = 0.0;            // L
  double initial_velocity = 0.0;  // along +x
  bool far_end_fixed = false;

  double wave_speed() const;  // C0 = sqrt(E / rho)
  double impedance() const;   // Z = rho * C0 * A (force per velocity)
  double mass() const;        // rho * A * L
};

struct ContactInterval {
  double start = 0.0;
  double end = 0.0;
};

struct RodState {
  double velocity = 0.0;  // along +x
  double stress = 0.0;    // positive in tension
};

// Solves the collision over [0, t_end] once at construction; every query below is exact.
class ExactRodImpact {
 public:
  ExactRodImpact(const ExactRod& left, const ExactRod& right, double gap, double t_end);

  // Contact intervals in time order (empty if the rods never touch before t_end).
  const std::vector<ContactInterval>& contacts() const;
  // Compressive interface force at time t (0 while apart). At a jump returns the value after it.
  double contact_force(double t) const;
  // Times in (0, t_end) where contact_force jumps, sorted.
  std::vector<double> force_breakpoints() const;
  // Interface gap (right face minus left face position), >= 0 up to rounding.
  double gap(double t) const;
  // State at x (global coordinate of the undeformed rod, left rod x in [-L1, 0], right rod
  // x in [gap, gap + L2]) and time t. rod = 0 for left, 1 for right.
  RodState state(int rod, double x, double t) const;
  // Centre-of-mass velocity of a rod at time t (momentum / mass).
  double centre_of_mass_velocity(int rod, double t) const;

  double t_end() const;

 private:
  struct Impl;
  std::shared_ptr<const Impl> impl_;
};

}  // namespace pound::verification
