// SPDX-License-Identifier: MIT
// The rules of the primal-dual active set with the wetted state of mixture contact
// (docs/theory/contact.md §5.2): sealed -> wetted -> open on tension, open -> sealed on contact,
// and wetted -> sealed when pressed again, except in the step in which the node was released.
#include "trifem/contact/active_set.hpp"

#include <gtest/gtest.h>

namespace trifem::contact {
namespace {

constexpr Real kThreshold = 1e-8; ///< ε_t

ActiveSet one_node() {
  ActiveSetSettings s;
  s.release_threshold = kThreshold;
  s.gap_tolerance = 1e-6;
  return ActiveSet(1, s);
}

/// A wettable, admissible node at zero gap with indicator `chi` (t + c_N g).
std::vector<NodeStatus> node(Real chi) {
  return {{.admissible = true, .gap = 0.0, .indicator = chi, .wettable = true}};
}

NodeContact state(const ActiveSet& a) {
  return static_cast<NodeContact>(a.flags()[0]);
}

TEST(ActiveSet, TensionReleasesASealedNodeThroughTheWettedState) {
  ActiveSet a = one_node();
  a.update(1.0, node(0.0)); // geometric: touching -> sealed
  EXPECT_EQ(state(a), NodeContact::Sealed);
  a.update(1.0, node(10 * kThreshold));
  EXPECT_EQ(state(a), NodeContact::Wetted);
  a.update(1.0, node(10 * kThreshold));
  EXPECT_EQ(state(a), NodeContact::Open);
}

TEST(ActiveSet, APressedWettedNodeSealsInALaterStep) {
  ActiveSet a = one_node();
  a.update(1.0, node(0.0));
  a.update(1.0, node(10 * kThreshold)); // round-off tension at zero traction: wetted
  ASSERT_EQ(state(a), NodeContact::Wetted);
  a.commit();
  a.update(2.0, node(-1.0)); // the next step presses it: the interface closes again
  EXPECT_EQ(state(a), NodeContact::Sealed);
  EXPECT_EQ(a.pending(), 0);
}

TEST(ActiveSet, AWettedNodeWithinTheThresholdStaysWetted) {
  ActiveSet a = one_node();
  a.update(1.0, node(0.0));
  a.update(1.0, node(10 * kThreshold));
  a.commit();
  a.update(2.0, node(-0.5 * kThreshold)); // compressive, but within ε_t: no chattering
  EXPECT_EQ(state(a), NodeContact::Wetted);
}

TEST(ActiveSet, ANodeReleasedInAStepDoesNotSealAgainInThatStep) {
  // sealed, it pulls; wetted, the layers swell against each other (compressive): re-sealing it
  // within the step would cycle, so it stays wetted and the step is consistent
  ActiveSet a = one_node();
  a.update(1.0, node(0.0));
  a.commit();
  a.update(2.0, node(10 * kThreshold));
  ASSERT_EQ(state(a), NodeContact::Wetted);
  for (int k = 0; k < 8; ++k) {
    a.update(2.0, node(-1.0));
    EXPECT_EQ(state(a), NodeContact::Wetted) << "evaluation " << k;
    EXPECT_EQ(a.pending(), 0) << "evaluation " << k;
  }
  a.commit();
  a.update(3.0, node(-1.0)); // a new step: pressed, it seals
  EXPECT_EQ(state(a), NodeContact::Sealed);
}

TEST(ActiveSet, ARetriedStepMayReleaseAndSealAfresh) {
  ActiveSet a = one_node();
  a.update(1.0, node(0.0));
  a.commit();
  a.update(2.0, node(10 * kThreshold)); // released in the attempt at t = 2
  ASSERT_EQ(state(a), NodeContact::Wetted);
  a.update(1.5, node(-1.0)); // the step is retried at t = 1.5: a new step begins
  EXPECT_EQ(state(a), NodeContact::Sealed);
}

} // namespace
} // namespace trifem::contact
