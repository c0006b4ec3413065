// SPDX-License-Identifier: MIT
#include "trifem/model/cell_axes.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/rotated_law.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <utility>

namespace trifem::model {
namespace {

/// The bits of Q: bases that compare equal as keys are identical to the bit.
using BasisKey = std::array<std::uint64_t, 9>;

BasisKey key_of(const Mat3& Q) {
  BasisKey k;
  for (int i = 0; i < 9; ++i)
    std::memcpy(&k[static_cast<std::size_t>(i)], Q.data() + i, sizeof(Real));
  return k;
}

Vec3 centroid(const mesh::Mesh& mesh, Index cell) {
  Vec3 x = Vec3::Zero();
  for (Index n : mesh.cells()[static_cast<std::size_t>(cell)])
    x += mesh.node(n);
  return x / 8.0;
}

/// The basis of `cell` of the material `name` with `axes`.
Mat3 cell_basis(const material::AxesSpec& axes, const mesh::Mesh& mesh, Index cell,
                const std::string& name) {
  const std::string context = fmt::format("materials.{}.axes (cell {})", name, cell);
  return material::axes_basis(axes, centroid(mesh, cell), context);
}

/// `m` with its solid law (or its mixture's solid) in the basis Q.
CellMaterial rotated(const CellMaterial& m, const Mat3& Q) {
  CellMaterial r = m;
  if (m.mixture) {
    auto mixture = std::make_shared<material::MixtureProperties>(*m.mixture);
    mixture->solid = std::make_shared<material::RotatedLaw>(m.mixture->solid, Q);
    r.mixture = std::move(mixture);
  } else {
    r.solid = std::make_shared<material::RotatedLaw>(m.solid, Q);
  }
  return r;
}

} // namespace

std::vector<Mat3> orient_cells(const io::CaseSpec& spec, const mesh::Mesh& mesh,
                               const std::map<std::string, std::string>& blocks,
                               std::vector<CellMaterial>& per_cell) {
  bool any = false;
  for (const auto& [name, m] : spec.materials)
    any = any || m.axes.has_value();
  if (!any)
    return {};
  // The material of each cell, assigned in the order of cell_materials (the last block wins).
  std::vector<const std::string*> material_of(static_cast<std::size_t>(mesh.num_cells()));
  for (const auto& [block, material] : blocks)
    for (Index c : mesh.cell_block(block))
      material_of[static_cast<std::size_t>(c)] = &material;

  std::vector<Mat3> basis(material_of.size(), Mat3::Identity());
  std::map<std::pair<std::string, BasisKey>, CellMaterial> shared;
  for (std::size_t c = 0; c < material_of.size(); ++c) {
    const std::string& name = *material_of[c];
    const auto& axes = spec.materials.at(name).axes;
    if (!axes)
      continue;
    const Mat3 Q = cell_basis(*axes, mesh, static_cast<Index>(c), name);
    basis[c] = Q;
    if (Q == Mat3::Identity())
      continue; // the global basis: the law as it is, to the bit
    auto [it, inserted] = shared.try_emplace({name, key_of(Q)});
    if (inserted)
      it->second = rotated(per_cell[c], Q);
    per_cell[c] = it->second;
  }
  return basis;
}

} // namespace trifem::model
