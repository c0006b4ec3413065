// SPDX-License-Identifier: MIT
#include "trifem/linalg/block_split.hpp"

#include <algorithm>

namespace trifem::linalg {

BlockSplit BlockSplit::from_fields(const std::vector<int>& equation_fields,
                                   const std::vector<FieldRole>& roles) {
  BlockSplit split;
  for (std::size_t eq = 0; eq < equation_fields.size(); ++eq) {
    const int field = equation_fields[eq];
    const FieldRole role = field >= 0 && field < static_cast<int>(roles.size())
                               ? roles[field]
                               : FieldRole::displacement;
    std::vector<Index>& group = role == FieldRole::flux        ? split.flux
                                : role == FieldRole::potential ? split.potential
                                                               : split.displacement;
    group.push_back(static_cast<Index>(eq));
  }
  return split;
}

std::vector<Index> BlockSplit::primal() const {
  std::vector<Index> all(displacement);
  all.insert(all.end(), flux.begin(), flux.end());
  std::sort(all.begin(), all.end());
  return all;
}

} // namespace trifem::linalg
