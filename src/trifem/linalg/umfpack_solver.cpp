// SPDX-License-Identifier: MIT
#include "trifem/linalg/umfpack_solver.hpp"

#include <Eigen/UmfPackSupport>

namespace trifem::linalg {
namespace {

class UmfpackSolver final : public LinearSolver {
public:
  UmfpackSolver() {
    // Fill-reducing ordering: UMFPACK tries AMD/COLAMD and METIS and keeps the sparsest; the
    // symbolic analysis is done once per pattern, so the extra analysis time is amortised.
    lu_.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_BEST;
  }
  void analyze_pattern(const SparseMatrix& A) override { lu_.analyzePattern(A); }
  bool factorize(const SparseMatrix& A) override {
    lu_.factorize(A);
    return lu_.info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x) override {
    x = lu_.solve(b);
    return lu_.info() == Eigen::Success && x.allFinite();
  }
  std::string name() const override { return "umfpack"; }

private:
  Eigen::UmfPackLU<SparseMatrix> lu_;
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() {
  return std::make_unique<UmfpackSolver>();
}

} // namespace trifem::linalg
