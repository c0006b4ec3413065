// SPDX-License-Identifier: MIT
#include "trifem/core/error.hpp"

namespace trifem::detail {

void throw_logic_error(const std::string& message, const std::source_location& where) {
  throw LogicError(
      fmt::format("internal error: {} ({}:{})", message, where.file_name(), where.line()));
}

} // namespace trifem::detail
