// SPDX-License-Identifier: MIT
// Adapter from an Eigen sparse direct solver (analyzePattern/factorize/solve) to LinearSolver.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

#include <cstdint>
#include <string>

namespace trifem::linalg {

/// Wraps an Eigen sparse solver type `Lu` under the backend name `name`. An empty system
/// (every unknown prescribed) is solved trivially.
template <class Lu>
class EigenDirectSolver : public LinearSolver {
public:
  explicit EigenDirectSolver(std::string name) : name_(std::move(name)) {}
  void analyze_pattern(const SparseMatrix& A) override {
    empty_ = A.rows() == 0;
    if (!empty_)
      lu_.analyzePattern(A);
  }
  bool factorize(const SparseMatrix& A) override {
    failure_ = {};
    if (empty_)
      return true;
    lu_.factorize(A);
    if (lu_.info() == Eigen::Success)
      return true;
    failure_.reason = name_ + ": " + message();
    failure_.equation = empty_column(A);
    return false;
  }
  bool solve(const Vector& b, Vector& x) override {
    failure_ = {};
    if (empty_) {
      x.resize(0);
      return true;
    }
    x = lu_.solve(b);
    if (lu_.info() == Eigen::Success && x.allFinite())
      return true;
    failure_.reason = name_ + ": the solution is not finite (the matrix is singular)";
    return false;
  }
  std::string name() const override { return name_; }
  std::int64_t factor_nonzeros() const override {
    if constexpr (requires(const Lu& lu) { lu.nnzL(); })
      return empty_ ? 0 : static_cast<std::int64_t>(lu_.nnzL()) + lu_.nnzU();
    return 0;
  }
  LinearSolverFailure failure() const override { return failure_; }

protected:
  Lu lu_;

private:
  /// The backend's own diagnosis, where it has one.
  std::string message() {
    if constexpr (requires(Lu & lu) { lu.lastErrorMessage(); }) {
      if (!lu_.lastErrorMessage().empty())
        return "the matrix is singular (" + lu_.lastErrorMessage() + ")";
    }
    return "the matrix is singular";
  }

  std::string name_;
  bool empty_ = false;
  LinearSolverFailure failure_;
};

} // namespace trifem::linalg
