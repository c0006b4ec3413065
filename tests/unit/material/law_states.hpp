// SPDX-License-Identifier: MIT
// Reproducible states for the law tests: a fixed-width random generator (the same sequence on
// every platform), random matrices and rotations, and small reporting helpers.
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/tensor/tensor.hpp"

#include <Eigen/Geometry>

#include <cstdint>
#include <sstream>
#include <string>

namespace trifem::test {

/// A value in scientific notation, for RecordProperty.
inline std::string scientific(Real v) {
  std::ostringstream out;
  out << std::scientific << v;
  return out.str();
}

/// Uniform number in [-1, 1] from a 64-bit linear congruential generator.
inline Real uniform(std::uint64_t& state) {
  state = state * 6364136223846793005ULL + 1442695040888963407ULL;
  return Real(state >> 11) / Real(1ULL << 53) * 2.0 - 1.0;
}

/// A matrix with entries in [-1, 1].
inline Mat3 random_matrix(std::uint64_t seed) {
  std::uint64_t state = seed;
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      A(i, j) = uniform(state);
  return A;
}

/// The rotation by `angle` about `axis`.
inline Mat3 rotation(Real angle, const Vec3& axis) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

/// The message of the InputError thrown by `f`, or "" if none is thrown.
template <class F>
std::string input_error(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

} // namespace trifem::test
