// SPDX-License-Identifier: MIT
#include "trifem/dofs/dof_map.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>

namespace trifem::dofs {

FieldId DofMap::add_field(std::string name, FieldRole role, Index num_entities, int components) {
  TRIFEM_VERIFY(!finalized_, "cannot add field '{}' after finalize()", name);
  TRIFEM_VERIFY(num_entities >= 0 && components > 0, "bad size of field '{}'", name);
  fields_.push_back({std::move(name), role, num_entities, components, num_dofs_});
  num_dofs_ += num_entities * components;
  constrained_.resize(num_dofs_, 0);
  for (Index d = static_cast<Index>(leader_.size()); !leader_.empty() && d < num_dofs_; ++d)
    leader_.push_back(d);
  if (!dependent_.empty())
    dependent_.resize(num_dofs_, 0);
  return FieldId{static_cast<int>(fields_.size()) - 1};
}

FieldId DofMap::field_of(Index dof) const {
  for (int f = num_fields() - 1; f >= 0; --f)
    if (dof >= fields_[f].offset)
      return FieldId{f};
  TRIFEM_VERIFY(false, "DOF {} belongs to no field", dof);
  return {};
}

void DofMap::constrain(Index dof) {
  TRIFEM_VERIFY(!finalized_, "cannot constrain DOF {} after finalize()", dof);
  TRIFEM_VERIFY(dof >= 0 && dof < num_dofs_, "DOF {} out of range", dof);
  constrained_[dof] = 1;
}

void DofMap::tie(Index follower, Index leader) {
  TRIFEM_VERIFY(!finalized_, "cannot tie DOF {} after finalize()", follower);
  TRIFEM_VERIFY(follower >= 0 && follower < num_dofs_ && leader >= 0 && leader < num_dofs_,
                "tie {} -> {} out of range", follower, leader);
  if (leader_.empty()) {
    leader_.resize(num_dofs_);
    for (Index d = 0; d < num_dofs_; ++d)
      leader_[d] = d;
  }
  TRIFEM_VERIFY(leader_[leader] == leader, "DOF {} is tied to {}: it cannot lead DOF {}", leader,
                leader_[leader], follower);
  TRIFEM_VERIFY(leader_[follower] == follower || leader_[follower] == leader,
                "DOF {} is already tied to {}", follower, leader_[follower]);
  leader_[follower] = leader;
}

void DofMap::make_dependent(Index dof) {
  TRIFEM_VERIFY(!finalized_, "cannot make DOF {} dependent after finalize()", dof);
  TRIFEM_VERIFY(dof >= 0 && dof < num_dofs_, "DOF {} out of range", dof);
  dependent_.resize(num_dofs_, 0);
  dependent_[dof] = 1;
}

void DofMap::finalize() {
  equation_.assign(num_dofs_, -1);
  constrained_index_.assign(num_dofs_, -1);
  equation_dofs_.clear();
  constrained_dofs_.clear();
  for (Index d = 0; d < num_dofs_; ++d) {
    const Index lead = leader(d);
    if (is_dependent(d)) {
      TRIFEM_VERIFY(!constrained_[d] && lead == d, "DOF {} is dependent and {}", d,
                    constrained_[d] ? "constrained" : "tied");
      continue;
    }
    TRIFEM_VERIFY(!is_dependent(lead), "DOF {} is tied to the dependent DOF {}", d, lead);
    TRIFEM_VERIFY(constrained_[d] == constrained_[lead],
                  "tied DOFs {} and {}: one is constrained, the other free", d, lead);
    if (constrained_[d]) {
      constrained_index_[d] = static_cast<Index>(constrained_dofs_.size());
      constrained_dofs_.push_back(d);
    } else if (lead != d) {
      continue; // numbered after the loop (the leader may come later)
    } else {
      equation_[d] = static_cast<Index>(equation_dofs_.size());
      equation_dofs_.push_back(d);
    }
  }
  for (Index d = 0; d < num_dofs_ && has_ties(); ++d)
    if (!constrained_[d] && !is_dependent(d))
      equation_[d] = equation_[leader(d)];
  num_equations_ = static_cast<Index>(equation_dofs_.size());
  finalized_ = true;
}

void DofMap::reset_constraints() {
  std::fill(constrained_.begin(), constrained_.end(), 0);
  finalized_ = false;
}

} // namespace trifem::dofs
