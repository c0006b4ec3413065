// SPDX-License-Identifier: MIT
// The multiplier system of A2.21, A = (1/α) Γ + h² Hᵀ M⁻¹ H, on the P0 (one value per cell)
// multiplier: assembled from the cell vectors h_e without any global stiffness, factorized by
// Cholesky (linalg::make_cholmod_solver) with the symbolic analysis done once; on several
// processes by the distributed MUMPS (linalg::make_linear_solver), each process adding the
// couplings through its own nodes.
#pragma once

#include "trifem/explicit/cell_kernel.hpp"
#include "trifem/linalg/linear_solver.hpp"

#include <memory>

namespace trifem::explicit_dynamics {

/// Accumulated wall-clock seconds spent in the multiplier system.
struct LambdaTimings {
  double assemble = 0.0;
  double factorize = 0.0;
  double solve = 0.0;
  long factorizations = 0;
};

/// A_ef = δ_ef V_e/α + h² Σ_{a,k} h_e[a,k] M⁻¹_{ak} h_f[a,k] (cells e, f sharing node a).
/// Symmetric positive definite when α < ∞ or H has full column rank; stored as the lower
/// triangle (on several processes: this process's part of both triangles). Sparsity = cells
/// sharing a node (27 neighbours in a structured mesh).
class LambdaSystem {
public:
  /// Builds the pattern from the model's incidence and runs the symbolic analysis (AMD/METIS
  /// ordering as CHOLMOD chooses; MUMPS's own on several processes).
  explicit LambdaSystem(const ExplicitView& model);

  /// Assembles A with scale h² [s²/... as in A2.21] and diagonal shift `diagonal` (V_e/α per
  /// cell, size num_cells) and factorizes it. Returns false if A is not positive definite.
  bool factorize(const CellVectors& h, const Vector& inverse_mass, Real h2, const Vector& diagonal);
  /// Solves A x = b with the last factorization.
  void solve(const Vector& b, Vector& x);
  const LambdaTimings& timings() const { return timings_; }

private:
  void build_pattern();
  void build_part_pattern();
  void assemble_part(const CellVectors& h, const Vector& inverse_mass, Real h2,
                     const Vector& diagonal);
  void assemble(const CellVectors& h, const Vector& inverse_mass, Real h2, const Vector& diagonal);

  const ExplicitView& model_;
  SparseMatrix A_;                  ///< lower triangle, compressed
  std::vector<Index> slot_offsets_; ///< per column: start of its traversal slots
  std::vector<Index> slots_;        ///< value index of each (column, node, incident cell) visit
  std::unique_ptr<linalg::LinearSolver> solver_;
  LambdaTimings timings_;
};

} // namespace trifem::explicit_dynamics
