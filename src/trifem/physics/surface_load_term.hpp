// SPDX-License-Identifier: MIT
// Surface loads on facets of any family (quad4 by facet_area.hpp, tri3, tri6 and quad8 by
// facet_area_any.hpp): follower pressure and dead traction.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/mesh/mesh.hpp"
#include "trifem/physics/facet_area_any.hpp"
#include "trifem/physics/term.hpp"

namespace trifem::physics {

/// Which normal and area a pressure acts with.
enum class PressureNormal {
  Current,   ///< a follower: the current normal and area
  Reference, ///< a dead load: the reference normal and area
};

/// Pressure p(t) = magnitude * curve(t), positive pushing into the body: a follower on the
/// current surface, f_ext,a = -int N_a p n da = -int N_a p (x_xi x x_eta) dxi deta, whose
/// tangent is the (unsymmetric) load stiffness; or a dead load along the reference normal,
/// f_ext,a = -int N_a p N dA (no stiffness).
class PressureTerm final : public Term {
public:
  PressureTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
               std::vector<mesh::Facet> facets, Real magnitude, dofs::LoadCurve curve,
               PressureNormal normal = PressureNormal::Current);
  std::string name() const override { return "pressure"; }
  Index num_elements() const override { return static_cast<Index>(facets_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

private:
  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_;
  std::vector<mesh::Facet> facets_;
  Real magnitude_;
  dofs::LoadCurve curve_;
  std::vector<FacetVectorX> reference_areas_; ///< int N_a N dA per facet (Reference only)
};

/// The area a traction acts per.
enum class TractionArea {
  Reference, ///< per reference area: a dead load, f_ext,a = int N_a t dA
  Current,   ///< per current area, in a fixed direction: f_ext,a = int N_a t da
};

/// Traction t(t) = vector * curve(t) in a fixed direction, per reference area (a dead load) or
/// per current area: f_ext,a = int N_a t |x_s1 x x_s2| ds, whose tangent is
///   df_ext,a/dx_b = t (x) int N_a [N_b,s1 (x_s2 x n) + N_b,s2 (n x x_s1)] ds,  n = the unit normal
/// (d|a| = n . da, da = dx_s1 x x_s2 + x_s1 x dx_s2), by the facet's rule.
class TractionTerm final : public Term {
public:
  TractionTerm(const mesh::Mesh& mesh, const dofs::DofMap& dofs, dofs::FieldId displacement,
               std::vector<mesh::Facet> facets, Vec3 traction, dofs::LoadCurve curve,
               TractionArea area = TractionArea::Reference);
  std::string name() const override { return "traction"; }
  Index num_elements() const override { return static_cast<Index>(facets_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

private:
  const mesh::Mesh& mesh_;
  const dofs::DofMap& dofs_;
  dofs::FieldId u_;
  std::vector<mesh::Facet> facets_;
  std::vector<std::vector<Real>> nodal_area_; ///< int N_a dA per facet and node (Reference)
  Vec3 traction_;
  dofs::LoadCurve curve_;
  TractionArea area_;
};

} // namespace trifem::physics
