// SPDX-License-Identifier: MIT
#include "trifem/linalg/krylov_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/linalg/block_split.hpp"
#include "trifem/linalg/drained_schur.hpp"
#include "trifem/linalg/petsc_matrix.hpp"
#include "trifem/linalg/petsc_session.hpp"

#include <fmt/format.h>
#include <petscksp.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>

namespace trifem::linalg {
namespace {

using petsc::check;

/// An index set of `indices` (PETSc copies them).
IS make_index_set(const std::vector<Index>& indices) {
  std::vector<PetscInt> values(indices.begin(), indices.end());
  IS is = nullptr;
  check(ISCreateGeneral(PETSC_COMM_SELF, static_cast<PetscInt>(values.size()), values.data(),
                        PETSC_COPY_VALUES, &is),
        "PETSc index set");
  return is;
}

/// Positions of `subset` within the ascending list `all`.
std::vector<Index> positions_in(const std::vector<Index>& subset, const std::vector<Index>& all) {
  std::vector<Index> at;
  at.reserve(subset.size());
  for (Index i : subset)
    at.push_back(static_cast<Index>(std::lower_bound(all.begin(), all.end(), i) - all.begin()));
  return at;
}

/// `ksp` applies the preconditioner `type` once (a direct solve for PCLU, with MUMPS).
PC apply_once(KSP ksp, PCType type) {
  PC pc = nullptr;
  check(KSPSetType(ksp, KSPPREONLY), "PETSc KSP type");
  check(KSPGetPC(ksp, &pc), "PETSc PC");
  check(PCSetType(pc, type), "PETSc PC type");
  if (std::string(type) == PCLU)
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "MUMPS");
  return pc;
}

/// The columns of `modes` restricted to the rows `rows` and orthonormalized (modified
/// Gram–Schmidt; a column that adds nothing is dropped).
std::vector<Vector> orthonormal_restriction(const std::vector<Vector>& modes,
                                            const std::vector<Index>& rows) {
  std::vector<Vector> basis;
  for (const Vector& mode : modes) {
    Vector v(static_cast<Index>(rows.size()));
    for (std::size_t i = 0; i < rows.size(); ++i)
      v[static_cast<Index>(i)] = mode[rows[i]];
    const Real size = v.norm();
    for (const Vector& q : basis)
      v -= q.dot(v) * q;
    if (size > 0.0 && v.norm() > 1e-8 * size)
      basis.push_back(v / v.norm());
  }
  return basis;
}

/// Gives `matrix` the near-null space `basis` (orthonormal vectors over its rows), which
/// GAMG builds its coarse spaces from.
void attach_near_null_space(Mat matrix, const std::vector<Vector>& basis) {
  if (basis.empty())
    return;
  std::vector<Vec> vectors(basis.size(), nullptr);
  for (std::size_t k = 0; k < basis.size(); ++k) {
    check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(basis[k].size()), &vectors[k]),
          "PETSc vector");
    PetscScalar* values = nullptr;
    check(VecGetArray(vectors[k], &values), "PETSc vector");
    std::copy(basis[k].data(), basis[k].data() + basis[k].size(), values);
    check(VecRestoreArray(vectors[k], &values), "PETSc vector");
  }
  MatNullSpace space = nullptr;
  check(MatNullSpaceCreate(PETSC_COMM_SELF, PETSC_FALSE, static_cast<PetscInt>(vectors.size()),
                           vectors.data(), &space),
        "PETSc near-null space");
  check(MatSetNearNullSpace(matrix, space), "PETSc near-null space");
  MatNullSpaceDestroy(&space);
  for (Vec& v : vectors)
    VecDestroy(&v);
}

/// `ksp` is preconditioned by smoothed-aggregation multigrid (GAMG) whose coarse spaces carry
/// `near_null` (the rigid-body modes of the rows of its matrix).
void use_multigrid(KSP ksp, const std::vector<Vector>& near_null) {
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "PETSc PC");
  check(PCSetType(pc, PCGAMG), "PETSc PC type");
  PetscReal threshold = 0.01; // drop weak couplings when aggregating (GAMG's graph)
  check(PCGAMGSetThreshold(pc, &threshold, 1), "PETSc GAMG");
  Mat operators = nullptr, preconditioning = nullptr;
  check(KSPGetOperators(ksp, &operators, &preconditioning), "PETSc KSP operators");
  attach_near_null_space(preconditioning, near_null);
}

