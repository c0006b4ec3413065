// SPDX-License-Identifier: MIT
// The "krylov" backend: the grouping of equations by field, FGMRES with the Schur-complement
// fieldsplit on a mixed system (with its default direct block solves and with the displacement
// / flux split and AMG chosen through PETSc options), and a solve that does not converge.
#include "trifem/core/error.hpp"
#include "trifem/linalg/block_split.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <sstream>
#include <vector>

using namespace trifem;

namespace {

/// A mixed system of the triphasic kind: a displacement block K (1-D elasticity with a shift),
/// a flux block F (mass-like, coupled to the displacement but not conversely), and potentials
/// that constrain both through B (unsymmetric coupling) with a zero diagonal block.
struct MixedSystem {
  SparseMatrix A;
  std::vector<int> fields; ///< 0 displacement, 1 fluid flux, 2 pressure
  std::vector<FieldRole> roles{FieldRole::displacement, FieldRole::flux, FieldRole::potential};
};

/// `support`: the displacement block's diagonal shift over the number of cells (negative: an
/// indefinite block, as under an unbalanced initial pressure).
MixedSystem mixed_system(Index cells, Real support = 0.01) {
  const Index n = cells + 1; // nodes: displacement and flux per node, pressure per cell
  std::vector<Eigen::Triplet<Real>> t;
  const Index u = 0, w = n, p = 2 * n;
  for (Index e = 0; e < cells; ++e) {
    for (Index a = 0; a < 2; ++a)
      for (Index b = 0; b < 2; ++b) {
        t.emplace_back(u + e + a, u + e + b, (a == b ? 1.0 : -1.0) * cells);        // stiffness
        t.emplace_back(w + e + a, w + e + b, (a == b ? 2.0 : 1.0) / (6.0 * cells)); // mass
        t.emplace_back(w + e + a, u + e + b, 0.05 * (a == b ? 1.0 : -1.0)); // flux row sees u
      }
    for (Index a = 0; a < 2; ++a) {
      const Real g = a == 0 ? -1.0 : 1.0;
      t.emplace_back(u + e + a, p + e, -g);       // −g p in the displacement rows
      t.emplace_back(w + e + a, p + e, -0.8 * g); // −Δt g p in the flux rows
      t.emplace_back(p + e, u + e + a, -g);       // volume change
      t.emplace_back(p + e, w + e + a, -0.7 * g); // outflow (not the transpose: unsymmetric)
    }
  }
  for (Index i = 0; i < n; ++i)
    t.emplace_back(u + i, u + i, support * cells); // supported: no rigid translation
  MixedSystem s;
  s.A.resize(2 * n + cells, 2 * n + cells);
  s.A.setFromTriplets(t.begin(), t.end());
  s.fields.assign(n, 0);
  s.fields.insert(s.fields.end(), n, 1);
  s.fields.insert(s.fields.end(), cells, 2);
  return s;
}

Vector mixed_right_hand_side(Index size) {
  Vector b(size);
  for (Index i = 0; i < size; ++i)
    b[i] = std::cos(0.21 * i) + 0.05;
  return b;
}

/// Solves the mixed system with `solver` (fields given) and returns ‖A x − b‖ / ‖b‖.
Real relative_residual(linalg::LinearSolver& solver, const MixedSystem& s) {
  solver.set_hints({s.fields, s.roles, {}, {}});
  solver.analyze_pattern(s.A);
  EXPECT_TRUE(solver.factorize(s.A)) << solver.failure().reason;
  const Vector b = mixed_right_hand_side(s.A.rows());
  Vector x;
  EXPECT_TRUE(solver.solve(b, x)) << solver.failure().reason;
  return x.size() == b.size() ? (s.A * x - b).norm() / b.norm() : 1.0;
}

} // namespace

TEST(BlockSplit, GroupsEquationsIntoDisplacementFluxesAndPotentials) {
  using enum FieldRole;
  const std::vector<FieldRole> roles{displacement, flux,      flux,      flux,
                                     potential,    potential, multiplier};
  const std::vector<int> fields{0, 1, 0, 2, 3, 4, 5, 6, 1};
  const linalg::BlockSplit split = linalg::BlockSplit::from_fields(fields, roles);
  EXPECT_EQ(split.displacement, (std::vector<Index>{0, 2, 7})); // with the contact multipliers
  EXPECT_EQ(split.flux, (std::vector<Index>{1, 3, 4, 8}));
  EXPECT_EQ(split.potential, (std::vector<Index>{5, 6}));
  EXPECT_EQ(split.primal(), (std::vector<Index>{0, 1, 2, 3, 4, 7, 8}));
}

TEST(KrylovSolver, SolvesAMixedSystemThroughTheSchurFieldsplit) {
  const MixedSystem s = mixed_system(40);
  auto solver = linalg::make_linear_solver({LinearSolverKind::krylov});
  // FGMRES stops at 1e-10 of the right-hand side: the true residual is below it
  EXPECT_LT(relative_residual(*solver, s), 1e-9);
  EXPECT_GE(solver->last_iterations(), 1);
  EXPECT_LE(solver->last_iterations(), 30);
  EXPECT_EQ(solver->name(), "krylov");
}

TEST(KrylovSolver, MultigridPreconditionerSolvesAMixedSystem) {
  // "amg": GAMG on the displacement, ILU(0) on the fluxes, LU of the Schur approximation
  const MixedSystem s = mixed_system(40);
  auto solver = linalg::make_linear_solver(
      {.kind = LinearSolverKind::krylov, .preconditioner = KrylovPreconditioner::amg});
  EXPECT_LT(relative_residual(*solver, s), 1e-9);
  EXPECT_GE(solver->last_iterations(), 1);
  EXPECT_LE(solver->last_iterations(), 60);
}

