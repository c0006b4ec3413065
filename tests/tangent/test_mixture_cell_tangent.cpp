// SPDX-License-Identifier: MIT
// The mixture element on every cell family (physics::mixture_cell): on a hex8 it is the hex8
// element (mixture_hex8) to round-off; its flux map interpolates the corners' linear functions;
// and on a distorted cell of each family at a deformed,
// non-equilibrium state with non-zero fluxes its tangent matches central differences block by
// block (u, w, j+, j-, p, eta), triphasic and biphasic, with constant and strain-dependent
// transport laws.
#include "cell_families.hpp"
#include "mixture_setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

using namespace trifem;
using physics::LocalMatrix;
using physics::LocalVector;

namespace mixture_cell_test {

/// Typical magnitudes (mm-N-s-mmol) of the unknowns: FD steps and column scaling.
constexpr Real kU = 1e-2, kW = 1e-5, kJ = 1e-9, kP = 1e-2, kEta = 10.0;

/// Field of local unknown i: 0 u, 1 w, 2 j+, 3 j-, 4 p, 5 eta.
int field_of(const physics::MixtureLayout& L, int i) {
  if (i == L.p())
    return 4;
  if (L.ions && i == L.eta())
    return 5;
  return i < 3 * L.nodes ? 0 : 1 + (i - 3 * L.nodes) / (3 * L.flux_nodes);
}

Real typical(const physics::MixtureLayout& L, int i) {
  constexpr Real scale[6] = {kU, kW, kJ, kJ, kP, kEta};
  return scale[field_of(L, i)];
}

Real& unknown(physics::CellMixtureUnknowns& x, const physics::MixtureLayout& L, int i) {
  const int f = field_of(L, i);
  if (f == 4)
    return x.p;
  if (f == 5)
    return x.eta;
  fe::CellNodeCoords* fields[4] = {&x.u, &x.w, &x.jp, &x.jm};
  const int local = f == 0 ? i : (i - 3 * L.nodes) % (3 * L.flux_nodes);
  return (*fields[f])(local / 3, local % 3);
}

/// A deformed, non-equilibrium state of a distorted cell of `type` (the magnitudes of
/// mixture_setup.hpp's hex8 state).
struct CellSetup {
  physics::CellGeometry geo;
  physics::CellMixtureUnknowns x;
  test::Setup base; ///< history, mixture, chemistry and step (its hex8 parts unused)
  physics::MixtureLayout layout;
};

CellSetup make_cell_setup(fe::CellType type, bool ions, const std::string& solid,
                          const material::ParameterValues& laws = {}) {
  CellSetup s;
  s.base = test::make_setup(ions, solid, laws);
  s.base.step.chem = &s.base.chem;
  s.geo = *physics::cell_geometry(
      fe::reference_cell(type), test::distorted_cell(type, 11 + static_cast<unsigned>(type), 0.06));
  const auto n = static_cast<Index>(s.geo.num_nodes());
  const auto nf = static_cast<Index>(physics::mixture_flux_map(type).rows());
  s.layout = {ions, static_cast<int>(n), static_cast<int>(nf)};
  test::Noise noise(5);
  s.x.u.resize(n, 3);
  for (Index a = 0; a < n; ++a)
    for (int k = 0; k < 3; ++k)
      s.x.u(a, k) = 0.08 * noise.next();
  for (fe::CellNodeCoords* v : {&s.x.w, &s.x.jp, &s.x.jm})
    v->resize(nf, 3);
  for (Index a = 0; a < nf; ++a)
    for (int k = 0; k < 3; ++k) {
      s.x.w(a, k) = 2e-5 * noise.next();
      s.x.jp(a, k) = 3e-9 * noise.next();
      s.x.jm(a, k) = 2e-9 * noise.next();
    }
  s.x.p = 0.12;
  s.x.eta = -1500.0;
  // the history of make_setup's hex8, rescaled to this cell's volume
  Real V0 = 0.0;
  for (Real dV : s.geo.dV)
    V0 += dV;
  const Real ratio = V0 / s.base.h.V0;
  physics::MixtureHistory& h = s.base.h;
  h.V0 = V0;
  h.V_old *= ratio;
  h.N_fixed *= ratio;
  h.N_fixed_old *= ratio;
  h.N_plus *= ratio;
  h.N_minus *= ratio;
  return s;
}

bool evaluate(const CellSetup& s, const physics::CellMixtureUnknowns& x, LocalVector& r,
              LocalMatrix* K) {
  return physics::mixture_cell(s.geo, x, s.base.h, s.base.mat, s.base.step, s.layout, r, K);
}

void check_tangent(fe::CellType type, bool ions, const std::string& solid,
                   const material::ParameterValues& laws = {}) {
  const CellSetup s = make_cell_setup(type, ions, solid, laws);
  const physics::MixtureLayout& L = s.layout;
  LocalVector r, r_only;
  LocalMatrix K;
  ASSERT_TRUE(evaluate(s, s.x, r, &K));
  ASSERT_TRUE(evaluate(s, s.x, r_only, nullptr));
  EXPECT_LE((r - r_only).norm(), 1e-14 * r.norm());
  const int n = L.size();
  ASSERT_EQ(r.size(), n);
  LocalMatrix K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    const Real h = 1e-4 * typical(L, j);
    physics::CellMixtureUnknowns xp = s.x, xm = s.x;
    unknown(xp, L, j) += h;
    unknown(xm, L, j) -= h;
    LocalVector rp, rm;
    ASSERT_TRUE(evaluate(s, xp, rp, nullptr));
    ASSERT_TRUE(evaluate(s, xm, rm, nullptr));
    K_fd.col(j) = (rp - rm) / (2 * h);
  }
  // block by block (row field x column field), columns scaled by the typical values
  const char* names[6] = {"u", "w", "j+", "j-", "p", "eta"};
  Real worst = 0.0;
  std::string worst_block;
  for (int fr = 0; fr < 6; ++fr)
    for (int fc = 0; fc < 6; ++fc) {
      Real num = 0.0, den = 0.0, scale = 0.0;
      for (int i = 0; i < n; ++i)
        if (field_of(L, i) == fr)
          scale = std::max(scale, K.row(i).cwiseAbs().maxCoeff());
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          if (field_of(L, i) == fr && field_of(L, j) == fc) {
            const Real t = typical(L, j);
            num += std::pow((K(i, j) - K_fd(i, j)) * t, 2);
            den += std::pow(K(i, j) * t, 2);
          }
      if (den == 0.0 && num == 0.0)
        continue;
      // relative to the block, or to the row field's largest entry for tiny blocks
      const Real rel = std::sqrt(num) / std::max(std::sqrt(den), 1e-8 * scale * kU);
      if (rel > worst) {
        worst = rel;
        worst_block = std::string("d") + names[fr] + "/d" + names[fc];
      }
      EXPECT_LE(rel, 1e-6) << mesh::name(type) << (ions ? " triphasic " : " biphasic ") << solid
                           << " block d" << names[fr] << "/d" << names[fc];
    }
  std::cout << mesh::name(type) << (ions ? " triphasic" : " biphasic") << ": worst block "
            << worst_block << ", relative error " << worst << "\n";
}

} // namespace mixture_cell_test

