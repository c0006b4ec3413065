// SPDX-License-Identifier: MIT
// Case files edited in tests: a text with some of its passages replaced.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

namespace trifem::test {

/// `text` with the first occurrence of each `from` of `edits` replaced by its `to` (a `from`
/// that does not occur fails the test).
inline std::string edited(std::string text,
                          const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    const auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the text";
    if (at != std::string::npos)
      text.replace(at, from.size(), to);
  }
  return text;
}

} // namespace trifem::test
