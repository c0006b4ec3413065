// SPDX-License-Identifier: MIT
// Rotated nodal frames: the biphasic creep column, rotated arbitrarily in space, with its
// confinement and impermeability imposed as normal constraints on faces that are not aligned
// with the axes, gives the same answer as the axis-aligned column (to round-off).
#include "mixture_model.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

using namespace trifem;

namespace {

constexpr Real kFramesSigma0 = 1e-4;

/// Axis-aligned (Q = I, plain constraints) or rotated (frames) column of 1 x 1 x 6 cells.
test::MixtureModel column(const Mat3& Q, bool frames) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 6};
  mesh::Mesh mesh = mesh::make_box(spec);
  mesh.transform(Q);
  test::MixtureModel m(std::move(mesh), test::paper_tissue(false));
  m.loads.push_back(std::make_unique<physics::TractionTerm>(
      m.mesh, m.dofs, m.f.u, m.mesh.surface("box.zmax").facets, Q * Vec3(0, 0, -kFramesSigma0),
      dofs::LoadCurve({{0.0, 0.0}, {1e-9, 1.0}}, dofs::Interpolation::Linear)));
  for (int k = 0; k < 3; ++k)
    m.fix("box.zmin", m.f.u, k); // bonded base: all components, any frame
  if (!frames) {
    for (int k = 0; k < 2; ++k) {
      m.fix("box.all", m.f.u, k);
      m.impermeable("box.all", k);
    }
    m.impermeable("box.zmin", 2);
  } else {
    auto faces = [&](std::vector<std::string> names) {
      std::vector<std::vector<mesh::Facet>> out;
      for (const auto& n : names)
        out.push_back(m.mesh.surface(n).facets);
      return out;
    };
    std::vector<Index> constrained;
    auto f =
        dofs::normal_frames(m.mesh, m.dofs, {m.f.u},
                            faces({"box.xmin", "box.xmax", "box.ymin", "box.ymax"}), constrained);
    auto fw = dofs::normal_frames(
        m.mesh, m.dofs, {m.f.w},
        faces({"box.xmin", "box.xmax", "box.ymin", "box.ymax", "box.zmin"}), constrained);
    f.insert(f.end(), fw.begin(), fw.end());
    m.frames = dofs::NodalFrames(std::move(f), m.dofs.num_dofs());
    m.conditions.push_back({constrained, 0.0, dofs::LoadCurve::constant()});
  }
  m.build();
  return m;
}

} // namespace

TEST(RotatedFrames, RotatedConfinedCreepEqualsAxisAlignedColumn) {
  const Mat3 Q = Eigen::AngleAxisd(0.6, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  test::MixtureModel plain = column(Mat3::Identity(), false);
  test::MixtureModel rotated = column(Q, true);
  ASSERT_TRUE(plain.run(200.0, 5.0, 5.0).success);
  ASSERT_TRUE(rotated.run(200.0, 5.0, 5.0).success);
  const Vec3 axis = Q * Vec3::UnitZ();
  const auto displacement = [](const test::MixtureModel& m, Index n) {
    return Vec3(m.value(m.f.u, n, 0), m.value(m.f.u, n, 1), m.value(m.f.u, n, 2));
  };
  // Displacements are compared relative to the largest one of the column (its settlement), never
  // to a nodal value: near the bonded base u vanishes while the round-off of the solves (and of
  // the rotated unit coordinates) does not. The two runs differ by about 1e-11 of the settlement
  // (the round-off of the solves, on every BLAS kernel); a wrong frame or a lost constraint
  // would differ at order 1 of it.
  Real u_max = 0.0;
  for (Index n = 0; n < plain.mesh.num_nodes(); ++n)
    u_max = std::max(u_max, displacement(plain, n).norm());
  ASSERT_GT(u_max, 0.0);
  const Real tolerance = 1e-10 * u_max;
  Real worst = 0.0;
  for (Index n = 0; n < plain.mesh.num_nodes(); ++n) {
    const Vec3 u_plain = displacement(plain, n), u_rot = displacement(rotated, n);
    worst = std::max(worst, (Q * u_plain - u_rot).norm());
    EXPECT_LE((Q * u_plain - u_rot).norm(), tolerance) << "node " << n;
    EXPECT_NEAR(u_rot.dot(axis), u_plain.z(), tolerance) << "node " << n;
  }
  std::printf("largest |u| %.3e mm; largest |Q u_plain - u_rotated| %.3e mm (%.1e of it)\n", u_max,
              worst, worst / u_max);
  // p is compared on the scale of the applied stress (p carries it at early times)
  Real worst_p = 0.0;
  for (Index c = 0; c < plain.mesh.num_cells(); ++c) {
    const Real pr = rotated.value(rotated.f.p, c), pp = plain.value(plain.f.p, c);
    worst_p = std::max(worst_p, std::abs(pr - pp));
    EXPECT_NEAR(pr, pp, 1e-10 * kFramesSigma0) << "cell " << c;
  }
  std::printf("largest |p_plain - p_rotated| %.1e of the applied stress\n",
              worst_p / kFramesSigma0);
}
