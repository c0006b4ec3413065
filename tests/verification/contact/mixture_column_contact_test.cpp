// SPDX-License-Identifier: MIT
// The paper's §4.1 confined triphasic column split at mid-height by a contact interface
// (docs/theory/reference-solutions.md §R5, §R6.3): two 1 x 1 x 0.5 mm blocks of 5 cells in
// height, lower block = master, upper = slave, MixtureContactLaw (t, mū_w, c_ref mū_±). Bottom
// fixed and impermeable, lateral faces confined and impermeable, top = porous platen (bath)
// moved to u_z = -0.05 mm over 50 s; IC-1. The exact solution is 1-D, so
//   * with matching interface meshes (one cell across) the contact model equals the whole
//     model (1 x 1 x 10 cells) to solver tolerance;
//   * with non-matching lateral meshes (2 x 2 cells below, 3 x 3 above) the interface
//     multipliers are laterally uniform at every step and the model equals the whole one.
// Normal fluxes are compared on both sides of the interface.
#include "../mixture_model.hpp"
#include "contact_model.hpp"
#include "trifem/contact/mixture_contact_law.hpp"
#include "trifem/mesh/convert_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace trifem;

namespace {

constexpr Real kDt = 2.5;

void confine(test::MixtureModel& m, const std::string& block) {
  const char* faces[2][2] = {{".xmin", ".xmax"}, {".ymin", ".ymax"}};
  for (int k = 0; k < 2; ++k)
    for (const char* face : faces[k]) {
      m.fix(block + face, m.f.u, k);
      m.impermeable(block + face, k);
    }
}

dofs::LoadCurve platen_ramp() {
  return dofs::LoadCurve({{0.0, 0.0}, {50.0, 1.0}}, dofs::Interpolation::Linear);
}

/// The whole model of tests/verification/paper_column_test.cpp, of hex8 or hex20 cells.
std::unique_ptr<test::MixtureModel> whole_column(mesh::CellType cells = mesh::CellType::Hex8) {
  mesh::BoxSpec spec;
  spec.divisions = {1, 1, 10};
  auto m = std::make_unique<test::MixtureModel>(mesh::convert_cells(mesh::make_box(spec), cells),
                                                test::paper_tissue(true));
  for (int k = 0; k < 2; ++k) {
    m->fix("box.all", m->f.u, k);
    m->impermeable("box.all", k);
  }
  m->fix("box.zmin", m->f.u, 2);
  m->impermeable("box.zmin", 2);
  m->fix("box.zmax", m->f.u, 2, -0.05, platen_ramp());
  m->build();
  return m;
}

std::vector<Real> uniform(Real a, Real b, int n) {
  std::vector<Real> x(n + 1);
  for (int i = 0; i <= n; ++i)
    x[i] = a + (b - a) * i / n;
  return x;
}

/// The split column: a MixtureModel over both blocks plus a ContactTerm.
struct SplitColumn {
  std::unique_ptr<test::MixtureModel> m;
  dofs::FieldId lambda;
  contact::ContactTerm* contact = nullptr;

  /// `cells`: the family of both blocks (penta6: wedges extruded along the column, tri3
  /// facets on the interface).
  SplitColumn(int lower_cells, int upper_cells, mesh::CellType cells = mesh::CellType::Hex8) {
    mesh::Mesh mesh =
        mesh::convert_cells(test::make_block("lower", uniform(0, 1, lower_cells),
                                             uniform(0, 1, lower_cells), uniform(0, 0.5, 5)),
                            cells);
    mesh.append(
        mesh::convert_cells(test::make_block("upper", uniform(0, 1, upper_cells),
                                             uniform(0, 1, upper_cells), uniform(0.5, 1, 5)),
                            cells));
    m = std::make_unique<test::MixtureModel>(std::move(mesh), test::paper_tissue(true));
    const auto law = std::make_shared<contact::MixtureContactLaw>(
        contact::MixtureContactFields{m->f.u, m->f.w, m->f.j_plus, m->f.j_minus});
    lambda = m->dofs.add_field("contact_multipliers", FieldRole::multiplier,
                               static_cast<Index>(m->mesh.node_set("upper.zmin").size()),
                               law->num_components());
    confine(*m, "lower");
    confine(*m, "upper");
    m->fix("lower.zmin", m->f.u, 2);
    m->impermeable("lower.zmin", 2);
    m->fix("upper.zmax", m->f.u, 2, -0.05, platen_ramp());
    build(law);
  }

