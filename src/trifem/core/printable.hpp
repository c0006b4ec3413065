// SPDX-License-Identifier: MIT
// Messages that quote the input (a token of a mesh file, a line of a case file) must not carry
// its control characters to the terminal: a carriage return or an ANSI escape would mangle or
// erase the error line.
#pragma once

#include <string>
#include <string_view>

namespace trifem {

/// `text` with every byte that a terminal would not print as itself replaced by an escape:
/// control characters other than newline and tab as \r, \x1b, ..., and bytes that are not
/// part of well-formed UTF-8 as \xNN. Printable ASCII and valid UTF-8 are kept.
std::string printable(std::string_view text);

} // namespace trifem
