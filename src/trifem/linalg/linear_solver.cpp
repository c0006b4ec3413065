// SPDX-License-Identifier: MIT
#include "trifem/linalg/linear_solver.hpp"

#include "trifem/core/error.hpp"
#include "trifem/linalg/auto_solver.hpp"
#include "trifem/linalg/sparse_lu_solver.hpp"
#include "trifem/linalg/umfpack_solver.hpp"

namespace trifem::linalg {

std::vector<std::string> available_linear_solvers() {
  return {"auto", "umfpack", "sparselu"};
}

std::unique_ptr<LinearSolver> make_linear_solver(const std::string& name) {
  if (name == "auto")
    return make_auto_solver();
  if (name == "umfpack")
    return make_umfpack_solver();
  if (name == "sparselu")
    return make_sparse_lu_solver();
  throw InputError(
      fmt::format("unknown linear solver '{}' (expected auto, umfpack or sparselu)", name));
}

} // namespace trifem::linalg
