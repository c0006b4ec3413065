// SPDX-License-Identifier: MIT
// Shared by the tests of the .feb reader's error messages (test_feb_errors.cpp,
// test_feb_triphasic_errors.cpp).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace trifem::test {

/// Expects every one of `fragments` in `message`.
inline void expect_contains(const std::string& message, const std::vector<std::string>& fragments) {
  for (const std::string& f : fragments)
    EXPECT_NE(message.find(f), std::string::npos) << "'" << f << "' not in: " << message;
}

} // namespace trifem::test
