// SPDX-License-Identifier: MIT
// Fields -> degrees of freedom -> equations.
//
// Every field lives on a set of entities (nodes, cells, or any indexed set such as contact
// slave nodes) with a fixed number of components. DOFs are numbered field by field:
// dof = offset(field) + entity * components + component. After finalize(), every free DOF has
// an equation number; constrained DOFs have a constrained number instead. Vectors of "all DOFs"
// hold the full state (prescribed values included); residual entries at constrained DOFs are
// the reactions.
#pragma once

#include "trifem/core/field_role.hpp"
#include "trifem/core/types.hpp"

#include <string>
#include <vector>

namespace trifem::dofs {

/// Typed handle of a field (never a string lookup in hot code).
struct FieldId {
  int index = -1;
  bool valid() const { return index >= 0; }
  friend bool operator==(FieldId, FieldId) = default;
};

/// Description of a field.
struct FieldInfo {
  std::string name;
  FieldRole role = FieldRole::displacement;
  Index num_entities = 0;
  int components = 0;
  Index offset = 0; ///< first DOF of the field
};

/// DOF numbering and the free/constrained split.
class DofMap {
public:
  /// Adds a field of `role` on `num_entities` entities with `components` components each.
  FieldId add_field(std::string name, FieldRole role, Index num_entities, int components);

  Index num_dofs() const { return num_dofs_; }
  int num_fields() const { return static_cast<int>(fields_.size()); }
  const FieldInfo& field(FieldId f) const { return fields_[f.index]; }

  /// Global DOF of (field, entity, component).
  Index dof(FieldId f, Index entity, int component) const {
    return fields_[f.index].offset + entity * fields_[f.index].components + component;
  }
  /// Field that owns a DOF.
  FieldId field_of(Index dof) const;

  /// Marks a DOF as constrained (prescribed). Must precede finalize().
  void constrain(Index dof);
  bool is_constrained(Index dof) const { return constrained_[dof]; }

  /// Links `follower` to `leader`: both become one unknown (one equation whose residual is the
  /// sum of both rows), e.g. the nodes of a rigid body sharing its translation. The leader must
  /// not be a follower itself. Both must end up free, or both constrained (then the tie has no
  /// effect: each keeps its prescribed value). Must precede finalize().
  void tie(Index follower, Index leader);
  /// The DOF whose unknown `dof` shares (itself unless tied).
  Index leader(Index dof) const { return leader_.empty() ? dof : leader_[dof]; }
  bool has_ties() const { return !leader_.empty(); }

  /// Makes `dof` dependent: it gets neither an equation nor a constrained index, its value
  /// follows other unknowns (a node carried by a rotating rigid body, RigidMap). It may be
  /// neither constrained nor tied. Must precede finalize(); reset_constraints() keeps it.
  void make_dependent(Index dof);
  bool is_dependent(Index dof) const { return !dependent_.empty() && dependent_[dof]; }

  /// Numbers equations (free leader DOFs, in DOF order; followers get their leader's) and
  /// constrained DOFs.
  void finalize();
  bool finalized() const { return finalized_; }
  /// Frees every DOF and reopens the map for constrain() and finalize() (fields and ties are
  /// kept): the constraints of the next analysis step replace those of the last.
  void reset_constraints();

  Index num_equations() const { return num_equations_; }
  Index num_constrained() const { return static_cast<Index>(constrained_dofs_.size()); }
  /// Equation of a free DOF (tied DOFs share one), or -1 (constrained or dependent).
  Index equation(Index dof) const { return equation_[dof]; }
  /// Index among constrained DOFs, or -1 (free or dependent).
  Index constrained_index(Index dof) const { return constrained_index_[dof]; }
  /// Leader DOF of an equation.
  Index dof_of_equation(Index eq) const { return equation_dofs_[eq]; }
  /// DOF of a constrained index.
  Index dof_of_constrained(Index c) const { return constrained_dofs_[c]; }

private:
  std::vector<FieldInfo> fields_;
  Index num_dofs_ = 0;
  Index num_equations_ = 0;
  bool finalized_ = false;
  std::vector<char> constrained_;
  std::vector<Index> leader_;   ///< empty until the first tie()
  std::vector<char> dependent_; ///< empty until the first make_dependent()
  std::vector<Index> equation_, constrained_index_, equation_dofs_, constrained_dofs_;
};

} // namespace trifem::dofs
