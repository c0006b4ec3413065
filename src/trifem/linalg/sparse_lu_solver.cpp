// SPDX-License-Identifier: MIT
#include "trifem/linalg/sparse_lu_solver.hpp"

#include "trifem/linalg/eigen_direct_solver.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>

namespace trifem::linalg {

std::unique_ptr<LinearSolver> make_sparse_lu_solver() {
  using Lu = Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<Index>>;
  return std::make_unique<EigenDirectSolver<Lu>>("sparselu");
}

} // namespace trifem::linalg
