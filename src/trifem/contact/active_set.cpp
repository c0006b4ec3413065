// SPDX-License-Identifier: MIT
#include "trifem/contact/active_set.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::contact {

NodeContact ActiveSet::wanted(Index k, const NodeStatus& s) const {
  const NodeContact target = normal_wanted(k, s);
  if (!s.frictional || target == NodeContact::Open || !initialized_)
    return target;
  const auto current = static_cast<NodeContact>(active_[k]);
  if (current == NodeContact::Slipping)
    return s.slip < -settings_.release_threshold ? NodeContact::Sealed : NodeContact::Slipping;
  if (current == NodeContact::Sealed && s.slip > settings_.release_threshold)
    return NodeContact::Slipping;
  return NodeContact::Sealed;
}

NodeContact ActiveSet::normal_wanted(Index k, const NodeStatus& s) const {
  const auto current = static_cast<NodeContact>(active_[k]);
  if (!s.admissible)
    return NodeContact::Open;
  if (!initialized_)
    return s.gap <= settings_.gap_tolerance ? NodeContact::Sealed : NodeContact::Open;
  if (current == NodeContact::Open)
    return s.indicator < 0 ? NodeContact::Sealed : NodeContact::Open;
  if (current == NodeContact::Wetted && s.indicator < -settings_.release_threshold &&
      !wetted_in_step_[k])
    return NodeContact::Sealed; // pressed again: the surfaces close the interface to the bath
  if (s.indicator <= settings_.release_threshold)
    return current; // compressive or at most ε_t of tension: stays
  return current == NodeContact::Sealed && s.wettable ? NodeContact::Wetted : NodeContact::Open;
}

bool ActiveSet::settled(const std::vector<NodeStatus>& nodes) const {
  for (Index k = 0; k < static_cast<Index>(nodes.size()); ++k)
    if (active(k) && nodes[k].admissible && std::abs(nodes[k].gap) > settings_.gap_tolerance)
      return false;
  return true;
}

Index ActiveSet::update(Real time, const std::vector<NodeStatus>& nodes) {
  TRIFEM_VERIFY(nodes.size() == active_.size(), "one status per slave node");
  if (new_step_ || time != time_) {
    evaluations_ = 0;
    resolves_ = 0;
    flips_step_ = 0;
    new_step_ = false;
    time_ = time;
    std::fill(wetted_in_step_.begin(), wetted_in_step_.end(), 0);
  }
  ++evaluations_;
  std::vector<std::pair<Index, NodeContact>> wanted_flips;
  Index flips = 0;
  for (Index k = 0; k < static_cast<Index>(nodes.size()); ++k) {
    const NodeContact target = wanted(k, nodes[k]);
    if (static_cast<char>(target) == active_[k])
      continue;
    if (nodes[k].admissible) {
      wanted_flips.emplace_back(k, target);
    } else {
      active_[k] = 0; // lost its projection: always released
      ++flips;
    }
  }
  bool allow = !initialized_ || settings_.update;
  if (allow && initialized_ && evaluations_ > settings_.max_updates) {
    allow = resolves_ < settings_.max_resolves && settled(nodes);
    resolves_ += allow && !wanted_flips.empty();
  }
  pending_ = allow || !settings_.update ? 0 : static_cast<Index>(wanted_flips.size());
  if (allow)
    for (const auto& [k, target] : wanted_flips) {
      if (target == NodeContact::Wetted)
        wetted_in_step_[k] = 1; // no re-seal in this step: sealed it would pull (chatter)
      active_[k] = static_cast<char>(target);
      ++flips;
    }
  initialized_ = true;
  flips_step_ += flips;
  return flips;
}

void ActiveSet::assign(std::vector<char> active) {
  TRIFEM_VERIFY(active.size() == active_.size(), "one flag per slave node");
  active_ = std::move(active);
  std::fill(wetted_in_step_.begin(), wetted_in_step_.end(), 0);
  initialized_ = true;
}

Index ActiveSet::num_active() const {
  return static_cast<Index>(
      std::count_if(active_.begin(), active_.end(), [](char a) { return a != 0; }));
}

} // namespace trifem::contact
