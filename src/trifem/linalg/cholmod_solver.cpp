// SPDX-License-Identifier: MIT
#include "trifem/linalg/cholmod_solver.hpp"

#include <Eigen/CholmodSupport>

namespace trifem::linalg {
namespace {

class CholmodSolver final : public LinearSolver {
public:
  CholmodSolver() { llt_.setMode(Eigen::CholmodAuto); }

  void analyze_pattern(const SparseMatrix& A) override {
    failure_ = {};
    analysed_ = false;
    llt_.analyzePattern(A);
    if (llt_.info() == Eigen::Success)
      analysed_ = true;
    else
      failure_ = {"CHOLMOD symbolic analysis failed", true};
  }

  bool factorize(const SparseMatrix& A) override {
    if (!analysed_)
      return false; // failure_ says why
    failure_ = {};
    llt_.factorize(A);
    factorized_ = llt_.info() == Eigen::Success;
    if (!factorized_)
      failure_ = {"CHOLMOD factorization failed: the matrix is not positive definite", false};
    return factorized_;
  }

  bool solve(const Vector& b, Vector& x) override {
    if (!factorized_)
      return false;
    x = llt_.solve(b);
    if (llt_.info() == Eigen::Success && x.allFinite())
      return true;
    failure_ = {"CHOLMOD solve failed", false};
    return false;
  }

  std::string name() const override { return "cholmod"; }
  LinearSolverFailure failure() const override { return failure_; }

private:
  Eigen::CholmodDecomposition<SparseMatrix, Eigen::Lower> llt_;
  bool analysed_ = false;
  bool factorized_ = false;
  LinearSolverFailure failure_;
};

} // namespace

std::unique_ptr<LinearSolver> make_cholmod_solver() {
  return std::make_unique<CholmodSolver>();
}

} // namespace trifem::linalg