using namespace mixture_cell_test;

TEST(MixtureCell, OnAHex8IsTheHex8ElementToRoundOff) {
  for (bool ions : {true, false}) {
    test::Setup s = test::make_setup(ions, "neo-hookean", test::kHolmesMow);
    s.step.chem = &s.chem;
    const physics::MixtureLayout L{ions};
    LocalVector r_hex, r_cell;
    LocalMatrix K_hex, K_cell;
    ASSERT_TRUE(physics::mixture_hex8(s.geo, s.x, s.h, s.mat, s.step, L, r_hex, &K_hex));
    fe::CellNodeCoords X(8, 3);
    for (int a = 0; a < 8; ++a) // the corners of s.geo's cell (mixture_setup.hpp)
      X.row(a) = test::distorted_unit_cube(ions ? 3 : 4).row(a);
    const physics::CellGeometry geo =
        *physics::cell_geometry(fe::reference_cell(fe::CellType::Hex8), X);
    physics::CellMixtureUnknowns x{s.x.u, s.x.w, s.x.jp, s.x.jm, s.x.p, s.x.eta};
    ASSERT_TRUE(physics::mixture_cell(geo, x, s.h, s.mat, s.step, L, r_cell, &K_cell));
    ASSERT_EQ(r_cell.size(), r_hex.size());
    // each field's rows against that field's largest value: the rows mix units
    for (int f = 0; f < 6; ++f) {
      Real r_scale = 0.0, K_scale = 0.0, r_diff = 0.0, K_diff = 0.0;
      for (int i = 0; i < L.size(); ++i)
        if (field_of(L, i) == f) {
          r_scale = std::max(r_scale, std::abs(r_hex[i]));
          K_scale = std::max(K_scale, K_hex.row(i).cwiseAbs().maxCoeff());
          r_diff = std::max(r_diff, std::abs(r_cell[i] - r_hex[i]));
          K_diff = std::max(K_diff, (K_cell.row(i) - K_hex.row(i)).cwiseAbs().maxCoeff());
        }
      EXPECT_LE(r_diff, 1e-12 * r_scale) << "field " << f << (ions ? " triphasic" : " biphasic");
      EXPECT_LE(K_diff, 1e-12 * K_scale) << "field " << f << (ions ? " triphasic" : " biphasic");
    }
  }
}

