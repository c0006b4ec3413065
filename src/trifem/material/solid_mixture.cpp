// SPDX-License-Identifier: MIT
#include "trifem/material/solid_mixture.hpp"

#include "trifem/core/error.hpp"

namespace trifem::material {

SolidMixture::SolidMixture(std::vector<std::shared_ptr<const ElasticLaw>> constituents,
                           const std::string& context)
    : constituents_(std::move(constituents)) {
  TRIFEM_CHECK(!constituents_.empty(),
               "{}.constituent: a solid mixture needs at least one constituent", context);
  std::string types;
  for (const auto& law : constituents_) {
    TRIFEM_VERIFY(law != nullptr, "{}: null constituent", context);
    p_wave_modulus_ += law->p_wave_modulus();
    shear_modulus_ += law->shear_modulus();
    types += (types.empty() ? "" : ", ") + law->type();
  }
  TRIFEM_CHECK(p_wave_modulus_ > 0.0 && shear_modulus_ > 0.0,
               "{}: the solid mixture ({}) has no stiffness at zero strain: add a ground matrix "
               "(e.g. a neo-hookean constituent); fibres carry no load at zero strain and none "
               "across their direction",
               context, types);
}

Real SolidMixture::energy(const Mat3& C) const {
  Real W = 0.0;
  for (const auto& law : constituents_)
    W += law->energy(C);
  return W;
}

Mat3 SolidMixture::stress(const Mat3& C) const {
  Mat3 S = Mat3::Zero();
  for (const auto& law : constituents_)
    S += law->stress(C);
  return S;
}

StressTangent SolidMixture::stress_tangent(const Mat3& C) const {
  StressTangent sum{Mat3::Zero(), Mat6::Zero()};
  for (const auto& law : constituents_) {
    const StressTangent st = law->stress_tangent(C);
    sum.S += st.S;
    sum.D += st.D;
  }
  return sum;
}

} // namespace trifem::material
