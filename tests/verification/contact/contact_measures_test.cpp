// SPDX-License-Identifier: MIT
// Interface measures of a contact pair (ContactTerm::slave_states, contact_area): gaps, normals,
// projection flags, nodal area vectors and the contact area, checked against closed forms:
//   * contact patch test (3-D, non-matching slid meshes, uniform pressure q): every slave node
//     active and projected with g = 0 to solver tolerance, opposed normals, t = -q; the contact
//     area equals the current geometric overlap of the two faces and Σ t_k a_k equals the
//     interface force to round-off;
//   * two blocks a prescribed distance δ apart, rotated arbitrarily: g = δ exactly; a rigid
//     separation d and slide s of the slave body: g = δ + d where the slave node still projects,
//     and no projection (g = 0) for the nodes slid beyond the master's edge.
#include "contact_model.hpp"
#include "trifem/physics/surface_load_term.hpp"

#include <gtest/gtest.h>

using namespace trifem;

namespace {

constexpr Real kQ = 0.1; // applied pressure (E = 1)

/// Lower block [0,1]^3 (4^3 cells) and upper block [0,1] x [1,2] x [0,1] (3^3 cells) whose
/// interior nodes are slid by 0.37 cells in x and 0.22 in z: non-matching interface meshes.
mesh::Mesh patch_mesh() {
  mesh::Mesh mesh = test::make_block("lower", test::shifted_coordinates(0, 1, 4), {0, 0.5, 1},
                                     test::shifted_coordinates(0, 1, 4));
  mesh.append(test::make_block("upper", test::shifted_coordinates(0, 1, 3, 0.37), {1, 1.5, 2},
                               test::shifted_coordinates(0, 1, 3, 0.22)));
  return mesh;
}

/// The contact patch test of contact_patch_test.cpp (3-D, upper surface = slave), solved.
std::unique_ptr<test::ContactModel> solved_patch() {
  auto m = std::make_unique<test::ContactModel>(patch_mesh(), "neo-hookean",
                                                material::ParameterValues{{"E", 1.0}, {"nu", 0.3}},
                                                "lower.ymax", "upper.ymin");
  m->prescribe(m->mesh.node_set("lower.ymin"), 1);
  for (const char* block : {"lower", "upper"}) {
    m->prescribe(m->mesh.node_set(std::string(block) + ".xmin"), 0);
    m->prescribe(m->mesh.node_set(std::string(block) + ".zmin"), 2);
  }
  m->loads.push_back(std::make_unique<physics::PressureTerm>(
      m->mesh, m->dofs, m->u, m->mesh.surface("upper.ymax").facets, kQ,
      dofs::LoadCurve({{0, 0}, {1, 1}}, dofs::Interpolation::Linear)));
  contact::ContactSettings settings;
  settings.scale = 1.0 / 0.25; // E / h
  m->build(settings);
  solver::NewtonSettings newton;
  newton.residual_tolerance = 1e-13;
  newton.max_iterations = 30;
  for (int step = 1; step <= 2; ++step) {
    const auto report = m->solve_step(0.5 * step, 0.5, newton);
    EXPECT_EQ(report.status, solver::SolveStatus::Converged) << report.failure_reason;
  }
  return m;
}

/// Current bounding box (min, max) of the nodes of a surface.
std::pair<Vec3, Vec3> current_box(const test::ContactModel& m, const contact::ContactSurface& s) {
  Vec3 lo = Vec3::Constant(1e300), hi = -lo;
  for (Index n : s.nodes()) {
    Vec3 x = m.mesh.node(n);
    for (int i = 0; i < 3; ++i)
      x[i] += m.problem->state()[m.dofs.dof(m.u, n, i)];
    lo = lo.cwiseMin(x);
    hi = hi.cwiseMax(x);
  }
  return {lo, hi};
}

/// Overlap area of the (flat, rectangular, y-normal) master and slave faces: the intersection
/// of their current x and z extents.
Real overlap_area(const test::ContactModel& m) {
  const auto [ml, mh] = current_box(m, m.contact->master());
  const auto [sl, sh] = current_box(m, m.contact->slave());
  const Real wx = std::min(mh.x(), sh.x()) - std::max(ml.x(), sl.x());
  const Real wz = std::min(mh.z(), sh.z()) - std::max(ml.z(), sl.z());
  return wx * wz;
}

const Mat3 kRotation = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();

/// Lower block [0,1]^3 (3^3 cells) and upper block [0,1] x [1+δ, 2+δ] x [0,1] (2^3 cells), both
/// rotated by kRotation; upper.ymin (slave) faces lower.ymax (master) at the distance δ.
std::unique_ptr<test::ContactModel> separated_blocks(Real delta) {
  mesh::Mesh mesh = test::make_block("lower", test::shifted_coordinates(0, 1, 3), {0, 0.5, 1},
                                     test::shifted_coordinates(0, 1, 3));
  mesh.append(test::make_block("upper", test::shifted_coordinates(0, 1, 2),
                               {1 + delta, 1.5 + delta, 2 + delta},
                               test::shifted_coordinates(0, 1, 2)));
  auto m = std::make_unique<test::ContactModel>(
      test::map_nodes(mesh, [](const Vec3& X) { return Vec3(kRotation * X); }), "neo-hookean",
      material::ParameterValues{{"E", 1.0}, {"nu", 0.3}}, "lower.ymax", "upper.ymin");
  contact::ContactSettings settings;
  settings.scale = 1.0;
  m->build(settings);
  return m;
}

/// The state with the upper block moved rigidly by kRotation (s, d, 0): slid by s, lifted by d.
Vector rigid_motion(const test::ContactModel& m, Real s, Real d) {
  Vector x = Vector::Zero(m.dofs.num_dofs());
  const Vec3 u = kRotation * Vec3(s, d, 0);
  for (Index n : m.mesh.node_set("upper.all"))
    for (int i = 0; i < 3; ++i)
      x[m.dofs.dof(m.u, n, i)] = u[i];
  return x;
}

} // namespace

