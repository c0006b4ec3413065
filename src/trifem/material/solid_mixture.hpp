// SPDX-License-Identifier: MIT
// Solid mixture: the sum of solid laws, e.g. a ground matrix plus fibre families (the FEBio
// "solid mixture").
#pragma once

#include "trifem/material/elastic_law.hpp"

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::material {

/// The case-file type name of a solid mixture.
inline constexpr std::string_view kSolidMixtureType = "solid-mixture";

/// W = sum_i W_i, S = sum_i S_i, D = sum_i D_i over the constituents (FEBio user's manual,
/// "Solid Mixture", with every weight 1), e.g. a neo-Hookean ground matrix plus FibreExpPow
/// families. The small-strain moduli are the sums of the constituents'.
class SolidMixture final : public ElasticLaw {
public:
  /// The mixture of `constituents` (shared, immutable). InputError naming
  /// `context`.constituent if there is none, and naming `context` if the sum has no stiffness
  /// at C = I (p_wave_modulus() or shear_modulus() 0: fibres only, which carry no load at zero
  /// strain and none across their direction).
  SolidMixture(std::vector<std::shared_ptr<const ElasticLaw>> constituents,
               const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  Real p_wave_modulus() const override { return p_wave_modulus_; }
  Real shear_modulus() const override { return shear_modulus_; }
  std::string type() const override { return std::string(kSolidMixtureType); }

  /// The constituents, in the order given.
  const std::vector<std::shared_ptr<const ElasticLaw>>& constituents() const {
    return constituents_;
  }

private:
  std::vector<std::shared_ptr<const ElasticLaw>> constituents_;
  Real p_wave_modulus_ = 0.0;
  Real shear_modulus_ = 0.0;
};

} // namespace trifem::material