  /// As MixtureModel::build, with the contact term and its multiplier scale added.
  void build(std::shared_ptr<const contact::ContactLaw> law) {
    m->fix_mid_edge_fluxes();
    dofs::constrain_all(m->conditions, m->dofs);
    m->dofs.finalize();
    std::vector<Index> cells(m->mesh.num_cells());
    for (Index c = 0; c < m->mesh.num_cells(); ++c)
      cells[c] = c;
    std::vector<std::unique_ptr<physics::Term>> terms;
    auto mixture = std::make_unique<physics::MixtureTerm>(
        m->mesh, m->dofs, m->f, cells,
        std::vector<std::shared_ptr<const material::MixtureProperties>>(cells.size(), m->props),
        m->chem);
    m->mixture = mixture.get();
    terms.push_back(std::move(mixture));
    contact::ContactSettings settings;
    settings.scale = m->props->solid->p_wave_modulus() / 0.1; // c_N ≈ E / h
    auto c = std::make_unique<contact::ContactTerm>(m->mesh, m->dofs, m->f.u, lambda,
                                                    m->mesh.surface("lower.zmax"),
                                                    m->mesh.surface("upper.zmin"), law, settings);
    contact = c.get();
    terms.push_back(std::move(c));
    std::vector<solver::FieldScale> scales = m->scales();
    const Real M = m->props->solid->p_wave_modulus();
    scales[lambda.index] = {"contact_multipliers", 1.0, M}; // rows ~ L^3 = energy / M
    m->problem = std::make_unique<assembly::FeProblem>(m->dofs, m->conditions, std::move(terms),
                                                       scales, m->frames);
    Vector x = m->problem->state();
    m->mixture->initialize(physics::InitialState::Donnan, 0.0, x);
    for (Index k = 0; k < contact->slave().num_nodes(); ++k) // total stress -Π0 at IC-1
      x[contact->multiplier_dof(k, 0)] = -x[m->dofs.dof(m->f.p, Index{0}, 0)];
    m->problem->set_state(x);
  }

