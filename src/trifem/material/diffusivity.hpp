// SPDX-License-Identifier: MIT
// Ion diffusivity d(phi_w) of a mixture as a function of the porosity (water volume fraction):
// constant and Mackie-Meares laws.
#pragma once

#include "trifem/material/transport_law.hpp"

namespace trifem::material {

/// Isotropic diffusivity d(phi_w) [mm^2/s] of an ion in the interstitial water, a function of
/// the porosity phi_w = 1 - phi_s0/J in (0, 1) (docs/theory/triphasic.md §2a).
class DiffusivityLaw {
public:
  virtual ~DiffusivityLaw() = default;
  /// d(phi_w) [mm^2/s].
  virtual Real value(Real phi_w) const = 0;
  /// dd/dphi_w [mm^2/s].
  virtual Real derivative(Real phi_w) const = 0;
  /// True if d does not depend on phi_w (derivative() is exactly 0): the element then skips the
  /// derivative terms, keeping the arithmetic of a constant diffusivity.
  virtual bool is_constant() const { return false; }
};

/// A diffusivity d that does not depend on the porosity.
class ConstantDiffusivity final : public DiffusivityLaw {
public:
  /// Parameter: d [mm^2/s], > 0.
  explicit ConstantDiffusivity(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  Real value(Real) const override { return d_; }
  Real derivative(Real) const override { return 0.0; }
  bool is_constant() const override { return true; }

private:
  Real d_;
};

/// Mackie & Meares (1955) obstruction model with the free-solution diffusivity d0:
///   d = d0 (phi_w/(2 - phi_w))^2,   dd/dphi_w = 4 d0 phi_w/(2 - phi_w)^3.
/// d < d0 for every phi_w < 1 (d = d0 in free solution, phi_w = 1).
class MackieMearesDiffusivity final : public DiffusivityLaw {
public:
  /// Parameter: d0 [mm^2/s] > 0, the diffusivity of the ion in free solution.
  explicit MackieMearesDiffusivity(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  Real value(Real phi_w) const override;
  Real derivative(Real phi_w) const override;

private:
  Real d0_;
};

/// The registered diffusivity laws ("constant", "mackie-meares").
const std::vector<TransportLawEntry<DiffusivityLaw>>& diffusivity_laws();

/// Validates `values` for the law `type` (messages name `context.key`; an unknown type lists the
/// known ones) and constructs it.
std::unique_ptr<DiffusivityLaw> create_diffusivity(const std::string& type,
                                                   const ParameterValues& values,
                                                   const std::string& context);

/// The constant law d [mm^2/s].
std::unique_ptr<DiffusivityLaw> constant_diffusivity(Real d);

} // namespace trifem::material