TEST(ContactMeasures, PatchTestGapsNormalsTractionAndArea) {
  const auto m = solved_patch();
  const Vector& x = m->problem->state();
  const auto states = m->contact->slave_states(x);
  ASSERT_EQ(static_cast<Index>(states.size()), m->contact->slave().num_nodes());
  Real gap = 0, facing = 0, traction = 0;
  Vec3 force = Vec3::Zero();
  for (const auto& s : states) {
    EXPECT_TRUE(s.active && s.projected) << "slave node " << s.node;
    gap = std::max(gap, std::abs(s.gap));
    facing = std::max(facing, std::abs(1 + s.normal.dot(s.master_normal)));
    traction = std::max(traction, std::abs(s.multiplier[0] + kQ) / kQ);
    force += s.multiplier[0] * s.area_vector;
  }
  const Real area = m->contact->contact_area(x), overlap = overlap_area(*m);
  const Vec3 slave_force = m->contact->slave_force(x);
  std::printf("[ measures ] patch: max |g| %.2e mm, max |1 + n_s.n_m| %.2e, max |t + q|/q %.2e, "
              "area %.15f vs overlap %.15f, |sum t a - F| %.2e N\n",
              gap, facing, traction, area, overlap, (force - slave_force).norm());
  EXPECT_LE(gap, 1e-12); // A_k g_k is a residual row: converged to 1e-13 (A_k >= 0.01 mm^2)
  EXPECT_LE(facing, 1e-12);
  EXPECT_LE(traction, 1e-10);
  EXPECT_NEAR(area, overlap, 1e-13 * overlap);
  EXPECT_LE((force - slave_force).norm(), 1e-13 * slave_force.norm());
  // t n_s over the overlap, n_s = -e_y: the upper (slave) body is pushed up by q x area
  EXPECT_NEAR(slave_force.y(), kQ * overlap, 1e-10 * kQ * overlap);
}

TEST(ContactMeasures, PrescribedSeparationGivesTheExactGap) {
  constexpr Real kDelta = 0.01;
  const auto m = separated_blocks(kDelta);
  const Vec3 slave_normal = kRotation * Vec3(0, -1, 0);
  Real error = 0;
  for (const auto& s : m->contact->slave_states(Vector::Zero(m->dofs.num_dofs()))) {
    EXPECT_TRUE(s.projected) << "slave node " << s.node;
    EXPECT_FALSE(s.active) << "no prepare() yet: no node is active";
    error = std::max({error, std::abs(s.gap - kDelta), (s.normal - slave_normal).norm(),
                      (s.master_normal + slave_normal).norm()});
  }
  std::printf("[ measures ] separation %.2f mm (rotated): max |g - delta|, normal error %.2e\n",
              kDelta, error);
  // round-off of coordinates up to 2 mm (and of unit normals): 20 ulp of them
  const Real extent = 2.0;
  EXPECT_LE(error, 5e-15 * extent);
}

TEST(ContactMeasures, RigidSeparationAndSlideBeyondTheMasterEdge) {
  constexpr Real kDelta = 0.01, kLift = 0.03, kSlide = 0.1;
  const auto m = separated_blocks(kDelta);
  Index projected = 0;
  Real error = 0;
  for (const auto& s : m->contact->slave_states(rigid_motion(*m, kSlide, kLift))) {
    const Real X = (kRotation.transpose() * m->mesh.node(s.node)).x(); // unrotated x
    if (X > 0.75) { // slid beyond x = 1, the master's free edge
      EXPECT_FALSE(s.projected) << "slave node " << s.node;
      EXPECT_EQ(s.gap, 0.0);
      EXPECT_EQ(s.master_normal, Vec3::Zero());
      continue;
    }
    ++projected;
    EXPECT_TRUE(s.projected) << "slave node " << s.node;
    error = std::max(error, std::abs(s.gap - (kDelta + kLift)));
  }
  std::printf("[ measures ] lift %.2f, slide %.2f mm: %d of 9 projected, max |g - (delta + "
              "lift)| %.2e\n",
              kLift, kSlide, static_cast<int>(projected), error);
  EXPECT_EQ(projected, 6);
  const Real extent = 2.0; // round-off of coordinates up to 2 mm: 20 ulp of them
  EXPECT_LE(error, 5e-15 * extent);
}

TEST(ContactMeasures, ContactAreaSumsTheActiveNodes) {
  const auto m = separated_blocks(0.01);
  contact::ContactTerm& c = *m->contact;
  const Vector x = rigid_motion(*m, 0.1, 0.03); // rigid: current areas = reference areas
  std::vector<char> active(c.slave().num_nodes(), 0);
  Real expected = 0;
  for (Index k = 0; k < c.slave().num_nodes(); k += 2) {
    active[k] = 1;
    expected += c.tributary_area(k);
  }
  c.active_set().assign(active);
  // relative to the area: a sum of 9 tributary areas (a missing node would be off by >= 1/16)
  EXPECT_NEAR(c.contact_area(x), expected, 2e-15 * expected);
  c.active_set().assign(std::vector<char>(c.slave().num_nodes(), 1));
  const Real face = 1.0; // the whole 1 x 1 mm slave face
  EXPECT_NEAR(c.contact_area(x), face, 1e-15 * face) << "the whole 1 x 1 mm slave face";
}
