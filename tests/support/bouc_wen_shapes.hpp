#pragma once
// The Bouc-Wen shapes the uniaxial and the coupled law are tested on (tests/links/
// bouc_wen_test.cpp, tests/links/plane_bouc_wen_test.cpp): n from 1 to 25, beta against gamma
// either way, gamma < 0, A = 2.
#include <cmath>
#include <string>
#include <vector>

#include "links/bouc_wen.hpp"

namespace pound::testing {

inline constexpr double kBoucWenStiffness = 2e7;  // N/m
inline constexpr double kBoucWenZmax = 5e-3;      // m, for A = 1

struct BoucWenShape {
  std::string label;
  links::BoucWen::Parameters parameters;
};

// beta and gamma as fractions of (beta + gamma) = A / z_max^n, so every shape saturates at
// kBoucWenZmax (times A^(1/n) / A^(1/n) = 1 for A = 1; the amplitude-2 shape saturates at
// 2^(1/n) kBoucWenZmax).
inline links::BoucWen::Parameters bouc_wen_shape(double n, double beta_share, double gamma_share,
                                                 double hardening, double amplitude = 1.0) {
  const double sum = 1.0 / std::pow(kBoucWenZmax, n);
  return {.stiffness = kBoucWenStiffness,
          .hardening_ratio = hardening,
          .sharpness = n,
          .beta = beta_share * sum,
          .gamma = gamma_share * sum,
          .amplitude = amplitude};
}

inline std::vector<BoucWenShape> bouc_wen_shapes() {
  return {{"n = 1, beta = gamma", bouc_wen_shape(1.0, 0.5, 0.5, 0.05)},
          {"n = 1, gamma > beta", bouc_wen_shape(1.0, 0.1, 0.9, 0.0)},
          {"n = 1, gamma < 0", bouc_wen_shape(1.0, 1.5, -0.5, 0.1)},
          {"n = 2, beta = gamma", bouc_wen_shape(2.0, 0.5, 0.5, 0.05)},
          {"n = 1.25, gamma > beta", bouc_wen_shape(1.25, 0.1, 0.9, 0.02)},
          {"n = 2.5, gamma = 0, A = 2", bouc_wen_shape(2.5, 1.0, 0.0, 0.05, 2.0)},
          {"n = 10, beta > gamma", bouc_wen_shape(10.0, 0.75, 0.25, 0.05)},
          {"n = 25, gamma < 0", bouc_wen_shape(25.0, 1.2, -0.2, 0.0)}};
}

}  // namespace pound::testing
