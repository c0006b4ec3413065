// SPDX-License-Identifier: MIT
// Adapter from an Eigen sparse direct solver (analyzePattern/factorize/solve) to LinearSolver.
#pragma once

#include "trifem/linalg/linear_solver.hpp"

namespace trifem::linalg {

/// Wraps an Eigen sparse solver type `Lu` under the backend name `name`.
template <class Lu>
class EigenDirectSolver : public LinearSolver {
public:
  explicit EigenDirectSolver(std::string name) : name_(std::move(name)) {}
  void analyze_pattern(const SparseMatrix& A) override { lu_.analyzePattern(A); }
  bool factorize(const SparseMatrix& A) override {
    lu_.factorize(A);
    return lu_.info() == Eigen::Success;
  }
  bool solve(const Vector& b, Vector& x) override {
    x = lu_.solve(b);
    return lu_.info() == Eigen::Success && x.allFinite();
  }
  std::string name() const override { return name_; }

protected:
  Lu lu_;

private:
  std::string name_;
};

} // namespace trifem::linalg