/// The flux shape functions of a quadratic cell are its linear sibling's (tet4 for tet10, hex8
/// for hex20) at every point: they sum to one and reproduce x linearly on a straight-edged cell.
TEST(MixtureCell, FluxMapGivesTheLinearFunctionsOfTheCorners) {
  const std::pair<fe::CellType, fe::CellType> pairs[] = {
      {fe::CellType::Tet10, fe::CellType::Tet4},
      {fe::CellType::Hex20, fe::CellType::Hex8},
      {fe::CellType::Tet4, fe::CellType::Tet4},
      {fe::CellType::Penta6, fe::CellType::Penta6}};
  test::Noise noise(2);
  for (const auto& [quadratic, linear] : pairs) {
    const physics::MixtureFluxMap& P = physics::mixture_flux_map(quadratic);
    ASSERT_EQ(P.rows(), mesh::num_nodes(linear));
    for (int i = 0; i < 10; ++i) {
      const Vec3 xi = 0.3 * Vec3(noise.next(), noise.next(), noise.next()) + Vec3::Constant(0.2);
      const fe::ShapeValues mapped = P * fe::reference_cell(quadratic).shape(xi);
      const fe::ShapeValues expected = fe::reference_cell(linear).shape(xi);
      EXPECT_LE((mapped - expected).cwiseAbs().maxCoeff(), 1e-15) << mesh::name(quadratic);
      const fe::ShapeGrads mapped_grad = P * fe::reference_cell(quadratic).shape_grad(xi);
      EXPECT_LE((mapped_grad - fe::reference_cell(linear).shape_grad(xi)).cwiseAbs().maxCoeff(),
                1e-14)
          << mesh::name(quadratic);
    }
  }
}

TEST(MixtureCell, TriphasicTangentMatchesFiniteDifferencesOnEveryFamily) {
  for (fe::CellType type : test::kCellFamilies)
    check_tangent(type, true, "neo-hookean");
}

