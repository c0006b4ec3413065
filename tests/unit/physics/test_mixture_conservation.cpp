// SPDX-License-Identifier: MIT
// Exact answers checked: the element outflow sum_a g_a . j_a of the mixture hex8 equals the flux
// through its six current faces (2x2 Gauss, area vectors x_,xi x x_,eta), and the residual is
// invariant (scalar rows) / rotates with the element (vector rows) under a rigid rotation.
#include "trifem/fe/hex8.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/hex_faces.hpp"
#include "trifem/physics/mixture_kernel.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <cstdio>
#include <random>

using namespace trifem;
using physics::LocalVector;

namespace {

/// Unit cube with every node moved randomly by up to +-0.15 per coordinate.
fe::HexCoords distorted_cube(std::mt19937& rng) {
  std::uniform_real_distribution<Real> d(-0.15, 0.15);
  fe::HexCoords X;
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      X(a, k) = 0.5 * (mesh::kHexNodeCoords[a][k] + 1.0) + d(rng);
  return X;
}

fe::HexCoords random_nodal(std::mt19937& rng, Real amplitude) {
  std::uniform_real_distribution<Real> d(-amplitude, amplitude);
  fe::HexCoords v;
  for (int a = 0; a < 8; ++a)
    for (int k = 0; k < 3; ++k)
      v(a, k) = d(rng);
  return v;
}

/// A random deformation: a homogeneous stretch/shear plus a random nodal perturbation.
fe::HexCoords random_displacement(std::mt19937& rng, const fe::HexCoords& X) {
  Mat3 G = Mat3::Zero();
  std::uniform_real_distribution<Real> d(-0.15, 0.15);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      G(i, k) = d(rng);
  return X * G.transpose() + random_nodal(rng, 0.08);
}

/// Current volume sum_q det(dx/dxi) w_q, computed from the nodal positions only.
Real current_volume(const fe::HexCoords& x) {
  Real V = 0.0;
  for (const fe::HexQuadraturePoint& q : fe::hex_gauss_2x2x2()) {
    const Mat3 dx_dxi = x.transpose() * fe::hex8_shape_grad(q.xi);
    V += dx_dxi.determinant() * q.weight;
  }
  return V;
}

/// Outflow of a nodal vector field through the six current faces: per face,
/// int v . (x_,xi x x_,eta) dxi deta by 2x2 Gauss (kHexFaces gives outward normals).
/// Returns {net outflow, sum of |face outflows|}.
std::pair<Real, Real> face_outflow(const fe::HexCoords& x, const fe::HexCoords& v) {
  Real net = 0.0, magnitude = 0.0;
  for (const auto& face : mesh::kHexFaces) {
    Real flux = 0.0;
    for (const fe::QuadQuadraturePoint& q : fe::quad_gauss_2x2()) {
      const fe::QuadShape N = fe::quad4_shape(q.xi);
      const fe::QuadShapeGrad dN = fe::quad4_shape_grad(q.xi);
      Vec3 x_xi = Vec3::Zero(), x_eta = Vec3::Zero(), vq = Vec3::Zero();
      for (int i = 0; i < 4; ++i) {
        const int a = face[i];
        x_xi += dN(i, 0) * x.row(a).transpose();
        x_eta += dN(i, 1) * x.row(a).transpose();
        vq += N[i] * v.row(a).transpose();
      }
      flux += vq.dot(x_xi.cross(x_eta)) * q.weight;
    }
    net += flux;
    magnitude += std::abs(flux);
  }
  return {net, magnitude};
}

material::MixtureProperties tissue(bool ions, const std::string& solid) {
  material::ParameterValues v = {{"phi_s0", 0.25}, {"permeability", 1.07e-3}};
  if (ions) {
    v["fixed_charge"] = 2e-4;
    v["d_plus"] = 5e-4;
    v["d_minus"] = 8e-4;
    v["osmotic"] = 0.93;
  }
  return material::make_mixture(
      ions, material::create_law(solid, {{"E", 0.3}, {"nu", 0.2}}, "solid"), v, "m");
}

Real reference_volume(const fe::HexGeometry& geo) {
  Real V0 = 0.0;
  for (Real dV : geo.dV)
    V0 += dV;
  return V0;
}

} // namespace

