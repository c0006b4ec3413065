// SPDX-License-Identifier: MIT
#include "trifem/material/permeability.hpp"

#include <cmath>

namespace trifem::material {
namespace {

ParameterSchema k0_schema() {
  return {"k0", "mm^4/(N s)", "permeability in the reference state kappa(1)", Range::positive(),
          std::nullopt};
}

ParameterSchema M_schema() {
  return {"M", "", "exponential strain-dependence coefficient", Range::non_negative(), 0.0};
}

} // namespace

ConstantPermeability::ConstantPermeability(const ParameterValues& params) : k0_(params.at("k0")) {}

const std::vector<ParameterSchema>& ConstantPermeability::schema() {
  static const std::vector<ParameterSchema> s = {k0_schema()};
  return s;
}

HolmesMowPermeability::HolmesMowPermeability(const ParameterValues& params, Real phi_s0)
    : k0_(params.at("k0")), M_(params.at("M")), alpha_(params.at("alpha")), phi_s0_(phi_s0) {}

const std::vector<ParameterSchema>& HolmesMowPermeability::schema() {
  static const std::vector<ParameterSchema> s = {
      k0_schema(),
      M_schema(),
      {"alpha", "", "power-law exponent of the pore closure", Range::non_negative(), 0.0}};
  return s;
}

Real HolmesMowPermeability::value(Real J) const {
  return k0_ * std::pow((J - phi_s0_) / (1.0 - phi_s0_), alpha_) *
         std::exp(M_ * (J * J - 1.0) / 2.0);
}

Real HolmesMowPermeability::derivative(Real J) const {
  return value(J) * (alpha_ / (J - phi_s0_) + M_ * J);
}

ExponentialPermeability::ExponentialPermeability(const ParameterValues& params, Real phi_s0)
    : k0_(params.at("k0")), M_(params.at("M")), phi_s0_(phi_s0) {}

const std::vector<ParameterSchema>& ExponentialPermeability::schema() {
  static const std::vector<ParameterSchema> s = {k0_schema(), M_schema()};
  return s;
}

Real ExponentialPermeability::value(Real J) const {
  return k0_ * std::exp(M_ * (J - 1.0) / (J - phi_s0_));
}

Real ExponentialPermeability::derivative(Real J) const {
  const Real s = J - phi_s0_;
  return value(J) * M_ * (1.0 - phi_s0_) / (s * s);
}

const std::vector<TransportLawEntry<PermeabilityLaw>>& permeability_laws() {
  using Entry = TransportLawEntry<PermeabilityLaw>;
  static const std::vector<Entry> laws = {
      Entry{
          {"constant", "kappa = k0", &ConstantPermeability::schema()},
          [](const ParameterValues& p, Real) { return std::make_unique<ConstantPermeability>(p); }},
      Entry{{"holmes-mow", "kappa = k0 ((J - phi_s0)/(1 - phi_s0))^alpha exp(M (J^2 - 1)/2)",
             &HolmesMowPermeability::schema()},
            [](const ParameterValues& p, Real phi_s0) {
              return std::make_unique<HolmesMowPermeability>(p, phi_s0);
            }},
      Entry{{"exponential", "kappa = k0 exp(M (J - 1)/(J - phi_s0))",
             &ExponentialPermeability::schema()},
            [](const ParameterValues& p, Real phi_s0) {
              return std::make_unique<ExponentialPermeability>(p, phi_s0);
            }},
  };
  return laws;
}

std::unique_ptr<PermeabilityLaw> create_permeability(const std::string& type,
                                                     const ParameterValues& values, Real phi_s0,
                                                     const std::string& context) {
  return create_transport_law(permeability_laws(), type, values, phi_s0, context,
                              "permeability law");
}

std::unique_ptr<PermeabilityLaw> constant_permeability(Real k0) {
  return std::make_unique<ConstantPermeability>(ParameterValues{{"k0", k0}});
}

} // namespace trifem::material
