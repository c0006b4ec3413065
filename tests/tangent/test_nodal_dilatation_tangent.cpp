// SPDX-License-Identifier: MIT
// Finite-difference checks of the nodally averaged dilatation element
// (physics/nodal_dilatation.hpp) and of the pieces it is made of: the cell energy with a given
// dilatation J̄ (dilatation_split) rebuilds the mean-dilatation element when J̄ = v/V, the cell
// volume's gradient and second derivative, and on patches of distorted tet4 and penta6 cells
// the assembled force is the gradient of the patch energy Σ_e Σ_q W(C̄) w, written here from its
// definition, and the tangent the Jacobian of the force.
#include "cell_families.hpp"
#include "mapped_mesh.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/convert_cells.hpp"
#include "trifem/physics/nodal_dilatation.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace trifem;
using test::as_rows;
using test::kCellFamilies;
using test::Noise;

namespace nodal_dilatation_test {
namespace {

Eigen::VectorXd random_state(Index n, unsigned seed, Real amplitude) {
  Noise noise(seed);
  Eigen::VectorXd u(n);
  for (Index i = 0; i < n; ++i)
    u[i] = amplitude * noise.next();
  return u;
}

} // namespace

// With J̄ = v/V of the cell itself, f = f_u + π ∇J̄ and K = K_uu + f_uJ ∇J̄ᵀ + ∇J̄ f_uJᵀ +
// π_J ∇J̄ ∇J̄ᵀ + π ∇²J̄ are the mean-dilatation element's force and tangent (written apart), on a
// distorted cell of every family for every registered law.
TEST(DilatationSplit, RebuildsTheMeanDilatationElementWithTheCellsOwnDilatation) {
  for (const fe::CellType type : kCellFamilies)
    for (const auto& entry : material::registered_laws()) {
      SCOPED_TRACE(::testing::Message()
                   << "cell type " << static_cast<int>(type) << ", law " << entry.type);
      const auto law = material::create_law(entry.type, entry.example, "m");
      const auto geo =
          physics::cell_geometry(fe::reference_cell(type), test::distorted_cell(type, 3, 0.08));
      ASSERT_TRUE(geo.has_value());
      const fe::CellNodeCoords u = as_rows(random_state(3 * geo->num_nodes(), 19, 0.1));
      physics::CellVolume volume;
      ASSERT_TRUE(physics::cell_volume(*geo, u, true, volume));
      Real V = 0.0;
      for (const Real w : geo->dV)
        V += w;
      physics::DilatationSplit split;
      ASSERT_TRUE(physics::dilatation_split(*geo, u, *law, volume.v / V, true, split));
      const Eigen::VectorXd g = volume.grad / V;
      const Eigen::MatrixXd H = volume.hess / V;
      const Eigen::VectorXd f = split.f_u + split.pi * g;
      const Eigen::MatrixXd K = split.K_uu + split.f_uJ * g.transpose() +
                                g * split.f_uJ.transpose() + split.pi_J * g * g.transpose() +
                                split.pi * H;
      physics::CellVectorX f_md;
      physics::CellMatrixX K_md;
      ASSERT_TRUE(physics::mean_dilatation_cell(*geo, u, *law, f_md, &K_md));
      EXPECT_LE((f - Eigen::VectorXd(f_md)).norm(), 1e-11 * f_md.norm());
      EXPECT_LE((K - Eigen::MatrixXd(K_md)).norm(), 1e-11 * K_md.norm());
    }
}

// The volume v = Σ J w of a distorted cell of every family: its gradient and second derivative
// against central differences.
TEST(DilatationSplit, CellVolumeGradientAndHessianMatchCentralDifferences) {
  for (const fe::CellType type : kCellFamilies) {
    SCOPED_TRACE(::testing::Message() << "cell type " << static_cast<int>(type));
    const auto geo =
        physics::cell_geometry(fe::reference_cell(type), test::distorted_cell(type, 3, 0.08));
    ASSERT_TRUE(geo.has_value());
    const Index n = 3 * geo->num_nodes();
    const Eigen::VectorXd u0 = random_state(n, 19, 0.1);
    physics::CellVolume at;
    ASSERT_TRUE(physics::cell_volume(*geo, as_rows(u0), true, at));
    const Real h = 1e-6;
    Eigen::VectorXd grad_fd(n);
    Eigen::MatrixXd hess_fd(n, n);
    for (Index j = 0; j < n; ++j) {
      Eigen::VectorXd up = u0, um = u0;
      up[j] += h;
      um[j] -= h;
      physics::CellVolume p, m;
      ASSERT_TRUE(physics::cell_volume(*geo, as_rows(up), false, p));
      ASSERT_TRUE(physics::cell_volume(*geo, as_rows(um), false, m));
      grad_fd[j] = (p.v - m.v) / (2 * h);
      hess_fd.col(j) = (p.grad - m.grad) / (2 * h);
    }
    EXPECT_LE((Eigen::VectorXd(at.grad) - grad_fd).norm(), 1e-8 * at.grad.norm());
    EXPECT_LE((Eigen::MatrixXd(at.hess) - hess_fd).norm(), 1e-7 * at.hess.norm());
  }
}

namespace {

/// A 2 x 2 x 2 box of `type` cells (tet4: six per hex; penta6: two per hex), every node moved
/// by up to 0.04 of the 1 mm box.
mesh::Mesh distorted_box(fe::CellType type) {
  mesh::BoxSpec spec;
  spec.divisions = {2, 2, 2};
  Noise noise(29);
  return test::map_nodes(mesh::convert_cells(mesh::make_box(spec), type), [&](const Vec3& x) {
    return Vec3(x + 0.04 * Vec3(noise.next(), noise.next(), noise.next()));
  });
}

/// Π(U) = Σ_e Σ_q W(C̄_q) w_q with C̄ = (J̄_e/J)^(2/3) C and J̄_e the mean over the cell's nodes of
/// θ_a = v_a / V_a, v_a = Σ_{e∋a} v_e / n_e: the element's energy from its definition
/// (U: 3 per mesh node).
Real patch_energy(const mesh::Mesh& mesh, const std::vector<physics::CellGeometry>& geo,
                  const Eigen::VectorXd& U, const material::ElasticLaw& law) {
  const Index cells = mesh.num_cells();
  std::vector<Real> v(static_cast<std::size_t>(cells)), V(v.size());
  std::vector<Real> v_node(static_cast<std::size_t>(mesh.num_nodes()), 0.0),
      V_node(v_node.size(), 0.0);
  auto displacement = [&](Index c) {
    const std::span<const Index> nodes = mesh.cell_nodes(c);
    fe::CellNodeCoords u(static_cast<Index>(nodes.size()), 3);
    for (std::size_t a = 0; a < nodes.size(); ++a)
      u.row(static_cast<Index>(a)) = U.segment<3>(3 * nodes[a]).transpose();
    return u;
  };
  for (Index c = 0; c < cells; ++c) {
    const auto& g = geo[static_cast<std::size_t>(c)];
    const fe::CellNodeCoords u = displacement(c);
    Real vc = 0.0, Vc = 0.0;
    for (std::size_t q = 0; q < g.dV.size(); ++q) {
      vc += (Mat3::Identity() + u.transpose() * g.dN_dX[q]).determinant() * g.dV[q];
      Vc += g.dV[q];
    }
    const std::span<const Index> nodes = mesh.cell_nodes(c);
    for (const Index a : nodes) {
      v_node[static_cast<std::size_t>(a)] += vc / static_cast<Real>(nodes.size());
      V_node[static_cast<std::size_t>(a)] += Vc / static_cast<Real>(nodes.size());
    }
  }
  Real energy = 0.0;
  for (Index c = 0; c < cells; ++c) {
    const std::span<const Index> nodes = mesh.cell_nodes(c);
    Real Jbar = 0.0;
    for (const Index a : nodes)
      Jbar += v_node[static_cast<std::size_t>(a)] / V_node[static_cast<std::size_t>(a)] /
              static_cast<Real>(nodes.size());
    const auto& g = geo[static_cast<std::size_t>(c)];
    const fe::CellNodeCoords u = displacement(c);
    for (std::size_t q = 0; q < g.dV.size(); ++q) {
      const Mat3 F = Mat3::Identity() + u.transpose() * g.dN_dX[q];
      const Real alpha2 = std::pow(Jbar / F.determinant(), 2.0 / 3.0);
      energy += law.energy(alpha2 * F.transpose() * F) * g.dV[q];
    }
  }
  return energy;
}

/// The assembled force (and tangent) of every element of `nodal` at U.
void assemble(const mesh::Mesh& mesh, const physics::NodalDilatation& nodal,
              const Eigen::VectorXd& U, const material::ElasticLaw& law, Eigen::VectorXd& R,
              Eigen::MatrixXd* K) {
  R.setZero(U.size());
  if (K)
    K->setZero(U.size(), U.size());
  for (Index e = 0; e < mesh.num_cells(); ++e) {
    const std::span<const Index> patch = nodal.patch(e);
    Eigen::MatrixX3d u(static_cast<Index>(patch.size()), 3);
    for (std::size_t a = 0; a < patch.size(); ++a)
      u.row(static_cast<Index>(a)) = U.segment<3>(3 * patch[a]).transpose();
    physics::LocalVector r;
    physics::LocalMatrix Ke;
    ASSERT_TRUE(nodal.evaluate(e, u, law, r, K ? &Ke : nullptr));
    for (std::size_t a = 0; a < patch.size(); ++a) {
      R.segment<3>(3 * patch[a]) += r.segment<3>(3 * static_cast<Index>(a));
      if (!K)
        continue;
      for (std::size_t b = 0; b < patch.size(); ++b)
        K->block<3, 3>(3 * patch[a], 3 * patch[b]) +=
            Ke.block<3, 3>(3 * static_cast<Index>(a), 3 * static_cast<Index>(b));
    }
  }
}

} // namespace

// On distorted boxes of tet4 and of penta6 cells at a random state, for a coupled and an
// uncoupled law: the assembled force = ∂Π/∂U of the patch energy and the tangent = ∂R/∂U by
// central differences, symmetric; at U = 0 the force is 0.
TEST(NodalDilatation, ForceIsTheGradientOfThePatchEnergyAndTangentTheJacobianOfTheForce) {
  for (const fe::CellType type : {fe::CellType::Tet4, fe::CellType::Penta6})
    for (const char* law_type : {"neo-hookean", "mooney-rivlin"}) {
      SCOPED_TRACE(::testing::Message()
                   << "cell type " << static_cast<int>(type) << ", law " << law_type);
      const mesh::Mesh mesh = distorted_box(type);
      const auto law =
          std::string(law_type) == "neo-hookean"
              ? material::create_law(law_type, {{"E", 1.0}, {"nu", 0.45}}, "m")
              : material::create_law(law_type, {{"c1", 0.2}, {"c2", 0.05}, {"k", 10.0}}, "m");
      std::vector<physics::CellGeometry> geo;
      std::vector<const physics::CellGeometry*> pointers;
      std::vector<Index> cells;
      for (Index c = 0; c < mesh.num_cells(); ++c)
        geo.push_back(std::get<physics::CellGeometry>(physics::reference_geometry(mesh, c)));
      for (Index c = 0; c < mesh.num_cells(); ++c) {
        pointers.push_back(&geo[static_cast<std::size_t>(c)]);
        cells.push_back(c);
      }
      const physics::NodalDilatation nodal(mesh, cells, pointers);
      const Index n = 3 * mesh.num_nodes();
      Eigen::VectorXd R;
      assemble(mesh, nodal, Eigen::VectorXd::Zero(n), *law, R, nullptr);
      EXPECT_LE(R.norm(), 1e-14);
      const Eigen::VectorXd U = random_state(n, 31, 0.05);
      Eigen::MatrixXd K;
      assemble(mesh, nodal, U, *law, R, &K);
      const Real h = 1e-6;
      Eigen::VectorXd R_fd(n);
      Eigen::MatrixXd K_fd(n, n);
      for (Index j = 0; j < n; ++j) {
        Eigen::VectorXd up = U, um = U;
        up[j] += h;
        um[j] -= h;
        R_fd[j] = (patch_energy(mesh, geo, up, *law) - patch_energy(mesh, geo, um, *law)) / (2 * h);
        Eigen::VectorXd Rp, Rm;
        assemble(mesh, nodal, up, *law, Rp, nullptr);
        assemble(mesh, nodal, um, *law, Rm, nullptr);
        K_fd.col(j) = (Rp - Rm) / (2 * h);
      }
      EXPECT_LE((R - R_fd).norm() / R.norm(), 1e-6);
      EXPECT_LE((K - K_fd).norm() / K.norm(), 1e-6);
      EXPECT_LE((K - K.transpose()).norm() / K.norm(), 1e-12);
      RecordProperty(fmt::format("{}_{}", static_cast<int>(type), law_type),
                     fmt::format("force {:.1e}, tangent {:.1e}, symmetry {:.1e}",
                                 (R - R_fd).norm() / R.norm(), (K - K_fd).norm() / K.norm(),
                                 (K - K.transpose()).norm() / K.norm()));
    }
}

} // namespace nodal_dilatation_test