/// (i) R^p (biphasic, dt = 1, V_old = V) = sum_a g_a . w_a = face integral of w . n, and
/// R^eta (triphasic, N+ - N- = N_F) = sum_a g_a . (j+_a - j-_a) = face integral of (j+ - j-) . n.
TEST(MixtureConservation, ElementOutflowEqualsCurrentFaceIntegral) {
  material::Electrochemistry chem;
  Real worst = 0.0;
  for (unsigned seed = 1; seed <= 8; ++seed) {
    std::mt19937 rng(seed);
    const fe::HexCoords X = distorted_cube(rng);
    const auto geo = fe::hex8_geometry(X);
    ASSERT_TRUE(geo.has_value());
    physics::MixtureUnknowns x;
    x.u = random_displacement(rng, X);
    const fe::HexCoords xc = X + x.u;
    // O(1) fluxes: the check is an identity, and (V - V_old) round-off must stay negligible
    x.w = random_nodal(rng, 1.0);
    x.jp = random_nodal(rng, 1.0);
    x.jm = random_nodal(rng, 1.0);
    x.p = 0.1;
    x.eta = -300.0;

    // biphasic: the p row is (V - V_old)/dt + sum_a g_a . w_a
    {
      const material::MixtureProperties mat = tissue(false, "saint-venant-kirchhoff");
      physics::MixtureHistory h;
      h.V0 = reference_volume(*geo);
      h.V_old = current_volume(xc);
      const physics::MixtureStep step{1.0, 0.0, &chem};
      const physics::MixtureLayout L{false};
      LocalVector r;
      ASSERT_TRUE(physics::mixture_hex8(*geo, x, h, mat, step, L, r, nullptr));
      const auto [flux, magnitude] = face_outflow(xc, x.w);
      const Real rel = std::abs(r[L.p()] - flux) / magnitude;
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-13) << "seed " << seed << ": R^p " << r[L.p()] << " vs " << flux;
    }
    // triphasic: the eta row is Q+ - Q- - (N+ - N- - N_F)/dt with N+ - N- - N_F = 0 exactly
    {
      const material::MixtureProperties mat = tissue(true, "neo-hookean");
      physics::MixtureHistory h;
      h.V0 = reference_volume(*geo);
      h.V_old = h.V0;
      h.N_plus = 2.0;
      h.N_minus = 1.5;
      h.N_fixed = h.N_fixed_old = 0.5;
      const physics::MixtureStep step{1e-3, 0.0, &chem}; // keeps N+- = N - dt Q positive
      const physics::MixtureLayout L{true};
      LocalVector r;
      ASSERT_TRUE(physics::mixture_hex8(*geo, x, h, mat, step, L, r, nullptr));
      const auto [flux, magnitude] = face_outflow(xc, x.jp - x.jm);
      const Real rel = std::abs(r[L.eta()] - flux) / magnitude;
      worst = std::max(worst, rel);
      EXPECT_LE(rel, 1e-13) << "seed " << seed << ": R^eta " << r[L.eta()] << " vs " << flux;
    }
  }
  std::printf("worst |sum g.j - face integral| / sum |face fluxes| = %.3e\n", worst);
}

/// (ii) x' = Q x, w' = Q w, j+-' = Q j+-: R^p and R^eta unchanged, nodal rows R'_a = Q R_a.
TEST(MixtureConservation, ResidualIsObjectiveUnderRigidRotation) {
  material::Electrochemistry chem;
  Real worst_vector = 0.0, worst_scalar = 0.0;
  for (const std::string solid : {"saint-venant-kirchhoff", "neo-hookean"})
    for (unsigned seed = 11; seed <= 14; ++seed) {
      std::mt19937 rng(seed);
      const fe::HexCoords X = distorted_cube(rng);
      const auto geo = fe::hex8_geometry(X);
      ASSERT_TRUE(geo.has_value());
      physics::MixtureUnknowns x;
      x.u = random_displacement(rng, X);
      x.w = random_nodal(rng, 2e-5);
      x.jp = random_nodal(rng, 3e-9);
      x.jm = random_nodal(rng, 2e-9);
      x.p = 0.12;
      x.eta = -1500.0;
      const material::MixtureProperties mat = tissue(true, solid);
      physics::MixtureHistory h;
      h.V0 = reference_volume(*geo);
      h.V_old = 0.97 * h.V0;
      const Real Vw = 0.75 * h.V0;
      h.N_fixed = h.N_fixed_old = 2e-4 * Vw;
      h.N_plus = 2.9e-4 * Vw;
      h.N_minus = 0.85e-4 * Vw;
      const physics::MixtureStep step{0.7, 0.05, &chem};
      const physics::MixtureLayout L{true};

      std::uniform_real_distribution<Real> d(-1.0, 1.0);
      const Vec3 axis = Vec3(d(rng), d(rng), d(rng)).normalized();
      const Mat3 Q = Eigen::AngleAxisd(3.0 * d(rng), axis).toRotationMatrix();
      physics::MixtureUnknowns xr = x;
      xr.u = (X + x.u) * Q.transpose() - X; // x' = Q x
      xr.w = x.w * Q.transpose();
      xr.jp = x.jp * Q.transpose();
      xr.jm = x.jm * Q.transpose();

      LocalVector r, rr;
      ASSERT_TRUE(physics::mixture_hex8(*geo, x, h, mat, step, L, r, nullptr));
      ASSERT_TRUE(physics::mixture_hex8(*geo, xr, h, mat, step, L, rr, nullptr));

      const char* names[4] = {"u", "w", "j+", "j-"};
      for (int f = 0; f < 4; ++f) {
        Real difference = 0.0, magnitude = 0.0;
        for (int a = 0; a < 8; ++a) {
          const int i = 24 * f + 3 * a;
          const Vec3 Ra = r.segment<3>(i), Rra = rr.segment<3>(i);
          difference = std::max(difference, (Rra - Q * Ra).norm());
          magnitude = std::max(magnitude, Ra.norm());
        }
        ASSERT_GT(magnitude, 0.0);
        worst_vector = std::max(worst_vector, difference / magnitude);
        EXPECT_LE(difference, 1e-12 * magnitude)
            << solid << " seed " << seed << " rows " << names[f];
      }
      for (int i : {L.p(), L.eta()}) {
        const Real rel = std::abs(rr[i] - r[i]) / std::abs(r[i]);
        worst_scalar = std::max(worst_scalar, rel);
        EXPECT_LE(rel, 1e-12) << solid << " seed " << seed << " row " << i;
      }
    }
  std::printf("worst relative rotation error: vector rows %.3e, scalar rows %.3e\n", worst_vector,
              worst_scalar);
}
