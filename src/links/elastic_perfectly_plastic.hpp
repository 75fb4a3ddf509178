#pragma once
// Elastic-perfectly-plastic spring: a bilinear spring without hardening (b = 0), given by its
// elastic stiffness k and yield force F_y, the textbook hysteretic SDOF (Chopra, Dynamics of
// Structures, §7.1; OpenSees ElasticPP):
//
//   F = k (delta - p),  |F| <= F_y,  p grows while |F| = F_y
//
// It is made as a BilinearSpring(k, F_y, 0) named "elastic_perfectly_plastic": the same return
// mapping, the same tangent (k elastic, 0 while yielding). A symmetric cycle to +-delta_m
// (delta_m > delta_y = F_y / k) dissipates 4 F_y (delta_m - delta_y).
//
// Units: k [F/L], F_y [F].
#include "links/link_law.hpp"

namespace pound::links {

struct ElasticPerfectlyPlastic {
  // Its registry entry (links/law_registry.hpp); its factory makes BilinearSpring objects.
  static const LawEntry& entry();
};

}  // namespace pound::links
