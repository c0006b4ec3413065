// SPDX-License-Identifier: MIT
#include "trifem/contact/active_set.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::contact {

bool ActiveSet::wanted(Index k, const NodeStatus& s) const {
  if (!s.admissible)
    return false;
  if (!initialized_)
    return s.gap <= settings_.gap_tolerance;
  return active_[k] ? s.indicator <= settings_.release_threshold : s.indicator < 0;
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
  }
  ++evaluations_;
  std::vector<Index> wanted_flips;
  Index flips = 0;
  for (Index k = 0; k < static_cast<Index>(nodes.size()); ++k) {
    if (wanted(k, nodes[k]) == active(k))
      continue;
    if (nodes[k].admissible) {
      wanted_flips.push_back(k);
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
    for (Index k : wanted_flips) {
      active_[k] = !active_[k];
      ++flips;
    }
  initialized_ = true;
  flips_step_ += flips;
  return flips;
}

void ActiveSet::assign(std::vector<char> active) {
  TRIFEM_VERIFY(active.size() == active_.size(), "one flag per slave node");
  active_ = std::move(active);
  initialized_ = true;
}

Index ActiveSet::num_active() const {
  return static_cast<Index>(
      std::count_if(active_.begin(), active_.end(), [](char a) { return a != 0; }));
}

} // namespace trifem::contact
