// SPDX-License-Identifier: MIT
// Uniaxial large stretch (1.5 and 0.8) of a block with free lateral faces (symmetry planes):
// the FE stress equals the closed-form uniaxial stress of each law in every element.
#include "solid_model.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;

namespace {

constexpr Real kE = 1.0, kNu = 0.3;

/// Closed-form uniaxial Cauchy stress and lateral stretch at axial stretch l.
struct Uniaxial {
  Real sigma;
  Real lateral;
};

Uniaxial neo_hookean_uniaxial(Real l) {
  const auto [lambda, mu] = material::lame_from_young(kE, kNu);
  Real t = 1.0; // lateral stretch: mu (t^2 - 1) + lambda ln(l t^2) = 0
  for (int it = 0; it < 60; ++it)
    t -= (mu * (t * t - 1) + lambda * std::log(l * t * t)) / (2 * mu * t + 2 * lambda / t);
  const Real J = l * t * t;
  return {(mu * (l * l - 1) + lambda * std::log(J)) / J, t};
}

Uniaxial svk_uniaxial(Real l) {
  // S22 = 0 gives E22 = -nu E11 and S11 = E E11; sigma11 = l^2 S11 / J
  const Real E11 = 0.5 * (l * l - 1), E22 = -kNu * E11;
  const Real t = std::sqrt(1 + 2 * E22);
  return {l * l * kE * E11 / (l * t * t), t};
}

void run_uniaxial(const std::string& law, Real stretch, Uniaxial exact) {
  mesh::BoxSpec spec;
  spec.divisions = {3, 2, 2};
  spec.size = Vec3(2.0, 1.0, 1.0);
  test::SolidModel m(mesh::make_box(spec), law, {{"E", kE}, {"nu", kNu}});
  m.prescribe(m.mesh.node_set("box.xmin"), 0, 0.0);
  m.prescribe(m.mesh.node_set("box.ymin"), 1, 0.0);
  m.prescribe(m.mesh.node_set("box.zmin"), 2, 0.0);
  m.prescribe(m.mesh.node_set("box.xmax"), 0, 2.0 * (stretch - 1.0));
  m.build();
  const int steps = 4;
  for (int s = 1; s <= steps; ++s)
    ASSERT_EQ(m.solve_step(Real(s) / steps, 1.0 / steps).status, solver::SolveStatus::Converged);
  for (Index e = 0; e < m.solid->num_elements(); ++e) {
    const Mat3 sigma = m.solid->stress(e, m.problem->state()).cauchy;
    EXPECT_NEAR(sigma(0, 0), exact.sigma, 1e-10 * std::abs(exact.sigma)) << law << " " << stretch;
    EXPECT_NEAR(sigma(1, 1), 0.0, 1e-10 * std::abs(exact.sigma));
    EXPECT_NEAR(sigma(0, 1), 0.0, 1e-10 * std::abs(exact.sigma));
  }
  const Index corner = m.mesh.num_nodes() - 1; // (2, 1, 1)
  const Real width = 1.0;                      // lateral size: u_y = (lateral - 1) width
  EXPECT_NEAR(m.displacement(corner).y(), (exact.lateral - 1.0) * width, 1e-10 * width);
}

} // namespace

TEST(Uniaxial, NeoHookeanStretch1p5) {
  run_uniaxial("neo-hookean", 1.5, neo_hookean_uniaxial(1.5));
}
TEST(Uniaxial, NeoHookeanStretch0p8) {
  run_uniaxial("neo-hookean", 0.8, neo_hookean_uniaxial(0.8));
}
TEST(Uniaxial, SaintVenantKirchhoffStretch1p5) {
  run_uniaxial("saint-venant-kirchhoff", 1.5, svk_uniaxial(1.5));
}
TEST(Uniaxial, SaintVenantKirchhoffStretch0p8) {
  run_uniaxial("saint-venant-kirchhoff", 0.8, svk_uniaxial(0.8));
}
