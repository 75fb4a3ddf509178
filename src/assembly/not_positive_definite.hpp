#pragma once
// A factorization met a pivot that is not positive: the matrix is singular or indefinite at
// `equation`, which is how a DOF that nothing holds (no mass, no stiffness, a mechanism without
// mass) shows itself. The builder turns it into an error naming the node.
#include <fmt/format.h>

#include <stdexcept>

#include "core/types.hpp"

namespace pound::assembly {

class NotPositiveDefinite : public std::domain_error {
 public:
  NotPositiveDefinite(Index equation, double pivot)
      : std::domain_error(fmt::format(
            "matrix is not positive definite at equation {} (pivot {:.3e})", equation, pivot)),
        equation_(equation),
        pivot_(pivot) {}
  Index equation() const { return equation_; }
  double pivot() const { return pivot_; }

 private:
  Index equation_;
  double pivot_;
};

}  // namespace pound::assembly
