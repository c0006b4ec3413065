// SPDX-License-Identifier: MIT
#include "trifem/physics/nodal_dilatation.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>

namespace trifem::physics {

namespace {

/// The elements of `cells` at every mesh node (CSR over the mesh's nodes).
std::vector<std::vector<Index>> elements_at_nodes(const mesh::Mesh& mesh,
                                                  std::span<const Index> cells) {
  std::vector<std::vector<Index>> at(static_cast<std::size_t>(mesh.num_nodes()));
  for (std::size_t i = 0; i < cells.size(); ++i)
    for (const Index a : mesh.cell_nodes(cells[i]))
      at[static_cast<std::size_t>(a)].push_back(static_cast<Index>(i));
  return at;
}

Real reference_volume(const CellGeometry& geo) {
  Real V = 0.0;
  for (const Real w : geo.dV)
    V += w;
  return V;
}

} // namespace

NodalDilatation::NodalDilatation(const mesh::Mesh& mesh, std::span<const Index> cells,
                                 std::vector<const CellGeometry*> geometry)
    : geometry_(std::move(geometry)) {
  TRIFEM_VERIFY(geometry_.size() == cells.size(), "one geometry per cell expected");
  const std::vector<std::vector<Index>> at = elements_at_nodes(mesh, cells);
  // V_a = Σ_{e∋a} V_e / n_e
  std::vector<Real> node_volume(static_cast<std::size_t>(mesh.num_nodes()), 0.0);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::span<const Index> nodes = mesh.cell_nodes(cells[i]);
    const Real share = reference_volume(*geometry_[i]) / static_cast<Real>(nodes.size());
    for (const Index a : nodes)
      node_volume[static_cast<std::size_t>(a)] += share;
  }
  patch_offsets_ = {0};
  neighbour_offsets_ = {0};
  local_offsets_ = {0};
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::span<const Index> own = mesh.cell_nodes(cells[i]);
    const auto n_i = static_cast<Real>(own.size());
    // ω_ij = (1/n_i) Σ_{a∈i∩j} 1/(V_a n_j), the neighbours in increasing order
    std::vector<std::pair<Index, Real>> weights;
    for (const Index a : own)
      for (const Index j : at[static_cast<std::size_t>(a)]) {
        const auto n_j = static_cast<Real>(mesh.cell_nodes(cells[j]).size());
        weights.emplace_back(j, 1.0 / (n_i * node_volume[static_cast<std::size_t>(a)] * n_j));
      }
    std::sort(weights.begin(), weights.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<Index> patch(own.begin(), own.end());
    for (std::size_t k = 0; k < weights.size();) {
      Neighbour nb{weights[k].first, 0.0};
      for (; k < weights.size() && weights[k].first == nb.element; ++k)
        nb.weight += weights[k].second;
      neighbours_.push_back(nb);
      for (const Index b : mesh.cell_nodes(cells[nb.element])) {
        auto it = std::find(patch.begin(), patch.end(), b);
        if (it == patch.end())
          it = patch.insert(patch.end(), b);
        local_.push_back(static_cast<Index>(it - patch.begin()));
      }
      local_offsets_.push_back(static_cast<Index>(local_.size()));
    }
    neighbour_offsets_.push_back(static_cast<Index>(neighbours_.size()));
    patch_nodes_.insert(patch_nodes_.end(), patch.begin(), patch.end());
    patch_offsets_.push_back(static_cast<Index>(patch_nodes_.size()));
  }
}

std::span<const Index> NodalDilatation::patch(Index i) const {
  const auto first = static_cast<std::size_t>(patch_offsets_[i]);
  return {patch_nodes_.data() + first, static_cast<std::size_t>(patch_offsets_[i + 1]) - first};
}

std::span<const NodalDilatation::Neighbour> NodalDilatation::neighbours(Index i) const {
  const auto first = static_cast<std::size_t>(neighbour_offsets_[i]);
  return {neighbours_.data() + first, static_cast<std::size_t>(neighbour_offsets_[i + 1]) - first};
}

namespace {

/// The rows `local` of the patch displacements u.
fe::CellNodeCoords rows_of(const Eigen::MatrixX3d& u, std::span<const Index> local) {
  fe::CellNodeCoords out(static_cast<Index>(local.size()), 3);
  for (std::size_t a = 0; a < local.size(); ++a)
    out.row(static_cast<Index>(a)) = u.row(local[a]);
  return out;
}

} // namespace

bool NodalDilatation::evaluate(Index i, const Eigen::MatrixX3d& u, const material::ElasticLaw& law,
                               LocalVector& r, LocalMatrix* K) const {
  const auto m = static_cast<Index>(3 * u.rows());
  // J̄_i = Σ_j ω_ij v_j with its gradient g and second derivative H over the patch
  Real Jbar = 0.0;
  LocalVector g = LocalVector::Zero(m);
  LocalMatrix H;
  if (K)
    H.setZero(m, m);
  const Index first = neighbour_offsets_[i];
  CellVolume volume;
  for (Index k = first; k < neighbour_offsets_[i + 1]; ++k) {
    const Neighbour& nb = neighbours_[static_cast<std::size_t>(k)];
    const std::span<const Index> local(
        local_.data() + local_offsets_[k],
        static_cast<std::size_t>(local_offsets_[k + 1] - local_offsets_[k]));
    if (!cell_volume(*geometry_[nb.element], rows_of(u, local), K != nullptr, volume))
      return false;
    Jbar += nb.weight * volume.v;
    for (std::size_t a = 0; a < local.size(); ++a) {
      g.segment<3>(3 * local[a]) += nb.weight * volume.grad.segment<3>(3 * static_cast<Index>(a));
      if (!K)
        continue;
      for (std::size_t b = 0; b < local.size(); ++b)
        H.block<3, 3>(3 * local[a], 3 * local[b]) +=
            nb.weight *
            volume.hess.block<3, 3>(3 * static_cast<Index>(a), 3 * static_cast<Index>(b));
    }
  }
  const CellGeometry& geo = *geometry_[i];
  const int own = 3 * geo.num_nodes();
  DilatationSplit split;
  if (!(Jbar > 0.0) ||
      !dilatation_split(geo, u.topRows(geo.num_nodes()), law, Jbar, K != nullptr, split))
    return false;
  // Π_i(u, J̄_i(u)): f = f_u + π g, K = K_uu + f_uJ gᵀ + g f_uJᵀ + π_J g gᵀ + π H
  r = split.pi * g;
  r.head(own) += split.f_u;
  if (!K)
    return true;
  *K = split.pi * H;
  K->noalias() += split.pi_J * g * g.transpose();
  K->topLeftCorner(own, own) += split.K_uu;
  K->topRows(own).noalias() += split.f_uJ * g.transpose();
  K->leftCols(own).noalias() += g * split.f_uJ.transpose();
  return true;
}

Real NodalDilatation::dilatation(Index i, const Eigen::MatrixX3d& u) const {
  Real Jbar = 0.0;
  CellVolume volume;
  for (Index k = neighbour_offsets_[i]; k < neighbour_offsets_[i + 1]; ++k) {
    const Neighbour& nb = neighbours_[static_cast<std::size_t>(k)];
    const std::span<const Index> local(
        local_.data() + local_offsets_[k],
        static_cast<std::size_t>(local_offsets_[k + 1] - local_offsets_[k]));
    if (!cell_volume(*geometry_[nb.element], rows_of(u, local), false, volume))
      return 0.0;
    Jbar += nb.weight * volume.v;
  }
  return Jbar;
}

} // namespace trifem::physics
