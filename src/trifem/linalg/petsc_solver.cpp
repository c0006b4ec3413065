// SPDX-License-Identifier: MIT
#include "trifem/linalg/petsc_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/linalg/nested_dissection.hpp"
#include "trifem/linalg/petsc_matrix.hpp"
#include "trifem/linalg/petsc_mpi_matrix.hpp"
#include "trifem/linalg/petsc_session.hpp"
#include "trifem/linalg/single_precision_lu.hpp"
#include "trifem/parallel/communicator.hpp"

#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace trifem::linalg {
namespace {

using petsc::check;

/// Factorization reuse: each solve reduces the residual to the tolerance Newton asks for
/// (kReuseTolerance until it asks) of the right-hand side with FGMRES preconditioned by the
/// last factorization; more than kRefactorAfter iterations make the next Newton iteration
/// factorize again, and a solve that has not converged after kMaxReuseIterations is repeated
/// with a new factorization.
constexpr double kReuseTolerance = 1e-10;
constexpr int kRefactorAfter = 8;
constexpr int kMaxReuseIterations = 15;
/// From this many iterations on, a solve preconditioned by an earlier factorization is stopped
/// (and repeated with a new one) as soon as the reduction so far, extrapolated geometrically,
/// would not reach its tolerance within kMaxReuseIterations.
constexpr int kRateCheckIterations = 3;

/// A factorization whose workspace estimate was too small (INFOG(1) = -8, -9, -14, -15, -17,
/// -20: pivots delayed by the numerical pivoting of the saddle-point rows need more room than
/// the analysis foresaw) is repeated with the relaxation ICNTL(14) doubled (at least
/// kMinWorkspacePercent), up to kMaxWorkspaceRetries times.
constexpr int kMaxWorkspaceRetries = 4;
constexpr PetscInt kMinWorkspacePercent = 50;

bool workspace_too_small(PetscInt infog1) {
  return infog1 == -8 || infog1 == -9 || infog1 == -14 || infog1 == -15 || infog1 == -17 ||
         infog1 == -20;
}

/// Reason and permanence of a MUMPS failure from its INFOG(1), INFOG(2).
LinearSolverFailure mumps_failure(PetscInt infog1, PetscInt infog2) {
  switch (infog1) {
  case -10:
    return {"MUMPS: the matrix is numerically singular (INFOG(1) = -10)", false};
  case -13:
    return {fmt::format("MUMPS could not allocate its workspace ({} {} of memory; INFOG(1) = "
                        "-13): the model is too large for this machine's memory",
                        infog2 < 0 ? -infog2 : infog2, infog2 < 0 ? "million bytes" : "bytes"),
            true};
  case -8:
  case -9:
  case -14:
  case -15:
  case -17:
  case -20:
    return {fmt::format("MUMPS: its workspace estimate was too small (INFOG(1) = {}) even after "
                        "{} retries with a doubled relaxation; raise it with petsc_options = "
                        "\"-mat_mumps_icntl_14 1000\"",
                        infog1, kMaxWorkspaceRetries),
            true};
  default:
    return {fmt::format("MUMPS failed with INFOG(1) = {}, INFOG(2) = {} (see the MUMPS users' "
                        "guide)",
                        infog1, infog2),
            infog1 < 0 && infog1 != -10};
  }
}

const char* pc_failure_text(PCFailedReason reason) {
  switch (reason) {
  case PC_FACTOR_STRUCT_ZEROPIVOT:
    return "structurally zero pivot";
  case PC_FACTOR_NUMERIC_ZEROPIVOT:
    return "numerically zero pivot (singular matrix)";
  case PC_FACTOR_OUTMEMORY:
    return "out of memory in the factorization";
  default:
    return "the factorization failed";
  }
}

/// MUMPS LU through a PETSc KSP of type preonly, on one process or (after set_hints with a
/// partition) on all the processes of the run, each giving its part of the matrix.
class MumpsSolver final : public LinearSolver {
public:
  MumpsSolver(const std::string& options, bool reuse, FactorPrecision precision)
      : options_(options), reuse_(reuse), fixed_tolerance_(options_.has("-ksp_rtol")),
        single_asked_(reuse && precision == FactorPrecision::single), single_(single_asked_) {}
  ~MumpsSolver() override { release(); }
  MumpsSolver(const MumpsSolver&) = delete;
  MumpsSolver& operator=(const MumpsSolver&) = delete;