TEST(KrylovSolver, WhereMultigridFailsTheSolveIsRepeatedWithTheLuBlocks) {
  // an indefinite displacement block: multigrid gives up after its 200 iterations, the solve
  // is repeated with the LU blocks and the log says so; a second solve of the same matrix goes
  // to the LU blocks directly
  const MixedSystem s = mixed_system(400, -1.0);
  const Vector b = mixed_right_hand_side(s.A.rows());
  std::ostringstream log;
  spdlog::default_logger()->sinks().push_back(
      std::make_shared<spdlog::sinks::ostream_sink_st>(log));
  auto solver = linalg::make_linear_solver(
      {.kind = LinearSolverKind::krylov, .preconditioner = KrylovPreconditioner::amg});
  solver->set_hints({s.fields, s.roles, {}, {}});
  solver->analyze_pattern(s.A);
  ASSERT_TRUE(solver->factorize(s.A)) << solver->failure().reason;
  Vector x;
  const bool solved = solver->solve(b, x);
  spdlog::default_logger()->sinks().pop_back();
  ASSERT_TRUE(solved) << solver->failure().reason;
  EXPECT_LE((s.A * x - b).norm() / b.norm(), 1e-9);
  EXPECT_GT(solver->last_iterations(), 200); // multigrid's attempt, then the LU blocks'
  EXPECT_NE(log.str().find("solved again with the LU blocks"), std::string::npos) << log.str();
  Vector again;
  ASSERT_TRUE(solver->solve(b, again)) << solver->failure().reason;
  EXPECT_LE((s.A * again - b).norm() / b.norm(), 1e-9);
  EXPECT_LT(solver->last_iterations(), 100);
}

TEST(KrylovSolver, ASolveToALooseToleranceIsContinuedToATightOne) {
  // Newton's forcing term: a solve to 1e-3, then continued from its result to 1e-10; a
  // tolerance among the PETSc options wins over the ones asked
  const MixedSystem s = mixed_system(40);
  const Vector b = mixed_right_hand_side(s.A.rows());
  for (const KrylovPreconditioner preconditioner :
       {KrylovPreconditioner::lu, KrylovPreconditioner::amg}) {
    SCOPED_TRACE(to_string(preconditioner));
    auto solver = linalg::make_linear_solver(
        {.kind = LinearSolverKind::krylov, .preconditioner = preconditioner});
    solver->set_hints({s.fields, s.roles, {}, {}});
    solver->analyze_pattern(s.A);
    ASSERT_TRUE(solver->factorize(s.A)) << solver->failure().reason;
    Vector x;
    solver->set_relative_tolerance(1e-3);
    ASSERT_TRUE(solver->solve(b, x)) << solver->failure().reason;
    const Real loose = (s.A * x - b).norm() / b.norm();
    EXPECT_LE(loose, 1e-3);
    EXPECT_GT(loose, 1e-10); // stopped early
    solver->set_relative_tolerance(1e-10);
    ASSERT_TRUE(solver->refine(b, x)) << solver->failure().reason;
    EXPECT_LE((s.A * x - b).norm() / b.norm(), 1e-9);
    EXPECT_GE(solver->last_iterations(), 1);
  }
  auto fixed = linalg::make_linear_solver(
      {.kind = LinearSolverKind::krylov, .petsc_options = "-ksp_rtol 1e-11"});
  fixed->set_relative_tolerance(1e-2); // ignored
  EXPECT_LT(relative_residual(*fixed, s), 1e-10);
}

TEST(KrylovSolver, OptionsSplitThePrimalBlockIntoDisplacementAndFluxes) {
  // the primal block as a fieldsplit: trifem supplies the displacement / flux index sets,
  // BoomerAMG on the displacement and ILU on the fluxes; a wrong set would fail the solve
  const MixedSystem s = mixed_system(40);
  auto solver = linalg::make_linear_solver(
      {.kind = LinearSolverKind::krylov,
       .petsc_options = "-fieldsplit_primal_pc_type fieldsplit -ksp_rtol 1e-11"});
  EXPECT_LT(relative_residual(*solver, s), 1e-10);
  EXPECT_GE(solver->last_iterations(), 1);
}

TEST(KrylovSolver, ASolveThatDoesNotConvergeSaysWhyAndIsCurable) {
  const MixedSystem s = mixed_system(40);
  auto solver = linalg::make_linear_solver({.kind = LinearSolverKind::krylov,
                                            .petsc_options =
                                                "-ksp_max_it 2 -fieldsplit_primal_pc_type jacobi "
                                                "-fieldsplit_potential_pc_type jacobi"});
  solver->set_hints({s.fields, s.roles, {}, {}});
  solver->analyze_pattern(s.A);
  ASSERT_TRUE(solver->factorize(s.A)) << solver->failure().reason;
  Vector x;
  EXPECT_FALSE(solver->solve(mixed_right_hand_side(s.A.rows()), x));
  const std::string reason = solver->failure().reason;
  EXPECT_NE(reason.find("did not converge"), std::string::npos) << reason;
  EXPECT_NE(reason.find("after 2 iterations"), std::string::npos) << reason;
  EXPECT_NE(reason.find("of the right-hand side"), std::string::npos) << reason;
  EXPECT_FALSE(solver->failure().permanent); // a smaller step may converge
}

TEST(KrylovSolver, UnusedPetscOptionIsAnInputErrorNamingIt) {
  try {
    linalg::make_linear_solver({.kind = LinearSolverKind::krylov,
                                .petsc_options = "-ksp_rtol 1e-9 -fieldsplit_primal_pc_typo lu"});
    FAIL() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("-fieldsplit_primal_pc_typo lu"), std::string::npos) << what;
    EXPECT_NE(what.find("krylov"), std::string::npos) << what;
  }
}
