// SPDX-License-Identifier: MIT
#include "trifem/explicit/settings.hpp"

#include "trifem/core/error.hpp"

#include <cmath>

namespace trifem::explicit_dynamics {

void ExplicitSettings::verify() const {
  TRIFEM_VERIFY(penalty > 0.0 && std::isfinite(damping) && damping >= 0.0,
                "explicit penalty {} must be > 0 and damping {} >= 0", penalty, damping);
  TRIFEM_VERIFY(std::isfinite(time_step) && time_step >= 0.0 &&
                    (time_step > 0.0 || stable_step != StableStepMethod::None),
                "explicit time step {}: must be >= 0, and given when not estimated", time_step);
  TRIFEM_VERIFY(!safety_factor || (*safety_factor > 0.0 && *safety_factor <= 1.0),
                "explicit safety factor must be in (0, 1]");
  TRIFEM_VERIFY(stable_step_interval >= 0 && factorization_age >= 1 && max_iterations >= 1 &&
                    max_halvings >= 0,
                "explicit counts out of range");
  TRIFEM_VERIFY(displacement_tolerance > 0.0 && constraint_tolerance > 0.0,
                "explicit tolerances must be > 0");
}

} // namespace trifem::explicit_dynamics