  void analyze_pattern(const SparseMatrix& A) override {
    release();
    broken_ = false;
    failure_ = {};
    matrix_values_ = &A;
    n_ = static_cast<Index>(A.rows());
    if (n_ == 0)
      return;
    if (layout_) {
      analyze_distributed(A);
      return;
    }
    try {
      // METIS nested dissection unless the options choose a MUMPS ordering (ICNTL(7)); the
      // matrix is handed over permuted, and MUMPS keeps that order (PETSc's "natural")
      PetscBool mumps_orders = PETSC_FALSE;
      check(PetscOptionsHasName(nullptr, nullptr, "-mat_mumps_icntl_7", &mumps_orders),
            "PETSc options");
      order_.clear();
      if (!mumps_orders) // A's columns read as rows: the pattern of Aᵀ, the same graph
        order_ = nested_dissection_order({n_, A.outerIndexPtr(), A.innerIndexPtr()});
      matrix_ = std::make_unique<petsc::SeqAijMatrix>(A, order_);
      if (single_) {
        set_up_ksp(PETSC_COMM_SELF, matrix_->mat(), matrix_->mat(), nullptr);
        return;
      }
      if (reuse_)
        factored_matrix_ = std::make_unique<petsc::SeqAijMatrix>(A, order_);
      set_up_ksp(PETSC_COMM_SELF, matrix_->mat(), reuse_ ? factored_matrix_->mat() : nullptr,
                 mumps_orders ? MATORDERINGEXTERNAL : MATORDERINGNATURAL);
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), true};
      release();
    }
  }

  bool factorize(const SparseMatrix& A) override {
    if (n_ == 0)
      return true;
    matrix_values_ = &A;
    if (broken_) // a PETSc error left the KSP in an unknown state: set it up anew
      analyze_pattern(A);
    if (!ksp_)
      return false; // the set-up failed: failure_ says why
    failure_ = {};
    factored_ = false;
    try {
      update_matrix(A);           // same pattern: a numeric factorization only
      if (reuse_ && !refactor_) { // the last factorization preconditions this matrix
        check(KSPSetReusePreconditioner(ksp_, PETSC_TRUE), "PETSc KSP");
        stale_ = true;
        factored_ = true;
        return true;
      }
      return refactorize();
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), false};
      broken_ = true;
      return false;
    }
  }

  void set_relative_tolerance(Real tolerance) override {
    if (!fixed_tolerance_)
      reuse_tolerance_ = tolerance;
  }

  bool solve(const Vector& b, Vector& x) override { return solve_from(b, x, false); }

  bool refine(const Vector& b, Vector& x) override {
    const bool warm = reuse_ && !layout_ && x.size() == n_;
    return solve_from(b, x, warm);
  }

  void set_hints(const SystemHints& hints) override {
    layout_.reset();
    if (!hints.equation_owner.empty())
      layout_ = std::make_unique<petsc::RowLayout>(hints.equation_owner, parallel::rank(),
                                                   parallel::size());
    single_ = single_asked_ && !layout_; // SinglePrecisionLu runs on one process
  }

  std::string name() const override { return "mumps"; }
  int last_iterations() const override { return iterations_; }
  LinearSolverFailure failure() const override { return failure_; }

