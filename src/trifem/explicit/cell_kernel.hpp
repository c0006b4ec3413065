// SPDX-License-Identifier: MIT
// Cell loop of the explicit scheme: internal force Q_V (A2.10), constraint gradient H (A2.11),
// constraint integral Ψ (A2.14) and strain energy of every cell (hex8, tet10, hex20),
// OpenMP-parallel, no assembly.
#pragma once

#include "trifem/explicit/explicit_view.hpp"
#include "trifem/explicit/settings.hpp"

#include <string>
#include <vector>

namespace trifem::explicit_dynamics {

/// The nodal vectors of every cell one after another: cell c's 3 values per node, node-major
/// (a_0x, a_0y, a_0z, a_1x, ...), from ExplicitView::cell_offsets()[c].
using CellVectors = Vector;

/// Which quantities evaluate_cells computes.
struct CellRequest {
  bool internal = true; ///< q_e
  bool gradient = true; ///< h_e
  bool psi = true;      ///< Ψ_e
  bool energy = false;  ///< ∫ W dV
};

/// Per-cell results (struct of arrays, indexed by cell).
struct CellFields {
  CellVectors internal;       ///< q_e,a = ∫ F S ∇N_a dV, S = 2 ∂W/∂C [N]
  CellVectors gradient;       ///< h_e,a = ∫ F D_C ∇N_a dV = ∫ ∂Ψ/∂F ∇N_a dV [mm²]
  Vector psi;                 ///< Ψ_e = ∫ Ψ(C) dV [mm³]
  Vector energy;              ///< ∫ W(C) dV [mJ]
  Vector volume_change;       ///< cell mean J̄ − 1 = ∫ (J − 1) dV / V_e [-]
  Vector gauss_volume_change; ///< max over the Gauss points of |J − 1| [-]

  /// Sized to the cells of `model`.
  void resize(const ExplicitView& model);
};

/// Why a cell evaluation failed.
enum class CellFailure : unsigned char {
  None,
  NegativeJacobian, ///< det F ≤ 0 at a Gauss point (recoverable by a smaller step)
  NonFinite         ///< NaN or Inf in the input displacement or in a result (fatal)
};

/// Outcome of evaluate_cells: the first failing cell (lowest index) and the quantity.
struct CellStatus {
  CellFailure failure = CellFailure::None;
  Index cell = -1;
  std::string quantity; ///< e.g. "det F", "displacement", "internal force"
  bool ok() const { return failure == CellFailure::None; }
};

/// Evaluates the requested quantities of every cell at the displacement U (OpenMP over cells).
/// Ψ = J − 1 gives ∂Ψ/∂F = J F⁻ᵀ; Ψ = ln J gives F⁻ᵀ. On several processes each evaluates its
/// cells (ExplicitView::evaluates): the cell vectors (q_e, h_e) hold those, the scalars are
/// whole, and the status is that of the first failing cell of all (collective).
CellStatus evaluate_cells(const ExplicitView& model, Constraint constraint, const Vector& U,
                          const CellRequest& request, CellFields& out);

/// y_{3a+k} = Σ_{(e,l) incident to a} w_e v_e[3l+k] with w_e = weights[e] (or 1 if empty):
/// the nodal assembly of cell vectors, as a gather (deterministic, no atomics; OpenMP over nodes).
/// On several processes each gathers its own nodes and the parts are summed (collective).
void gather(const ExplicitView& model, const CellVectors& v, const Vector* weights, Vector& y);

/// z_e = Σ_a Σ_k v_e[3a+k] x_{3 node(e,a) + k}: the transpose of gather, per cell (H^T x); on
/// several processes, each of its own cells, summed (collective).
void cell_dot(const ExplicitView& model, const CellVectors& v, const Vector& x, Vector& z);

} // namespace trifem::explicit_dynamics
