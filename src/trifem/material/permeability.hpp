// SPDX-License-Identifier: MIT
// Hydraulic permeability kappa(J) of a mixture as a function of the volume ratio J = V/V0:
// constant, Holmes-Mow (FEBio perm-Holmes-Mow) and exponential (FEBio perm-exp-iso) laws.
#pragma once

#include "trifem/material/transport_law.hpp"

namespace trifem::material {

/// Isotropic hydraulic permeability kappa(J) [mm^4/(N s)] of the solid matrix, a function of the
/// volume ratio J = V/V0 (docs/theory/triphasic.md §2a). Defined for J > phi_s0 (the pores
/// close at J = phi_s0); kappa(1) is the permeability of the reference state.
class PermeabilityLaw {
public:
  virtual ~PermeabilityLaw() = default;
  /// kappa(J) [mm^4/(N s)].
  virtual Real value(Real J) const = 0;
  /// dkappa/dJ [mm^4/(N s)].
  virtual Real derivative(Real J) const = 0;
  /// True if kappa does not depend on J (derivative() is exactly 0): the element then skips the
  /// derivative terms, keeping the arithmetic of a constant permeability.
  virtual bool is_constant() const { return false; }
};

/// kappa = k0.
class ConstantPermeability final : public PermeabilityLaw {
public:
  /// Parameter: k0 [mm^4/(N s)], > 0.
  explicit ConstantPermeability(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  Real value(Real) const override { return k0_; }
  Real derivative(Real) const override { return 0.0; }
  bool is_constant() const override { return true; }

private:
  Real k0_;
};

/// Holmes & Mow (1990), as FEBio's perm-Holmes-Mow:
///   kappa = k0 ((J - phi_s0)/(1 - phi_s0))^alpha exp(M (J^2 - 1)/2),
///   dkappa/dJ = kappa (alpha/(J - phi_s0) + M J).
class HolmesMowPermeability final : public PermeabilityLaw {
public:
  /// Parameters: k0 [mm^4/(N s)] > 0, M >= 0, alpha >= 0 (both default 0: constant).
  HolmesMowPermeability(const ParameterValues& params, Real phi_s0);
  static const std::vector<ParameterSchema>& schema();
  Real value(Real J) const override;
  Real derivative(Real J) const override;

private:
  Real k0_, M_, alpha_, phi_s0_;
};

/// Exponential law of Lai & Mow (1980) in FEBio's finite-strain form (perm-exp-iso):
///   kappa = k0 exp(M (J - 1)/(J - phi_s0)),
///   dkappa/dJ = kappa M (1 - phi_s0)/(J - phi_s0)^2.
/// For small strain e = J - 1 it is k0 exp(M e/(1 - phi_s0)) to first order.
class ExponentialPermeability final : public PermeabilityLaw {
public:
  /// Parameters: k0 [mm^4/(N s)] > 0, M >= 0 (default 0: constant).
  ExponentialPermeability(const ParameterValues& params, Real phi_s0);
  static const std::vector<ParameterSchema>& schema();
  Real value(Real J) const override;
  Real derivative(Real J) const override;

private:
  Real k0_, M_, phi_s0_;
};

/// The registered permeability laws ("constant", "holmes-mow", "exponential").
const std::vector<TransportLawEntry<PermeabilityLaw>>& permeability_laws();

/// Validates `values` for the law `type` (messages name `context.key`; an unknown type lists the
/// known ones) and constructs it for a mixture of solid volume fraction phi_s0.
std::unique_ptr<PermeabilityLaw> create_permeability(const std::string& type,
                                                     const ParameterValues& values, Real phi_s0,
                                                     const std::string& context);

/// The constant law kappa = k0 [mm^4/(N s)].
std::unique_ptr<PermeabilityLaw> constant_permeability(Real k0);

} // namespace trifem::material
