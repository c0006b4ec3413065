// SPDX-License-Identifier: MIT
// Element of the triphasic (and biphasic) mixture on a hex8, and on a cell of any family:
// residual of the paper's eqs 14-19 with backward Euler and its consistent tangent
// (docs/theory/triphasic.md §2-§4).
#pragma once

#include "trifem/fe/hex8.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/physics/solid_cell.hpp"
#include "trifem/physics/term.hpp"

#include <array>
#include <optional>

namespace trifem::physics {

/// Local DOF layout of a cell of n displacement nodes and nf flux nodes (the cell's corners:
/// mixture_flux_map), field-major: u (3n), w (3nf), [j+ (3nf), j- (3nf)], p, [eta]. A hex8's
/// (n = nf = 8) has 98 unknowns, or 49 without ions.
struct MixtureLayout {
  bool ions = true;
  int nodes = 8;
  int flux_nodes = 8;
  int size() const { return ions ? size_with_ions() : 3 * nodes + 3 * flux_nodes + 1; }
  int size_with_ions() const { return 3 * nodes + 9 * flux_nodes + 2; }
  int u(int a, int k) const { return 3 * a + k; }
  int w(int a, int k) const { return 3 * nodes + 3 * a + k; }
  int jp(int a, int k) const { return 3 * nodes + 3 * flux_nodes + 3 * a + k; }
  int jm(int a, int k) const { return 3 * nodes + 6 * flux_nodes + 3 * a + k; }
  int p() const { return ions ? 3 * nodes + 9 * flux_nodes : 3 * nodes + 3 * flux_nodes; }
  int eta() const { return 3 * nodes + 9 * flux_nodes + 1; }
};

/// Row a = the flux shape function of corner a in terms of the cell's shape functions:
/// N^f_a = Σ_b P_ab N_b.
using MixtureFluxMap = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic, 0, 8, fe::kMaxCellNodes>;

/// How a cell of `type` interpolates the fluxes w, j±: linearly from its corners, N^f_a = N_a +
/// ½ Σ N_m over the mid-edge nodes m of the edges at corner a (the tet4 or hex8 function of
/// the corner on a tet10 or hex20), and by the cell's own functions on a linear cell (identity).
/// With the potentials constant per cell, quadratic fluxes would leave the flux inside a cell
/// undriven and the consolidation too fast (docs/theory/elements.md §3).
const MixtureFluxMap& mixture_flux_map(fe::CellType type);

/// The same for the facets: a tri6's fluxes are the tri3 functions of its corners, a quad8's the
/// quad4 functions; identity on tri3 and quad4 facets.
const MixtureFluxMap& mixture_flux_map(fe::FacetType type);

/// Nodal and element unknowns of one cell, in physical units; `Coords` holds one row per node
/// (fe::HexCoords for a hex8, fe::CellNodeCoords for a cell of any family).
template <class Coords>
struct MixtureUnknownsOf {
  Coords u, w, jp, jm; ///< rows = nodes; fluxes are spatial vectors
  Real p = 0.0;        ///< hydrostatic pressure [MPa]
  Real eta = 0.0;      ///< Faraday constant x electric potential [mJ/mmol]
};
using MixtureUnknowns = MixtureUnknownsOf<fe::HexCoords>;
using CellMixtureUnknowns = MixtureUnknownsOf<fe::CellNodeCoords>;

/// Element history and invariant data.
struct MixtureHistory {
  Real V0 = 0.0;          ///< reference volume [mm^3]
  Real V_old = 0.0;       ///< volume at the last converged step [mm^3]
  Real N_plus = 0.0;      ///< cation moles at the last converged step [mmol]
  Real N_minus = 0.0;     ///< anion moles at the last converged step [mmol]
  Real N_fixed = 0.0;     ///< fixed-charge moles at the end of the step [mEq]
  Real N_fixed_old = 0.0; ///< fixed-charge moles at the last converged step [mEq]
};

/// Step data shared by all elements.
struct MixtureStep {
  Real dt = 1.0;        ///< step size [s]
  Real prestress = 0.0; ///< constant Cauchy prestress Pi0: momentum uses p - Pi0 (IC-3a)
  const material::Electrochemistry* chem = nullptr;
  /// The friction terms with the lumped mass diag(∫ N_a dv) in place of m_ab = ∫ N_a N_b dv
  /// ([analysis] flux_mass = "lumped", docs/theory/solvers.md §4)
  bool lumped_flux_mass = false;
};

/// Element-constant chemistry derived from the unknowns (also used for output).
struct MixtureChemistry {
  Real V = 0, Vw = 0, phi_w = 0;             ///< volume, water volume [mm^3], porosity
  Real kappa = 0;                            ///< permeability kappa(V/V0) [mm^4/(N s)]
  Real d_plus = 0, d_minus = 0;              ///< ion diffusivities d+-(phi_w) [mm^2/s]
  Real c_plus = 0, c_minus = 0, c_fixed = 0; ///< concentrations per water volume [mmol/mm^3]
  Real mu_w = 0;                             ///< bath-normalised water potential [MPa]
  Real mu_plus = 0, mu_minus = 0;            ///< bath-normalised ion potentials [mJ/mmol]
  Real A_ww = 0, A_wp = 0, A_wm = 0, A_pp = 0, A_mm = 0; ///< resistance coefficients
  bool admissible = false;                               ///< Vw > 0, N+- > 0, J > 0 everywhere
};

/// Residual (natural rows, physical units: R^u [N], R^w [N], R^+- [mJ mm^2/mmol... see docs],
/// R^p [mm^3/s], R^eta [mmol/s]) and, if K is given, dR/d(unknowns). Returns false if the
/// state is inadmissible (J <= 0 at a Gauss point, water volume or ion moles <= 0).
bool mixture_hex8(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                  const MixtureHistory& history, const material::MixtureProperties& mat,
                  const MixtureStep& step, const MixtureLayout& layout, LocalVector& r,
                  LocalMatrix* K);

/// The parts of the element's flux block that do not depend on the flux values, in natural
/// units (docs/theory/triphasic.md §4, docs/theory/solvers.md §4). Over the fields
/// i, j ∈ (w, j+, j−) and the components k, l, the tangent's flux block is
///
///     K(f_i(a,k), f_j(b,l)) = δ_kl m_ab friction(i,j) + g_a[k] gamma(i,j) g_b[l]
///
///     + flux_rate(3a + k, 3i + j) g_b[l]
///
/// where flux_rate, proportional to the fluxes, holds the resistances' derivatives by the
/// divergences times the mass products W, P, M; and the rows (p, η) of the flux columns are
/// coupling · (g_b[l] for each field). Biphasic elements fill the w entries only.
struct MixtureFluxBlock {
  Mat3 friction = Mat3::Zero(); ///< the friction coefficients −A_ww, A_w±, −A_±±
  Mat3 gamma = Mat3::Zero();    ///< the concentration terms dμ̄_i/dc dc/d(div j_j)
  /// Row 3a + k, column 3i + j: d(flux equation i at node a, component k)/d(div j_j) beyond
  /// g_a[k] gamma(i, j)
  Eigen::Matrix<Real, 24, 9> flux_rate = Eigen::Matrix<Real, 24, 9>::Zero();
  Eigen::Matrix<Real, 2, 3> coupling = Eigen::Matrix<Real, 2, 3>::Zero();    ///< K^pw, K^η± per g
  Eigen::Matrix<Real, 8, 3> area = Eigen::Matrix<Real, 8, 3>::Zero();        ///< g_a (rows: nodes)
  Eigen::Matrix<Real, 8, 1> lumped_mass = Eigen::Matrix<Real, 8, 1>::Zero(); ///< Σ_b m_ab
};

/// The flux block of the element at a state (the inputs of mixture_hex8); nothing if the state
/// is inadmissible (J <= 0 at a Gauss point, water volume or ion moles <= 0).
std::optional<MixtureFluxBlock>
mixture_hex8_flux_block(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                        const MixtureHistory& history, const material::MixtureProperties& mat,
                        const MixtureStep& step, const MixtureLayout& layout);

/// Element chemistry and volume-averaged fluxes at a state (for output and initial states).
struct MixtureCellOutput {
  MixtureChemistry chem;
  Vec3 w = Vec3::Zero(), j_plus = Vec3::Zero(), j_minus = Vec3::Zero();
  Mat3 solid_stress = Mat3::Zero(); ///< Cauchy stress of the solid matrix [MPa]
  Real J = 1.0;
};
MixtureCellOutput mixture_hex8_output(const fe::HexGeometry& geo, const MixtureUnknowns& x,
                                      const MixtureHistory& history,
                                      const material::MixtureProperties& mat,
                                      const MixtureStep& step, bool ions);

/// The same element on a cell of any family (solid_cell.hpp) with its family's rule: u
/// interpolated by the cell's shape functions, w and j± by mixture_flux_map's, p and η constant
/// over the cell (docs/theory/elements.md §3); x's flux rows and `layout` are those of the flux
/// nodes.
bool mixture_cell(const CellGeometry& geo, const CellMixtureUnknowns& x,
                  const MixtureHistory& history, const material::MixtureProperties& mat,
                  const MixtureStep& step, const MixtureLayout& layout, LocalVector& r,
                  LocalMatrix* K);

/// The potentials of a tet cell, continuous and linear from its four corners
/// (docs/theory/elements.md): their values there and, for the water balance tested with the
/// corners' functions, the volumes those functions weigh at the last converged step.
struct CornerPotentials {
  std::array<Real, 4> p{};          ///< hydrostatic pressure at the corners [MPa]
  std::array<Real, 4> eta{};        ///< Faraday constant x electric potential [mJ/mmol]
  std::array<Real, 4> volume_old{}; ///< V_b = ∫ N_b J dV at the last converged step [mm^3]
};

/// The local layout of a cell with corner potentials: `layout`'s up to the fluxes, then p at
/// the four corners, then η at the four corners (with ions).
inline int corner_layout_size(const MixtureLayout& layout) {
  return layout.p() + (layout.ions ? 8 : 4);
}

/// V_b = ∫ N_b J dV for the corners b of a tet4 or tet10 cell at the displacement u [mm^3].
std::array<Real, 4> corner_volumes(const CellGeometry& geo, const fe::CellNodeCoords& u);

/// mixture_cell on a tet4 or tet10 with the potentials of `corners` (x.p and x.eta are not
/// read): the fluxes see their means (the divergence of the linear fluxes is constant per
/// cell, so ∫ p div(N_a) dv = p̄ ∫ div N_a dv), the momentum sees p(x) at every point, and the
/// water balance is tested with the corners' functions. Rows and columns in
/// corner_layout_size's layout.
bool mixture_tet(const CellGeometry& geo, const CellMixtureUnknowns& x,
                 const CornerPotentials& corners, const MixtureHistory& history,
                 const material::MixtureProperties& mat, const MixtureStep& step,
                 const MixtureLayout& layout, LocalVector& r, LocalMatrix* K);

/// mixture_hex8_output for a cell of any family.
MixtureCellOutput mixture_cell_output(const CellGeometry& geo, const CellMixtureUnknowns& x,
                                      const MixtureHistory& history,
                                      const material::MixtureProperties& mat,
                                      const MixtureStep& step, bool ions);

} // namespace trifem::physics
