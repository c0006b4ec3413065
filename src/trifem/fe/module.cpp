// SPDX-License-Identifier: MIT
// (placeholder translation unit so that the library is never empty)
namespace trifem {}
