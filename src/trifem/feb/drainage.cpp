// SPDX-License-Identifier: MIT
// FEBio's natural boundary condition of mixtures written out: a face without a fluid pressure
// condition is impermeable in FEBio and free-draining in trifem (docs/feb.md).
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <numbers>
#include <set>

namespace trifem::feb::detail {
namespace {

/// Facets of one smooth patch meet at less than this angle; a sharper edge (a box corner)
/// separates two patches, whose normals are both constrained at the nodes they share.
constexpr Real kFeatureAngleDegrees = 60.0;

using FaceKey = std::array<Index, 4>;

FaceKey key_of(std::array<Index, 4> nodes) {
  std::sort(nodes.begin(), nodes.end());
  return nodes;
}

/// The cells whose material is a mixture.
std::vector<char> mixture_cells(const Reader& r) {
  std::vector<char> mixture(r.mesh.mesh.num_cells(), 0);
  for (const auto& [block, material] : r.mesh.materials)
    if (r.spec.materials.at(material).is_mixture())
      for (Index c : r.mesh.mesh.cell_block(block))
        mixture[c] = 1;
  return mixture;
}

Vec3 unit_normal(const mesh::Mesh& mesh, const mesh::Facet& f) {
  const Vec3 n = (mesh.node(f.nodes[2]) - mesh.node(f.nodes[0]))
                     .cross(mesh.node(f.nodes[3]) - mesh.node(f.nodes[1]));
  return n.normalized();
}

/// The axis a plane patch is normal to (-1: none).
int normal_axis(const mesh::Mesh& mesh, const std::vector<mesh::Facet>& facets) {
  const Vec3 n = unit_normal(mesh, facets.front());
  int axis = 0;
  n.cwiseAbs().maxCoeff(&axis);
  if (std::abs(std::abs(n[axis]) - 1.0) > 1e-12)
    return -1;
  for (const mesh::Facet& f : facets)
    if ((unit_normal(mesh, f) - n).norm() > 1e-12)
      return -1;
  return axis;
}

/// Splits facets into patches: facets sharing an edge belong to one patch if their normals meet
/// at less than the feature angle.
std::vector<std::vector<mesh::Facet>> patches(const mesh::Mesh& mesh,
                                              const std::vector<mesh::Facet>& facets) {
  const Real cos_limit = std::cos(kFeatureAngleDegrees * std::numbers::pi / 180.0);
  std::vector<Vec3> normals;
  std::map<std::pair<Index, Index>, std::vector<std::size_t>> by_edge;
  for (std::size_t i = 0; i < facets.size(); ++i) {
    normals.push_back(unit_normal(mesh, facets[i]));
    for (int k = 0; k < 4; ++k) {
      Index a = facets[i].nodes[k], b = facets[i].nodes[(k + 1) % 4];
      if (a != b) // (a triangle's fourth corner repeats its third)
        by_edge[{std::min(a, b), std::max(a, b)}].push_back(i);
    }
  }
  std::vector<int> patch(facets.size(), -1);
  std::vector<std::vector<mesh::Facet>> out;
  for (std::size_t seed = 0; seed < facets.size(); ++seed) {
    if (patch[seed] >= 0)
      continue;
    const int p = static_cast<int>(out.size());
    out.emplace_back();
    std::vector<std::size_t> stack{seed};
    patch[seed] = p;
    while (!stack.empty()) {
      const std::size_t i = stack.back();
      stack.pop_back();
      out[p].push_back(facets[i]);
      for (int k = 0; k < 4; ++k) {
        Index a = facets[i].nodes[k], b = facets[i].nodes[(k + 1) % 4];
        for (std::size_t j : by_edge[{std::min(a, b), std::max(a, b)}])
          if (patch[j] < 0 && normals[i].dot(normals[j]) > cos_limit) {
            patch[j] = p;
            stack.push_back(j);
          }
      }
    }
  }
  return out;
}

/// The baths of the prescribed fluid pressures of a biphasic model: the boundary faces whose
/// nodes all carry the condition, at gauge pressure value x curve(t) (FEBio's pressure does not
/// push on the surface, nor does the bath's).
void add_pressure_baths(Reader& r, const std::vector<mesh::Facet>& boundary,
                        std::set<FaceKey>& open) {
  for (std::size_t k = 0; k < r.pressure_baths.size(); ++k) {
    const EffectiveCondition& c = *r.pressure_baths[k];
    const auto& set = r.mesh.mesh.node_set(c.set);
    const std::set<Index> nodes(set.begin(), set.end());
    std::vector<mesh::Facet> faces;
    for (const mesh::Facet& f : boundary)
      if (!open.contains(key_of(f.nodes)) &&
          std::all_of(f.nodes.begin(), f.nodes.end(), [&](Index n) { return nodes.contains(n); }))
        faces.push_back(f);
    if (faces.empty())
      r.doc.fail(c.bc, "no boundary face of the mixture has all its nodes in this set: trifem "
                       "prescribes a fluid pressure as a bath on faces");
    for (const mesh::Facet& f : faces)
      open.insert(key_of(f.nodes));
    const std::string name = fmt::format("bath#{}", k + 1);
    r.mesh.mesh.add_surface(name, mesh::Surface{faces});
    io::BathSpec bath;
    bath.surface = name;
    bath.pressure = c.value;
    bath.curve = c.curve;
    r.spec.baths.push_back(bath);
  }
}

} // namespace

void add_impermeable_faces(Reader& r) {
  const std::vector<char> mixture = mixture_cells(r);
  if (std::none_of(mixture.begin(), mixture.end(), [](char m) { return m != 0; }))
    return;
  // faces of contact surfaces (the contact law governs them) and of prescribed fluid fluxes
  std::set<FaceKey> open;
  for (const io::ContactSpec& c : r.spec.contacts)
    for (const std::string& name : {c.master, c.slave})
      for (const mesh::Facet& f : r.mesh.mesh.surface(name).facets)
        open.insert(key_of(f.nodes));
  for (const std::string& name : r.flux_surfaces)
    for (const mesh::Facet& f : r.mesh.mesh.surface(name).facets)
      open.insert(key_of(f.nodes));
  // faces of mixture cells that no other mixture cell shares (the mesh boundary and interfaces
  // with solid cells), outward-oriented
  const std::vector<mesh::Facet> boundary = r.mesh.mesh.boundary_facets(mixture);
  add_pressure_baths(r, boundary, open);
  std::vector<mesh::Facet> closed;
  for (const mesh::Facet& f : boundary)
    if (!open.contains(key_of(f.nodes)) &&
        !std::all_of(f.nodes.begin(), f.nodes.end(), [&](Index n) { return r.drained[n] != 0; }))
      closed.push_back(f);
  const auto groups = patches(r.mesh.mesh, closed);
  const bool ions = r.multiphasic_module;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const std::string name = fmt::format("impermeable#{}", k + 1);
    const std::string key = fmt::format("FEBio's natural condition (no flux), faces without "
                                        "drainage or flux conditions, patch {}",
                                        k + 1);
    r.mesh.mesh.add_surface(name, mesh::Surface{groups[k]});
    // a plane patch normal to an axis: that flux component is zero at its nodes (which combines
    // with flux conditions of other components there); any other patch: nodal normal frames
    if (const int axis = normal_axis(r.mesh.mesh, groups[k]); axis >= 0) {
      io::FixedSpec fixed{key, name, {axis}, {io::FieldKind::FluidFlux}};
      if (ions)
        fixed.fields = {io::FieldKind::FluidFlux, io::FieldKind::CationFlux,
                        io::FieldKind::AnionFlux};
      r.spec.fixed.push_back(fixed);
    } else {
      r.spec.impermeable_surfaces.push_back({key, name});
    }
  }
}

} // namespace trifem::feb::detail
