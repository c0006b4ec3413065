// SPDX-License-Identifier: MIT
// Material axes: the local orthonormal basis in which a material's directions (fibre vectors,
// ellipsoid semi-axes) are given, constant or varying over the body (FEBio's mat_axis in spirit).
#pragma once

#include "trifem/tensor/tensor.hpp"

#include <string>

namespace trifem::material {

/// How the local basis Q = [e1 e2 e3] of a material is built ([materials.<name>.axes]).
enum class AxesKind {
  Vector,      ///< constant: e1 along a, e2 in the plane of a and d
  Cylindrical, ///< per cell: e1 radial, e2 circumferential, e3 along the axis
  Spherical,   ///< per cell: e1 radial, e2 azimuthal about the pole axis, e3 = e1 x e2
  Mesh,        ///< per cell: e1 (and optionally d) from cell data of the mesh (Gmsh $ElementData)
};

/// The axes of a material, as the case gives them (validated by the case reader).
struct AxesSpec {
  AxesKind kind = AxesKind::Vector;
  Vec3 a = Vec3::UnitX();     ///< Vector: the direction of e1
  Vec3 d = Vec3::UnitY();     ///< Vector: a direction in the (e1, e2) plane, not along a
  Vec3 center = Vec3::Zero(); ///< Cylindrical: a point of the axis; Spherical: the centre
  Vec3 axis = Vec3::UnitZ();  ///< Cylindrical: the cylinder axis; Spherical: the pole axis
  std::string view;           ///< Mesh: the cell data (3 components) giving e1
  std::string d_view; ///< Mesh: the cell data giving d as for Vector; empty: completed_basis
};

/// The basis of `kind` = Vector: e1 = a/|a|, e2 = (d - (d.e1) e1)/|...|, e3 = e1 x e2.
/// InputError naming `context`.a / `context`.d if a is zero or d is (nearly) parallel to a:
/// |d - (d.e1) e1| <= 1e-8 |d|.
Mat3 vector_basis(const Vec3& a, const Vec3& d, const std::string& context);

/// The cylindrical basis at `point`: e3 = axis/|axis|, e1 = the unit radial direction (the part
/// of point - center normal to the axis), e2 = e3 x e1 (circumferential, counter-clockwise
/// about the axis). InputError naming `context` if the point lies on the axis (radial distance
/// <= 1e-8 times |point - center|, or exactly 0).
Mat3 cylindrical_basis(const Vec3& center, const Vec3& axis, const Vec3& point,
                       const std::string& context);

/// The spherical basis at `point`: e1 = (point - center)/|...| (radial), e2 = unit(axis x e1)
/// (azimuthal about the pole axis), e3 = e1 x e2 (towards the pole +axis along the meridian).
/// InputError naming `context` if the point is the centre or lies on the pole axis through
/// it (where the azimuthal direction is undefined).
Mat3 spherical_basis(const Vec3& center, const Vec3& axis, const Vec3& point,
                     const std::string& context);

/// The basis completing one direction e1 (the rule for directions given per cell by mesh
/// element data without a d view): e2 = the unit part normal to e1 of
/// the global axis least aligned with e1 (x, y, z in that order on ties), e3 = e1 x e2.
/// InputError naming `context` if e1 is zero or not finite.
Mat3 completed_basis(const Vec3& e1, const std::string& context);

/// The basis of `axes` at `point` (a cell centroid; unused by Vector). Not for Mesh, whose
/// directions are per cell (model::orient_cells): LogicError.
Mat3 axes_basis(const AxesSpec& axes, const Vec3& point, const std::string& context);

} // namespace trifem::material
