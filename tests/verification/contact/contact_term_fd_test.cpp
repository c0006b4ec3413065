// SPDX-License-Identifier: MIT
// Central-difference check of the whole ContactTerm (residual of slave facets, master facets and
// slave-node constraint rows) with respect to all its DOFs (positions and multipliers), for both
// integration options, at warped configurations where (i) all projections are interior and
// near facet centres, (ii) slave and master nodes project close to facet edges (|ξ| up to
// 0.97); in both, neighbouring master nodes project onto different slave facets (asserted)
// and the outer master nodes lie beyond the slave surface (λ^m = 0). Active and inactive rows
// are both present. Error = max |K - K_fd| / max |K| over the whole term.
#include "contact_model.hpp"

#include "dense_assembly.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <random>
#include <set>

using namespace trifem;

namespace {

using Layout = test::FdLayout;

struct Setup {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  dofs::FieldId u, lambda;
  std::unique_ptr<contact::ContactTerm> term;
  Vector x;
};

std::unique_ptr<Setup> make_setup(const Layout& layout, contact::Integration integration,
                                  unsigned seed) {
  auto s = std::make_unique<Setup>();
  s->mesh = mesh::convert_cells(
      test::make_block("master", layout.master, {-0.5, 0.0}, layout.master), layout.master_cells);
  s->mesh.append(mesh::convert_cells(
      test::make_block("slave", layout.slave, {0.0, 0.5}, layout.slave), layout.slave_cells));
  s->u = s->dofs.add_field("displacement", FieldRole::displacement, s->mesh.num_nodes(), 3);
  const auto ns = static_cast<Index>(s->mesh.node_set("slave.ymin").size());
  s->lambda = s->dofs.add_field("contact_pressure", FieldRole::multiplier, ns, 1);
  contact::ContactSettings settings;
  settings.integration = integration;
  settings.scale = 4.0;
  settings.search_distance = 0.6;
  settings.update_active_set = false;
  s->term = std::make_unique<contact::ContactTerm>(
      s->mesh, s->dofs, s->u, s->lambda, s->mesh.surface("master.ymax"),
      s->mesh.surface("slave.ymin"), std::make_shared<contact::FrictionlessLaw>(s->u), settings);
  // Random state: small tangential, larger normal motion (warped, twisted facets; some nodes
  // penetrate, some are separated), multipliers of both signs.
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> unit(-1, 1);
  s->x = Vector::Zero(s->dofs.num_dofs());
  for (Index n = 0; n < s->mesh.num_nodes(); ++n)
    for (int i = 0; i < 3; ++i)
      s->x[s->dofs.dof(s->u, n, i)] = (i == 1 ? 0.03 : 0.002) * unit(rng);
  std::vector<char> active(ns);
  for (Index k = 0; k < ns; ++k) {
    s->x[s->dofs.dof(s->lambda, k, 0)] = -0.1 + 0.12 * unit(rng);
    active[k] = k % 3 != 0;
  }
  s->term->active_set().assign(active);
  return s;
}

bool assemble(contact::ContactTerm& term, const Vector& x, Vector& R, Eigen::MatrixXd* K) {
  return test::assemble_dense(term, x, 1.0, R, K);
}

/// Smallest distance of an interior projection's ξ to the edges of its reference facet, over
/// all projections.
Real edge_margin(const contact::ContactTerm& term) {
  Real margin = 1;
  const auto visit = [&](const std::optional<contact::Projection>& pr,
                         const contact::ContactSurface& onto) {
    if (!pr || pr->on_boundary)
      return;
    const Vec2& xi = pr->xi;
    margin = std::min(margin, contact::is_triangle(onto.facet_type(pr->facet))
                                  ? std::min({xi[0], xi[1], 1 - xi.sum()})
                                  : 1 - xi.cwiseAbs().maxCoeff());
  };
  for (Index k = 0; k < term.slave().num_nodes(); ++k)
    visit(term.slave_projection(k), term.master());
  for (Index i = 0; i < term.master().num_nodes(); ++i)
    visit(term.master_projection(i), term.slave());
  return margin;
}

void check(const Layout& layout, contact::Integration integration, const char* option) {
  auto s = make_setup(layout, integration, 7);
  Vector R;
  Eigen::MatrixXd K;
  assemble(*s->term, s->x, R, &K);
  for (Index k = 0; k < s->term->slave().num_nodes(); ++k) {
    const auto& pr = s->term->slave_projection(k);
    ASSERT_TRUE(pr && !pr->on_free_boundary) << "slave node " << k << " must project onto it";
  }
  std::set<Index> master_targets; // slave facets that interior master nodes project onto
  for (Index i = 0; i < s->term->master().num_nodes(); ++i) {
    const auto& pr = s->term->master_projection(i);
    if (pr && !pr->on_free_boundary)
      master_targets.insert(pr->facet);
  }
  if (integration == contact::Integration::BothSurfaces) {
    EXPECT_GT(master_targets.size(), 1u) << "neighbouring master nodes on different facets";
  }
  const Eigen::MatrixXd fd = test::fd_jacobian(*s->term, s->x, s->x, 1.0);
  const Real error = (K - fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
  std::printf("[ tangent ] contact %-12s %-10s edge margin %.3f, |K| %.3e, relative FD error "
              "%.2e (active %d of %d)\n",
              option, layout.name, edge_margin(*s->term), K.cwiseAbs().maxCoeff(), error,
              static_cast<int>(s->term->active_set().num_active()),
              static_cast<int>(s->term->slave().num_nodes()));
  EXPECT_LE(error, 1e-6) << option << " " << layout.name;
}

const Layout& kInterior = test::kFdInterior;
const Layout& kNearEdges = test::kFdNearEdges;
// The cell families: curved tri6 slave facets on quad8 master facets, tri3 on tri6, quad8 on
// tri3.
const Layout& kTri6OnQuad8 = test::kFdTri6OnQuad8;
const Layout kTri3OnTri6{"tri3/tri6",
                         {-0.25, 0.25, 0.75, 1.25},
                         {0.0, 0.5, 1.0},
                         mesh::CellType::Tet10,
                         mesh::CellType::Tet4};
const Layout kQuad8OnTri3{"quad8/tri3",
                          {-0.25, 0.25, 0.75, 1.25},
                          {0.0, 0.5, 1.0},
                          mesh::CellType::Tet4,
                          mesh::CellType::Hex20};

} // namespace

TEST(ContactTermTangent, BothSurfacesInterior) {
  check(kInterior, contact::Integration::BothSurfaces, "both");
}
TEST(ContactTermTangent, BothSurfacesNearFacetEdges) {
  check(kNearEdges, contact::Integration::BothSurfaces, "both");
}
TEST(ContactTermTangent, SlaveNodesInterior) {
  check(kInterior, contact::Integration::SlaveNodes, "slave-nodes");
}
TEST(ContactTermTangent, SlaveNodesNearFacetEdges) {
  check(kNearEdges, contact::Integration::SlaveNodes, "slave-nodes");
}
TEST(ContactTermTangent, BothSurfacesTri6SlaveOnQuad8Master) {
  check(kTri6OnQuad8, contact::Integration::BothSurfaces, "both");
}
TEST(ContactTermTangent, BothSurfacesTri3SlaveOnTri6Master) {
  check(kTri3OnTri6, contact::Integration::BothSurfaces, "both");
}
TEST(ContactTermTangent, BothSurfacesQuad8SlaveOnTri3Master) {
  check(kQuad8OnTri3, contact::Integration::BothSurfaces, "both");
}
TEST(ContactTermTangent, SlaveNodesTri6SlaveOnQuad8Master) {
  check(kTri6OnQuad8, contact::Integration::SlaveNodes, "slave-nodes");
}
