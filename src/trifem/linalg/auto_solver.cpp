// SPDX-License-Identifier: MIT
#include "trifem/linalg/auto_solver.hpp"

#include "trifem/core/log.hpp"
#include "trifem/linalg/petsc_solver.hpp"
#include "trifem/linalg/sparse_lu_solver.hpp"

#include <optional>

namespace trifem::linalg {
namespace {

class AutoSolver final : public LinearSolver {
public:
  explicit AutoSolver(FactorPrecision precision) : precision_(precision) {}
  void analyze_pattern(const SparseMatrix& A) override {
    const bool small = A.rows() < kAutoSparseLuLimit && !fill_heavy_;
    if (!backend_ || small != small_)
      backend_ = small ? make_sparse_lu_solver() : make_mumps_solver("", true, precision_);
    if (tolerance_)
      backend_->set_relative_tolerance(*tolerance_);
    small_ = small;
    backend_->analyze_pattern(A);
  }
  bool factorize(const SparseMatrix& A) override {
    if (!backend_ || !backend_->factorize(A))
      return false;
    if (!small_ || A.rows() < kAutoFillCheckRows ||
        static_cast<Real>(backend_->factor_nonzeros()) <
            kAutoFillRatio * static_cast<Real>(A.nonZeros()))
      return true;
    // the factors of a 2-D or 3-D model: MUMPS from now on, for this pattern and later ones
    log::info("  linear solver: auto takes mumps reusing factorizations from here (SparseLU's "
              "factors hold {:.1f} times the nonzeros of the matrix of {} equations)",
              static_cast<Real>(backend_->factor_nonzeros()) / static_cast<Real>(A.nonZeros()),
              A.rows());
    fill_heavy_ = true;
    analyze_pattern(A);
    return backend_->factorize(A);
  }
  void set_relative_tolerance(Real tolerance) override {
    tolerance_ = tolerance;
    if (backend_)
      backend_->set_relative_tolerance(tolerance);
  }
  bool solve(const Vector& b, Vector& x) override { return backend_ && backend_->solve(b, x); }
  bool refine(const Vector& b, Vector& x) override { return backend_ && backend_->refine(b, x); }
  int last_iterations() const override { return backend_ ? backend_->last_iterations() : 0; }
  std::int64_t factor_nonzeros() const override {
    return backend_ ? backend_->factor_nonzeros() : 0;
  }
  std::string name() const override {
    return backend_ ? "auto (" + backend_->name() + ")" : "auto";
  }
  LinearSolverFailure failure() const override {
    return backend_ ? backend_->failure() : LinearSolverFailure{};
  }

private:
  const FactorPrecision precision_;
  std::unique_ptr<LinearSolver> backend_;
  bool small_ = false;
  std::optional<Real> tolerance_; ///< asked of MUMPS's FGMRES when it reuses factorizations
  bool fill_heavy_ = false;       ///< SparseLU's fill was measured too high: MUMPS at every size
};

} // namespace

std::unique_ptr<LinearSolver> make_auto_solver(FactorPrecision precision) {
  return std::make_unique<AutoSolver>(precision);
}

} // namespace trifem::linalg