TEST(MixtureCell, BiphasicTangentMatchesFiniteDifferencesOnEveryFamily) {
  for (fe::CellType type : test::kCellFamilies)
    check_tangent(type, false, "saint-venant-kirchhoff");
}

TEST(MixtureCell, TangentWithStrainDependentTransportLawsMatchesFiniteDifferences) {
  for (fe::CellType type : {fe::CellType::Tet10, fe::CellType::Penta6, fe::CellType::Hex20}) {
    check_tangent(type, false, "neo-hookean", test::kHolmesMow);
    check_tangent(type, true, "saint-venant-kirchhoff", test::kMackieMeares);
  }
}

namespace mixture_cell_test {

/// Field of local unknown i of a tet with corner potentials: 0 u, 1 w, 2 j+, 3 j-, 4 p, 5 eta.
int corner_field_of(const physics::MixtureLayout& L, int i) {
  if (i >= L.p())
    return i < L.p() + 4 ? 4 : 5;
  return i < 3 * L.nodes ? 0 : 1 + (i - 3 * L.nodes) / (3 * L.flux_nodes);
}

/// A tet's state with corner potentials that differ by corner (p varies by 10 %).
struct CornerSetup {
  CellSetup cell;
  physics::CornerPotentials corners;
};

CornerSetup make_corner_setup(fe::CellType type, bool ions, const std::string& solid,
                              const material::ParameterValues& laws = {}) {
  CornerSetup s{make_cell_setup(type, ions, solid, laws), {}};
  test::Noise noise(9);
  // the last step's corner volumes: those at a displacement 0.9 times the current one
  s.corners.volume_old = physics::corner_volumes(s.cell.geo, 0.9 * s.cell.x.u);
  for (std::size_t b = 0; b < 4; ++b) {
    s.corners.p[b] = s.cell.x.p * (1.0 + 0.1 * noise.next());
    s.corners.eta[b] = s.cell.x.eta * (1.0 + 0.1 * noise.next());
  }
  return s;
}

bool evaluate_corners(const CornerSetup& s, const physics::CellMixtureUnknowns& x,
                      const physics::CornerPotentials& corners, LocalVector& r, LocalMatrix* K) {
  return physics::mixture_tet(s.cell.geo, x, corners, s.cell.base.h, s.cell.base.mat,
                              s.cell.base.step, s.cell.layout, r, K);
}

/// The tangent of mixture_tet against central differences, block by block as check_tangent.
void check_corner_tangent(fe::CellType type, bool ions, const std::string& solid,
                          const material::ParameterValues& laws = {}) {
  const CornerSetup s = make_corner_setup(type, ions, solid, laws);
  const physics::MixtureLayout& L = s.cell.layout;
  LocalVector r, r_only;
  LocalMatrix K;
  ASSERT_TRUE(evaluate_corners(s, s.cell.x, s.corners, r, &K));
  ASSERT_TRUE(evaluate_corners(s, s.cell.x, s.corners, r_only, nullptr));
  EXPECT_LE((r - r_only).norm(), 1e-14 * r.norm());
  const int n = physics::corner_layout_size(L);
  ASSERT_EQ(r.size(), n);
  constexpr Real scale[6] = {kU, kW, kJ, kJ, kP, kEta};
  LocalMatrix K_fd(n, n);
  for (int j = 0; j < n; ++j) {
    const int f = corner_field_of(L, j);
    const Real h = 1e-4 * scale[f];
    physics::CellMixtureUnknowns xp = s.cell.x, xm = s.cell.x;
    physics::CornerPotentials cp = s.corners, cm = s.corners;
    if (f == 4 || f == 5) {
      auto& values_p = f == 4 ? cp.p : cp.eta;
      auto& values_m = f == 4 ? cm.p : cm.eta;
      const auto b = static_cast<std::size_t>((j - L.p()) % 4);
      values_p[b] += h;
      values_m[b] -= h;
    } else {
      unknown(xp, L, j) += h;
      unknown(xm, L, j) -= h;
    }
    LocalVector rp, rm;
    ASSERT_TRUE(evaluate_corners(s, xp, cp, rp, nullptr));
    ASSERT_TRUE(evaluate_corners(s, xm, cm, rm, nullptr));
    K_fd.col(j) = (rp - rm) / (2 * h);
  }
  const char* names[6] = {"u", "w", "j+", "j-", "p", "eta"};
  Real worst = 0.0;
  for (int fr = 0; fr < 6; ++fr)
    for (int fc = 0; fc < 6; ++fc) {
      Real num = 0.0, den = 0.0, row_scale = 0.0;
      for (int i = 0; i < n; ++i)
        if (corner_field_of(L, i) == fr)
          row_scale = std::max(row_scale, K.row(i).cwiseAbs().maxCoeff());
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          if (corner_field_of(L, i) == fr && corner_field_of(L, j) == fc) {
            const Real t = scale[fc];
            num += std::pow((K(i, j) - K_fd(i, j)) * t, 2);
            den += std::pow(K(i, j) * t, 2);
          }
      if (den == 0.0 && num == 0.0)
        continue;
      const Real rel = std::sqrt(num) / std::max(std::sqrt(den), 1e-8 * row_scale * kU);
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-6) << mesh::name(type) << (ions ? " triphasic " : " biphasic ") << solid
                           << " block d" << names[fr] << "/d" << names[fc];
    }
  std::cout << mesh::name(type) << (ions ? " triphasic" : " biphasic")
            << " with corner potentials: worst block relative error " << worst << "\n";
}

} // namespace mixture_cell_test

