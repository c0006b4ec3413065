// SPDX-License-Identifier: MIT
#include "trifem/material/orthotropic_elastic.hpp"

#include "trifem/core/error.hpp"

#include <Eigen/Eigenvalues>

namespace trifem::material {
namespace {

/// The normal block of the compliance of the engineering constants (orthotropic_elastic.hpp).
Mat3 normal_compliance(const ParameterValues& p) {
  const Real E1 = p.at("E1"), E2 = p.at("E2"), E3 = p.at("E3");
  const Real v12 = p.at("v12"), v23 = p.at("v23"), v31 = p.at("v31");
  Mat3 S;
  S << 1.0 / E1, -v12 / E1, -v31 / E3, //
      -v12 / E1, 1.0 / E2, -v23 / E2,  //
      -v31 / E3, -v23 / E2, 1.0 / E3;
  return S;
}

} // namespace

const std::vector<ParameterSchema>& OrthotropicElastic::schema() {
  static const std::vector<ParameterSchema> s = {
      {"E1", "MPa", "Young's modulus along e1", Range::positive(), std::nullopt},
      {"E2", "MPa", "Young's modulus along e2", Range::positive(), std::nullopt},
      {"E3", "MPa", "Young's modulus along e3", Range::positive(), std::nullopt},
      {"G12", "MPa", "shear modulus in the (e1, e2) plane", Range::positive(), std::nullopt},
      {"G23", "MPa", "shear modulus in the (e2, e3) plane", Range::positive(), std::nullopt},
      {"G31", "MPa", "shear modulus in the (e3, e1) plane", Range::positive(), std::nullopt},
      {"v12", "", "Poisson's ratio: -strain along e2 / strain along e1 under stress along e1",
       Range{}, std::nullopt},
      {"v23", "", "Poisson's ratio: -strain along e3 / strain along e2 under stress along e2",
       Range{}, std::nullopt},
      {"v31", "", "Poisson's ratio: -strain along e1 / strain along e3 under stress along e3",
       Range{}, std::nullopt},
  };
  return s;
}

void OrthotropicElastic::check(const ParameterValues& p, const std::string& context) {
  const Real smallest =
      Eigen::SelfAdjointEigenSolver<Mat3>(normal_compliance(p), Eigen::EigenvaluesOnly)
          .eigenvalues()
          .minCoeff();
  TRIFEM_CHECK(smallest > 0.0,
               "{0}.v12 = {1}, {0}.v23 = {2}, {0}.v31 = {3}: with these Young's moduli the "
               "compliance is not positive definite (an unstable material; each |v_ij| must be "
               "below sqrt(E_i/E_j) and their combination bounded)",
               context, p.at("v12"), p.at("v23"), p.at("v31"));
}

OrthotropicElastic::OrthotropicElastic(const ParameterValues& p) {
  check(p, "orthotropic-elastic");
  D_.topLeftCorner<3, 3>() = normal_compliance(p).inverse();
  D_(3, 3) = p.at("G12"); // Voigt order xx, yy, zz, xy, yz, xz
  D_(4, 4) = p.at("G23");
  D_(5, 5) = p.at("G31");
  p_wave_modulus_ = D_.diagonal().head<3>().maxCoeff();
  shear_modulus_ = D_.diagonal().tail<3>().maxCoeff();
}

Real OrthotropicElastic::energy(const Mat3& C) const {
  const Vec6 e = voigt::strain(0.5 * (C - Mat3::Identity()));
  return 0.5 * e.dot(D_ * e);
}

Mat3 OrthotropicElastic::stress(const Mat3& C) const {
  return voigt::from_stress(D_ * voigt::strain(0.5 * (C - Mat3::Identity())));
}

StressTangent OrthotropicElastic::stress_tangent(const Mat3& C) const {
  return {stress(C), D_};
}

} // namespace trifem::material
