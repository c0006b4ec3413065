// SPDX-License-Identifier: MIT
#include "trifem/linalg/umfpack_solver.hpp"

#include <fmt/format.h>
#include <umfpack.h>

#include <array>
#include <vector>

namespace trifem::linalg {
namespace {

using Long = SuiteSparse_long;

/// UMFPACK through its 64-bit interface (umfpack_dl_*): the 32-bit one overflows its integer
/// workspace at a few 10^4 equations of the triphasic system.
class UmfpackSolver final : public LinearSolver {
public:
  UmfpackSolver() {
    umfpack_dl_defaults(control_.data());
    // Fill-reducing ordering: UMFPACK tries AMD/COLAMD and METIS and keeps the sparsest; the
    // symbolic analysis is done once per pattern, so the extra analysis time is amortised.
    control_[UMFPACK_ORDERING] = UMFPACK_ORDERING_BEST;
  }
  ~UmfpackSolver() override { release(); }
  UmfpackSolver(const UmfpackSolver&) = delete;
  UmfpackSolver& operator=(const UmfpackSolver&) = delete;

  void analyze_pattern(const SparseMatrix& A) override {
    release();
    failure_ = {};
    n_ = A.rows();
    col_start_.assign(A.outerIndexPtr(), A.outerIndexPtr() + A.cols() + 1);
    row_index_.assign(A.innerIndexPtr(), A.innerIndexPtr() + A.nonZeros());
    if (n_ == 0)
      return;
    const Long status =
        umfpack_dl_symbolic(n_, n_, col_start_.data(), row_index_.data(), A.valuePtr(), &symbolic_,
                            control_.data(), info_.data());
    if (status != UMFPACK_OK)
      fail("symbolic analysis", status);
  }

  bool factorize(const SparseMatrix& A) override {
    if (n_ == 0)
      return true;
    if (!symbolic_)
      return false; // the analysis failed: failure_ says why
    failure_ = {};
    if (numeric_)
      umfpack_dl_free_numeric(&numeric_);
    const Long status = umfpack_dl_numeric(col_start_.data(), row_index_.data(), A.valuePtr(),
                                           symbolic_, &numeric_, control_.data(), info_.data());
    values_ = A.valuePtr();
    if (status == UMFPACK_OK)
      return true;
    fail("numeric factorization", status);
    failure_.equation = empty_column(A);
    return false;
  }

  bool solve(const Vector& b, Vector& x) override {
    x.resize(n_);
    if (n_ == 0)
      return true;
    if (!numeric_)
      return false;
    const Long status =
        umfpack_dl_solve(UMFPACK_A, col_start_.data(), row_index_.data(), values_, x.data(),
                         b.data(), numeric_, control_.data(), info_.data());
    if (status == UMFPACK_OK && x.allFinite())
      return true;
    fail("solve", status);
    return false;
  }

  std::string name() const override { return "umfpack"; }
  LinearSolverFailure failure() const override { return failure_; }

private:
  void release() {
    if (numeric_)
      umfpack_dl_free_numeric(&numeric_);
    if (symbolic_)
      umfpack_dl_free_symbolic(&symbolic_);
    numeric_ = symbolic_ = nullptr;
  }

  /// Records why `what` failed, from UMFPACK's status and its memory estimate.
  void fail(const char* what, Long status) {
    const double unit = info_[UMFPACK_SIZE_OF_UNIT];
    const double peak_gb = info_[UMFPACK_PEAK_MEMORY_ESTIMATE] * unit / 1e9;
    failure_.permanent = status != UMFPACK_OK && status != UMFPACK_WARNING_singular_matrix;
    if (status == UMFPACK_WARNING_singular_matrix)
      failure_.reason = fmt::format("umfpack {}: the matrix is singular (a zero pivot)", what);
    else if (status == UMFPACK_ERROR_out_of_memory)
      failure_.reason = fmt::format(
          "umfpack {}: out of memory for the LU factors of {} equations (estimated peak {:.3g} "
          "GB); the model is too large for a direct solver on this machine",
          what, n_, peak_gb);
    else if (status == UMFPACK_OK)
      failure_.reason = fmt::format("umfpack {}: the solution is not finite", what);
    else
      failure_.reason = fmt::format("umfpack {} failed (UMFPACK status {})", what, status);
  }

  std::array<double, UMFPACK_CONTROL> control_{};
  std::array<double, UMFPACK_INFO> info_{};
  std::vector<Long> col_start_, row_index_;
  const Real* values_ = nullptr; // the matrix of the last factorization (for refinement)
  Long n_ = 0;
  void* symbolic_ = nullptr;
  void* numeric_ = nullptr;
  LinearSolverFailure failure_;
};

} // namespace

std::unique_ptr<LinearSolver> make_umfpack_solver() {
  return std::make_unique<UmfpackSolver>();
}

} // namespace trifem::linalg
