#pragma once
// Renumbering the equations for a narrow band: the reverse Cuthill-McKee order of a symmetric
// sparse matrix (Boost Graph's cuthill_mckee_ordering). The model numbers DOFs element chain by
// element chain; link rows folded into the factored matrix (integrators/newmark.hpp) join DOFs
// of different chains, a bearing's girder end and pier top, which that numbering puts far apart.
#include <Eigen/SparseCore>
#include <vector>

#include "core/types.hpp"

namespace pound::assembly {

// order[k] is the equation that comes k-th (a permutation of 0 .. n - 1).
std::vector<Index> reverse_cuthill_mckee(const Eigen::SparseMatrix<double>& matrix);

// P A P^T with (P A P^T)(k, l) = A(order[k], order[l]).
Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& matrix,
                                     const std::vector<Index>& order);

}  // namespace pound::assembly
