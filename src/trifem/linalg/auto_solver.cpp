// SPDX-License-Identifier: MIT
#include "trifem/linalg/auto_solver.hpp"

#include "trifem/linalg/petsc_solver.hpp"
#include "trifem/linalg/sparse_lu_solver.hpp"

namespace trifem::linalg {
namespace {

class AutoSolver final : public LinearSolver {
public:
  void analyze_pattern(const SparseMatrix& A) override {
    const bool small = A.rows() < kAutoSparseLuLimit;
    if (!backend_ || small != small_)
      backend_ = small ? make_sparse_lu_solver() : make_mumps_solver("", true);
    small_ = small;
    backend_->analyze_pattern(A);
  }
  bool factorize(const SparseMatrix& A) override { return backend_ && backend_->factorize(A); }
  bool solve(const Vector& b, Vector& x) override { return backend_ && backend_->solve(b, x); }
  int last_iterations() const override { return backend_ ? backend_->last_iterations() : 0; }
  std::string name() const override {
    return backend_ ? "auto (" + backend_->name() + ")" : "auto";
  }
  LinearSolverFailure failure() const override {
    return backend_ ? backend_->failure() : LinearSolverFailure{};
  }

private:
  std::unique_ptr<LinearSolver> backend_;
  bool small_ = false;
};

} // namespace

std::unique_ptr<LinearSolver> make_auto_solver() {
  return std::make_unique<AutoSolver>();
}

} // namespace trifem::linalg
