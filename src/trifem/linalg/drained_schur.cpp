// SPDX-License-Identifier: MIT
#include "trifem/linalg/drained_schur.hpp"

#include <Eigen/Dense>

#include <algorithm>

#include <cstdint>
#include <unordered_map>

namespace trifem::linalg {
namespace {

using Triplets = std::vector<Eigen::Triplet<Real, Index>>;

enum class Role : char { displacement, flux, potential };

/// Every equation's role and its position within its group.
struct Groups {
  std::vector<Role> role;
  std::vector<Index> position;
  Index displacements = 0, fluxes = 0, potentials = 0;

  Groups(const BlockSplit& split, Index n) : role(n, Role::displacement), position(n, -1) {
    place(split.displacement, Role::displacement, displacements);
    place(split.flux, Role::flux, fluxes);
    place(split.potential, Role::potential, potentials);
  }

private:
  void place(const std::vector<Index>& equations, Role r, Index& count) {
    for (Index eq : equations) {
      role[eq] = r;
      position[eq] = count++;
    }
  }
};

/// The couplings of the potentials with the primal groups, and the primal diagonals.
struct Blocks {
  SparseMatrix pu, up, pf, fp, pp; ///< rows × columns: potential, displacement, flux
  Vector du, df;                   ///< diagonals of the displacement and flux blocks
};

SparseMatrix from_triplets(Index rows, Index cols, const Triplets& t) {
  SparseMatrix m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

Blocks split_blocks(const SparseMatrix& A, const Groups& g) {
  Triplets pu, up, pf, fp, pp;
  Blocks b;
  b.du = Vector::Zero(g.displacements);
  b.df = Vector::Zero(g.fluxes);
  for (Index j = 0; j < A.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(A, j); it; ++it) {
      const Index i = it.row();
      const Index pi = g.position[i], pj = g.position[j];
      const Role ri = g.role[i], rj = g.role[j];
      if (i == j && ri == Role::displacement)
        b.du[pi] = it.value();
      else if (i == j && ri == Role::flux)
        b.df[pi] = it.value();
      if (ri == Role::potential) {
        Triplets& t = rj == Role::displacement ? pu : rj == Role::flux ? pf : pp;
        t.emplace_back(pi, pj, it.value());
      } else if (rj == Role::potential) {
        (ri == Role::displacement ? up : fp).emplace_back(pi, pj, it.value());
      }
    }
  b.pu = from_triplets(g.potentials, g.displacements, pu);
  b.up = from_triplets(g.displacements, g.potentials, up);
  b.pf = from_triplets(g.potentials, g.fluxes, pf);
  b.fp = from_triplets(g.fluxes, g.potentials, fp);
  b.pp = from_triplets(g.potentials, g.potentials, pp);
  return b;
}

Vector inverse_or_zero(const Vector& d) {
  return d.unaryExpr([](Real v) { return v != 0.0 ? 1.0 / v : 0.0; });
}

/// Ŝ_u: the diagonal approximation of the undrained part, and of the drained part where a
/// row or a column is a potential of no transport cell.
SparseMatrix undrained_part(const Blocks& b, const std::vector<char>& transport_potential) {
  const SparseMatrix up = inverse_or_zero(b.du).asDiagonal() * b.up;
  const SparseMatrix fp = inverse_or_zero(b.df).asDiagonal() * b.fp;
  SparseMatrix drained = b.pf * fp;
  drained.prune(
      [&](Index i, Index j, Real) { return !(transport_potential[i] && transport_potential[j]); });
  return SparseMatrix(-b.pp + b.pu * up + drained);
}

/// The fixed-stress term, filtered of the checkerboards: Σ_nodes β̄_a / (8 n_a) over the pairs
/// of the n_a cells around node a, β̄_a the mean over them of the pressure's diagonal β_c in the
/// undrained part (≈ V_c / H_c, H_c the constrained modulus). A smooth pressure sees β_c; a
/// checkerboard, which the divergences do not see either, sums to zero at the inner nodes.
SparseMatrix fixed_stress_part(const SparseMatrix& undrained, const TransportCells& cells,
                               const Groups& g) {
  std::vector<std::pair<Index, Index>> node_pressure; // (mesh node, pressure position)
  for (const TransportCell& c : cells)
    if (const Index eq = c.potential[0]; eq >= 0 && g.role[eq] == Role::potential)
      for (Index node : c.node)
        node_pressure.emplace_back(node, g.position[eq]);
  std::sort(node_pressure.begin(), node_pressure.end());
  Triplets t;
  for (auto first = node_pressure.begin(); first != node_pressure.end();) {
    auto last = first;
    Real beta = 0.0;
    for (; last != node_pressure.end() && last->first == first->first; ++last)
      beta += undrained.coeff(last->second, last->second);
    const Real n = static_cast<Real>(last - first);
    for (auto i = first; i != last; ++i)
      for (auto j = first; j != last; ++j)
        t.emplace_back(i->second, j->second, beta / (8.0 * n * n));
    first = last;
  }
  return from_triplets(g.potentials, g.potentials, t);
}

/// The lumped friction of one node and component: a fields × fields block and the flux
/// equations (group positions) of its fields.
struct Site {
  Eigen::Matrix3d friction = Eigen::Matrix3d::Zero();
  std::array<Index, 3> flux{-1, -1, -1};
};

/// D⁻¹ (fluxes × fluxes): each site's friction block inverted over its free fields.
SparseMatrix lumped_friction_inverse(const TransportCells& cells, const Groups& g) {
  std::unordered_map<std::int64_t, Site> sites;
  for (const TransportCell& c : cells)
    for (int a = 0; a < 8; ++a)
      for (int k = 0; k < 3; ++k) {
        Site& s = sites[3 * static_cast<std::int64_t>(c.node[a]) + k];
        s.friction += c.lumped_mass[a] * c.friction;
        for (int f = 0; f < 3; ++f)
          if (const Index eq = c.flux_equation(3 * a + k, f); eq >= 0)
            s.flux[f] = g.position[eq];
      }
  Triplets t;
  for (const auto& [key, s] : sites) {
    std::array<int, 3> free{};
    int n = 0;
    for (int f = 0; f < 3; ++f)
      if (s.flux[f] >= 0)
        free[n++] = f;
    Eigen::MatrixXd block(n, n);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        block(i, j) = s.friction(free[i], free[j]);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(block);
    if (n == 0 || !lu.isInvertible())
      continue;
    const Eigen::MatrixXd inverse = lu.inverse();
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        t.emplace_back(s.flux[free[i]], s.flux[free[j]], inverse(i, j));
  }
  return from_triplets(g.fluxes, g.fluxes, t);
}

/// Calls visit(cell, row 3a + k, field, flux position) for every free flux equation of the cells.
template <typename Visit>
void for_each_flux_equation(const TransportCells& cells, const Groups& g, Visit visit) {
  for (std::size_t c = 0; c < cells.size(); ++c)
    for (int row = 0; row < 24; ++row)
      for (int f = 0; f < 3; ++f)
        if (const Index eq = cells[c].flux_equation(row, f); eq >= 0)
          visit(c, row, f, g.position[eq]);
}

/// G (3 per cell × fluxes): the cells' divergences of each flux field.
SparseMatrix divergences(const TransportCells& cells, const Groups& g) {
  Triplets t;
  for_each_flux_equation(cells, g, [&](std::size_t c, int row, int f, Index flux) {
    t.emplace_back(static_cast<Index>(3 * c + f), flux, cells[c].divergence(row, f));
  });
  return from_triplets(static_cast<Index>(3 * cells.size()), g.fluxes, t);
}

/// R (fluxes × 3 per cell): the flux equations' derivatives by the cells' divergences,
/// Gᵀ Γ + the rates proportional to the fluxes.
SparseMatrix divergence_rates(const TransportCells& cells, const Groups& g) {
  Triplets t;
  for_each_flux_equation(cells, g, [&](std::size_t c, int row, int f, Index flux) {
    for (int h = 0; h < 3; ++h)
      if (const Real rate = cells[c].divergence(row, f) * cells[c].gamma(f, h) +
                            cells[c].flux_rate(row, 3 * f + h);
          rate != 0.0)
        t.emplace_back(flux, static_cast<Index>(3 * c + h), rate);
  });
  return from_triplets(g.fluxes, static_cast<Index>(3 * cells.size()), t);
}

/// T (potentials × 3 per cell).
void cell_maps(const TransportCells& cells, const Groups& g, SparseMatrix& T,
               std::vector<char>& transport_potential) {
  Triplets tt;
  transport_potential.assign(g.potentials, 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const Index z = static_cast<Index>(3 * c);
    for (int r = 0; r < 2; ++r)
      if (const Index eq = cells[c].potential[r]; eq >= 0 && g.role[eq] == Role::potential) {
        transport_potential[g.position[eq]] = 1;
        for (int f = 0; f < 3; ++f)
          tt.emplace_back(g.position[eq], z + f, cells[c].coupling(r, f));
      }
  }
  T = from_triplets(g.potentials, static_cast<Index>(3 * cells.size()), tt);
}

void append(Triplets& t, const SparseMatrix& m, Index row, Index col, Real factor) {
  for (Index j = 0; j < m.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(m, j); it; ++it)
      t.emplace_back(row + it.row(), col + j, factor * it.value());
}

/// The products the augmented system and the transport solve share.
struct Parts {
  const TransportCells& cells;
  Groups g;
  Blocks b;
  SparseMatrix T, G, R, Dinv;
  std::vector<char> transport_potential;

  Parts(const SparseMatrix& A, const BlockSplit& split, const TransportCells& transport_cells)
      : cells(transport_cells), g(split, static_cast<Index>(A.rows())), b(split_blocks(A, g)) {
    cell_maps(cells, g, T, transport_potential);
    G = divergences(cells, g);
    R = divergence_rates(cells, g);
    Dinv = lumped_friction_inverse(cells, g);
  }

  SparseMatrix system(Real fixed_stress) const {
    const SparseMatrix GDinv = G * Dinv;
    const SparseMatrix LTt = GDinv * SparseMatrix(G.transpose()) * SparseMatrix(T.transpose());
    const SparseMatrix LR = GDinv * R;
    const Index P = g.potentials, Z = static_cast<Index>(G.rows());
    Triplets t;
    const SparseMatrix undrained = undrained_part(b, transport_potential);
    append(t, undrained, 0, 0, 1.0);
    if (fixed_stress != 0.0)
      append(t, fixed_stress_part(undrained, cells, g), 0, 0, fixed_stress);
    append(t, T, 0, P, 1.0);
    append(t, LTt, P, 0, -1.0);
    append(t, LR, P, P, 1.0);
    for (Index i = 0; i < Z; ++i)
      t.emplace_back(P + i, P + i, 1.0);
    return from_triplets(P + Z, P + Z, t);
  }

  /// D⁻¹, with 1 / diag(A_ff) on the fluxes of no cell (or of a singular friction block).
  SparseMatrix flux_inverse() const {
    Vector covered = Vector::Zero(g.fluxes);
    for (Index j = 0; j < Dinv.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(Dinv, j); it; ++it)
        covered[it.row()] = 1.0;
    Triplets t;
    const Vector diagonal = inverse_or_zero(b.df);
    for (Index i = 0; i < g.fluxes; ++i)
      if (covered[i] == 0.0)
        t.emplace_back(i, i, diagonal[i]);
    return SparseMatrix(Dinv + from_triplets(g.fluxes, g.fluxes, t));
  }

  /// K_πf on the potentials of no transport cell (rows negated as in the solver), zero on the
  /// others.
  SparseMatrix multiplier_flux_coupling() const {
    SparseMatrix m = -b.pf;
    m.prune([&](Index i, Index, Real) { return !transport_potential[i]; });
    return m;
  }
};

} // namespace

SparseMatrix drained_schur_system(const SparseMatrix& A, const BlockSplit& split,
                                  const TransportCells& cells, Real fixed_stress) {
  return Parts(A, split, cells).system(fixed_stress);
}

DrainedTransport::DrainedTransport(const SparseMatrix& A, const BlockSplit& split,
                                   const TransportCells& cells, Real fixed_stress) {
  const Parts parts(A, split, cells);
  system_ = parts.system(fixed_stress);
  flux_inverse_ = parts.flux_inverse();
  divergence_ = parts.G;
  divergence_rate_ = parts.R;
  flux_potential_ = parts.b.fp;
  multiplier_flux_ = parts.multiplier_flux_coupling();
}

Vector DrainedTransport::right_hand_side(const Vector& r_flux, const Vector& r_potential) const {
  const Vector lumped = flux_inverse_ * r_flux;
  Vector rhs(system_.rows());
  const Index P = r_potential.size();
  rhs.head(P) = r_potential - multiplier_flux_ * lumped;
  rhs.tail(rhs.size() - P) = -(divergence_ * lumped);
  return rhs;
}

Vector DrainedTransport::fluxes(const Vector& r_flux, const Vector& solution) const {
  const Index P = flux_potential_.cols();
  const Vector b = r_flux + divergence_rate_ * solution.tail(solution.size() - P) -
                   flux_potential_ * solution.head(P);
  return flux_inverse_ * b;
}

} // namespace trifem::linalg
