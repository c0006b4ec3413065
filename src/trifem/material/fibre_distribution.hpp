// SPDX-License-Identifier: MIT
// Continuous distribution of tension-only exponential-power fibres over all directions
// (FEBio's "continuous fiber distribution" with a spherical or ellipsoidal density).
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>
#include <vector>

namespace trifem::material {

/// Fibres in every direction n of the unit sphere, each a tension-only exp-pow fibre (the
/// FibreExpPow energy W_f of I_n = n . C n), weighted by the density R(n):
///   W(C) = int_S2 R(n) W_f(I_n) dS / int_S2 R dS,
///   R(n) = (n1^2/a1^2 + n2^2/a2^2 + n3^2/a3^2)^(-1/2)   (ellipsoidal, semi-axes a along the
///          global x, y, z; a1 = a2 = a3: R = const, the spherical distribution),
///   S = 2 <W_f'(I_n) n (x) n>,   D = 4 <W_f''(I_n) n (x) n (x) n (x) n>,
/// where <.> is the R-weighted mean over directions and only directions with I_n > 1 contribute
/// (Lanir 1983; Ateshian et al. 2009, FEBio's "continuous fiber distribution"). The mean is a
/// fixed rule on the sphere, the cubed sphere: a `resolution` x `resolution` Gauss-Legendre rule
/// in equiangular coordinates on each face of the cube, on the half sphere (three faces) since
/// n and -n give the same term, with weights normalised to sum to 1, so that the spherical
/// distribution is the mean over the rule's directions. The rule has the symmetries of the cube
/// and integrates every polynomial of degree <= 5 in n exactly, so a dilatation is exact at every
/// resolution; elsewhere the integrand has a kink where I_n = 1 and the rule converges
/// algebraically (docs/theory/materials.md has the measured rates). S and D are the exact
/// derivatives of the discrete W. The law is inert at C = I (S = 0, D = 0): valid only as a
/// constituent of a SolidMixture with a ground matrix (registry: constituent_laws()).
class FibreDistribution final : public ElasticLaw {
public:
  /// Parameters: ksi (MPa, >= 0), alpha (>= 0), beta (>= 2) of the fibres, semi_axes (Vector,
  /// each > 0) of the ellipsoidal density, resolution (integer in [3, 64], default 12).
  explicit FibreDistribution(const ParameterValues& params);
  static const std::vector<ParameterSchema>& schema();
  /// The check the schema's ranges cannot express, an integer resolution: InputError naming
  /// `context.resolution` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  /// 0: no fibre carries load at C = I.
  Real p_wave_modulus() const override { return 0.0; }
  /// 0, as p_wave_modulus().
  Real shear_modulus() const override { return 0.0; }
  std::string type() const override { return "fibre-distribution"; }

  /// One direction of the rule: n (x) n as a stress-like Voigt vector and its normalised weight
  /// R(n) w / sum R w (the weights of all directions sum to 1).
  struct Direction {
    Vec6 N;
    Real weight;
  };
  /// The directions of the rule on the half sphere (3 resolution^2 of them).
  const std::vector<Direction>& directions() const { return directions_; }

private:
  /// S as a stress-like Voigt vector and, if `D` is not null, D: the weighted sums over the
  /// directions in tension.
  Vec6 sum(const Mat3& C, Mat6* D) const;

  Real ksi_;
  Real alpha_;
  Real beta_;
  std::vector<Direction> directions_;
};

} // namespace trifem::material
