// SPDX-License-Identifier: MIT
// .feb files of tet4, tet10, penta6 and hex20 elements with tri3, tri6, quad4 and quad8 surfaces,
// written here in FEBio's node orders (FESolidElementShape, FESurfaceElementShape): a unit cube
// stretched 20 % along z through its surface's nodes gives the closed-form neo-Hookean uniaxial
// reaction, and a node list in trifem's order (the mid-edge nodes of a tet10 swapped) is told
// apart.
#include "feb_run.hpp"
#include "trifem/feb/feb_reader.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <fmt/ranges.h>

using namespace trifem;

namespace feb_families_test {

/// For each node of trifem's order, its position in FEBio's list (docs/feb.md, Mesh).
std::vector<int> febio_position(mesh::CellType type) {
  std::vector<int> p(static_cast<std::size_t>(mesh::num_nodes(type)));
  for (std::size_t a = 0; a < p.size(); ++a)
    p[a] = static_cast<int>(a);
  if (type == mesh::CellType::Tet10)
    std::swap(p[8], p[9]);           // FEBio: (1,3) then (2,3); Gmsh and trifem: (2,3) then (1,3)
  if (type == mesh::CellType::Hex20) // FEBio: bottom ring, top ring, vertical edges
    p = {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 16, 9, 17, 10, 18, 19, 12, 15, 13, 14};
  return p;
}

/// The nodes of cell c in FEBio's order (1-based ids), or in trifem's with `trifem_order`.
std::string element_nodes(const mesh::Mesh& m, Index c, bool trifem_order) {
  const auto nodes = m.cell_nodes(c);
  const std::vector<int> position = febio_position(m.cell_type(c));
  std::vector<Index> listed(nodes.size());
  for (std::size_t a = 0; a < nodes.size(); ++a)
    listed[trifem_order ? a : static_cast<std::size_t>(position[a])] = nodes[a] + 1;
  return fmt::format("{}", fmt::join(listed, ","));
}

/// A unit cube of `type` cells (one box cell split), neo-Hookean E = 1, nu = 0.3, symmetry planes
/// x, y, z = 0, the nodes of the surface "Top" moved 0.2 along z in ten steps.
std::string cube_file(mesh::CellType type, bool trifem_order = false) {
  const mesh::Mesh m = mesh::convert_cells(mesh::make_box({}), type);
  std::string nodes, cells, sets, top;
  for (Index n = 0; n < m.num_nodes(); ++n)
    nodes += fmt::format("<node id=\"{}\">{},{},{}</node>\n", n + 1, m.node(n).x(), m.node(n).y(),
                         m.node(n).z());
  for (Index c = 0; c < m.num_cells(); ++c)
    cells += fmt::format("<elem id=\"{}\">{}</elem>\n", c + 1, element_nodes(m, c, trifem_order));
  for (int k = 0; k < 3; ++k) {
    std::vector<Index> on;
    for (Index n = 0; n < m.num_nodes(); ++n)
      if (std::abs(m.node(n)[k]) < 1e-12)
        on.push_back(n + 1);
    sets += fmt::format("<NodeSet name=\"{}0\">{}</NodeSet>\n", "xyz"[k], fmt::join(on, ","));
  }
  int id = 0;
  for (const mesh::Facet& f : m.surface("box.zmax").facets) {
    std::vector<Index> listed;
    for (int a = 0; a < f.num_nodes(); ++a)
      listed.push_back(f.node(a) + 1);
    top += fmt::format("<{0} id=\"{1}\">{2}</{0}>\n", mesh::name(f.type), ++id,
                       fmt::join(listed, ","));
  }
  return fmt::format(R"(<?xml version="1.0"?>
<febio_spec version="4.0">
<Module type="solid"/>
<Control><analysis>STATIC</analysis><time_steps>10</time_steps><step_size>0.1</step_size>
<solver type="solid"><symmetric_stiffness>symmetric</symmetric_stiffness></solver></Control>
<Material><material id="1" name="Rubber" type="neo-Hookean"><E>1</E><v>0.3</v></material></Material>
<Mesh>
<Nodes name="Cube">
{}</Nodes>
<Elements type="{}" name="Part1">
{}</Elements>
{}<Surface name="Top">
{}</Surface>
</Mesh>
<MeshDomains><SolidDomain name="Part1" mat="Rubber"/></MeshDomains>
<Boundary>
<bc name="SymX" node_set="x0" type="zero displacement"><x_dof>1</x_dof><y_dof>0</y_dof><z_dof>0</z_dof></bc>
<bc name="SymY" node_set="y0" type="zero displacement"><x_dof>0</x_dof><y_dof>1</y_dof><z_dof>0</z_dof></bc>
<bc name="SymZ" node_set="z0" type="zero displacement"><x_dof>0</x_dof><y_dof>0</y_dof><z_dof>1</z_dof></bc>
<bc name="Pull" node_set="@surface:Top" type="prescribed displacement"><dof>z</dof><value lc="1">0.2</value><relative>0</relative></bc>
</Boundary>
<LoadData><load_controller id="1" name="ramp" type="loadcurve"><interpolate>LINEAR</interpolate>
<points><pt>0,0</pt><pt>1,1</pt></points></load_controller></LoadData>
</febio_spec>
)",
                     nodes, mesh::name(type), cells, sets, top);
}

