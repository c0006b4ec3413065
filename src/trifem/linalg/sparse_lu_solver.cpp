// SPDX-License-Identifier: MIT
#include "trifem/linalg/sparse_lu_solver.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseLU>

namespace trifem::linalg {
namespace {

class SparseLuSolver final : public LinearSolver {
public:
  void analyze_pattern(const SparseMatrix& A) override { lu_.analyzePattern(A); }
  bool factorize(const SparseMatrix& A) override {
    lu_.factorize(A);
    return lu_.info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x) override {
    x = lu_.solve(b);
    return lu_.info() == Eigen::Success && x.allFinite();
  }
  std::string name() const override { return "sparselu"; }

private:
  Eigen::SparseLU<SparseMatrix, Eigen::COLAMDOrdering<Index>> lu_;
};

} // namespace

std::unique_ptr<LinearSolver> make_sparse_lu_solver() {
  return std::make_unique<SparseLuSolver>();
}

} // namespace trifem::linalg
