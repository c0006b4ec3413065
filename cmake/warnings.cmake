# SPDX-License-Identifier: MIT
# Project-wide warning flags, applied through the trifem_warnings interface target.
add_library(trifem_warnings INTERFACE)
# -Wno-missing-field-initializers: option structs (LinearSolverChoice, NumberRule, ...) have a
# default for every member and are initialized by naming only the members that differ.
target_compile_options(trifem_warnings INTERFACE -Wall -Wextra -Wpedantic
                                                 -Wno-missing-field-initializers)
if(TRIFEM_WERROR)
  target_compile_options(trifem_warnings INTERFACE -Werror)
endif()