/// The z reaction of uniaxial stress at axial stretch 1.2 on a unit face, and the lateral
/// stretch: sigma_i = [mu (l_i^2 - 1) + lambda ln J] / J with sigma_xx = 0 (E = 1, nu = 0.3).
std::pair<Real, Real> uniaxial(Real c) {
  const Real mu = 1.0 / 2.6, lambda = 0.3 / (1.3 * 0.4);
  Real a = 1.0;
  for (int it = 0; it < 60; ++it)
    a -= (mu * (a * a - 1.0) + lambda * std::log(a * a * c)) / (2.0 * mu * a + 2.0 * lambda / a);
  const Real J = a * a * c;
  return {(mu * (c * c - 1.0) + lambda * std::log(J)) / J * a * a, a};
}

} // namespace feb_families_test

using namespace feb_families_test;

TEST(FebCellFamilies, AStretchedCubeOfEveryFamilyGivesTheClosedFormReaction) {
  const auto [force, lateral] = uniaxial(1.2);
  for (mesh::CellType type : {mesh::CellType::Tet4, mesh::CellType::Tet10, mesh::CellType::Penta6,
                              mesh::CellType::Hex20}) {
    const test::FebRun r = test::run_feb_case(feb::parse_feb(cube_file(type), "cube.feb"));
    ASSERT_TRUE(r.report.success) << mesh::name(type) << ": " << r.report.failure;
    const model::Model& m = *r.model;
    EXPECT_EQ(m.mesh.cell_type(0), type);
    Real reaction = 0.0;
    for (Index n : m.mesh.node_set("Top"))
      reaction += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
    EXPECT_NEAR(reaction, force, 1e-8) << mesh::name(type);
    for (Index n = 0; n < m.mesh.num_nodes(); ++n) // homogeneous: every node on (a - 1) x
      EXPECT_NEAR(m.problem->state()[m.dofs.dof(m.fields.u, n, 0)],
                  (lateral - 1.0) * m.mesh.node(n).x(), 1e-9)
          << mesh::name(type) << " node " << n;
    // the surface is the cells' faces, with their mid-edge nodes
    for (const mesh::Facet& f : m.mesh.surface("Top").facets)
      EXPECT_GE(f.cell, 0);
  }
}

TEST(FebCellFamilies, ATet10InTrifemsNodeOrderIsNotFebiosAndSaysSo) {
  // read in FEBio's order, the swapped mid-edge nodes lie on other edges
  try {
    feb::parse_feb(cube_file(mesh::CellType::Tet10, true), "cube.feb");
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cube.feb:"), std::string::npos) << what;
    EXPECT_NE(what.find("febio_spec/Mesh/Elements[@type='tet10'][@name='Part1']/elem[@id="),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("off the edge of its nodes"), std::string::npos) << what;
  }
}
