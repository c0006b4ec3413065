// SPDX-License-Identifier: MIT
// Prescribed DOF values: value(t) = magnitude * curve(t) (or a given law) on a list of DOFs.
#pragma once

#include "trifem/dofs/dof_map.hpp"
#include "trifem/dofs/load_curve.hpp"

#include <functional>
#include <vector>

namespace trifem::dofs {

/// A set of DOFs sharing one prescribed value history (zero: a fixed condition).
struct DirichletCondition {
  std::vector<Index> dofs;
  Real magnitude = 0.0;
  LoadCurve curve = LoadCurve::constant(1.0);
  /// Per DOF (empty: none): added to the value, e.g. the state at the start of a step for a
  /// condition relative to it.
  std::vector<Real> offsets = {};
  /// A value history other than magnitude × curve (e.g. a component of the rotation vector of
  /// prescribed Euler angles); empty: magnitude × curve.
  std::function<Real(Real)> law = {};

  Real value(Real t) const { return law ? law(t) : magnitude * curve(t); }
};

/// Marks the DOFs of every condition as constrained in `map` (before finalize()).
void constrain_all(const std::vector<DirichletCondition>& conditions, DofMap& map);

/// Writes the prescribed values at time t into `target` (size num_dofs; other entries kept).
/// Later conditions override earlier ones on shared DOFs.
void prescribed_values(const std::vector<DirichletCondition>& conditions, Real t, Vector& target);

} // namespace trifem::dofs
