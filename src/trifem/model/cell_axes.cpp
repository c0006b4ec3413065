// SPDX-License-Identifier: MIT
#include "trifem/model/cell_axes.hpp"

#include "trifem/core/error.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/rotated_law.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fmt/ranges.h>
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
  const std::span<const Index> nodes = mesh.cell_nodes(cell);
  for (Index n : nodes)
    x += mesh.node(n);
  return x / static_cast<Real>(nodes.size());
}

std::string text(const Vec3& v) {
  return fmt::format("[{}, {}, {}]", v.x(), v.y(), v.z());
}

/// The cell data `view` (the value of materials.<name>.axes.<key>): InputError listing the
/// views of the mesh if there is none of this name, or if it is no vector (3 components).
const mesh::CellData& direction_view(const mesh::Mesh& mesh, const std::string& view,
                                     const std::string& name, const std::string& key) {
  if (!mesh.has_cell_data(view)) {
    std::vector<std::string> views;
    for (const auto& [view_name, data] : mesh.cell_data())
      views.push_back(view_name);
    throw InputError(fmt::format(
        "materials.{}.axes.{} = '{}': the mesh has no element data view of this name (views: "
        "{}; a Gmsh $ElementData section names its view in its first string tag)",
        name, key, view,
        views.empty() ? std::string("none") : fmt::to_string(fmt::join(views, ", "))));
  }
  const mesh::CellData& data = mesh.cell_data(view);
  TRIFEM_CHECK(data.components == 3,
               "materials.{}.axes.{} = '{}': the view has {} components per element, a "
               "direction needs 3",
               name, key, view, data.components);
  return data;
}

/// The vector of `cell` in the view `key` = `view`: InputError naming the cell if the view has
/// no value there or a zero vector.
Vec3 view_vector(const mesh::Mesh& mesh, Index cell, const std::string& name,
                 const std::string& key, const std::string& view) {
  const mesh::CellData& data = direction_view(mesh, view, name, key);
  TRIFEM_CHECK(data.covers(cell),
               "materials.{}.axes (cell {}, centroid {}): the view '{}' ({}) has no value for "
               "this cell; every cell of the material needs one",
               name, cell, text(centroid(mesh, cell)), view, key);
  const Vec3 v(data.value(cell, 0), data.value(cell, 1), data.value(cell, 2));
  TRIFEM_CHECK(v.norm() > 0.0,
               "materials.{}.axes (cell {}, centroid {}): the view '{}' ({}) gives the zero "
               "vector, which has no direction",
               name, cell, text(centroid(mesh, cell)), view, key);
  return v;
}

/// The basis of a cell from the views of axes of kind Mesh: e1 along the view `view`, completed
/// by material::completed_basis or, with a `d_view`, e2 = the part of d normal to e1.
Mat3 mesh_basis(const material::AxesSpec& axes, const mesh::Mesh& mesh, Index cell,
                const std::string& name) {
  const Vec3 a = view_vector(mesh, cell, name, "view", axes.view);
  const std::string context = fmt::format("materials.{}.axes (cell {})", name, cell);
  if (axes.d_view.empty())
    return material::completed_basis(a, context);
  const Vec3 d = view_vector(mesh, cell, name, "d_view", axes.d_view);
  try {
    return material::vector_basis(a, d, context);
  } catch (const InputError&) {
    throw InputError(fmt::format(
        "{}: the direction {} of view '{}' (d_view) is parallel to the direction {} of view "
        "'{}' (view), so it fixes no (e1, e2) plane",
        context, text(d), axes.d_view, text(a), axes.view));
  }
}

/// The basis of `cell` of the material `name` with `axes`.
Mat3 cell_basis(const material::AxesSpec& axes, const mesh::Mesh& mesh, Index cell,
                const std::string& name) {
  if (axes.kind == material::AxesKind::Mesh)
    return mesh_basis(axes, mesh, cell, name);
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
    if (!material_of[c])
      continue; // a cell of a rigid body
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