/// `ksp` applies one V-cycle of use_multigrid.
void apply_multigrid(KSP ksp, const std::vector<Vector>& near_null) {
  check(KSPSetType(ksp, KSPPREONLY), "PETSc KSP type");
  use_multigrid(ksp, near_null);
}

/// Options prefix of the solver of the drained Schur approximation's augmented system.
constexpr const char* kDrainedSchurPrefix = "drained_schur_";

/// Largest system for which "amg" repeats a failed solve with the LU blocks: their memory
/// grows faster than the model's (a 405 000-equation block grew from 11 to 19 GB).
constexpr Index kLuFallbackLimit = 100000;

/// Iterations a multigrid solve gets before it is repeated with the LU blocks (unless the
/// options fix -ksp_max_it): multigrid solves that converge take 25-60 (docs/performance.md),
/// and one on an indefinite displacement block crawls (570 to 1e-4 on the 8^3 block).
constexpr int kMultigridAttempt = 200;

/// FGMRES preconditioned by a Schur-complement fieldsplit (or by one preconditioner for a
/// system of one kind).
class KrylovSolver final : public LinearSolver {
public:
  KrylovSolver(const std::string& options, KrylovSettings settings)
      : options_(options), settings_(settings), tolerance_(settings.relative_tolerance),
        fixed_tolerance_(options_.has("-ksp_rtol")),
        fixed_iterations_(options_.has("-ksp_max_it")) {}
  ~KrylovSolver() override { release(); }
  KrylovSolver(const KrylovSolver&) = delete;
  KrylovSolver& operator=(const KrylovSolver&) = delete;

  void set_hints(const SystemHints& hints) override {
    LinearSolver::set_hints(hints); // one process only
    split_ = BlockSplit::from_fields(hints.equation_fields, hints.field_roles);
    hints_ = hints;
    fallback_.reset();
  }

  bool wants_transport_cells() const override {
    return settings_.schur == SchurApproximation::drained && !split_.flux.empty() &&
           !split_.potential.empty();
  }

  void set_transport_cells(TransportCells cells) override { cells_ = std::move(cells); }

  void set_relative_tolerance(Real tolerance) override {
    if (fixed_tolerance_)
      return;
    tolerance_ = tolerance;
    if (fallback_)
      fallback_->set_relative_tolerance(tolerance_);
  }

  void analyze_pattern(const SparseMatrix& A) override {
    release();
    fallback_.reset(); // set up for the old pattern
    broken_ = false;
    failure_ = {};
    n_ = static_cast<Index>(A.rows());
    if (n_ == 0)
      return;
    if (split_.empty() || static_cast<Index>(split_.displacement.size() + split_.flux.size() +
                                             split_.potential.size()) != n_)
      split_ = BlockSplit{}; // no (matching) field information: one block
    try {
      set_up(A);
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), true};
      release();
    }
  }

  bool factorize(const SparseMatrix& A) override {
    if (n_ == 0)
      return true;
    if (broken_) // a PETSc error left the KSP in an unknown state: set it up anew
      analyze_pattern(A);
    if (!ksp_)
      return false; // the set-up failed: failure_ says why
    failure_ = {};
    ready_ = false;
    matrix_values_ = &A;
    fallback_ready_ = false;
    try {
      matrix_->update(A, row_sign_);
      check(KSPSetUp(ksp_), "PETSc KSP set-up");
      PC pc = nullptr;
      check(KSPGetPC(ksp_, &pc), "PETSc PC");
      check(PCSetUp(pc), "preconditioner set-up");
      if (!sub_solvers_configured_)
        configure_sub_solvers(pc);
      if (drained_)
        factorize_drained_schur(A);
      ready_ = true;
      return true;
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), false};
      broken_ = true;
      return false;
    }
  }

  bool solve(const Vector& b, Vector& x) override { return solve_from(b, x, false); }

  bool refine(const Vector& b, Vector& x) override {
    return x.size() == n_ ? solve_from(b, x, true) : solve(b, x);
  }

  std::string name() const override { return "krylov"; }
  LinearSolverFailure failure() const override { return failure_; }
  int last_iterations() const override { return iterations_; }

