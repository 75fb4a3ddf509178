#pragma once
// Suzuki & Toi's two-element model (1987, section 2.3): masses m1, m2 on springs k1, k2 to
// fixed supports, joined by an extended-penalty contact (alpha0 spring, alpha2 mass). The
// program assembles it as any model (trusses, lumped masses, a link whose law supplies its
// tangents), solves the generalised eigenproblem K x = w^2 M x, and compares with the closed
// forms: eq. 4 (alpha0 only) and eqs. 23-24 (alpha0 and alpha2).
#include <vector>

namespace pound::verification {

struct TwoElementCase {
  double k1, k2, m1, m2, alpha0, alpha2;
};

struct TwoElementResult {
  TwoElementCase input;
  double omega1_squared, omega2_squared;                // the program's
  double closed_omega1_squared, closed_omega2_squared;  // eq. 4 or eqs. 23-24
  double exact_omega_squared;                           // merged body (k1 + k2) / (m1 + m2), eq. 2
  double relative_error;                                // largest of the two
};

TwoElementResult solve_two_element(const TwoElementCase& input);
// alpha0 / k1 in {1 .. 1e4}, alpha2 / (alpha0 (m1 + m2) / (k1 + k2)) in {0, 0.1, 1, 10},
// k2 / k1 in {1, 0.1, 3}, m2 / m1 in {1, 0.5, 4}.
std::vector<TwoElementResult> two_element_sweep();

}  // namespace pound::verification
