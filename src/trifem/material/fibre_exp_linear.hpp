// SPDX-License-Identifier: MIT
// Tension-only fibre family, exponential then linear in its stretch: uncoupled (the fibre of
// FEBio's "trans iso Mooney-Rivlin" and "trans iso Veronda-Westmann", "uncoupled
// fiber-exp-linear") or coupled (FEBio's "fiber-exp-linear").
#pragma once

#include "trifem/material/elastic_law.hpp"
#include "trifem/material/schema.hpp"

#include <string>

namespace trifem::material {

/// One fibre family of reference direction a0 (|a0| = 1) with the deviatoric fibre stretch
/// l = sqrt(I4~), I4~ = J^(-2/3) a0 . C a0, and the fibre "stress" F(l) = l dW/dl:
///   F = 0                             for l <= 1 (no load in compression),
///   F = c3 (exp(c4 (l - 1)) - 1)      for 1 < l < lam_max,
///   F = c5 l + c6                     for l >= lam_max, c6 = c3 (exp(c4 (lam_max - 1)) - 1)
///                                     - c5 lam_max (F continuous),
/// (FEBio's FEUncoupledFiberExpLinear; with c3 = 0 FEBio takes c3 = c5/c4 exp(-c4 (lam_max - 1)),
/// which makes dF/dl continuous too, and so does this law). The energy is
///   W = c3 [exp(-c4) (Ei(c4 l) - Ei(c4)) - ln l]                 below lam_max,
///   W = W(lam_max) + c5 (l - lam_max) + c6 ln(l / lam_max)        above,
/// (Ei the exponential integral), with dW/dI4~ = F/(2 I4~), d2W/dI4~2 = (l F'(l) - 2 F)/(4 I4~^2)
/// and I4~ the isochoric scaling of a0 . C a0 (uncoupled::isochoric): a purely deviatoric law,
/// inert at C = I (S = 0, D = 0), valid only as a constituent of a SolidMixture with a ground
/// matrix that carries the volume (registry: constituent_laws()). The coupled variant
/// ("fibre-exp-linear-coupled", FEBio's FEFiberExpLinear) takes the same F and W of the whole
/// fibre stretch l = sqrt(a0 . C a0) instead: its stress is not deviatoric.
class FibreExpLinear final : public ElasticLaw {
public:
  /// Parameters: c3, c4, c5 (MPa, MPa^0, MPa; >= 0; c4 > 0 if c3 = 0 and c5 > 0), lam_max (>= 1),
  /// fibre (Vector, nonzero; normalised here). `coupled`: the stretch of the whole deformation.
  explicit FibreExpLinear(const ParameterValues& params, bool coupled = false);
  static const std::vector<ParameterSchema>& schema();
  /// The checks the schema's ranges cannot express, fibre != 0 and c4 > 0 where c3 is derived
  /// from c5: InputError naming `context.key` otherwise.
  static void check(const ParameterValues& params, const std::string& context);

  Real energy(const Mat3& C) const override;
  Mat3 stress(const Mat3& C) const override;
  StressTangent stress_tangent(const Mat3& C) const override;
  /// 0: the fibre carries no load at C = I.
  Real p_wave_modulus() const override { return 0.0; }
  /// 0, as p_wave_modulus().
  Real shear_modulus() const override { return 0.0; }
  std::string type() const override {
    return coupled_ ? "fibre-exp-linear-coupled" : "fibre-exp-linear";
  }

  const Vec3& direction() const { return a0_; }

private:
  /// W(C), dW/dC and, if d2W is given, d2W/dC2.
  void evaluate(const Mat3& C, Real& W, Mat3& dW, Mat6* d2W) const;
  /// W(l), F(l) = l W'(l) and F'(l) at the deviatoric stretch l > 1.
  void fibre(Real l, Real& W, Real& F, Real& dF) const;
  /// W below lam_max: c3 [exp(-c4) (Ei(c4 l) - Ei(c4)) - ln l] (0 if c4 = 0, where F = 0).
  Real exponential_energy(Real l) const;

  Real c3_, c4_, c5_, c6_, lam_max_;
  Vec3 a0_;
  bool coupled_;
};

} // namespace trifem::material