private:
  /// A solve from zero, or (`warm`) from x.
  bool solve_from(const Vector& b, Vector& x, bool warm) {
    if (!warm)
      x.resize(n_);
    if (n_ == 0)
      return true;
    if (!ready_)
      return false;
    if (fallback_ready_) { // multigrid failed on this matrix already
      failure_ = {};
      iterations_ = 0;
      return solve_with_lu_blocks(b, x, warm);
    }
    try {
      petsc::set_vector(b_, b, {}, row_sign_);
      if (warm)
        petsc::set_vector(x_, x);
      check(KSPSetInitialGuessNonzero(ksp_, warm ? PETSC_TRUE : PETSC_FALSE), "PETSc KSP");
      if (!fixed_tolerance_)
        petsc::set_relative_tolerance(ksp_, tolerance_);
      if (can_fall_back() && !fixed_iterations_) // with the LU blocks to fall back on
        petsc::set_max_iterations(ksp_, std::min(settings_.max_iterations, kMultigridAttempt));
      check(KSPSolve(ksp_, b_, x_), "Krylov solve");
      KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
      check(KSPGetConvergedReason(ksp_, &reason), "PETSc KSP");
      PetscInt iterations = 0;
      check(KSPGetIterationNumber(ksp_, &iterations), "PETSc KSP");
      iterations_ = static_cast<int>(iterations);
      if (reason < 0) {
        failure_ = {not_converged(reason), false};
        return can_fall_back() && solve_with_lu_blocks(b, x, warm);
      }
      petsc::get_vector(x_, x);
    } catch (const petsc::PetscError& e) {
      failure_ = {e.what(), false};
      broken_ = true;
      return false;
    }
    if (x.allFinite())
      return true;
    failure_ = {"the Krylov solve gave non-finite values", false};
    return false;
  }

  void set_up(const SparseMatrix& A) {
    const bool blocks = !split_.potential.empty() && split_.potential.size() < std::size_t(n_);
    row_sign_.clear();
    if (blocks) { // potential rows negated: the Schur complement becomes positive
      row_sign_.assign(n_, 1.0);
      for (Index q : split_.potential)
        row_sign_[q] = -1.0;
    }
    matrix_ = std::make_unique<petsc::SeqAijMatrix>(A);
    check(MatCreateVecs(matrix_->mat(), &x_, &b_), "PETSc vectors");
    check(KSPCreate(PETSC_COMM_SELF, &ksp_), "PETSc KSP");
    check(KSPSetOperators(ksp_, matrix_->mat(), matrix_->mat()), "PETSc KSP operators");
    check(KSPSetType(ksp_, KSPFGMRES), "PETSc KSP type");
    check(KSPGMRESSetRestart(ksp_, 100), "PETSc GMRES restart");
    check(KSPSetTolerances(ksp_, settings_.relative_tolerance, 0.0, PETSC_DEFAULT,
                           settings_.max_iterations),
          "PETSc KSP tolerances");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "PETSc PC");
    transport_split_ = wants_transport_cells() && !split_.displacement.empty() && !has_contact();
    if (transport_split_) {
      split_displacement_from_transport(pc);
    } else if (blocks) {
      primal_ = split_.primal();
      schur_split(pc, {"primal", primal_}, {"potential", split_.potential},
                  PC_FIELDSPLIT_SCHUR_PRE_SELFP);
    } else if (amg()) { // one kind of unknown: the displacement
      use_multigrid(ksp_, modes_over(all_equations()));
      sub_solvers_configured_ = true;
    } else {
      check(PCSetType(pc, PCLU), "PETSc PC type");
      check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "MUMPS");
      sub_solvers_configured_ = true;
    }
    check(KSPSetFromOptions(ksp_), "PETSc options");
  }

  /// The drained approximation's fieldsplit: the displacement, then the transport block
  /// (fluxes and potentials) through its Schur complement, which the shell of
  /// use_drained_schur approximates (no product is formed for it: A11 is its matrix).
  void split_displacement_from_transport(PC pc) {
    transport_.clear();
    std::merge(split_.flux.begin(), split_.flux.end(), split_.potential.begin(),
               split_.potential.end(), std::back_inserter(transport_));
    transport_flux_ = positions_in(split_.flux, transport_);
    transport_potential_ = positions_in(split_.potential, transport_);
    schur_split(pc, {"displacement", split_.displacement}, {"transport", transport_},
                PC_FIELDSPLIT_SCHUR_PRE_A11);
  }

  using NamedSplit = std::pair<const char*, const std::vector<Index>&>;

  /// `pc` becomes a fieldsplit of `first` and `second` in the full Schur factorization, the
  /// Schur complement's preconditioning matrix `pre`.
  static void schur_split(PC pc, NamedSplit first, NamedSplit second,
                          PCFieldSplitSchurPreType pre) {
    check(PCSetType(pc, PCFIELDSPLIT), "PETSc fieldsplit");
    for (const NamedSplit& split : {first, second}) {
      IS is = make_index_set(split.second);
      check(PCFieldSplitSetIS(pc, split.first, is), "PETSc fieldsplit");
      ISDestroy(&is);
    }
    check(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR), "PETSc fieldsplit");
    check(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_FULL), "PETSc fieldsplit");
    check(PCFieldSplitSetSchurPre(pc, pre, nullptr), "PETSc fieldsplit");
  }

  /// Defaults of the solvers inside the fieldsplit (they exist after its first set-up), then
  /// the user's options over them.
  void configure_sub_solvers(PC pc) {
    sub_solvers_configured_ = true;
    if (!has_type(pc, PCFIELDSPLIT))
      return; // replaced through the options
    const std::vector<KSP> solvers = sub_solvers(pc);
    if (solvers.size() != 2)
      return;
    if (transport_split_) {
      configure_drained_solvers(solvers[0], solvers[1]);
      return;
    }
    PC primal = apply_once(solvers[0], PCLU);
    if (amg() && !split_.flux.empty())
      check(PCSetType(primal, PCFIELDSPLIT), "PETSc fieldsplit");
    else if (amg())
      apply_multigrid(solvers[0], modes_over(primal_)); // the primal block: displacements
    check(KSPSetFromOptions(solvers[0]), "PETSc options");
    if (has_type(primal, PCFIELDSPLIT))
      split_primal(solvers[0], primal);
    if (wants_transport_cells()) { // with contact multipliers: the potentials' Schur block
      use_drained_schur(solvers[1], &KrylovSolver::apply_drained_potentials);
      drained_ = true;
    } else {
      apply_once(solvers[1], PCLU);
    }
    check(KSPSetFromOptions(solvers[1]), "PETSc options");
  }

  /// The model has contact multipliers (active or not): the displacement block alone may then
  /// hold a body only the contact supports, and the drained transport block does not hold the
  /// multipliers.
  bool has_contact() const {
    const std::vector<FieldRole>& roles = hints_.field_roles;
    return std::find(roles.begin(), roles.end(), FieldRole::multiplier) != roles.end();
  }

  /// The displacement block: multigrid ("amg") or MUMPS LU; the transport block: the drained
  /// approximation.
  void configure_drained_solvers(KSP displacement, KSP transport) {
    if (amg())
      apply_multigrid(displacement, modes_over(split_.displacement));
    else
      apply_once(displacement, PCLU);
    check(KSPSetFromOptions(displacement), "PETSc options");
    use_drained_schur(transport, &KrylovSolver::apply_drained_transport);
    check(KSPSetFromOptions(transport), "PETSc options");
    drained_ = true;
  }

  using ShellApply = PetscErrorCode (*)(PC, Vec, Vec);

  /// The solver `ksp` (of the transport block, or of the potentials' Schur complement)
  /// applies the drained approximation: a shell around the factorization of the augmented
  /// system (factorize_drained_schur).
  void use_drained_schur(KSP ksp, ShellApply apply) {
    PC pc = apply_once(ksp, PCSHELL);
    check(PCShellSetContext(pc, this), "PETSc shell preconditioner");
    check(PCShellSetApply(pc, apply), "PETSc shell preconditioner");
    check(PCShellSetName(pc, "drained approximation (augmented system, MUMPS LU)"),
          "PETSc shell preconditioner");
  }

  /// x → the augmented system's solution for the right-hand side `rhs`.
  PetscErrorCode solve_augmented(const Vector& rhs, Vector& solution) {
    PetscScalar* to = nullptr;
    PetscCall(VecGetArray(schur_b_, &to));
    std::copy(rhs.data(), rhs.data() + rhs.size(), to);
    PetscCall(VecRestoreArray(schur_b_, &to));
    PetscCall(KSPSolve(schur_ksp_, schur_b_, schur_x_));
    solution.resize(rhs.size());
    const PetscScalar* from = nullptr;
    PetscCall(VecGetArrayRead(schur_x_, &from));
    std::copy(from, from + solution.size(), solution.data());
    PetscCall(VecRestoreArrayRead(schur_x_, &from));
    return 0;
  }

  /// y = Ŝ⁻¹ x for the potentials' Schur block (models with contact multipliers): the
  /// augmented system solved with right-hand side (x, 0), its potentials.
  static PetscErrorCode apply_drained_potentials(PC pc, Vec x, Vec y) {
    void* context = nullptr;
    PetscCall(PCShellGetContext(pc, &context));
    auto* self = static_cast<KrylovSolver*>(context);
    PetscInt potentials = 0;
    PetscCall(VecGetLocalSize(x, &potentials));
    Vector rhs = Vector::Zero(self->transport_solve_->system().rows());
    const PetscScalar* from = nullptr;
    PetscCall(VecGetArrayRead(x, &from));
    std::copy(from, from + potentials, rhs.data());
    PetscCall(VecRestoreArrayRead(x, &from));
    Vector solution;
    PetscCall(self->solve_augmented(rhs, solution));
    PetscScalar* to = nullptr;
    PetscCall(VecGetArray(y, &to));
    std::copy(solution.data(), solution.data() + potentials, to);
    PetscCall(VecRestoreArray(y, &to));
    return 0;
  }

  /// Builds the augmented system of drained_schur.hpp for the matrix `A` and the cells of its
  /// state, and factorizes it (the symbolic analysis is kept while its pattern is unchanged).
  void factorize_drained_schur(const SparseMatrix& A) {
    log::debug(cells_.empty()
                   ? std::string("  drained approximation: no mixture cells given (diagonal "
                                 "flux block)")
                   : fmt::format("  drained approximation: {} mixture cells", cells_.size()));
    PetscReal fixed_stress = 1.0; // -drained_schur_fixed_stress: the term's weight
    check(
        PetscOptionsGetReal(nullptr, kDrainedSchurPrefix, "-fixed_stress", &fixed_stress, nullptr),
        "PETSc options");
    transport_solve_ = std::make_unique<DrainedTransport>(A, split_, cells_, fixed_stress);
    const SparseMatrix& system = transport_solve_->system();
    const std::vector<Index> pattern = pattern_of(system);
    if (schur_matrix_ && pattern == schur_pattern_) {
      schur_matrix_->update(system);
    } else {
      release_drained_schur();
      schur_matrix_ = std::make_unique<petsc::SeqAijMatrix>(system);
      schur_pattern_ = pattern;
      check(MatCreateVecs(schur_matrix_->mat(), &schur_x_, &schur_b_), "PETSc vectors");
      check(KSPCreate(PETSC_COMM_SELF, &schur_ksp_), "PETSc KSP");
      check(KSPSetOptionsPrefix(schur_ksp_, kDrainedSchurPrefix), "PETSc KSP");
      apply_once(schur_ksp_, PCLU);
      check(KSPSetFromOptions(schur_ksp_), "PETSc options");
    }
    check(KSPSetOperators(schur_ksp_, schur_matrix_->mat(), schur_matrix_->mat()),
          "PETSc KSP operators");
    check(KSPSetUp(schur_ksp_), "drained Schur approximation: factorization");
  }

  /// The column starts and row indices of a compressed matrix, in one list.
  static std::vector<Index> pattern_of(const SparseMatrix& m) {
    std::vector<Index> pattern(m.outerIndexPtr(), m.outerIndexPtr() + m.outerSize() + 1);
    pattern.insert(pattern.end(), m.innerIndexPtr(), m.innerIndexPtr() + m.nonZeros());
    return pattern;
  }

  /// y = the drained approximation of the transport block's inverse applied to x
  /// (DrainedTransport: the augmented system's solve between two sparse products).
  static PetscErrorCode apply_drained_transport(PC pc, Vec x, Vec y) {
    void* context = nullptr;
    PetscCall(PCShellGetContext(pc, &context));
    auto* self = static_cast<KrylovSolver*>(context);
    const std::vector<Index>& at_flux = self->transport_flux_;
    const std::vector<Index>& at_potential = self->transport_potential_;
    Vector r_flux(static_cast<Index>(at_flux.size()));
    Vector r_potential(static_cast<Index>(at_potential.size()));
    const PetscScalar* from = nullptr;
    PetscCall(VecGetArrayRead(x, &from));
    for (std::size_t i = 0; i < at_flux.size(); ++i)
      r_flux[static_cast<Index>(i)] = from[at_flux[i]];
    for (std::size_t i = 0; i < at_potential.size(); ++i)
      r_potential[static_cast<Index>(i)] = from[at_potential[i]];
    PetscCall(VecRestoreArrayRead(x, &from));

    Vector solution;
    PetscCall(self->solve_augmented(self->transport_solve_->right_hand_side(r_flux, r_potential),
                                    solution));
    const Vector fluxes = self->transport_solve_->fluxes(r_flux, solution);
    PetscScalar* to = nullptr;
    PetscCall(VecGetArray(y, &to));
    for (std::size_t i = 0; i < at_flux.size(); ++i)
      to[at_flux[i]] = fluxes[static_cast<Index>(i)];
    for (std::size_t i = 0; i < at_potential.size(); ++i)
      to[at_potential[i]] = solution[static_cast<Index>(i)];
    PetscCall(VecRestoreArray(y, &to));
    return 0;
  }

  void release_drained_schur() {
    if (schur_ksp_)
      KSPDestroy(&schur_ksp_);
    if (schur_x_)
      VecDestroy(&schur_x_);
    if (schur_b_)
      VecDestroy(&schur_b_);
    schur_matrix_.reset();
    schur_ksp_ = nullptr;
    schur_x_ = schur_b_ = nullptr;
  }

  /// A fieldsplit of the primal block (the "amg" preconditioner, or chosen through the
  /// options): displacement, then fluxes (the flux rows depend on the displacement but not
  /// conversely, so the multiplicative split is exact with exact sub-solves); algebraic
  /// multigrid on the displacement (GAMG with the rigid-body modes for "amg", BoomerAMG
  /// otherwise) and ILU(0) on the fluxes.
  void split_primal(KSP ksp, PC pc) {
    if (split_.flux.empty() || split_.displacement.empty())
      return;
    check(PCFieldSplitSetType(pc, PC_COMPOSITE_MULTIPLICATIVE), "PETSc fieldsplit");
    IS displacement = make_index_set(positions_in(split_.displacement, primal_));
    IS flux = make_index_set(positions_in(split_.flux, primal_));
    check(PCFieldSplitSetIS(pc, "displacement", displacement), "PETSc fieldsplit");
    check(PCFieldSplitSetIS(pc, "flux", flux), "PETSc fieldsplit");
    ISDestroy(&displacement);
    ISDestroy(&flux);
    check(KSPSetFromOptions(ksp), "PETSc options");
    check(PCSetUp(pc), "primal block set-up");
    const std::vector<KSP> solvers = sub_solvers(pc);
    if (solvers.size() != 2)
      return;
    if (amg())
      apply_multigrid(solvers[0], modes_over(split_.displacement));
    else
      apply_once(solvers[0], PCHYPRE);
    apply_once(solvers[1], PCILU);
    for (KSP s : solvers)
      check(KSPSetFromOptions(s), "PETSc options");
  }

  bool amg() const { return settings_.preconditioner == KrylovPreconditioner::amg; }

  /// A solve multigrid does not converge is repeated with the LU blocks.
  bool can_fall_back() const { return amg() && n_ <= kLuFallbackLimit; }

  /// After multigrid failed (e.g. an indefinite displacement block: a body under an unbalanced
  /// initial pressure): the same solve (`warm`: continued from x) with the LU blocks, logged;
  /// false if that fails too. Later solves of the same matrix go to the LU blocks directly.
  bool solve_with_lu_blocks(const Vector& b, Vector& x, bool warm) {
    const std::string why = failure_.reason;
    const std::string failed =
        why.empty() ? "with the LU blocks: " : why + "; with the LU blocks: ";
    if (!fallback_) {
      // the user's options are in force already (they were checked against this backend)
      fallback_ = std::make_unique<KrylovSolver>(
          "", KrylovSettings{.relative_tolerance = tolerance_,
                             .max_iterations = settings_.max_iterations});
      fallback_->set_hints(hints_);
      fallback_->analyze_pattern(*matrix_values_);
    }
    if (!fixed_tolerance_)
      fallback_->set_relative_tolerance(tolerance_);
    if (!fallback_ready_ && !(fallback_ready_ = fallback_->factorize(*matrix_values_))) {
      failure_ = {failed + fallback_->failure().reason, false};
      return false;
    }
    const int failed_iterations = iterations_;
    if (!(warm ? fallback_->refine(b, x) : fallback_->solve(b, x))) {
      failure_ = {failed + fallback_->failure().reason, false};
      return false;
    }
    iterations_ = failed_iterations + fallback_->last_iterations();
    failure_ = {};
    if (!why.empty())
      log::info("  linear solve: multigrid did not converge ({}); solved again with the LU "
                "blocks in {} iterations",
                why, fallback_->last_iterations());
    return true;
  }

  std::vector<Index> all_equations() const {
    std::vector<Index> all(static_cast<std::size_t>(n_));
    std::iota(all.begin(), all.end(), Index{0});
    return all;
  }

  /// The rigid-body modes on the equations `rows` (ascending), orthonormal; empty when the
  /// problem gave none.
  std::vector<Vector> modes_over(const std::vector<Index>& rows) const {
    for (const Vector& mode : hints_.near_null_space)
      if (mode.size() != n_)
        return {};
    return orthonormal_restriction(hints_.near_null_space, rows);
  }

  static bool has_type(PC pc, PCType type) {
    PCType current = nullptr;
    check(PCGetType(pc, &current), "PETSc PC");
    return current != nullptr && std::string(current) == type;
  }

  static std::vector<KSP> sub_solvers(PC pc) {
    PetscInt count = 0;
    KSP* sub = nullptr;
    check(PCFieldSplitGetSubKSP(pc, &count, &sub), "PETSc fieldsplit");
    std::vector<KSP> solvers(sub, sub + count);
    PetscFree(sub);
    return solvers;
  }

  std::string not_converged(KSPConvergedReason reason) const {
    PetscReal residual = 0.0, initial = 0.0, tolerance = 0.0;
    KSPGetResidualNorm(ksp_, &residual);
    KSPGetTolerances(ksp_, &tolerance, nullptr, nullptr, nullptr);
    VecNorm(b_, NORM_2, &initial);
    const Real reached = initial > 0.0 ? residual / initial : residual;
    if (!std::isfinite(reached))
      return fmt::format("the Krylov solver did not converge ({} after {} iterations; the "
                         "residual is not finite)",
                         KSPConvergedReasons[reason], iterations_);
    return fmt::format("the Krylov solver did not converge ({} after {} iterations; residual "
                       "reduced to {:.3g} of the right-hand side, tolerance {:.3g})",
                       KSPConvergedReasons[reason], iterations_, reached, tolerance);
  }

  void release() {
    release_drained_schur();
    transport_solve_.reset();
    drained_ = false;
    if (ksp_)
      KSPDestroy(&ksp_);
    if (x_)
      VecDestroy(&x_);
    if (b_)
      VecDestroy(&b_);
    matrix_.reset();
    ksp_ = nullptr;
    x_ = b_ = nullptr;
    ready_ = false;
    sub_solvers_configured_ = false;
  }

  petsc::ScopedOptions options_; // first: the options outlive the PETSc objects
  KrylovSettings settings_;
  Real tolerance_;              ///< relative tolerance of the next solves (Newton's forcing term)
  const bool fixed_tolerance_;  ///< -ksp_rtol among the options: it wins
  const bool fixed_iterations_; ///< -ksp_max_it among the options: it wins
  BlockSplit split_;
  SystemHints hints_; ///< the fields' roles, the rigid-body modes over the equations
  const SparseMatrix* matrix_values_ = nullptr; ///< the matrix of the last factorize
  std::unique_ptr<LinearSolver> fallback_;      ///< "amg": LU blocks after a failed solve
  bool fallback_ready_ = false; ///< fallback_ factorized matrix_values_ (and serves it)
  std::vector<Index> primal_;
  std::vector<Real> row_sign_; ///< −1 on potential rows (empty: no negation)
  Index n_ = 0;
  std::unique_ptr<petsc::SeqAijMatrix> matrix_;
  Vec x_ = nullptr, b_ = nullptr;
  KSP ksp_ = nullptr;
  TransportCells cells_;         ///< the mixture cells at the state of the next matrix
  bool transport_split_ = false; ///< the fieldsplit is displacement | transport (drained)
  std::vector<Index> transport_; ///< the transport block's equations (fluxes, potentials)
  std::vector<Index> transport_flux_, transport_potential_; ///< their positions in it
  bool drained_ = false; ///< the transport block applies the drained approximation
  std::unique_ptr<DrainedTransport> transport_solve_; ///< its products
  std::unique_ptr<petsc::SeqAijMatrix> schur_matrix_; ///< its augmented system
  std::vector<Index> schur_pattern_;                  ///< its pattern (pattern_of)
  Vec schur_x_ = nullptr, schur_b_ = nullptr;
  KSP schur_ksp_ = nullptr;
  bool ready_ = false;
  bool sub_solvers_configured_ = false;
  bool broken_ = false; ///< a PETSc error interrupted an operation: set up anew (as MUMPS)
  int iterations_ = 0;
  LinearSolverFailure failure_;
};

