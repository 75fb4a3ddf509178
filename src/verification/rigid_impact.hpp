#pragma once
// Exact impulse solutions of a rigid body in plan striking fixed obstacles, the reference for
// skewed decks hitting their backwalls (issue 18; docs/design.md 4.5).
//
// A body of mass m and polar inertia J about its centre of mass moves at (v_x, v_y) and spins at
// w (counter-clockwise). A contact k at r_k from the centre, with the unit normal n_k from the
// obstacle into the body and the tangent t_k = z x n_k, has the velocities
//   g_N = (v + w z x r) . n,   g_T = (v + w z x r) . t   (g_N < 0: approaching).
// An impulse Lambda_N n + Lambda_T t at the contact changes them by W (Lambda_N, Lambda_T) with
//   W = [[1/m + (rho.n)^2 / J, (rho.n)(rho.t) / J], [(rho.n)(rho.t) / J, 1/m + (rho.t)^2 / J]],
// rho = z x r. Laws at each contact on the velocities after the impact (Newton's kinematic
// restitution with Coulomb friction, the impact law pound's hard contact imposes, Moreau-Jean):
//   pressing (Lambda_N > 0): g_N+ = -e g_N-, and either sticking (g_T+ = 0, |Lambda_T| <= mu
//   Lambda_N) or slipping (Lambda_T = -mu Lambda_N sign(g_T+)); or lifting off (Lambda = 0,
//   g_N+ >= -e g_N-).
//
// One contact is solved by Routh's method (Routh 1905; Stronge, "Impact Mechanics", 2000, ch. 5):
// the velocities follow the growing normal impulse along straight lines in impulse space, the
// slide stopping (then sticking, when |W_NT| <= mu W_TT, or reversing) on the way, and the impact
// ends when g_N reaches -e g_N-. Several contacts at once (a deck end flush against its wall
// touches at both corners) are solved by the laws above at every contact together, each contact's
// state (lifting, sticking, slipping either way) enumerated and the consistent combination kept.
#include <string>
#include <vector>

namespace pound::verification {

struct PlaneVector {
  double x = 0.0, y = 0.0;
};

struct RigidBodyInPlan {
  double mass = 0.0;     // m [M]
  double inertia = 0.0;  // J about the centre of mass [M L^2]
};

struct PlanVelocity {
  double x = 0.0, y = 0.0;  // of the centre of mass [L/T]
  double spin = 0.0;        // counter-clockwise [1/T]
};

struct PlanContact {
  PlaneVector point;   // r, from the centre of mass [L]
  PlaneVector normal;  // n, unit, from the obstacle into the body
};

// How a contact ended the impact.
enum class ContactEnd { lifted, sticking, slipping };

struct PlanImpact {
  PlanVelocity after;
  std::vector<double> normal_impulse, tangential_impulse;  // Lambda_N, Lambda_T per contact
  std::vector<ContactEnd> ends;
  bool slide_reversed = false;  // Routh's path: the slide turned back during the impact
  double energy_lost = 0.0;     // kinetic energy before less after [F L]
};

// Routh's method at one contact; `restitution` e in [0, 1], `friction` mu >= 0. A contact that is
// not approaching (g_N >= 0) takes no impulse.
PlanImpact routh_impact(const RigidBodyInPlan& body, const PlanVelocity& before,
                        const PlanContact& contact, double restitution, double friction);

// Every approaching contact at once, by enumeration (at most 4 contacts); throws
// std::runtime_error when no combination of states is consistent, or more than one gives
// different velocities.
PlanImpact simultaneous_impact(const RigidBodyInPlan& body, const PlanVelocity& before,
                               const std::vector<PlanContact>& contacts, double restitution,
                               double friction);

// A skewed deck: a parallelogram of length L along its axis x and width W, its ends along the
// skew (the angle `skew` [rad] between an end and the y axis, positive with the corner at +y
// further along x, the acute one), of uniform mass (J = m (L^2 + W^2 / cos^2 skew) / 12), sliding
// along +x at `speed` into a rigid backwall along its right end, touching it at both corners.
struct SkewedDeck {
  double length = 0.0, width = 0.0, skew = 0.0, mass = 0.0, speed = 0.0;
  RigidBodyInPlan body() const;
  // The right end's corners, acute (at +y) first, and the wall's normal into the deck.
  std::vector<PlanContact> corners() const;
};
PlanImpact skewed_deck_impact(const SkewedDeck& deck, double restitution, double friction);

}  // namespace pound::verification
