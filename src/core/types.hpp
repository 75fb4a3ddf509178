#pragma once
#include <Eigen/Core>
#include <cstddef>

namespace pound {
using Index = Eigen::Index;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
}  // namespace pound