private:
  /// PETSc's default test, and the stop of a stale factorization's hopeless solve (from zero:
  /// the tolerance is relative to the first residual).
  static PetscErrorCode reuse_convergence_test(KSP ksp, PetscInt it, PetscReal rnorm,
                                               KSPConvergedReason* reason, void* context) {
    auto* self = static_cast<MumpsSolver*>(context);
    PetscCall(KSPConvergedDefault(ksp, it, rnorm, reason, self->default_test_));
    if (it == 0)
      self->first_residual_ = rnorm;
    if (*reason != KSP_CONVERGED_ITERATING || !self->check_rate_ || it < kRateCheckIterations)
      return 0;
    PetscReal rtol = 0.0, abstol = 0.0, dtol = 0.0;
    PetscInt max_it = 0;
    PetscCall(KSPGetTolerances(ksp, &rtol, &abstol, &dtol, &max_it));
    const Real reduction = rnorm / self->first_residual_;
    if (reduction >= 1.0 ||
        static_cast<Real>(it) * std::log(rtol) / std::log(reduction) > kMaxReuseIterations)
      *reason = KSP_DIVERGED_ITS;
    return 0;
  }

  /// The solve repeated after a new factorization (its vectors may be new: a workspace retry or
  /// the turn to double precision sets the KSP up anew), its iterations added to iterations_.
  void solve_again(const Vector& b, KSPConvergedReason& reason, PetscInt& iterations) {
    to_petsc(b);
    check(KSPSolve(ksp_, b_, x_), "MUMPS solve");
    check(KSPGetConvergedReason(ksp_, &reason), "PETSc KSP");
    check(KSPGetIterationNumber(ksp_, &iterations), "PETSc KSP");
    iterations_ += static_cast<int>(iterations);
  }

  /// A solve (reusing: FGMRES from zero, or with `warm` from x).
  bool solve_from(const Vector& b, Vector& x, bool warm) {
    if (!warm)
      x.resize(n_);
    if (n_ == 0)
      return true;
    if (!factored_)
      return false;
    try {
      to_petsc(b);
      if (warm)
        petsc::set_vector(x_, x, order_);
      if (reuse_)
        check(KSPSetInitialGuessNonzero(ksp_, warm ? PETSC_TRUE : PETSC_FALSE), "PETSc KSP");
      if (reuse_ && !fixed_tolerance_)
        petsc::set_relative_tolerance(ksp_, reuse_tolerance_);
      check_rate_ = stale_ && !warm;
      check(KSPSolve(ksp_, b_, x_), "MUMPS solve");
      KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
      check(KSPGetConvergedReason(ksp_, &reason), "PETSc KSP");
      if (reuse_) {
        PetscInt iterations = 0;
        check(KSPGetIterationNumber(ksp_, &iterations), "PETSc KSP");
        iterations_ = static_cast<int>(iterations);
        if (reason < 0 && stale_) { // the old factorization no longer serves: a new one
          check_rate_ = false;
          if (!refactorize())
            return false;
          solve_again(b, reason, iterations);
        }
        if (reason < 0 && single_) { // a fresh single-precision factorization does not serve
          PetscReal residual = 0.0;
          check(KSPGetResidualNorm(ksp_, &residual), "PETSc KSP");
          if (!factorize_in_double_precision(
                  fmt::format("FGMRES preconditioned by a new single-precision factorization "
                              "stopped at a residual of {:.2e} after {} iterations",
                              residual, iterations)))
            return false;
          solve_again(b, reason, iterations);
        }
        refactor_ = iterations > kRefactorAfter; // cheaper to factorize again next time
      }
      if (reason < 0) {
        failure_ = {fmt::format("MUMPS solve failed ({})", KSPConvergedReasons[reason]), false};
        return false;
      }
      from_petsc(x);
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), false};
      broken_ = true;
      return false;
    }
    if (x.allFinite())
      return true;
    failure_ = {"MUMPS solve gave non-finite values", false};
    return false;
  }

  /// The set-up on several processes: a distributed matrix, MUMPS's own (parallel) analysis.
  void analyze_distributed(const SparseMatrix& A) {
    try {
      mpi_matrix_ = std::make_unique<petsc::MpiAijMatrix>(A, *layout_);
      const Real entries = parallel::sum(static_cast<Real>(mpi_matrix_->entries()));
      const Real sent = parallel::sum(static_cast<Real>(mpi_matrix_->sent_entries()));
      const std::string text =
          fmt::format("  distributed matrix: {} rows on {} processes; {:.0f} of the {:.0f} entries "
                      "assembled ({:.1f} %) go to another process",
                      layout_->rows(), parallel::size(), sent, entries, 100.0 * sent / entries);
      if (told_) // after a change of pattern (contact)
        log::debug("{}", text);
      else
        log::info("{}", text);
      told_ = true;
      if (reuse_)
        mpi_factored_ = std::make_unique<petsc::MpiAijMatrix>(A, *layout_);
      set_up_ksp(PETSC_COMM_WORLD, mpi_matrix_->mat(), reuse_ ? mpi_factored_->mat() : nullptr,
                 nullptr);
      gather_ = std::make_unique<petsc::Gather>(x_);
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), true};
      release();
    }
  }

  /// The vectors and the KSP on `comm`: MUMPS LU of `A`, or with `factored` (reuse) FGMRES on
  /// `A` preconditioned by the LU of `factored`. `ordering`: PETSc's ordering type (null: MUMPS's
  /// own choice).
  void set_up_ksp(MPI_Comm comm, Mat A, Mat factored, MatOrderingType ordering) {
    check(MatCreateVecs(A, &x_, &b_), "PETSc vectors");
    check(KSPCreate(comm, &ksp_), "PETSc KSP");
    if (factored) { // FGMRES on the current matrix, preconditioned by the last factorization
      check(KSPSetOperators(ksp_, A, factored), "PETSc KSP operators");
      check(KSPSetType(ksp_, KSPFGMRES), "PETSc KSP type");
      check(KSPGMRESSetRestart(ksp_, kMaxReuseIterations), "PETSc GMRES restart");
      check(KSPSetTolerances(ksp_, kReuseTolerance, 0.0, PETSC_DEFAULT, kMaxReuseIterations),
            "PETSc KSP tolerances");
      void* default_test = nullptr;
      check(KSPConvergedDefaultCreate(&default_test), "PETSc KSP");
      default_test_ = default_test;
      check(KSPSetConvergenceTest(ksp_, reuse_convergence_test, this, nullptr),
            "PETSc KSP convergence test");
    } else {
      check(KSPSetOperators(ksp_, A, A), "PETSc KSP operators");
      check(KSPSetType(ksp_, KSPPREONLY), "PETSc KSP type");
    }
    refactor_ = true;
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "PETSc PC");
    if (single_) { // the single-precision factors, applied by a shell
      check(PCSetType(pc, PCSHELL), "PETSc PC type");
      check(PCShellSetContext(pc, this), "PETSc PC");
      check(PCShellSetApply(pc, apply_single_precision_lu), "PETSc PC");
      check(KSPSetFromOptions(ksp_), "PETSc options");
      return;
    }
    check(PCSetType(pc, PCLU), "PETSc PC type");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "MUMPS");
    if (ordering)
      check(PCFactorSetMatOrderingType(pc, ordering), "PETSc ordering");
    check(KSPSetFromOptions(ksp_), "PETSc options");
    if (workspace_percent_ > 0) { // a retry after a too small workspace
      Mat factor = nullptr;
      check(PCFactorSetUpMatSolverType(pc), "MUMPS");
      check(PCFactorGetMatrix(pc, &factor), "MUMPS");
      check(MatMumpsSetIcntl(factor, 14, workspace_percent_), "MUMPS ICNTL(14)");
    }
  }

  /// The values of A in the matrix PETSc solves with.
  void update_matrix(const SparseMatrix& A) {
    if (layout_)
      mpi_matrix_->update(A);
    else
      matrix_->update(A);
  }

  void to_petsc(const Vector& b) {
    if (layout_)
      petsc::set_vector(b_, b, *layout_);
    else
      petsc::set_vector(b_, b, order_);
  }

  void from_petsc(Vector& x) {
    if (layout_)
      (*gather_)(x_, x, *layout_);
    else
      petsc::get_vector(x_, x, order_);
  }

  /// A new numeric factorization of the current matrix, repeated with a larger workspace while
  /// MUMPS reports its estimate too small.
  bool refactorize() {
    for (int retry = 0;; ++retry) {
      if (factorize_once())
        return true;
      if (!workspace_failed_ || retry == kMaxWorkspaceRetries || matrix_values_ == nullptr)
        return false;
      workspace_percent_ = std::max(kMinWorkspacePercent, 2 * workspace_used_);
      log::info("  MUMPS: workspace estimate too small (INFOG(1) = {}); factorizing again with "
                "ICNTL(14) = {} %",
                workspace_infog_, workspace_percent_);
      const PetscInt percent = workspace_percent_;
      analyze_pattern(*matrix_values_); // a new analysis: MUMPS keeps a failed state otherwise
      workspace_percent_ = percent;
      if (!ksp_)
        return false;
    }
  }

  static PetscErrorCode apply_single_precision_lu(PC pc, Vec b, Vec x) {
    void* context = nullptr;
    PetscCall(PCShellGetContext(pc, &context));
    auto* self = static_cast<MumpsSolver*>(context);
    const PetscScalar* from = nullptr;
    PetscScalar* to = nullptr;
    PetscCall(VecGetArrayRead(b, &from));
    PetscCall(VecGetArray(x, &to));
    const bool solved = self->single_lu_->solve(from, to);
    PetscCall(VecRestoreArray(x, &to));
    PetscCall(VecRestoreArrayRead(b, &from));
    return solved ? 0 : PETSC_ERR_LIB;
  }

  /// For the rest of the run: factorizations in double precision (the matrix is too badly
  /// conditioned for single precision: `why`), beginning with one of the current matrix.
  bool factorize_in_double_precision(const std::string& why) {
    log::info("  MUMPS: {}; factorizing in double precision from here", why);
    single_ = false;
    analyze_pattern(*matrix_values_);
    if (!ksp_)
      return false;
    check_rate_ = false;
    return refactorize();
  }

  /// One numeric factorization in single precision.
  bool factorize_single() {
    const PetscScalar* values = nullptr;
    check(MatSeqAIJGetArrayRead(matrix_->mat(), &values), "PETSc matrix");
    bool done = true;
    if (!single_lu_) {
      single_lu_ = std::make_unique<SinglePrecisionLu>();
      const auto& pattern = matrix_->pattern();
      done = single_lu_->analyze(n_, pattern.row_start.data(), pattern.column.data(), values);
    }
    done = done && single_lu_->factorize(values);
    check(MatSeqAIJRestoreArrayRead(matrix_->mat(), &values), "PETSc matrix");
    if (!done) {
      const PetscInt infog1 = single_lu_->infog1(), infog2 = single_lu_->infog2();
      single_lu_.reset();
      if (infog1 == -13) { // out of memory: double precision would need more
        failure_ = mumps_failure(infog1, infog2);
        return false;
      }
      return factorize_in_double_precision(fmt::format(
          "the single-precision factorization failed ({})", mumps_failure(infog1, infog2).reason));
    }
    refactor_ = stale_ = false;
    factored_ = true;
    return true;
  }

  /// One numeric factorization of the current matrix.
  bool factorize_once() {
    if (single_)
      return factorize_single();
    workspace_failed_ = false;
    if (reuse_ && layout_) {
      mpi_factored_->assign_values(*mpi_matrix_);
      check(KSPSetReusePreconditioner(ksp_, PETSC_FALSE), "PETSc KSP");
    } else if (reuse_) {
      factored_matrix_->assign_values(*matrix_);
      check(KSPSetReusePreconditioner(ksp_, PETSC_FALSE), "PETSc KSP");
    }
    check(KSPSetUp(ksp_), "PETSc KSP set-up");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "PETSc PC");
    check(PCSetUp(pc), "MUMPS factorization"); // KSPSetUp runs it only the first time
    PCFailedReason reason = PC_NOERROR;
    check(PCGetFailedReason(pc, &reason), "PETSc PC");
    if (reason != PC_NOERROR) {
      failure_ = factor_failure(pc, reason);
      broken_ = true; // MUMPS keeps the failed factors: set up anew before the next matrix
      return false;
    }
    workspace_percent_ = 0; // later analyses start from MUMPS's own estimate again
    refactor_ = stale_ = false;
    factored_ = true;
    return true;
  }

  LinearSolverFailure factor_failure(PC pc, PCFailedReason reason) {
    Mat factor = nullptr;
    PetscInt infog1 = 0, infog2 = 0;
    if (PCFactorGetMatrix(pc, &factor) == 0 && factor != nullptr &&
        MatMumpsGetInfog(factor, 1, &infog1) == 0 && MatMumpsGetInfog(factor, 2, &infog2) == 0 &&
        infog1 < 0) {
      workspace_failed_ = workspace_too_small(infog1);
      workspace_infog_ = infog1;
      if (MatMumpsGetIcntl(factor, 14, &workspace_used_) != 0)
        workspace_used_ = 20;
      return mumps_failure(infog1, infog2);
    }
    return {fmt::format("MUMPS: {}", pc_failure_text(reason)), reason == PC_FACTOR_OUTMEMORY};
  }

  void release() {
    if (ksp_)
      KSPDestroy(&ksp_);
    if (default_test_)
      KSPConvergedDefaultDestroy(default_test_);
    default_test_ = nullptr;
    if (x_)
      VecDestroy(&x_);
    if (b_)
      VecDestroy(&b_);
    gather_.reset();
    single_lu_.reset();
    matrix_.reset();
    factored_matrix_.reset();
    mpi_matrix_.reset();
    mpi_factored_.reset();
    ksp_ = nullptr;
    x_ = b_ = nullptr;
    factored_ = false;
  }

  petsc::ScopedOptions options_; // first: the options outlive the PETSc objects
  Index n_ = 0;
  std::vector<Index> order_; ///< row and column order[i] of A is row and column i for MUMPS
  std::unique_ptr<petsc::SeqAijMatrix> matrix_;
  std::unique_ptr<petsc::SeqAijMatrix> factored_matrix_; ///< values last factorized (reuse)
  std::unique_ptr<petsc::RowLayout> layout_;             ///< on several processes: the rows of each
  std::unique_ptr<petsc::MpiAijMatrix> mpi_matrix_, mpi_factored_; ///< ... and the matrices
  std::unique_ptr<petsc::Gather> gather_; ///< ... and the gathering of the solution
  bool told_ = false;                     ///< the distributed matrix's size was logged
  bool reuse_ = false;         ///< precondition later matrices with an earlier factorization
  const bool fixed_tolerance_; ///< -ksp_rtol among the options: it wins
  Real reuse_tolerance_ = kReuseTolerance; ///< of the FGMRES solves when reusing (forcing term)
  bool refactor_ = true;                   ///< the next factorize() factorizes
  const bool single_asked_; ///< reusing: factorize in single precision where possible
  bool single_;             ///< ... and here (on one process)
  std::unique_ptr<SinglePrecisionLu> single_lu_;
  bool stale_ = false; ///< the factorization in use is of an earlier matrix
  int iterations_ = 0;
  void* default_test_ = nullptr; ///< the context of PETSc's default convergence test (reuse)
  PetscReal first_residual_ = 0.0;
  bool check_rate_ = false; ///< the solve under way may stop early (reuse_convergence_test)
  Vec x_ = nullptr, b_ = nullptr;
  KSP ksp_ = nullptr;
  bool factored_ = false; ///< the symbolic analysis runs with the first factorization
  /// A factorization failed or a PETSc error interrupted a solve: PETSc's objects may be left
  /// mid-operation (a KSPSolve without its PCPostSolve, after which every later solve fails;
  /// failed factors that a reused preconditioner would apply, INFOG(1) = -3), so the next
  /// factorize() sets them up anew.
  bool broken_ = false;
  const SparseMatrix* matrix_values_ = nullptr; ///< the last matrix given (alive while in use)
  PetscInt workspace_percent_ = 0; ///< ICNTL(14) of the next set-up (0: MUMPS's default)
  bool workspace_failed_ = false;  ///< the last factorization ran out of its estimated workspace
  PetscInt workspace_infog_ = 0;   ///< its INFOG(1)
  PetscInt workspace_used_ = 20;   ///< the ICNTL(14) it had
  LinearSolverFailure failure_;
};

