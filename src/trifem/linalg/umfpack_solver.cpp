// SPDX-License-Identifier: MIT
#include "trifem/linalg/umfpack_solver.hpp"

#include "trifem/linalg/eigen_direct_solver.hpp"

#include <Eigen/UmfPackSupport>

namespace trifem::linalg {
namespace {

class UmfpackSolver final : public EigenDirectSolver<Eigen::UmfPackLU<SparseMatrix>> {
public:
  UmfpackSolver() : EigenDirectSolver("umfpack") {
    // Fill-reducing ordering: UMFPACK tries AMD/COLAMD and METIS and keeps the sparsest; the
    // symbolic analysis is done once per pattern, so the extra analysis time is amortised.
    lu_.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_BEST;
  }
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() {
  return std::make_unique<UmfpackSolver>();
}

} // namespace trifem::linalg
