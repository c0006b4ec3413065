// SPDX-License-Identifier: MIT
// Shared by the tests of FEBio's own test problems (test_febio_testsuite.cpp, the problems
// against independent answers; test_febio_refinement.cpp, the same under refinement): where the
// files are, how a problem runs, and the quantities measured on its model.
#pragma once

#include "feb_run.hpp"
#include "trifem/analysis/case_file.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>

namespace trifem::test {

/// The file `name` of the test suite folder, or "" (the test is skipped) without one.
inline std::filesystem::path suite_file(const std::string& name) {
  const char* dir = std::getenv("TRIFEM_FEBIO_TESTSUITE");
  if (!dir || !*dir)
    return {};
  return std::filesystem::path(dir) / name;
}

#define SUITE_FILE(var, name)                                                                      \
  const std::filesystem::path var = suite_file(name);                                              \
  if (var.empty())                                                                                 \
    GTEST_SKIP() << "TRIFEM_FEBIO_TESTSUITE is not set (FEBio's TestSuite/Verify folder)";         \
  ASSERT_TRUE(std::filesystem::exists(var)) << var

using SuiteRun = FebRun;

inline SuiteRun run(const std::filesystem::path& file,
                    const std::function<void(const model::Model&, Real)>& observer = {}) {
  return run_feb_case(analysis::read_case_file(file), observer);
}

/// The nodes at the largest (end = +1) or smallest (end = -1) coordinate along `axis`.
inline std::vector<Index> end_nodes(const model::Model& m, int axis, int end) {
  Real extreme = end > 0 ? -1e300 : 1e300;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    extreme =
        end > 0 ? std::max(extreme, m.mesh.node(n)[axis]) : std::min(extreme, m.mesh.node(n)[axis]);
  std::vector<Index> nodes;
  for (Index n = 0; n < m.mesh.num_nodes(); ++n)
    if (std::abs(m.mesh.node(n)[axis] - extreme) < 1e-9)
      nodes.push_back(n);
  return nodes;
}

inline Real extent(const model::Model& m, int axis) {
  return m.mesh.node(end_nodes(m, axis, 1).front())[axis] -
         m.mesh.node(end_nodes(m, axis, -1).front())[axis];
}

/// Reaction along `axis` summed over `nodes`, and their mean displacement and fluid flux.
inline Real reaction(const model::Model& m, const std::vector<Index>& nodes, int axis) {
  Real sum = 0.0;
  for (Index n : nodes)
    sum += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, axis)];
  return sum;
}

inline Real mean_of(const model::Model& m, dofs::FieldId field, const std::vector<Index>& nodes,
                    int axis) {
  Real sum = 0.0;
  for (Index n : nodes)
    sum += m.problem->state()[m.dofs.dof(field, n, axis)];
  return sum / static_cast<Real>(nodes.size());
}

/// Reference cross-section normal to `axis` (a box).
inline Real section_area(const model::Model& m, int axis) {
  Real area = 1.0;
  for (int k = 0; k < 3; ++k)
    if (k != axis)
      area *= extent(m, k);
  return area;
}

inline void report(const char* name, const char* quantity, Real value, Real reference) {
  std::printf("[testsuite] %s: %s %.9g, reference %.9g, relative difference %.2e\n", name, quantity,
              value, reference, std::abs(value / reference - 1.0));
}

/// Confined neo-Hookean with nu = 0: sigma_zz = mu (s - 1/s).
inline Real neo_hookean_confined(Real E, Real s) {
  return 0.5 * E * (s - 1.0 / s);
}

/// Confined Holmes-Mow with nu = 0 (FEBio's law): sigma = e^Q (s - 1/s) E / 2,
/// Q = beta (s^2 - 1 - 2 ln s).
inline Real holmes_mow_confined(Real E, Real beta, Real s) {
  return 0.5 * E * std::exp(beta * (s * s - 1.0 - 2.0 * std::log(s))) * (s - 1.0 / s);
}

/// bp13's inflow [mm/s] and permeability [mm^4/(N s)].
inline constexpr Real kBp13Flux = 2e-4;
inline constexpr Real kBp13Permeability = 1e-3;

/// bp13: the largest difference of a cell pressure from the steady linear profile
/// q (H - z) / k at the cell's current centroid [MPa].
inline Real bp13_pressure_error(const model::Model& m) {
  const Real H = extent(m, 2);
  Real worst = 0.0;
  for (Index c = 0; c < m.mesh.num_cells(); ++c) {
    Real z = 0.0;
    for (Index n : m.mesh.cell(c))
      z += (m.mesh.node(n).z() + m.problem->state()[m.dofs.dof(m.fields.u, n, 2)]) / 8.0;
    const Real p = m.problem->state()[m.dofs.dof(m.fields.p, c, 0)];
    worst = std::max(worst, std::abs(p - kBp13Flux * (H - z) / kBp13Permeability));
  }
  return worst;
}

/// `file` with its mesh refined `level` times and its time steps halved `level` times
/// (analysis::refine_case), run to its end.
inline SuiteRun run_refined(const std::filesystem::path& file, int level) {
  io::CaseSpec spec = analysis::read_case_file(file);
  analysis::refine_case(spec, {.mesh_levels = level, .time_levels = level});
  return run_feb_case(std::move(spec));
}

} // namespace trifem::test
