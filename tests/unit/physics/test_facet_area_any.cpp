// SPDX-License-Identifier: MIT
// Nodal area vectors of facets of every family (physics/facet_area_any.hpp) against answers that
// do not use them: a closed surface (the facets of a curved, distorted cell) has ∮ n da = 0 and
// ∮ x × n da = 0, a flat triangle's area vectors sum to its area times its normal, the quad4
// family is the quad4 function, and the derivative is that of finite differences.
#include "cell_families.hpp"
#include "trifem/physics/facet_area.hpp"
#include "trifem/physics/facet_area_any.hpp"

#include <gtest/gtest.h>

using namespace trifem;
using test::Noise;

namespace {

constexpr fe::FacetType kFacets[] = {fe::FacetType::Tri3, fe::FacetType::Tri6, fe::FacetType::Quad4,
                                     fe::FacetType::Quad8};

physics::FacetPositions facet_positions(const fe::CellNodeCoords& X, const fe::CellFacet& f) {
  physics::FacetPositions x(static_cast<Index>(f.nodes.size()), 3);
  for (std::size_t i = 0; i < f.nodes.size(); ++i)
    x.row(static_cast<Index>(i)) = X.row(f.nodes[i]);
  return x;
}

} // namespace

TEST(FacetAreaVectors, AClosedSurfaceHasNoNetAreaAndNoNetMoment) {
  for (const fe::CellType type : test::kCellFamilies) {
    const fe::CellNodeCoords X = test::distorted_cell(type, 3, 0.1);
    Vec3 area = Vec3::Zero(), moment = Vec3::Zero(), gross = Vec3::Zero();
    for (const fe::CellFacet& facet : fe::reference_cell(type).facets()) {
      const physics::FacetPositions x = facet_positions(X, facet);
      const physics::FacetVectorX a =
          physics::facet_area_vectors(fe::reference_facet(facet.type), x);
      for (Index i = 0; i < x.rows(); ++i) {
        area += a.segment<3>(3 * i);
        moment += x.row(i).transpose().cross(a.segment<3>(3 * i));
        gross += a.segment<3>(3 * i).cwiseAbs();
      }
    }
    // Σ_a a_a = ∮ n da and Σ_a x_a × a_a = ∮ x × n da over the watertight surface of the
    // facets (shared edges interpolate the same nodes), both 0, integrated exactly by the rules
    EXPECT_LE(area.norm(), 1e-14 * gross.norm()) << static_cast<int>(type);
    EXPECT_LE(moment.norm(), 1e-14 * gross.norm()) << static_cast<int>(type);
  }
}

TEST(FacetAreaVectors, AFlatTriangleCarriesItsAreaTimesItsNormalOneThirdAtEachCorner) {
  physics::FacetPositions x(3, 3);
  x << 0.2, 0.1, 0.3, 2.2, 0.4, -0.1, 0.5, 1.9, 0.6;
  const Vec3 normal_area = 0.5 * Vec3(x.row(1) - x.row(0)).cross(Vec3(x.row(2) - x.row(0)));
  const physics::FacetVectorX a =
      physics::facet_area_vectors(fe::reference_facet(fe::FacetType::Tri3), x);
  for (int i = 0; i < 3; ++i)
    EXPECT_LE((a.segment<3>(3 * i) - normal_area / 3.0).norm(), 1e-15 * normal_area.norm());
  // the same triangle as a tri6 with straight edges: corners 0, mid-edge nodes a third each
  physics::FacetPositions x6(6, 3);
  x6.topRows<3>() = x;
  x6.row(3) = 0.5 * (x.row(0) + x.row(1));
  x6.row(4) = 0.5 * (x.row(1) + x.row(2));
  x6.row(5) = 0.5 * (x.row(2) + x.row(0));
  const physics::FacetVectorX a6 =
      physics::facet_area_vectors(fe::reference_facet(fe::FacetType::Tri6), x6);
  for (int i = 0; i < 6; ++i)
    EXPECT_LE((a6.segment<3>(3 * i) - (i < 3 ? 0.0 : 1.0 / 3.0) * normal_area).norm(),
              1e-14 * normal_area.norm())
        << i;
}

TEST(FacetAreaVectors, TheQuad4FamilyIsTheQuad4Function) {
  fe::QuadCoords q;
  q << 0.0, 0.0, 0.1, 1.2, -0.1, 0.0, 1.1, 0.9, 0.2, -0.1, 1.0, -0.05;
  physics::FacetMatrix D4;
  const physics::FacetVector a4 = physics::facet_area_vectors(q, &D4);
  physics::FacetMatrixX D;
  const physics::FacetVectorX a =
      physics::facet_area_vectors(fe::reference_facet(fe::FacetType::Quad4), q, &D);
  EXPECT_LE((a - a4).lpNorm<Eigen::Infinity>(), 1e-15 * a4.lpNorm<Eigen::Infinity>());
  EXPECT_LE((D - D4).lpNorm<Eigen::Infinity>(), 1e-15 * D4.lpNorm<Eigen::Infinity>());
}

TEST(FacetAreaVectors, TheDerivativeIsThatOfFiniteDifferences) {
  for (const fe::FacetType type : kFacets) {
    const fe::ReferenceFacet& ref = fe::reference_facet(type);
    Noise noise(5);
    physics::FacetPositions x(ref.num_nodes(), 3);
    for (Index i = 0; i < x.rows(); ++i)
      x.row(i) << ref.nodes()(i, 0) + 0.1 * noise.next(), ref.nodes()(i, 1) + 0.1 * noise.next(),
          0.2 * noise.next();
    physics::FacetMatrixX D;
    physics::facet_area_vectors(ref, x, &D);
    const Real h = 1e-6;
    physics::FacetMatrixX D_fd(D.rows(), D.cols());
    for (Index j = 0; j < D.cols(); ++j) {
      physics::FacetPositions xp = x, xm = x;
      xp(j / 3, j % 3) += h;
      xm(j / 3, j % 3) -= h;
      D_fd.col(j) =
          (physics::facet_area_vectors(ref, xp) - physics::facet_area_vectors(ref, xm)) / (2 * h);
    }
    EXPECT_LE((D - D_fd).norm(), 1e-8 * D.norm()) << static_cast<int>(type);
  }
}
