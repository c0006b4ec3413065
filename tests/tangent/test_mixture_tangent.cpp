// SPDX-License-Identifier: MIT
// Finite-difference check of the full triphasic (98 columns) and biphasic (49 columns) element
// tangent at a deformed, non-equilibrium state with non-zero fluxes on a distorted hex8, with
// constant and strain-dependent permeability and diffusivity laws.
#include "mixture_setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace trifem;
using namespace trifem::test;
using physics::LocalMatrix;
using physics::LocalVector;

namespace {

/// Typical magnitudes (mm-N-s-mmol) used for the FD steps and the column scaling.
constexpr Real kU = 1e-2, kW = 1e-5, kJ = 1e-9, kP = 1e-2, kEta = 10.0;

/// Scale of local unknown i.
Real typical(const physics::MixtureLayout& L, int i) {
  if (i < 24)
    return kU;
  if (i < 48)
    return kW;
  if (i == L.p())
    return kP;
  if (L.ions && i == L.eta())
    return kEta;
  return kJ;
}

void set_unknown(physics::MixtureUnknowns& x, const physics::MixtureLayout& L, int i, Real v) {
  if (i == L.p())
    x.p = v;
  else if (L.ions && i == L.eta())
    x.eta = v;
  else {
    fe::HexCoords* fields[4] = {&x.u, &x.w, &x.jp, &x.jm};
    (*fields[i / 24])((i % 24) / 3, i % 3) = v;
  }
}

Real get_unknown(const physics::MixtureUnknowns& x, const physics::MixtureLayout& L, int i) {
  if (i == L.p())
    return x.p;
  if (L.ions && i == L.eta())
    return x.eta;
  const fe::HexCoords* fields[4] = {&x.u, &x.w, &x.jp, &x.jm};
  return (*fields[i / 24])((i % 24) / 3, i % 3);
}

void check_tangent(bool ions, const std::string& solid, const material::ParameterValues& laws = {},
                   bool lumped = false) {
  Setup s = make_setup(ions, solid, laws);
  s.step.chem = &s.chem;
  s.step.lumped_flux_mass = lumped;
  const physics::MixtureLayout L{ions};
  LocalVector r;
  LocalMatrix K;
  ASSERT_TRUE(physics::mixture_hex8(s.geo, s.x, s.h, s.mat, s.step, L, r, &K));
  LocalVector r_only;
  ASSERT_TRUE(physics::mixture_hex8(s.geo, s.x, s.h, s.mat, s.step, L, r_only, nullptr));
  EXPECT_LE((r - r_only).norm(), 1e-14 * r.norm());
  const int n = L.size();
  LocalMatrix K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    const Real h = 1e-4 * typical(L, j), x0 = get_unknown(s.x, L, j);
    physics::MixtureUnknowns xp = s.x, xm = s.x;
    set_unknown(xp, L, j, x0 + h);
    set_unknown(xm, L, j, x0 - h);
    LocalVector rp, rm;
    ASSERT_TRUE(physics::mixture_hex8(s.geo, xp, s.h, s.mat, s.step, L, rp, nullptr));
    ASSERT_TRUE(physics::mixture_hex8(s.geo, xm, s.h, s.mat, s.step, L, rm, nullptr));
    K_fd.col(j) = (rp - rm) / (2 * h);
  }
  // compare block by block (row field x column field), columns scaled by typical values
  const char* names[6] = {"u", "w", "j+", "j-", "p", "eta"};
  Real worst = 0.0;
  std::string worst_block;
  auto field = [&](int i) { return i < 96 && i < L.p() ? i / 24 : (i == L.p() ? 4 : 5); };
  for (int fr = 0; fr < 6; ++fr) {
    for (int fc = 0; fc < 6; ++fc) {
      Real num = 0.0, den = 0.0, scale = 0.0;
      for (int i = 0; i < n; ++i)
        scale = std::max(scale, field(i) == fr ? K.row(i).cwiseAbs().maxCoeff() : 0.0);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          if (field(i) == fr && field(j) == fc) {
            const Real t = typical(L, j);
            num += std::pow((K(i, j) - K_fd(i, j)) * t, 2);
            den += std::pow(K(i, j) * t, 2);
          }
      if (den == 0.0 && num == 0.0)
        continue;
      // relative to the block, or to the row-field's largest entry for tiny blocks
      const Real rel = std::sqrt(num) / std::max(std::sqrt(den), 1e-8 * scale * typical(L, 0));
      if (rel > worst) {
        worst = rel;
        worst_block = std::string("d") + names[fr] + "/d" + names[fc];
      }
      EXPECT_LE(rel, 1e-6) << "rel " << rel << " " << (ions ? "triphasic " : "biphasic ") << solid
                           << " block d" << names[fr] << "/d" << names[fc];
    }
  }
  std::cout << "worst block " << worst_block << ": " << worst << "\n";
}

} // namespace