TEST(MixtureCell, CornerPotentialTangentMatchesFiniteDifferencesOnTets) {
  for (fe::CellType type : {fe::CellType::Tet10, fe::CellType::Tet4}) {
    check_corner_tangent(type, true, "neo-hookean");
    check_corner_tangent(type, false, "saint-venant-kirchhoff");
  }
  check_corner_tangent(fe::CellType::Tet10, false, "neo-hookean", test::kHolmesMow);
  check_corner_tangent(fe::CellType::Tet10, true, "saint-venant-kirchhoff", test::kMackieMeares);
}

/// With the same potential at every corner, mixture_tet is mixture_cell with that potential
/// (its rows of p and η summed over the corners, each a quarter) and the corners' volumes of
/// the last step at V_old / 4 each: the element of the other families.
TEST(MixtureCell, EqualCornerPotentialsGiveTheCellElementOnAStraightTet) {
  for (bool ions : {true, false}) {
    CellSetup s = make_cell_setup(fe::CellType::Tet4, ions, "neo-hookean");
    physics::CornerPotentials corners;
    corners.p.fill(s.x.p);
    corners.eta.fill(s.x.eta);
    corners.volume_old.fill(0.25 * s.base.h.V_old);
    LocalVector r_cell, r_tet;
    ASSERT_TRUE(evaluate(s, s.x, r_cell, nullptr));
    ASSERT_TRUE(physics::mixture_tet(s.geo, s.x, corners, s.base.h, s.base.mat, s.base.step,
                                     s.layout, r_tet, nullptr));
    const physics::MixtureLayout& L = s.layout;
    const int head = L.p();
    EXPECT_LE((r_tet.head(head) - r_cell.head(head)).cwiseAbs().maxCoeff(),
              1e-13 * r_cell.head(head).cwiseAbs().maxCoeff());
    for (int b = 0; b < 4; ++b) {
      EXPECT_NEAR(r_tet[head + b], 0.25 * r_cell[L.p()], 1e-13 * std::abs(r_cell[L.p()]));
      if (ions) {
        EXPECT_NEAR(r_tet[head + 4 + b], 0.25 * r_cell[L.eta()], 1e-13 * std::abs(r_cell[L.eta()]));
      }
    }
  }
}
