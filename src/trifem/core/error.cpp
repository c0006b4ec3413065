// SPDX-License-Identifier: MIT
#include "trifem/core/error.hpp"

namespace trifem::detail {

void throw_logic_error(const std::string& message, const char* file, int line) {
  throw LogicError(fmt::format("internal error: {} ({}:{})", message, file, line));
}

} // namespace trifem::detail
