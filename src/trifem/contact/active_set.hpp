// SPDX-License-Identifier: MIT
// Primal-dual active set (semismooth Newton) for the normal contact complementarity
// g ≥ 0, t ≤ 0, t g = 0 at the slave nodes (docs/theory/contact.md §5.2).
#pragma once

#include "trifem/core/types.hpp"

#include <vector>

namespace trifem::contact {

/// Parameters of the active-set strategy.
struct ActiveSetSettings {
  Real release_threshold = 0; ///< ε_t ≥ 0 [stress]: an active node is released only if its
                              ///< indicator t + c_N g exceeds ε_t (hysteresis)
  Real gap_tolerance = 0;     ///< [length] initial set: active where g ≤ gap_tolerance;
                              ///< a frozen set has settled when every active |g| ≤ it
  int max_updates = 5;        ///< free updates per step; then the set is frozen ...
  int max_resolves = 10;      ///< ... and updated again only once it has settled, at most
                              ///< this many times per step
  bool update = true;         ///< false: the set stays as initialised/assigned (tests)
};

/// What the active set needs to know of one slave node at one evaluation.
struct NodeStatus {
  bool admissible = false; ///< projects onto the master surface, not beyond its free boundary
  Real gap = 0;            ///< g_k [length]
  Real indicator = 0;      ///< complementarity function, e.g. t_k + c_N g_k [stress]
  bool wettable = false;   ///< the law has a wetted state (mixtures: see ActiveSet)
  bool frictional = false; ///< the law tells sticking from slipping nodes
  Real slip = 0;           ///< frictional: slip indicator, > 0 slipping [stress]
};

/// Contact status of a slave node (the stored flag; `Open` = 0 is inactive).
enum class NodeContact : char {
  Open = 0,   ///< separated or not projecting: traction-free (and free-draining for mixtures)
  Sealed = 1, ///< in contact; for mixtures the interface is sealed (potential and flux continuity)
  Wetted = 2, ///< in contact, but the interface is wetted by the bath (mixtures: free-draining)
  Slipping = 3, ///< in contact and slipping (frictional laws; Sealed is then sticking)
};

/// The set of active slave nodes. Rules, applied at every system evaluation (Term::prepare):
///   * a node that is not admissible is inactive (its row is t_k = 0);
///   * first evaluation of the run: active ⇔ admissible and g_k ≤ gap_tolerance (geometry);
///   * then (primal-dual): an inactive node becomes active (sealed) if t_k + c_N g_k < 0, an
///     active node is released if t_k + c_N g_k > ε_t. For a wettable node (mixture contact)
///     the release of a sealed node goes through the wetted state: a sealed interface that
///     would carry tension lets the bath in while the surfaces still touch (Wetted: gap row,
///     free-draining potentials); a wetted node is released (Open) when it carries tension as
///     well. A sealed interface that goes tensile would otherwise chatter: released, it drains
///     to the bath, swells and penetrates; closed, it pulls (the separation test). A wetted
///     node re-seals when it is pressed (t_k + c_N g_k < −ε_t), except in the step in which it
///     was released from sealed: there the sealed state was just found to pull, and re-sealing
///     would cycle. So layers that were wetted while their traction was about zero (free
///     swelling) close the interface again when a platen compresses them;
///   * a frictional node in contact sticks (Sealed) or slips: a sticking node starts to slip
///     when its slip indicator exceeds ε_t, a slipping node sticks when it falls below -ε_t; a
///     node that comes into contact sticks first;
///   * after `max_updates` evaluations of a step the set is frozen (only non-admissible nodes
///     are still released) until it has *settled*: every active node has |g_k| ≤
///     gap_tolerance, i.e. Newton has converged for the frozen set. Then the rule is applied
///     once more (a re-solve with the new set that starts from the converged state), at most
///     `max_resolves` times per step. This keeps the early, far-from-solution iterates of a
///     step from cycling the set while still ending on a consistent set.
///   * nodes the rule would flip but the freeze holds are counted in pending(): a converged
///     step with pending() > 0 solved the wrong set and must be cut back by the caller.
/// A new step starts at commit() or when the evaluation time changes (a retried step).
class ActiveSet {
public:
  ActiveSet(Index num_nodes, ActiveSetSettings settings)
      : settings_(settings), active_(num_nodes, 0), wetted_in_step_(num_nodes, 0) {}

  /// Applies the rules above at an evaluation at `time`; returns the number of flips.
  Index update(Real time, const std::vector<NodeStatus>& nodes);
  /// The step converged: the next evaluation starts a new step.
  void commit() { new_step_ = true; }
  /// Replaces the set (flags: NodeContact values; e.g. a restart or a test); marks it
  /// initialised.
  void assign(std::vector<char> active);

  bool active(Index k) const { return active_[k] != 0; }
  /// In contact and slipping (frictional laws).
  bool slipping(Index k) const { return active_[k] == static_cast<char>(NodeContact::Slipping); }
  /// In contact with a wetted (free-draining) interface.
  bool wetted(Index k) const { return active_[k] == static_cast<char>(NodeContact::Wetted); }
  const std::vector<char>& flags() const { return active_; }
  Index num_active() const;
  const ActiveSetSettings& settings() const { return settings_; }
  ActiveSetSettings& settings() { return settings_; }

  /// Flips since the step began.
  Index flips_in_step() const { return flips_step_; }
  /// Nodes the rule would flip at the last evaluation but the freeze held (0: consistent).
  Index pending() const { return pending_; }

private:
  NodeContact wanted(Index k, const NodeStatus& s) const;
  NodeContact normal_wanted(Index k, const NodeStatus& s) const;
  bool settled(const std::vector<NodeStatus>& nodes) const;

  ActiveSetSettings settings_;
  std::vector<char> active_;
  std::vector<char> wetted_in_step_; ///< released from sealed to wetted in the current step
  bool initialized_ = false;
  bool new_step_ = true;
  Real time_ = 0;
  int evaluations_ = 0;
  int resolves_ = 0;
  Index flips_step_ = 0;
  Index pending_ = 0;
};

} // namespace trifem::contact
