// SPDX-License-Identifier: MIT
#include "trifem/contact/contact_law.hpp"

namespace trifem::contact {

Real FrictionlessLaw::indicator(const SlaveNodeRows& node) const {
  if (!node.projection)
    return std::numeric_limits<Real>::infinity();
  return node.multiplier[0] + node.scale * node.projection->gap;
}

void FrictionlessLaw::active_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  TRIFEM_VERIFY(node.projection && node.derivatives, "an active slave node needs a projection");
  const Index row = node.lambda_at;
  out.r()[row] += node.weight * node.projection->gap;
  if (!out.with_jacobian())
    return;
  for (int j = 0; j < node.nodes.size; ++j)
    for (int i = 0; i < 3; ++i)
      out.K()(row, node.x_at[j] + i) += node.weight * node.derivatives->dgap(3 * j + i);
}

void FrictionlessLaw::inactive_rows(const SlaveNodeRows& node, LocalSystem& out) const {
  const Index row = node.lambda_at;
  const Real w = node.weight / node.scale;
  out.r()[row] += w * node.multiplier[0];
  if (out.with_jacobian())
    out.K()(row, row) += w;
}

} // namespace trifem::contact
