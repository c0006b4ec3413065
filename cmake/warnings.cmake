# SPDX-License-Identifier: MIT
# Project-wide warning flags, applied through the trifem_warnings interface target.
add_library(trifem_warnings INTERFACE)
target_compile_options(trifem_warnings INTERFACE -Wall -Wextra -Wpedantic)
if(TRIFEM_WERROR)
  target_compile_options(trifem_warnings INTERFACE -Werror)
endif()
