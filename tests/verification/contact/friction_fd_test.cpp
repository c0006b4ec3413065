// SPDX-License-Identifier: MIT
// Central-difference check of ContactTerm with Coulomb friction (FrictionalLaw): the residual of
// the slave and master facets (pressure and friction traction) and the slave-node rows of
// separated, sticking and slipping nodes with respect to all DOFs (positions, pressures and
// tractions), for both integration options, on warped configurations with interior and
// near-edge projections and on quadratic facets. The step starts at a state slid tangentially
// against the current one (non-zero slip). Error = max |K - K_fd| / max |K| over the whole term.
#include "contact_model.hpp"

#include "dense_assembly.hpp"
#include "trifem/contact/frictional_law.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;

namespace {

using FrictionLayout = test::FdLayout;

struct FrictionSetup {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u, lambda;
  std::unique_ptr<contact::ContactTerm> term;
  Vector x, x_old;
};

constexpr Real kMu = 0.4;

std::unique_ptr<FrictionSetup> make_friction_setup(const FrictionLayout& layout,
                                                   contact::Integration integration) {
  auto s = std::make_unique<FrictionSetup>();
  s->mesh = mesh::convert_cells(
      test::make_block("master", layout.master, {-0.5, 0.0}, layout.master), layout.master_cells);
  s->mesh.append(mesh::convert_cells(
      test::make_block("slave", layout.slave, {0.0, 0.5}, layout.slave), layout.slave_cells));
  s->u = s->dofs.add_field("displacement", FieldRole::displacement, s->mesh.num_nodes(), 3);
  const auto ns = static_cast<Index>(s->mesh.node_set("slave.ymin").size());
  s->lambda = s->dofs.add_field("contact_multipliers", FieldRole::multiplier, ns, 4);
  contact::ContactSettings settings;
  settings.integration = integration;
  settings.scale = 4.0;
  settings.search_distance = 0.6;
  settings.update_active_set = false;
  s->term = std::make_unique<contact::ContactTerm>(
      s->mesh, s->dofs, s->u, s->lambda, s->mesh.surface("master.ymax"),
      s->mesh.surface("slave.ymin"), std::make_shared<contact::FrictionalLaw>(s->u, kMu), settings);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> unit(-1, 1);
  s->x = Vector::Zero(s->dofs.num_dofs());
  s->x_old = Vector::Zero(s->dofs.num_dofs());
  for (Index n = 0; n < s->mesh.num_nodes(); ++n)
    for (int i = 0; i < 3; ++i) {
      s->x[s->dofs.dof(s->u, n, i)] = (i == 1 ? 0.03 : 0.002) * unit(rng);
      // the step start: slid by up to 0.05 against the current state
      s->x_old[s->dofs.dof(s->u, n, i)] = s->x[s->dofs.dof(s->u, n, i)] + 0.05 * unit(rng);
    }
  std::vector<char> flags(ns);
  for (Index k = 0; k < ns; ++k) {
    s->x[s->dofs.dof(s->lambda, k, 0)] = -0.1 + 0.05 * unit(rng);
    for (int c = 1; c < 4; ++c)
      s->x[s->dofs.dof(s->lambda, k, c)] = 0.03 * unit(rng);
    flags[k] = static_cast<char>(k % 3 == 0   ? contact::NodeContact::Open
                                 : k % 3 == 1 ? contact::NodeContact::Sealed
                                              : contact::NodeContact::Slipping);
  }
  s->term->active_set().assign(flags);
  return s;
}

void check_friction(const FrictionLayout& layout, contact::Integration integration,
                    const char* option) {
  auto s = make_friction_setup(layout, integration);
  Vector R;
  Eigen::MatrixXd K;
  test::assemble_dense(*s->term, s->x, s->x_old, 1.0, R, &K);
  Index slipping = 0;
  for (Index k = 0; k < s->term->slave().num_nodes(); ++k)
    slipping += s->term->active_set().slipping(k) ? 1 : 0;
  ASSERT_GT(slipping, 0);
  const Eigen::MatrixXd fd = test::fd_jacobian(*s->term, s->x, s->x_old, 1.0);
  const Real error = (K - fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
  std::printf("[ tangent ] friction %-12s %-10s |K| %.3e, relative FD error %.2e (%d slipping)\n",
              option, layout.name, K.cwiseAbs().maxCoeff(), error, static_cast<int>(slipping));
  EXPECT_LE(error, 1e-6) << option << " " << layout.name;
}

const FrictionLayout& kFlat = test::kFdInterior;
const FrictionLayout& kEdges = test::kFdNearEdges;
const FrictionLayout& kQuadratic = test::kFdTri6OnQuad8;

} // namespace

TEST(FrictionTangent, BothSurfacesInterior) {
  check_friction(kFlat, contact::Integration::BothSurfaces, "both");
}
TEST(FrictionTangent, BothSurfacesNearFacetEdges) {
  check_friction(kEdges, contact::Integration::BothSurfaces, "both");
}
TEST(FrictionTangent, SlaveNodesInterior) {
  check_friction(kFlat, contact::Integration::SlaveNodes, "slave-nodes");
}
TEST(FrictionTangent, BothSurfacesQuadraticFacets) {
  check_friction(kQuadratic, contact::Integration::BothSurfaces, "both");
}

/// A slipping node's traction has the friction limit's size and opposes the slip; a sticking
/// node's rows vanish where the slip does: the rows of FrictionalLaw at one node.
TEST(FrictionLaw, SlipRowsHoldTheCoulombLimitAgainstTheSlip) {
  auto s = make_friction_setup(kFlat, contact::Integration::BothSurfaces);
  const contact::FrictionalLaw law(s->u, kMu);
  contact::Projection pr;
  pr.facet = 0;
  pr.xi = Vec2(0.1, -0.2);
  pr.normal = Vec3(0, 1, 0);
  contact::SlaveNodeRows node;
  node.projection = &pr;
  node.facet_type = mesh::FacetType::Quad4;
  node.nodes.size = 5;
  node.scale = 4.0;
  node.weight = 0.25;
  // the master facet stays, the slave node moved by (0.01, 0, -0.02) in the step
  node.x_old[0] = Vec3(0.3, 0.0, 0.4);
  const std::array<Vec3, 4> corners{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, 1), Vec3(0, 0, 1)};
  for (int a = 0; a < 4; ++a)
    node.x_old[a + 1] = corners[a];
  const fe::FacetShapeValues N = fe::reference_facet(mesh::FacetType::Quad4).shape(pr.xi);
  Vec3 point = Vec3::Zero();
  for (int a = 0; a < 4; ++a)
    point += N[a] * corners[a];
  node.x_old[0] = point - Vec3(0.01, 0.0, -0.02);
  const Real p = 0.5;
  const Vec3 slip = Vec3(0.01, 0.0, -0.02);
  const Vec3 t = -kMu * p * slip.normalized();
  node.multiplier.resize(4);
  node.multiplier << -p, t.x(), t.y(), t.z();
  const contact::Slip kin = contact::slip_of(node);
  EXPECT_NEAR((kin.v - slip).norm(), 0.0, 1e-15);
  // at the Coulomb limit against the slip the slip indicator is c |v| > 0 (less the band
  // within which a node keeps its state) ...
  const Real band = contact::FrictionalLaw::kSlipBand * kMu * p;
  EXPECT_NEAR(law.slip_indicator(node), node.scale * slip.norm() - band, 1e-14);
  // ... and the slipping rows vanish
  std::vector<Index> dofs{0, 1, 2, 3};
  physics::LocalVector r;
  contact::LocalSystem out(dofs, r, nullptr);
  node.lambda_at = 0;
  node.slipping = true;
  contact::ProjectionDerivatives d; // residual only: no derivatives read
  node.derivatives = &d;
  node.projection = &pr;
  pr.gap = 0.0;
  law.active_rows(node, out);
  EXPECT_LE(r.norm(), 1e-15);
  // a traction below the limit does not slip: the indicator of a node at rest is |t| - μ p < 0
  node.x_old[0] = point;
  node.multiplier << -p, 0.5 * t.x(), 0.5 * t.y(), 0.5 * t.z();
  EXPECT_NEAR(law.slip_indicator(node), -0.5 * kMu * p + band, 1e-14);
  // and within the band of the limit it is zero: the node keeps its state
  node.multiplier << -p, (1 - 0.5 * contact::FrictionalLaw::kSlipBand) * t.x(), 0.0,
      (1 - 0.5 * contact::FrictionalLaw::kSlipBand) * t.z();
  EXPECT_EQ(law.slip_indicator(node), 0.0);
}
