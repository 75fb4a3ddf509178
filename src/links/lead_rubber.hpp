#pragma once
// Lead-rubber isolator (lead-plug elastomeric bearing) as the bilinear model of the isolation
// codes, given by the numbers a bearing's data sheet gives: the characteristic strength Q_d (the
// force intercept of the post-yield branch at zero displacement), the post-yield stiffness k_d
// and the elastic (unloading) stiffness k_u, by default 10 k_d, the usual estimate when a test
// gives none (AASHTO Guide Specifications for Seismic Isolation Design, 3rd ed. 2010; Naeim &
// Kelly 1999, Design of Seismic Isolated Structures):
//
//   F_y = Q_d k_u / (k_u - k_d),  delta_y = Q_d / (k_u - k_d),  b = k_d / k_u
//
// It is made as a BilinearSpring(k_u, F_y, b) named "lead_rubber", whose yield lines are then
// F = k_d delta +- Q_d. A cycle to +-D (D > delta_y) dissipates EDC = 4 Q_d (D - delta_y), and
// the effective (secant) stiffness at D is k_eff = k_d + Q_d / D. k_u <= k_d has no yield point:
// an input error.
//
// Units: Q_d [F], k_d and k_u [F/L].
#include "links/link_law.hpp"

namespace pound::links {

struct LeadRubber {
  // Its registry entry (links/law_registry.hpp); its factory makes BilinearSpring objects.
  static const LawEntry& entry();
};

}  // namespace pound::links
