// SPDX-License-Identifier: MIT
#include "trifem/explicit/settings.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace trifem::explicit_dynamics {

void ExplicitSettings::validate() const {
  TRIFEM_CHECK(penalty > 0.0, "explicit.penalty = {}: must be > 0 (inf = exact constraint)",
               penalty);
  TRIFEM_CHECK(std::isfinite(damping) && damping >= 0.0, "explicit.damping = {}: must be >= 0",
               damping);
  TRIFEM_CHECK(std::isfinite(time_step) && time_step >= 0.0,
               "explicit.time_step = {}: must be >= 0 (0 = stability estimate)", time_step);
  TRIFEM_CHECK(time_step > 0.0 || stable_step != StableStepMethod::None,
               "explicit.time_step must be given when the stable step is not estimated");
  if (safety_factor)
    TRIFEM_CHECK(*safety_factor > 0.0 && *safety_factor <= 1.0,
                 "explicit.safety_factor = {}: must be in (0, 1]", *safety_factor);
  TRIFEM_CHECK(stable_step_interval >= 0, "explicit.stable_step_interval = {}: must be >= 0",
               stable_step_interval);
  TRIFEM_CHECK(power_iterations >= 2, "explicit.power_iterations = {}: must be >= 2",
               power_iterations);
  TRIFEM_CHECK(power_tolerance > 0.0, "explicit.power_tolerance must be > 0");
  TRIFEM_CHECK(displacement_tolerance > 0.0 && constraint_tolerance > 0.0,
               "explicit tolerances must be > 0");
  TRIFEM_CHECK(max_factorization_age >= 1, "explicit.max_factorization_age = {}: must be >= 1",
               max_factorization_age);
  TRIFEM_CHECK(max_iterations >= 1, "explicit.max_iterations = {}: must be >= 1", max_iterations);
  TRIFEM_CHECK(max_halvings >= 0, "explicit.max_halvings = {}: must be >= 0", max_halvings);
  TRIFEM_CHECK(recovery_steps >= 1, "explicit.recovery_steps = {}: must be >= 1", recovery_steps);
}

ExplicitSettings explicit_settings(const io::ExplicitSpec& e, Real time_step) {
  ExplicitSettings s;
  s.reading = e.reading == io::ExplicitReading::A ? Reading::A : Reading::B;
  s.constraint =
      e.constraint == io::VolumeConstraint::LogJ ? Constraint::LogJ : Constraint::JMinusOne;
  s.multiplier = e.multiplier;
  s.penalty = e.penalty;
  s.damping = e.damping;
  s.time_step = time_step;
  s.safety_factor = e.safety_factor;
  s.max_factorization_age = e.factorization_age;
  switch (e.stable_step) {
  case io::StableStepEstimate::PowerIteration:
    s.stable_step = StableStepMethod::PowerIteration;
    break;
  case io::StableStepEstimate::ElementBound:
    s.stable_step = StableStepMethod::ElementBound;
    break;
  case io::StableStepEstimate::None:
    s.stable_step = StableStepMethod::None;
    break;
  }
  s.stable_step_interval = e.stable_step_interval;
  s.displacement_tolerance = e.displacement_tolerance;
  s.constraint_tolerance = e.constraint_tolerance;
  s.max_iterations = e.max_iterations;
  s.max_halvings = e.max_halvings;
  s.validate();
  return s;
}

namespace {
std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}
} // namespace

Reading parse_reading(const std::string& text) {
  const std::string t = lower(text);
  if (t == "a")
    return Reading::A;
  if (t == "b")
    return Reading::B;
  throw InputError(fmt::format("explicit.reading = '{}': expected 'A' or 'B'", text));
}

Constraint parse_constraint(const std::string& text) {
  const std::string t = lower(text);
  if (t == "j-1" || t == "j - 1")
    return Constraint::JMinusOne;
  if (t == "lnj" || t == "ln j" || t == "log")
    return Constraint::LogJ;
  throw InputError(fmt::format("explicit.constraint = '{}': expected 'J-1' or 'lnJ'", text));
}

} // namespace trifem::explicit_dynamics
