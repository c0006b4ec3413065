// SPDX-License-Identifier: MIT
// A term that acts only during one analysis step: the loads given in a [[step]].
#pragma once

#include "trifem/physics/term.hpp"

#include <memory>

namespace trifem::physics {

/// Forwards to `inner` while the evaluated time (the end of the current step) lies in
/// (start, end] (within 1e-10 of the span); contributes zero residual and stiffness (on the
/// same DOFs, so the pattern does not change) outside.
class StepWindowTerm final : public Term {
public:
  StepWindowTerm(std::unique_ptr<Term> inner, Real start, Real end)
      : inner_(std::move(inner)), start_(start), end_(end) {}

  std::string name() const override { return inner_->name(); }
  Index num_elements() const override { return inner_->num_elements(); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override {
    inner_->element_dofs(e, dofs);
  }
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override {
    if (active(state.time))
      return inner_->evaluate(e, state, r, K);
    std::vector<Index> dofs;
    inner_->element_dofs(e, dofs);
    const auto n = static_cast<Eigen::Index>(dofs.size());
    r.setZero(n);
    if (K)
      K->setZero(n, n);
    return true;
  }
  void commit(const EvalState& state) override { inner_->commit(state); }
  bool prepare(const EvalState& state) override { return inner_->prepare(state); }
  void reject() override { inner_->reject(); }
  std::string step_rejection(const EvalState& state) const override {
    return inner_->step_rejection(state);
  }
  std::string step_caution(const EvalState& state) const override {
    return inner_->step_caution(state);
  }
  std::vector<double> history() const override { return inner_->history(); }
  void restore_history(const std::vector<double>& values) override {
    inner_->restore_history(values);
  }

private:
  bool active(Real t) const {
    const Real tol = 1e-10 * (end_ - start_);
    return t > start_ + tol && t <= end_ + tol;
  }

  std::unique_ptr<Term> inner_;
  Real start_;
  Real end_;
};

} // namespace trifem::physics
