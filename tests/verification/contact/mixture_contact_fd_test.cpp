// SPDX-License-Identifier: MIT
// Central-difference check of the ContactTerm with a MixtureContactLaw (biphasic: t, mū_w;
// triphasic: t, mū_w, c_ref mū_±) with respect to all its DOFs (positions, fluid and ion fluxes,
// multipliers) at warped configurations with interior and near-edge projections, active and
// inactive slave nodes, Δt ≠ 1 (the flux rows carry Δt). Error = max |K - K_fd| / max |K|.
#include "contact_model.hpp"
#include "trifem/contact/mixture_contact_law.hpp"

#include "dense_assembly.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <random>

using namespace trifem;

namespace {

constexpr Real kDt = 0.7;

struct Setup {
  mesh::Mesh mesh;
  dofs::DofMap dofs;
  contact::MixtureContactFields f;
  dofs::FieldId lambda;
  std::unique_ptr<contact::ContactTerm> term;
  Vector x;
};

std::unique_ptr<Setup> make_setup(const std::vector<Real>& master, const std::vector<Real>& slave,
                                  bool ions, contact::Integration integration,
                                  mesh::CellType cells) {
  auto s = std::make_unique<Setup>();
  s->mesh = mesh::convert_cells(test::make_block("master", master, {-0.5, 0.0}, master), cells);
  s->mesh.append(mesh::convert_cells(test::make_block("slave", slave, {0.0, 0.5}, slave), cells));
  const Index nn = s->mesh.num_nodes();
  s->f.u = s->dofs.add_field("displacement", FieldRole::displacement, nn, 3);
  s->f.w = s->dofs.add_field("fluid_flux", FieldRole::flux, nn, 3);
  if (ions) {
    s->f.j_plus = s->dofs.add_field("cation_flux", FieldRole::flux, nn, 3);
    s->f.j_minus = s->dofs.add_field("anion_flux", FieldRole::flux, nn, 3);
  }
  auto law = std::make_shared<contact::MixtureContactLaw>(s->f);
  const auto ns = static_cast<Index>(s->mesh.node_set("slave.ymin").size());
  s->lambda =
      s->dofs.add_field("contact_multipliers", FieldRole::multiplier, ns, law->num_components());
  contact::ContactSettings settings;
  settings.integration = integration;
  settings.scale = 4.0;
  settings.search_distance = 0.6;
  settings.update_active_set = false;
  s->term = std::make_unique<contact::ContactTerm>(s->mesh, s->dofs, s->f.u, s->lambda,
                                                   s->mesh.surface("master.ymax"),
                                                   s->mesh.surface("slave.ymin"), law, settings);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> unit(-1, 1);
  s->x = Vector::Zero(s->dofs.num_dofs());
  for (Index n = 0; n < nn; ++n)
    for (int i = 0; i < 3; ++i) {
      s->x[s->dofs.dof(s->f.u, n, i)] = (i == 1 ? 0.03 : 0.002) * unit(rng);
      for (dofs::FieldId F : {s->f.w, s->f.j_plus, s->f.j_minus})
        if (F.valid())
          s->x[s->dofs.dof(F, n, i)] = 0.01 * unit(rng);
    }
  std::vector<char> active(ns);
  for (Index k = 0; k < ns; ++k) {
    for (int c = 0; c < law->num_components(); ++c)
      s->x[s->dofs.dof(s->lambda, k, c)] = (c == 0 ? -0.1 : 0.05) + 0.12 * unit(rng);
    active[k] = static_cast<char>(k % 3); // open, sealed and wetted nodes (NodeContact)
  }
  s->term->active_set().assign(active);
  return s;
}

bool assemble(contact::ContactTerm& term, const Vector& x, Vector& R, Eigen::MatrixXd* K) {
  return test::assemble_dense(term, x, kDt, R, K);
}

void check(const char* name, const std::vector<Real>& master, const std::vector<Real>& slave,
           bool ions, contact::Integration integration = contact::Integration::BothSurfaces,
           mesh::CellType cells = mesh::CellType::Hex8) {
  auto s = make_setup(master, slave, ions, integration, cells);
  Vector R;
  Eigen::MatrixXd K;
  assemble(*s->term, s->x, R, &K);
  const Eigen::MatrixXd fd = test::fd_jacobian(*s->term, s->x, s->x, kDt);
  const Real error = (K - fd).cwiseAbs().maxCoeff() / K.cwiseAbs().maxCoeff();
  // the flux rows and the multiplier columns of the flux rows must be present
  const Index lw = s->term->multiplier_dof(1, 1);
  EXPECT_GT(K.row(lw).cwiseAbs().maxCoeff() + K.col(lw).cwiseAbs().maxCoeff(), 0.0);
  std::printf("[ tangent ] mixture contact %-10s %-10s |K| %.3e, relative FD error %.2e "
              "(active %d of %d)\n",
              ions ? "triphasic" : "biphasic", name, K.cwiseAbs().maxCoeff(), error,
              static_cast<int>(s->term->active_set().num_active()),
              static_cast<int>(s->term->slave().num_nodes()));
  EXPECT_LE(error, 1e-6) << name;
}

const std::vector<Real> kMaster{-0.25, 0.25, 0.75, 1.25};
const std::vector<Real> kSlave{0.0, 0.5, 1.0};
const std::vector<Real> kSlaveNearEdges{0.0, 0.24, 0.5, 0.77, 1.0};

} // namespace

TEST(MixtureContactTangent, BiphasicInterior) {
  check("interior", kMaster, kSlave, false);
}
TEST(MixtureContactTangent, BiphasicNearFacetEdges) {
  check("near-edges", kMaster, kSlaveNearEdges, false);
}
TEST(MixtureContactTangent, TriphasicInterior) {
  check("interior", kMaster, kSlave, true);
}
TEST(MixtureContactTangent, TriphasicNearFacetEdges) {
  check("near-edges", kMaster, kSlaveNearEdges, true);
}
TEST(MixtureContactTangent, TriphasicSlaveNodes) {
  check("slave-nodes", kMaster, kSlave, true, contact::Integration::SlaveNodes);
}
// tri3 facets (the faces of tet4 cells; at the model level those of penta6 cells carry
// mixture contact) on both sides.
TEST(MixtureContactTangent, TriphasicOnTri3Facets) {
  check("tri3", kMaster, kSlave, true, contact::Integration::BothSurfaces, mesh::CellType::Tet4);
}
TEST(MixtureContactTangent, BiphasicOnTri3FacetsNearEdges) {
  check("tri3 edges", kMaster, kSlaveNearEdges, false, contact::Integration::BothSurfaces,
        mesh::CellType::Tet4);
}
// Quadratic facets (tet10: tri6, hex20: quad8): the pressure multiplier at every node, the
// potentials' multipliers and the fluxes linear from the corners.
TEST(MixtureContactTangent, TriphasicOnTri6Facets) {
  check("tri6", kMaster, kSlave, true, contact::Integration::BothSurfaces, mesh::CellType::Tet10);
}
TEST(MixtureContactTangent, TriphasicOnQuad8FacetsNearEdges) {
  check("quad8 edges", kMaster, kSlaveNearEdges, true, contact::Integration::BothSurfaces,
        mesh::CellType::Hex20);
}