/// Solves a small system of every block kind with `options`, then refuses options nobody read
/// (or a set-up that fails with them).
void check_options_are_used(const std::string& options, KrylovSettings settings) {
  // displacement (0, 1), fluid flux (2, 3), pressure (4)
  const Real dense[5][5] = {
      {4, 1, 0, 0, 1}, {1, 4, 0, 0, 0}, {0.5, 0, 3, 0, 1}, {0, 0, 0, 3, 1}, {1, 0, 1, 1, 0}};
  SparseMatrix A(5, 5);
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j)
      if (dense[i][j] != 0.0)
        A.insert(i, j) = dense[i][j];
  A.makeCompressed();
  KrylovSolver probe(options, settings);
  probe.set_hints(
      {{0, 0, 1, 1, 2}, {FieldRole::displacement, FieldRole::flux, FieldRole::potential}, {}, {}});
  probe.analyze_pattern(A);
  if (!probe.factorize(A))
    throw InputError(fmt::format("solver.petsc_options = '{}': a 5x5 test system could not be "
                                 "set up with these options: {}",
                                 options, probe.failure().reason));
  Vector x;
  probe.solve(Vector::Ones(5), x); // reads the options of the solve; convergence is not asked
  petsc::refuse_unused_options(options, "krylov");
}

} // namespace

std::unique_ptr<LinearSolver> make_krylov_solver(const std::string& petsc_options,
                                                 KrylovSettings settings) {
  if (!petsc_options.empty())
    check_options_are_used(petsc_options, settings);
  return std::make_unique<KrylovSolver>(petsc_options, settings);
}

} // namespace trifem::linalg