TEST(MixtureHex8, TriphasicTangentMatchesFiniteDifferencesSvk) {
  check_tangent(true, "saint-venant-kirchhoff");
}
TEST(MixtureHex8, TriphasicTangentMatchesFiniteDifferencesNeoHookean) {
  check_tangent(true, "neo-hookean");
}
TEST(MixtureHex8, BiphasicTangentMatchesFiniteDifferences) {
  check_tangent(false, "saint-venant-kirchhoff");
}

// Strain-dependent transport laws (docs/theory/triphasic.md §2a): the derivatives of kappa(J)
// and d+-(phi_w) enter the u columns of the flux rows (laws in mixture_setup.hpp).

TEST(MixtureHex8, BiphasicTangentWithHolmesMowPermeability) {
  check_tangent(false, "saint-venant-kirchhoff", kHolmesMow);
}
TEST(MixtureHex8, BiphasicTangentWithExponentialPermeability) {
  check_tangent(false, "neo-hookean", kExponential);
}
TEST(MixtureHex8, TriphasicTangentWithHolmesMowPermeability) {
  check_tangent(true, "saint-venant-kirchhoff", kHolmesMow);
}
TEST(MixtureHex8, TriphasicTangentWithExponentialPermeability) {
  check_tangent(true, "neo-hookean", kExponential);
}
TEST(MixtureHex8, TriphasicTangentWithMackieMearesDiffusivities) {
  check_tangent(true, "saint-venant-kirchhoff", kMackieMeares);
}
TEST(MixtureHex8, TriphasicTangentWithAllStrainDependentLaws) {
  material::ParameterValues laws = kHolmesMow;
  laws.insert(kMackieMeares.begin(), kMackieMeares.end());
  check_tangent(true, "neo-hookean", laws);
}

// Free-solution diffusivities above the tissue's (FEBio's free_diff > diff: the ions also drag
// on the solid), with constant and with Mackie-Meares tissue diffusivities
TEST(MixtureHex8, TriphasicTangentWithFreeDiffusivities) {
  const material::ParameterValues free = {{"free_d_plus", 9e-4}, {"free_d_minus", 2.5e-3}};
  check_tangent(true, "neo-hookean", free);
  material::ParameterValues laws = kMackieMeares;
  laws.insert(free.begin(), free.end());
  laws.insert(kHolmesMow.begin(), kHolmesMow.end());
  check_tangent(true, "neo-hookean", laws);
}

// [analysis] flux_mass = "lumped": the friction terms with diag(∫ N_a dv), and the shape
// derivatives of their mass products with the nodal fluxes
TEST(MixtureHex8, TriphasicTangentWithLumpedFluxMass) {
  material::ParameterValues laws = kHolmesMow;
  laws.insert(kMackieMeares.begin(), kMackieMeares.end());
  check_tangent(true, "neo-hookean", laws, true);
}
TEST(MixtureHex8, BiphasicTangentWithLumpedFluxMass) {
  check_tangent(false, "saint-venant-kirchhoff", kHolmesMow, true);
}
