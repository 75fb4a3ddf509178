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

// P A P^T with (P A P^T)(k, l) = A(order[k], order[l]). `order` may list a subset of the
// equations: the principal submatrix on them, in that order.
Eigen::SparseMatrix<double> permuted(const Eigen::SparseMatrix<double>& matrix,
                                     const std::vector<Index>& order);

// Each equation's connected component in the matrix's graph (numbered 0, 1, ...) and how many
// there are: structures that only unfolded links join (two buildings that pound) are apart.
struct Components {
  std::vector<int> of;
  int count = 0;
};
Components connected_components(const Eigen::SparseMatrix<double>& matrix);

}  // namespace pound::assembly