/// Solves a 2×2 system with a solver made with `options` (reusing factorizations or not: the
/// FGMRES of reuse reads -ksp_* options), then refuses options nobody read.
void check_options_are_used(const std::string& options, bool reuse, FactorPrecision precision) {
  if (reuse && precision == FactorPrecision::single &&
      options.find("-mat_mumps_") != std::string::npos)
    throw InputError(fmt::format("solver.petsc_options = '{}': the -mat_mumps_* options set "
                                 "MUMPS in double precision, but reused factorizations are in "
                                 "single precision; add factorization_precision = \"double\"",
                                 options));
  SparseMatrix A(2, 2);
  A.insert(0, 0) = 2.0;
  A.insert(1, 0) = 1.0;
  A.insert(1, 1) = 3.0;
  A.makeCompressed();
  MumpsSolver probe(options, reuse, precision);
  probe.analyze_pattern(A);
  Vector x;
  if (!probe.factorize(A) || !probe.solve(Vector::Ones(2), x))
    throw InputError(fmt::format("solver.petsc_options = '{}': a 2x2 test system failed with "
                                 "these options: {}",
                                 options, probe.failure().reason));
  petsc::refuse_unused_options(options, "mumps");
}

} // namespace

std::unique_ptr<LinearSolver> make_mumps_solver(const std::string& petsc_options,
                                                bool reuse_factorization,
                                                FactorPrecision precision) {
  if (!petsc_options.empty())
    check_options_are_used(petsc_options, reuse_factorization, precision);
  return std::make_unique<MumpsSolver>(petsc_options, reuse_factorization, precision);
}

} // namespace trifem::linalg
