// SPDX-License-Identifier: MIT
// The explicit integrator's state for restart files: what a step needs beyond the displacement.
#include "trifem/core/error.hpp"
#include "trifem/explicit/explicit_solver.hpp"

#include <cmath>

namespace trifem::explicit_dynamics {
namespace {

/// The scalars, in the order state() writes them before the vectors.
enum Scalar : std::size_t {
  kTime,
  kPreviousStep,
  kCurrentStep,
  kStepCount,
  kTotalIterations,
  kSuccessesSinceHalving,
  kExternalWork,
  kDampingWork,
  kInitialEnergy,
  kOmega,
  kCritical,
  kStable,
  kRequested,
  kUsed,
  kReduced,
  kScalars
};

/// A count stored as a double: a whole number in [0, 2^53].
bool is_count(double v) {
  return v >= 0.0 && v <= 9007199254740992.0 && std::floor(v) == v;
}

} // namespace

std::size_t ExplicitSolver::state_size(Index dofs, Index cells, std::size_t bodies) {
  return kScalars + 2 * static_cast<std::size_t>(dofs + cells) +
         (bodies > 0 ? 1 + BodyMotion::kValues * bodies : 0);
}

std::vector<double> ExplicitSolver::state() const {
  std::vector<double> s(kScalars);
  s[kTime] = time_;
  s[kPreviousStep] = dt_prev_;
  s[kCurrentStep] = dt_current_;
  s[kStepCount] = static_cast<double>(step_count_);
  s[kTotalIterations] = static_cast<double>(total_iterations_);
  s[kSuccessesSinceHalving] = successes_since_halving_;
  s[kExternalWork] = external_work_;
  s[kDampingWork] = damping_work_;
  s[kInitialEnergy] = initial_energy_;
  s[kOmega] = dt_info_.omega;
  s[kCritical] = dt_info_.critical;
  s[kStable] = dt_info_.stable;
  s[kRequested] = dt_info_.requested;
  s[kUsed] = dt_info_.used;
  s[kReduced] = dt_info_.reduced ? 1.0 : 0.0;
  for (const Vector* v : {&V_, &lambda_, &lambda_old_, &support_step_})
    s.insert(s.end(), v->data(), v->data() + v->size());
  if (!motions_.empty()) // the bodies' drives' work over the last step, their motions
    s.push_back(drive_work_);
  for (const BodyMotion& m : motions_)
    m.to_values(s);
  return s;
}

void ExplicitSolver::restore(const Vector& U, const std::vector<double>& state) {
  const Index n = model_.num_dofs(), cells = model_.num_cells();
  const std::size_t expected = state_size(n, cells, model_.bodies().size());
  TRIFEM_CHECK(state.size() == expected && U.size() == n,
               "the explicit integrator's state has {} values, this model's needs {}", state.size(),
               expected);
  const auto& s = state;
  TRIFEM_CHECK(s[kPreviousStep] >= 0.0 && s[kCurrentStep] > 0.0 && s[kUsed] > 0.0 &&
                   is_count(s[kStepCount]) && is_count(s[kTotalIterations]) &&
                   is_count(s[kSuccessesSinceHalving]) &&
                   (s[kReduced] == 0.0 || s[kReduced] == 1.0),
               "the explicit integrator's state is invalid (steps {}, {} and {} s, counts {}, {} "
               "and {})",
               s[kPreviousStep], s[kCurrentStep], s[kUsed], s[kStepCount], s[kTotalIterations],
               s[kSuccessesSinceHalving]);
  const CellStatus status =
      evaluate_cells(model_, settings_.constraint, U, {true, true, true, false}, fields_);
  TRIFEM_CHECK(status.ok(), "the explicit integrator's state: {} in cell {}", status.quantity,
               status.cell);
  U_ = U;
  time_ = s[kTime];
  dt_prev_ = s[kPreviousStep];
  dt_current_ = s[kCurrentStep];
  step_count_ = static_cast<long>(s[kStepCount]);
  total_iterations_ = static_cast<long>(s[kTotalIterations]);
  successes_since_halving_ = static_cast<int>(s[kSuccessesSinceHalving]);
  external_work_ = s[kExternalWork];
  damping_work_ = s[kDampingWork];
  initial_energy_ = s[kInitialEnergy];
  dt_info_ = {s[kOmega], s[kCritical], s[kStable], s[kRequested], s[kUsed], s[kReduced] == 1.0};
  const double* at = s.data() + kScalars;
  for (Vector* v : {&V_, &lambda_, &lambda_old_, &support_step_}) {
    const Index size = v == &lambda_ || v == &lambda_old_ ? cells : n;
    *v = Eigen::Map<const Vector>(at, size);
    at += size;
  }
  if (!motions_.empty())
    drive_work_ = *at++;
  for (BodyMotion& m : motions_) {
    m = BodyMotion::from_values(at);
    at += BodyMotion::kValues;
    TRIFEM_CHECK((m.R.transpose() * m.R - Mat3::Identity()).norm() <= 1e-9,
                 "the explicit integrator's state holds a rigid body rotation that is not one");
  }
  trial_motions_ = motions_;
  update_end_forces();
  refactorize();
}

} // namespace trifem::explicit_dynamics
