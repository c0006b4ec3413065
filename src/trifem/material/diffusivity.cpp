// SPDX-License-Identifier: MIT
#include "trifem/material/diffusivity.hpp"

namespace trifem::material {

ConstantDiffusivity::ConstantDiffusivity(const ParameterValues& params) : d_(params.at("d")) {}

const std::vector<ParameterSchema>& ConstantDiffusivity::schema() {
  static const std::vector<ParameterSchema> s = {
      {"d", "mm^2/s", "diffusivity in the tissue", Range::positive(), std::nullopt}};
  return s;
}

MackieMearesDiffusivity::MackieMearesDiffusivity(const ParameterValues& params)
    : d0_(params.at("d0")) {}

const std::vector<ParameterSchema>& MackieMearesDiffusivity::schema() {
  static const std::vector<ParameterSchema> s = {
      {"d0", "mm^2/s", "diffusivity in free solution", Range::positive(), std::nullopt}};
  return s;
}

Real MackieMearesDiffusivity::value(Real phi_w) const {
  const Real r = phi_w / (2.0 - phi_w);
  return d0_ * r * r;
}

Real MackieMearesDiffusivity::derivative(Real phi_w) const {
  const Real s = 2.0 - phi_w;
  return 4.0 * d0_ * phi_w / (s * s * s);
}

const std::vector<TransportLawEntry<DiffusivityLaw>>& diffusivity_laws() {
  using Entry = TransportLawEntry<DiffusivityLaw>;
  static const std::vector<Entry> laws = {
      Entry{
          {"constant", "d (independent of phi_w)", &ConstantDiffusivity::schema()},
          [](const ParameterValues& p, Real) { return std::make_unique<ConstantDiffusivity>(p); }},
      Entry{{"mackie-meares", "d = d0 (phi_w/(2 - phi_w))^2", &MackieMearesDiffusivity::schema()},
            [](const ParameterValues& p, Real) {
              return std::make_unique<MackieMearesDiffusivity>(p);
            }},
  };
  return laws;
}

std::unique_ptr<DiffusivityLaw> create_diffusivity(const std::string& type,
                                                   const ParameterValues& values,
                                                   const std::string& context) {
  return create_transport_law(diffusivity_laws(), type, values, 0.0, context, "diffusivity law");
}

std::unique_ptr<DiffusivityLaw> constant_diffusivity(Real d) {
  return std::make_unique<ConstantDiffusivity>(ParameterValues{{"d", d}});
}

} // namespace trifem::material