  /// Component c of every slave multiplier in physical units (mū_± in mJ/mmol); the potentials'
  /// at the corner slave nodes (on quadratic facets they are linear from the corners).
  std::vector<Real> multipliers(int c) const {
    std::vector<Real> v;
    for (Index k = 0; k < contact->slave().num_nodes(); ++k)
      if (c == 0 || !contact->slave().is_mid_edge_node(k))
        v.push_back(m->problem->state()[contact->multiplier_dof(k, c)] /
                    (c >= 2 ? m->chem.c_ref : 1.0));
    return v;
  }
};

/// Platen reaction (total axial stress, area 1 mm²).
Real platen_stress(const test::MixtureModel& m, const std::string& set) {
  Real force = 0.0;
  for (Index n : m.mesh.node_set(set))
    force += m.problem->full_residual()[m.dofs.dof(m.f.u, n, 2)];
  return force;
}

/// Mean of a per-cell quantity over the cells whose centroid z lies in (z0, z1).
template <class F>
Real cell_mean(const test::MixtureModel& m, Real z0, Real z1, F&& value) {
  Real sum = 0;
  int n = 0;
  for (Index e = 0; e < m.mesh.num_cells(); ++e) {
    Real z = 0;
    const auto nodes = m.mesh.cell_nodes(e);
    for (Index node : nodes)
      z += m.mesh.node(node)[2] / static_cast<Real>(nodes.size());
    if (z > z0 && z < z1) {
      sum += value(e);
      ++n;
    }
  }
  return sum / n;
}

/// Normal (z) component of a flux field at the nodes of a set: (min, max).
std::pair<Real, Real> flux_range(const test::MixtureModel& m, dofs::FieldId F,
                                 const std::string& set) {
  Real lo = INFINITY, hi = -INFINITY;
  std::vector<char> corner(static_cast<std::size_t>(m.mesh.num_nodes()), 0);
  for (Index c = 0; c < m.mesh.num_cells(); ++c) // (the fluxes live at the corners)
    for (Index n : m.mesh.cell_nodes(c).first(
             static_cast<std::size_t>(mesh::num_corners(m.mesh.cell_type(c)))))
      corner[static_cast<std::size_t>(n)] = 1;
  for (Index n : m.mesh.node_set(set)) {
    if (!corner[static_cast<std::size_t>(n)])
      continue;
    const Real v = m.problem->state()[m.dofs.dof(F, n, 2)];
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  return {lo, hi};
}

/// Lateral spread of v relative to its magnitude, at least to `scale` (a value that cannot
/// vanish: a multiplier passing through zero must not turn round-off into a large spread).
Real spread(const std::vector<Real>& v, Real scale) {
  const auto [lo, hi] = std::minmax_element(v.begin(), v.end());
  return (*hi - *lo) / std::max({std::abs(*hi), std::abs(*lo), scale});
}

Real rel(Real a, Real b) {
  return std::abs(a - b) / std::max(std::abs(b), 1e-300);
}

/// Whole-model interface values: total stress, mū_w, mū_+, mū_- (mean of the two cells at z =
/// 0.5: the P0 potentials' midpoint value), and the nodal w_z, j+_z, j-_z at z = 0.5.
struct InterfaceState {
  std::array<Real, 4> multipliers{};
  std::array<Real, 3> flux{};
};

InterfaceState whole_interface(const test::MixtureModel& w) {
  InterfaceState s;
  s.multipliers[0] = platen_stress(w, "box.zmax");
  const auto chem = [&](Index e) { return w.mixture->output(e, w.problem->state()).chem; };
  s.multipliers[1] = 0.5 * (chem(4).mu_w + chem(5).mu_w);
  s.multipliers[2] = 0.5 * (chem(4).mu_plus + chem(5).mu_plus);
  s.multipliers[3] = 0.5 * (chem(4).mu_minus + chem(5).mu_minus);
  const dofs::FieldId F[3] = {w.f.w, w.f.j_plus, w.f.j_minus};
  for (Index c = 0; c < w.mesh.num_cells(); ++c) // (the corners: the fluxes' nodes)
    for (Index n : w.mesh.cell_nodes(c).first(8))
      if (std::abs(w.mesh.node(n)[2] - 0.5) < 1e-12)
        for (int i = 0; i < 3; ++i)
          s.flux[i] = w.problem->state()[w.dofs.dof(F[i], n, 2)];
  return s;
}

struct Deviation {
  Real uniform = 0, flux_sides = 0, flux_whole = 0;
  std::array<Real, 4> to_whole{}; ///< per multiplier component
};

/// Steps both models to 50 s in lockstep; returns the largest deviations over the steps and
/// checks platen stress, p and eta of the bottom cell at t = 5, 25, 50 to `whole_tolerance`.
Deviation run_and_compare(SplitColumn& split, Real whole_tolerance,
                          mesh::CellType whole_cells = mesh::CellType::Hex8) {
  auto whole = whole_column(whole_cells);
  test::MixtureModel& m = *split.m;
  Deviation dev;
  const char* names[4] = {"t", "mu_w", "mu_+", "mu_-"};
  const Real flux_scale = m.props->solid->p_wave_modulus() * m.props->permeability;
  // floors of the multipliers' spread, 1e-4 of their natural scales: the modulus M for t and
  // mū_w [MPa], RT for mū_± [mJ/mmol] (the multipliers stay above them in this run)
  const Real floors[4] = {1e-4 * m.props->solid->p_wave_modulus(),
                          1e-4 * m.props->solid->p_wave_modulus(), 1e-4 * m.chem.RT(),
                          1e-4 * m.chem.RT()};
  for (int step = 1; step <= 20; ++step) {
    const Real t = step * kDt;
    const bool whole_ok = whole->run(t, kDt, kDt).success;
    EXPECT_TRUE(whole_ok) << "whole model at t = " << t;
    const bool split_ok = m.run(t, kDt, kDt).success;
    EXPECT_TRUE(split_ok) << "split model at t = " << t;
    if (!whole_ok || !split_ok)
      return dev;
    EXPECT_EQ(split.contact->active_set().num_active(), split.contact->slave().num_nodes());
    const InterfaceState ref = whole_interface(*whole);
    for (int c = 0; c < 4; ++c) {
      const std::vector<Real> v = split.multipliers(c);
      dev.uniform = std::max(dev.uniform, spread(v, floors[c]));
      const Real d = rel(v[0], ref.multipliers[c]);
      dev.to_whole[c] = std::max(dev.to_whole[c], d);
      // t against the platen stress (uniform in z); the potentials against the mean of the
      // two whole-model cells at z = 0.5 (the P0 potentials have no interface value; O(h²))
      EXPECT_LE(d, c == 0 ? 1e-8 : 5e-3)
          << names[c] << " at t = " << t << ": " << v[0] << " vs whole " << ref.multipliers[c];
    }
    const dofs::FieldId F[3] = {m.f.w, m.f.j_plus, m.f.j_minus};
    for (int i = 0; i < 3; ++i) {
      const auto [lo_m, hi_m] = flux_range(m, F[i], "lower.zmax");
      const auto [lo_s, hi_s] = flux_range(m, F[i], "upper.zmin");
      // relative to the flux, at least to the characteristic flux M κ / L of the Newton
      // increment test (the interface flux passes through zero-ish values early on)
      const Real scale = std::max(std::abs(ref.flux[i]), flux_scale);
      dev.flux_sides = std::max({dev.flux_sides, (hi_m - lo_m) / scale, (hi_s - lo_s) / scale,
                                 std::abs(hi_m - hi_s) / scale});
      dev.flux_whole = std::max(dev.flux_whole, std::abs(hi_s - ref.flux[i]) / scale);
    }
    if (step == 2 || step == 10 || step == 20) {
      const Real got[3] = {platen_stress(m, "upper.zmax"),
                           cell_mean(m, 0, 0.1, [&](Index e) { return m.value(m.f.p, e); }),
                           cell_mean(m, 0, 0.1, [&](Index e) { return m.value(m.f.eta, e); })};
      const Real want[3] = {platen_stress(*whole, "box.zmax"), whole->value(whole->f.p, 0),
                            whole->value(whole->f.eta, 0)};
      for (int i = 0; i < 3; ++i) {
        std::printf("  t = %4.1f %-13s split %.10e whole %.10e rel %.2e\n", t,
                    i == 0 ? "platen stress" : (i == 1 ? "p bottom" : "c_ref eta bot"), got[i],
                    want[i], rel(got[i], want[i]));
        EXPECT_LE(rel(got[i], want[i]), whole_tolerance) << i << " at t = " << t;
      }
    }
  }
  return dev;
}

void report(const char* name, const Deviation& d) {
  std::printf("[ verification ] split column %s: multipliers lateral spread %.2e; vs whole: t "
              "%.2e, mu_w %.2e, mu_+ %.2e, mu_- %.2e; interface normal fluxes (relative to "
              "max(|w|, M kappa / L)): spread and sides %.2e, vs whole %.2e\n",
              name, d.uniform, d.to_whole[0], d.to_whole[1], d.to_whole[2], d.to_whole[3],
              d.flux_sides, d.flux_whole);
}

} // namespace

TEST(MixtureColumnContact, MatchingInterfaceEqualsWholeModel) {
  SplitColumn split(1, 1);
  const Deviation d = run_and_compare(split, 1e-8);
  report("matching (1 vs 1)", d);
  EXPECT_LE(d.uniform, 1e-8);
  EXPECT_LE(d.flux_sides, 1e-8);
  EXPECT_LE(d.flux_whole, 1e-8);
}

TEST(MixtureColumnContact, NonMatchingInterfaceIsUniformAndEqualsWholeModel) {
  SplitColumn split(2, 3);
  // the issue asks for 0.5 %; the 1-D solution is reproduced exactly, so we hold 1e-8
  const Deviation d = run_and_compare(split, 1e-8);
  report("non-matching (2x2 vs 3x3)", d);
  EXPECT_LE(d.uniform, 1e-8);
  EXPECT_LE(d.flux_sides, 1e-8);
  EXPECT_LE(d.flux_whole, 1e-8);
}

// The same with both blocks of wedges (issue 37): tri3 facets on both sides of the interface,
// non-matching triangulations (2 x 2 and 3 x 3 squares split along their diagonals).
TEST(MixtureColumnContact, NonMatchingTri3InterfaceOfWedgesEqualsWholeModel) {
  SplitColumn split(2, 3, mesh::CellType::Penta6);
  ASSERT_EQ(split.contact->slave().facet_type(0), mesh::FacetType::Tri3);
  ASSERT_EQ(split.contact->master().facet_type(0), mesh::FacetType::Tri3);
  const Deviation d = run_and_compare(split, 1e-8);
  report("non-matching wedges (2x2 vs 3x3, tri3)", d);
  EXPECT_LE(d.uniform, 1e-8);
  EXPECT_LE(d.flux_sides, 1e-8);
  EXPECT_LE(d.flux_whole, 1e-8);
}

// The same with both blocks of hex20 cells (issue 37): quad8 facets on both sides, the fluxes
// and the potentials' multipliers linear from the corners, the pressure multiplier at every
// node of the quadratic interface.
TEST(MixtureColumnContact, NonMatchingQuad8InterfaceOfHex20EqualsWholeModel) {
  SplitColumn split(1, 2, mesh::CellType::Hex20);
  ASSERT_EQ(split.contact->slave().facet_type(0), mesh::FacetType::Quad8);
  const Deviation d = run_and_compare(split, 1e-8, mesh::CellType::Hex20);
  report("non-matching hex20 (1x1 vs 2x2, quad8)", d);
  EXPECT_LE(d.uniform, 1e-8);
  EXPECT_LE(d.flux_sides, 1e-8);
  EXPECT_LE(d.flux_whole, 1e-8);
}
