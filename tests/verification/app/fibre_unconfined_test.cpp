// SPDX-License-Identifier: MIT
// Unconfined compression of a fibre-reinforced biphasic disc
// (examples/fibre_reinforced_unconfined): an eighth of a square disc between frictionless
// impermeable platens, compressed by 10 % in 20 s and held, with a neo-Hookean matrix alone
// (isotropic_unconfined.toml) and with two tension-only fibre-exp-pow families along x and y
// (fibre_reinforced_unconfined.toml).
// - At equilibrium the pore pressure is 0 and the state is homogeneous uniaxial stress of the
//   solid law: the platen force over the reference area equals P_zz = lambda_z S_zz of the law
//   (trifem::material, created here from the example's parameters) at axial stretch 0.9 with the
//   lateral stretch that makes S_xx = S_yy = 0, and the free edge has moved out by (t - 1) a.
// - The fibres stiffen the transient (Soulhat et al. 1999): the peak reaction is several times
//   that of the matrix alone, the equilibrium reaction nearly the same, the relaxation faster.
// - Fibres along the compressed axis z carry nothing: adding such a family changes no result.
#include "case_runner.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/schema.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <vector>

using namespace trifem;

namespace {

const std::filesystem::path kDir =
    std::filesystem::path(TRIFEM_EXAMPLES_DIR) / "fibre_reinforced_unconfined";
const std::filesystem::path kFibreCase = kDir / "fibre_reinforced_unconfined.toml";
const std::filesystem::path kMatrixCase = kDir / "isotropic_unconfined.toml";

// The example's geometry and materials.
constexpr Real kHalfWidth = 1.5;                      ///< a [mm], along x and y
constexpr Real kArea = kHalfWidth * kHalfWidth;       ///< reference platen area of the model [mm^2]
constexpr Real kAxialStretch = 0.9;                   ///< 0.05 mm of the 0.5 mm half-thickness
constexpr Real kRampEnd = 20.0;                       ///< [s]
constexpr Real kE = 0.5, kNu = 0.1;                   ///< neo-Hookean matrix
constexpr Real kKsi = 3.0, kAlpha = 0.0, kBeta = 2.0; ///< each fibre-exp-pow family

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

material::LawSpec matrix_spec() {
  return {"neo-hookean", {{"E", kE}, {"nu", kNu}}, {}};
}

material::LawSpec fibre_spec(int axis) {
  material::ParameterValues fibre = {{"ksi", kKsi}, {"alpha", kAlpha}, {"beta", kBeta}};
  material::set_vector(fibre, "fibre", Vec3::Unit(axis));
  return {"fibre-exp-pow", std::move(fibre), {}};
}

/// Drained homogeneous uniaxial stress of `law` at axial stretch kAxialStretch along z.
struct Drained {
  Real lateral; ///< lateral stretch t (x and y)
  Real P_zz;    ///< first Piola-Kirchhoff stress: the platen force per reference area [MPa]
};

Drained drained_uniaxial(const material::ElasticLaw& law) {
  const Real l = kAxialStretch;
  const auto pk2 = [&](Real t) { return law.stress(Vec3(t * t, t * t, l * l).asDiagonal()); };
  const auto lateral = [&](Real t) { return pk2(t)(0, 0); }; // S_xx = S_yy by symmetry
  Real t = 1.0;
  for (int it = 0; it < 60; ++it) {
    const Real h = 1e-7;
    const Real step = lateral(t) / ((lateral(t + h) - lateral(t - h)) / (2 * h));
    t -= step;
    if (std::abs(step) <= 1e-15)
      break;
  }
  const Mat3 S = pk2(t);
  EXPECT_LE(std::abs(S(0, 0)) + std::abs(S(1, 1)), 1e-13 * kE) << "lateral equilibrium";
  EXPECT_LE(std::abs(S(0, 1)) + std::abs(S(1, 2)) + std::abs(S(0, 2)), 1e-14 * kE);
  return {t, l * S(2, 2)};
}

/// The platen reaction history of a run and the final state.
struct History {
  std::vector<Real> time, reaction;          ///< Rz on the platen [N] (< 0: compression)
  Real edge_ux_min = 0.0, edge_ux_max = 0.0; ///< x displacement of the x = a face at the end
};

History run(const std::string& text, const std::filesystem::path& file) {
  History h;
  h.time.push_back(0.0);
  h.reaction.push_back(0.0);
  const auto result =
      test::run_case_text(text, file, [&](const test::CaseRun& r, const solver::StepInfo& info) {
        const model::Model& m = *r.model;
        Real sum = 0.0; // as [[output.reaction]]: the residual at the platen's z DOFs
        for (Index n : m.mesh.node_set("disc.zmax"))
          sum += m.problem->full_residual()[m.dofs.dof(m.fields.u, n, 2)];
        h.time.push_back(info.time);
        h.reaction.push_back(sum);
      });
  EXPECT_TRUE(result.report.success) << result.report.failure;
  EXPECT_EQ(result.report.end_time, result.spec.time.end_time);
  const model::Model& m = *result.model;
  h.edge_ux_min = std::numeric_limits<Real>::max();
  h.edge_ux_max = std::numeric_limits<Real>::lowest();
  for (Index n : m.mesh.node_set("disc.xmax")) {
    const Real ux = m.problem->state()[m.dofs.dof(m.fields.u, n, 0)];
    h.edge_ux_min = std::min(h.edge_ux_min, ux);
    h.edge_ux_max = std::max(h.edge_ux_max, ux);
  }
  return h;
}

/// Largest compressive platen stress |Rz| / A over the run and its time.
std::pair<Real, Real> peak(const History& h) {
  const auto k = std::max_element(h.reaction.begin(), h.reaction.end(),
                                  [](Real a, Real b) { return std::abs(a) < std::abs(b); }) -
                 h.reaction.begin();
  return {std::abs(h.reaction[k]) / kArea, h.time[k]};
}

/// Time after the ramp at which |Rz| has relaxed half way from its peak to its final value
/// (linear interpolation between steps).
Real half_relaxation_time(const History& h) {
  const Real top = peak(h).first * kArea, bottom = std::abs(h.reaction.back());
  const Real half = 0.5 * (top + bottom);
  for (std::size_t k = 1; k < h.time.size(); ++k)
    if (h.time[k - 1] >= kRampEnd && std::abs(h.reaction[k]) <= half) {
      const Real a = std::abs(h.reaction[k - 1]), b = std::abs(h.reaction[k]);
      return h.time[k - 1] + (a - half) / (a - b) * (h.time[k] - h.time[k - 1]) - kRampEnd;
    }
  ADD_FAILURE() << "no half relaxation";
  return 0.0;
}

TEST(FibreUnconfined, EquilibriumIsDrainedUniaxialStressAndFibresStiffenTheTransient) {
  const History matrix = run(read_text(kMatrixCase), kMatrixCase);
  const History fibre = run(read_text(kFibreCase), kFibreCase);

  // (1) equilibrium: the drained uniaxial stress of each solid law
  const auto matrix_law = material::create_law(matrix_spec(), "materials.cartilage.solid");
  const material::LawSpec mixture{
      "solid-mixture", {}, {matrix_spec(), fibre_spec(0), fibre_spec(1)}};
  const auto fibre_law = material::create_law(mixture, "materials.cartilage.solid");
  struct Check {
    const char* name;
    const History& run;
    Drained exact;
  };
  for (const Check& c : {Check{"matrix", matrix, drained_uniaxial(*matrix_law)},
                         Check{"fibre-reinforced", fibre, drained_uniaxial(*fibre_law)}}) {
    const Real fe = c.run.reaction.back() / kArea;
    const Real previous = c.run.reaction[c.run.reaction.size() - 2] / kArea;
    std::printf("%s: peak %.6f MPa at t = %g s, equilibrium P_zz %.10f MPa (drained closed form "
                "%.10f, relative difference %.2e; last step changed it by %.1e), lateral stretch "
                "%.8f, edge u_x %.8f..%.8f mm\n",
                c.name, peak(c.run).first, peak(c.run).second, fe, c.exact.P_zz,
                std::abs(fe / c.exact.P_zz - 1), std::abs(fe / previous - 1), c.exact.lateral,
                c.run.edge_ux_min, c.run.edge_ux_max);
    EXPECT_NEAR(fe, c.exact.P_zz, 1e-6 * std::abs(c.exact.P_zz)) << c.name;
    const Real ux = (c.exact.lateral - 1) * kHalfWidth; // homogeneous lateral expansion
    EXPECT_NEAR(c.run.edge_ux_min, ux, 1e-6 * ux) << c.name;
    EXPECT_NEAR(c.run.edge_ux_max, ux, 1e-6 * ux) << c.name;
    EXPECT_EQ(peak(c.run).second, kRampEnd)
        << c.name << ": the reaction relaxes once the ramp ends";
  }

  // (2) the fibres raise the peak several-fold, leave the equilibrium nearly unchanged (they
  // are stretched only by the small drained lateral expansion) and speed up the relaxation
  const Real peak_ratio = peak(fibre).first / peak(matrix).first;
  const Real equilibrium_change = fibre.reaction.back() / matrix.reaction.back() - 1;
  const Real t_fibre = half_relaxation_time(fibre), t_matrix = half_relaxation_time(matrix);
  std::printf("peak ratio %.3f, equilibrium ratio - 1 = %.4f, half relaxation after the ramp "
              "%.1f s (fibres) and %.1f s (matrix)\n",
              peak_ratio, equilibrium_change, t_fibre, t_matrix);
  EXPECT_GT(peak_ratio, 4.0);
  EXPECT_GT(equilibrium_change, 0.0); // the fibres hold the lateral expansion back
  EXPECT_LT(equilibrium_change, 0.05);
  EXPECT_LT(t_fibre, 0.2 * t_matrix);
}

// (3) A third fibre family along z, the compressed axis, is never stretched (lambda_z <= 1 in
// every cell at every time): it carries no load and has no tangent, so the run is the same.
TEST(FibreUnconfined, FibresAlongTheCompressedAxisCarryNothing) {
  const std::string text = read_text(kFibreCase);
  const History two = run(text, kFibreCase);
  const std::string key = "[curves.ramp]";
  const auto at = text.find(key);
  ASSERT_NE(at, std::string::npos);
  std::string with_z = text;
  with_z.insert(at, R"([[materials.cartilage.solid.constituent]]
type = "fibre-exp-pow"
ksi = 3.0
alpha = 0.0
beta = 2.0
fibre = [0.0, 0.0, 1.0]

)");
  const History three = run(with_z, kFibreCase);
  ASSERT_EQ(two.time.size(), three.time.size());
  Real worst = 0.0;
  for (std::size_t k = 0; k < two.time.size(); ++k) {
    EXPECT_EQ(two.time[k], three.time[k]);
    worst = std::max(worst, std::abs(two.reaction[k] - three.reaction[k]));
  }
  std::printf("largest reaction difference with the z fibres: %.2e N (peak %.4f N)\n", worst,
              peak(two).first * kArea);
  EXPECT_LE(worst, 1e-12 * peak(two).first * kArea);
}

} // namespace
