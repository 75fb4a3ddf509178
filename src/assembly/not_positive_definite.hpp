#pragma once
// A factorization met a pivot that is not positive: the matrix is singular or indefinite at
// `equation`, which is how a DOF that nothing holds (no mass, no stiffness, a mechanism without
// mass) shows itself. The builder turns it into an error naming the node.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/types.hpp"

namespace pound::assembly {

// A pivot d_i at or below kLostPivot times its row's diagonal A_ii has lost all but about three
// of its digits to cancellation (its round-off, eps A_ii / d_i, is 0.2 % or more): the matrix is
// singular to double precision there, and the factorisations refuse it like a pivot that is not
// positive. Stiffnesses 1e13 times apart at one DOF do that (NASTRAN's MAXRATIO test of
// A_ii / d_i, whose default warns from 1e7); a pivot that passes is accurate to better than that.
inline constexpr double kLostPivot = 1e-13;
inline bool pivot_holds(double pivot, double diagonal) {
  return pivot > std::max(0.0, kLostPivot * diagonal) && !std::isnan(diagonal);
}

class NotPositiveDefinite : public std::domain_error {
 public:
  // `diagonal`: A_ii of the pivot's row, where the factorisation knows it.
  NotPositiveDefinite(Index equation, double pivot, double diagonal = NAN)
      : std::domain_error(
            std::isnan(diagonal)
                ? fmt::format("matrix is not positive definite at equation {} (pivot {:.3e})",
                              equation, pivot)
                : fmt::format("matrix is not positive definite at equation {} (pivot {:.3e} of "
                              "its diagonal {:.3e})",
                              equation, pivot, diagonal)),
        equation_(equation),
        pivot_(pivot),
        diagonal_(diagonal) {}
  Index equation() const { return equation_; }
  double pivot() const { return pivot_; }
  double diagonal() const { return diagonal_; }
  // The pivot is round-off of its diagonal (of either sign, or zero): cancelled, not negative.
  // Round-off's own size is a few eps A_ii, well inside 10 kLostPivot A_ii; a negative pivot past
  // that is a negative stiffness or mass.
  bool cancelled() const {
    return diagonal_ > 0.0 && std::isfinite(diagonal_) && std::isfinite(pivot_) &&
           std::abs(pivot_) <= 10.0 * kLostPivot * diagonal_;
  }

 private:
  Index equation_;
  double pivot_;
  double diagonal_;
};

}  // namespace pound::assembly
