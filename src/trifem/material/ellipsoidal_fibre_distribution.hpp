// SPDX-License-Identifier: MIT
// Ellipsoidal fibre distribution: tension-only power-law fibres in every direction whose modulus
// and power vary over the sphere as ellipsoids (FEBio's "ellipsoidal fiber distribution", the
// fibrillar part of its cartilage models).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>
#include <vector>

namespace trifem::material {

/// Fibres in every direction n of the unit sphere, each with the energy
///   W_n = ksi(n) (I_n - 1)^beta(n)   for I_n = n . C n > 1,   0 otherwise,
///   ksi(n) = (n1^2/ksi1^2 + n2^2/ksi2^2 + n3^2/ksi3^2)^(-1/2),
///   beta(n) = (n1^2/beta1^2 + n2^2/beta2^2 + n3^2/beta3^2)^(-1/2),
/// (the ellipsoids' semi-axes along x, y, z of the material), summed over the whole sphere:
///   W(C) = int_S2 W_n dS,   S = 2 int_S2 ksi beta (I_n - 1)^(beta - 1) n (x) n dS,
///   D = 4 int_S2 ksi beta (beta - 1) (I_n - 1)^(beta - 2) n (x) n (x) n (x) n dS
/// (Ateshian et al. 2009; the integral is not normalised: FEBio's weights are areas summing to
/// 4 pi). The integral is the cubed-sphere rule of FibreDistribution (sphere_rule.hpp) on the
/// half sphere, doubled, with `resolution` points per cube-face edge; a direction whose
/// component i is nonzero has ksi(n) = 0 if ksi_i = 0. S and D are the exact derivatives of the
/// discrete W; inert at C = I, so valid only as a constituent of a SolidMixture with a ground
/// matrix (registry: constituent_laws()). The uncoupled variant
/// ("ellipsoidal-fibre-distribution-uncoupled", FEBio's "EFD uncoupled" of its EFD Mooney-Rivlin
/// and Veronda-Westmann) takes I_n~ = J^(-2/3) I_n, the deviatoric part: its stress is
/// deviatoric and a ground matrix with a bulk modulus carries the volume.
class EllipsoidalFibreDistribution final : public ElasticLaw {
public:
  /// Parameters: ksi (Vector, MPa, each >= 0), beta (Vector, each >= 2), resolution (integer
  /// in [3, 64], default 12). `uncoupled`: of the deviatoric deformation.
  explicit EllipsoidalFibreDistribution(const ParameterValues& params, bool uncoupled = false);
  static const std::vector<ParameterSchema>& schema();
  /// An integer resolution: InputError naming `context.resolution` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  /// 0: no fibre carries load at C = I.
  Real p_wave_modulus() const override { return 0.0; }
  Real shear_modulus() const override { return 0.0; }
  std::string type() const override {
    return uncoupled_ ? "ellipsoidal-fibre-distribution-uncoupled"
                      : "ellipsoidal-fibre-distribution";
  }

private:
  /// One direction of the rule: n (x) n (stress-like Voigt), its weight (area) times ksi(n),
  /// and beta(n).
  struct Direction {
    Vec6 N;
    Real weight;
    Real beta;
  };
  /// S as a stress-like Voigt vector and, if `D` is not null, D.
  Vec6 sum(const Mat3& C, Mat6* D) const;
  /// The same of the uncoupled variant: S and, if `D` is not null, D; W if `W` is not null.
  Mat3 deviatoric_sum(const Mat3& C, Mat6* D, Real* W) const;

  std::vector<Direction> directions_;
  bool uncoupled_;
};

} // namespace trifem::material
