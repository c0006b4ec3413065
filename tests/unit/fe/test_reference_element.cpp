// SPDX-License-Identifier: MIT
// Reference elements: shape functions, quadrature rules, facets, node orders (Gmsh's) and VTK
// orders of every cell and facet type.
#include "trifem/fe/hex8.hpp"
#include "trifem/fe/reference_element.hpp"
#include "trifem/mesh/hex_faces.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

using namespace trifem;

namespace {

constexpr std::array<fe::CellType, 5> kAllCellTypes = {fe::CellType::Hex8, fe::CellType::Tet4,
                                                       fe::CellType::Tet10, fe::CellType::Penta6,
                                                       fe::CellType::Hex20};
constexpr std::array<fe::FacetType, 4> kAllFacetTypes = {
    fe::FacetType::Tri3, fe::FacetType::Tri6, fe::FacetType::Quad4, fe::FacetType::Quad8};

std::string type_name(fe::CellType type) {
  constexpr std::array<const char*, 5> names = {"Hex8", "Tet4", "Tet10", "Penta6", "Hex20"};
  return names[static_cast<std::size_t>(type)];
}

std::string type_name(fe::FacetType type) {
  constexpr std::array<const char*, 4> names = {"Tri3", "Tri6", "Quad4", "Quad8"};
  return names[static_cast<std::size_t>(type)];
}

/// Uniform numbers in [0, 1) from the raw output of std::mt19937, whose sequence the standard
/// fixes (unlike that of the distributions): the same points on every platform.
class UniformSource {
public:
  explicit UniformSource(unsigned seed) : engine_(seed) {}
  Real next() { return static_cast<Real>(engine_()) / 4294967296.0; }

private:
  std::mt19937 engine_;
};

/// The reference domains: [-1,1]^D, the unit simplex, the triangle x [-1,1].
enum class Domain { Cube, Simplex, Wedge };

template <int D>
using Point = Eigen::Matrix<Real, D, 1>;
template <int D>
using Exponents = std::array<int, D>;

Domain domain_of(const fe::ReferenceCell& cell) {
  switch (cell.type()) {
  case fe::CellType::Hex8:
  case fe::CellType::Hex20:
    return Domain::Cube;
  case fe::CellType::Penta6:
    return Domain::Wedge;
  default:
    return Domain::Simplex;
  }
}

Domain domain_of(const fe::ReferenceFacet& facet) {
  const bool quad = facet.type() == fe::FacetType::Quad4 || facet.type() == fe::FacetType::Quad8;
  return quad ? Domain::Cube : Domain::Simplex;
}

Real measure_of(const fe::ReferenceCell& cell) {
  return cell.volume();
}
Real measure_of(const fe::ReferenceFacet& facet) {
  return facet.area();
}

template <class Element>
constexpr int kDim = std::is_same_v<Element, fe::ReferenceCell> ? 3 : 2;

/// The number of leading coordinates that run over a simplex; the others run over [-1, 1].
int simplex_dim(Domain domain, int dim) {
  return domain == Domain::Cube ? 0 : (domain == Domain::Wedge ? dim - 1 : dim);
}

bool is_interval_coordinate(Domain domain, int d, int dim) {
  return d >= simplex_dim(domain, dim);
}

/// A point strictly inside the domain (rejection sampling on the simplex coordinates).
template <int D>
Point<D> random_point(Domain domain, UniformSource& random) {
  const int n = simplex_dim(domain, D);
  Point<D> x = Point<D>::Ones();
  for (int d = n; d < D; ++d)
    x[d] = 0.999 * (2.0 * random.next() - 1.0);
  while (n > 0 && !(x.head(n).sum() < 1.0 && x.head(n).minCoeff() > 0.0))
    for (int d = 0; d < n; ++d)
      x[d] = random.next();
  return x;
}

template <int D>
bool strictly_inside(Domain domain, const Point<D>& x) {
  const int n = simplex_dim(domain, D);
  for (int d = n; d < D; ++d)
    if (!(std::abs(x[d]) < 1.0))
      return false;
  return n == 0 || (x.head(n).minCoeff() > 0.0 && x.head(n).sum() < 1.0);
}

Real power(Real x, int n) {
  Real p = 1.0;
  for (int i = 0; i < n; ++i)
    p *= x;
  return p;
}

Real factorial(int n) {
  return n <= 1 ? 1.0 : n * factorial(n - 1);
}

template <int D>
Real monomial(const Exponents<D>& a, const Point<D>& x) {
  Real p = 1.0;
  for (int d = 0; d < D; ++d)
    p *= power(x[d], a[d]);
  return p;
}

template <int D>
Point<D> monomial_grad(const Exponents<D>& a, const Point<D>& x) {
  Point<D> g;
  for (int m = 0; m < D; ++m) {
    g[m] = a[m] == 0 ? 0.0 : a[m] * power(x[m], a[m] - 1);
    for (int d = 0; d < D; ++d)
      if (d != m)
        g[m] *= power(x[d], a[d]);
  }
  return g;
}

/// int_{-1}^{1} x^a dx.
Real interval_integral(int a) {
  return a % 2 == 1 ? 0.0 : 2.0 / (a + 1);
}

/// The exact integral of x^a over the domain: on the simplex a_1! ... a_n! / (|a| + n)!.
template <int D>
Real exact_integral(Domain domain, const Exponents<D>& a) {
  const int n = simplex_dim(domain, D);
  Real integral = 1.0;
  int simplex_degree = 0;
  for (int d = 0; d < n; ++d) {
    integral *= factorial(a[d]);
    simplex_degree += a[d];
  }
  if (n > 0)
    integral /= factorial(simplex_degree + n);
  for (int d = n; d < D; ++d)
    integral *= interval_integral(a[d]);
  return integral;
}

/// Every exponent vector with components <= max.
template <int D>
std::vector<Exponents<D>> exponents_up_to(int max) {
  std::vector<Exponents<D>> all;
  Exponents<D> a{};
  while (true) {
    all.push_back(a);
    int d = 0;
    while (d < D && ++a[d] > max)
      a[d++] = 0;
    if (d == D)
      return all;
  }
}

/// The monomials a rule of degree p integrates exactly on the domain (rule().degree documents
/// it): each exponent <= p on the cube, total degree <= p on the simplex, and on the wedge
/// degree <= p in (x, y) and <= 3 in z.
template <int D>
bool within_rule_degree(Domain domain, const Exponents<D>& a, int p) {
  int simplex_degree = 0;
  for (int d = 0; d < D; ++d) {
    if (!is_interval_coordinate(domain, d, D))
      simplex_degree += a[d];
    else if (a[d] > (domain == Domain::Wedge ? 3 : p))
      return false;
  }
  return simplex_degree <= p;
}

/// The polynomial space an element's shape functions span: the exponents of its monomials.
template <class Element>
std::vector<Exponents<kDim<Element>>> polynomial_space(const Element& element) {
  constexpr int D = kDim<Element>;
  const Domain domain = domain_of(element);
  std::vector<Exponents<D>> space;
  for (const auto& a : exponents_up_to<D>(2)) {
    int degree = 0, squares = 0, simplex_degree = 0;
    for (int d = 0; d < D; ++d) {
      degree += a[d];
      squares += a[d] == 2;
      simplex_degree += is_interval_coordinate(domain, d, D) ? 0 : a[d];
    }
    bool in_space = false;
    if (domain == Domain::Simplex)
      in_space = degree <= element.order();
    else if (domain == Domain::Wedge) // linear triangle x linear interval
      in_space = simplex_degree <= 1 && a[D - 1] <= 1;
    else // (bi/tri)linear, or serendipity: at most one square, the others linear
      in_space = element.order() == 1 ? squares == 0 : squares <= 1;
    if (in_space)
      space.push_back(a);
  }
  return space;
}

template <class Element>
Point<kDim<Element>> node(const Element& element, int a) {
  return element.nodes().row(a).transpose();
}

template <class Check>
void for_every_cell(Check check) {
  for (const auto type : kAllCellTypes) {
    SCOPED_TRACE(type_name(type));
    check(fe::reference_cell(type));
  }
}

template <class Check>
void for_every_facet(Check check) {
  for (const auto type : kAllFacetTypes) {
    SCOPED_TRACE(type_name(type));
    check(fe::reference_facet(type));
  }
}

// ---- checks shared by cells and facets ---------------------------------------------------

template <class Element>
void expect_partition_of_unity(const Element& element) {
  constexpr int D = kDim<Element>;
  UniformSource random(11);
  for (int i = 0; i < 100; ++i) {
    const Point<D> xi = random_point<D>(domain_of(element), random);
    EXPECT_NEAR(element.shape(xi).sum(), 1.0, 1e-14);
    EXPECT_LE(element.shape_grad(xi).colwise().sum().norm(), 1e-14);
  }
}

template <class Element>
void expect_kronecker_delta_at_nodes(const Element& element) {
  for (int b = 0; b < element.num_nodes(); ++b) {
    const auto N = element.shape(node(element, b));
    for (int a = 0; a < element.num_nodes(); ++a)
      EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, 1e-14) << "N_" << a << " at node " << b;
  }
}

template <class Element>
void expect_gradients_match_central_differences(const Element& element) {
  constexpr int D = kDim<Element>;
  constexpr Real h = 1e-6;
  UniformSource random(12);
  for (int i = 0; i < 20; ++i) {
    const Point<D> xi = random_point<D>(domain_of(element), random);
    const auto G = element.shape_grad(xi);
    for (int d = 0; d < D; ++d) {
      const Point<D> step = h * Point<D>::Unit(d);
      const Eigen::VectorXd forward = element.shape(xi + step);
      const Eigen::VectorXd backward = element.shape(xi - step);
      EXPECT_LE(((forward - backward) / (2 * h) - G.col(d)).cwiseAbs().maxCoeff(), 1e-8);
    }
  }
}

/// sum_a N_a X_a = xi and sum_a X_a (x) dN_a/dxi = I.
template <class Element>
void expect_linear_fields_interpolated_exactly(const Element& element) {
  constexpr int D = kDim<Element>;
  UniformSource random(13);
  for (int i = 0; i < 50; ++i) {
    const Point<D> xi = random_point<D>(domain_of(element), random);
    const Point<D> x = element.nodes().transpose() * element.shape(xi);
    EXPECT_LE((x - xi).norm(), 1e-14);
    const Eigen::Matrix<Real, D, D> J = element.nodes().transpose() * element.shape_grad(xi);
    EXPECT_LE((J - Eigen::Matrix<Real, D, D>::Identity()).norm(), 1e-14);
  }
}

/// Every monomial of the element's polynomial space, and the space has one per node.
template <class Element>
void expect_polynomial_space_interpolated_exactly(const Element& element) {
  constexpr int D = kDim<Element>;
  const auto space = polynomial_space(element);
  EXPECT_EQ(static_cast<int>(space.size()), element.num_nodes());
  UniformSource random(14);
  for (const auto& a : space) {
    Eigen::VectorXd nodal(element.num_nodes());
    for (int b = 0; b < element.num_nodes(); ++b)
      nodal[b] = monomial<D>(a, node(element, b));
    for (int i = 0; i < 20; ++i) {
      const Point<D> xi = random_point<D>(domain_of(element), random);
      EXPECT_NEAR(element.shape(xi).dot(nodal), monomial<D>(a, xi), 1e-14);
      const Point<D> grad = element.shape_grad(xi).transpose() * nodal;
      EXPECT_LE((grad - monomial_grad<D>(a, xi)).norm(), 1e-13);
    }
  }
}

template <class Element>
void expect_weights_sum_to_measure(const Element& element) {
  Real sum = 0.0;
  for (const auto& p : element.rule().points)
    sum += p.weight;
  EXPECT_NEAR(sum, measure_of(element), 1e-14 * measure_of(element));
}

/// Every monomial the rule's degree covers, against its closed-form integral, to 1e-14 of
/// the integral of its absolute value (the exact integral of odd monomials on [-1,1] is 0).
template <class Element>
void expect_monomials_integrated_exactly(const Element& element) {
  constexpr int D = kDim<Element>;
  const Domain domain = domain_of(element);
  const int degree = element.rule().degree;
  EXPECT_GE(degree, 2 * element.order()); // the consistent mass matrix of an affine cell
  int checked = 0;
  for (const auto& a : exponents_up_to<D>(degree)) {
    if (!within_rule_degree<D>(domain, a, degree))
      continue;
    Real integral = 0.0, magnitude = 0.0;
    for (const auto& p : element.rule().points) {
      integral += p.weight * monomial<D>(a, p.xi);
      magnitude += p.weight * std::abs(monomial<D>(a, p.xi));
    }
    EXPECT_NEAR(integral, exact_integral<D>(domain, a), 1e-14 * magnitude)
        << "exponents " << a[0] << " " << a[1] << " " << a[D - 1];
    ++checked;
  }
  EXPECT_GE(checked, 6);
}

template <class Element>
void expect_positive_weights_inside(const Element& element) {
  constexpr int D = kDim<Element>;
  for (const auto& p : element.rule().points) {
    EXPECT_GT(p.weight, 0.0);
    EXPECT_TRUE(strictly_inside<D>(domain_of(element), p.xi)) << p.xi.transpose();
  }
}

using EdgeList = std::vector<std::array<int, 2>>;

/// Node a < corners.size() of the element lies at corners[a], node corners.size() + e halfway
/// between the corners of edges[e] (quadratic elements).
template <class Element>
void expect_nodes(const Element& element, const std::vector<Point<kDim<Element>>>& corners,
                  const EdgeList& edges) {
  const int n = static_cast<int>(corners.size());
  ASSERT_EQ(element.num_nodes(), n + (element.order() == 2 ? static_cast<int>(edges.size()) : 0));
  for (int a = 0; a < n; ++a)
    EXPECT_EQ(node(element, a), corners[static_cast<std::size_t>(a)]) << "corner " << a;
  for (int e = 0; e < element.num_nodes() - n; ++e) {
    const auto& [i, j] = edges[static_cast<std::size_t>(e)];
    EXPECT_EQ(node(element, n + e),
              0.5 * (corners[static_cast<std::size_t>(i)] + corners[static_cast<std::size_t>(j)]))
        << "mid-edge node " << n + e;
  }
}

// ---- cells: geometry helpers -------------------------------------------------------------

int corner_count(fe::CellType type) {
  switch (type) {
  case fe::CellType::Tet4:
  case fe::CellType::Tet10:
    return 4;
  case fe::CellType::Penta6:
    return 6;
  default:
    return 8;
  }
}

/// A 4-point Gauss product (degree 7 in each collapsed coordinate) built independently of
/// the library's rules; on the simplex through x = u, y = v (1 - u), z = w (1 - u)(1 - v).
/// Exact for every polynomial of degree <= 5 on each domain.
std::vector<fe::CellQuadraturePoint> fine_rule(Domain domain) {
  constexpr std::array<Real, 4> x = {-0.86113631159405257522, -0.33998104358485626480,
                                     0.33998104358485626480, 0.86113631159405257522};
  constexpr std::array<Real, 4> w = {0.34785484513745385737, 0.65214515486254614263,
                                     0.65214515486254614263, 0.34785484513745385737};
  std::vector<fe::CellQuadraturePoint> rule;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t k = 0; k < 4; ++k) {
        const Real weight = w[i] * w[j] * w[k];
        const Real u = 0.5 * (1 + x[i]), v = 0.5 * (1 + x[j]), t = 0.5 * (1 + x[k]);
        if (domain == Domain::Cube)
          rule.push_back({Vec3(x[i], x[j], x[k]), weight});
        else if (domain == Domain::Wedge)
          rule.push_back({Vec3(u, v * (1 - u), x[k]), weight * (1 - u) / 4});
        else
          rule.push_back({Vec3(u, v * (1 - u), t * (1 - u) * (1 - v)),
                          weight * (1 - u) * (1 - u) * (1 - v) / 8});
      }
  return rule;
}

/// The consistent mass matrix int N_a N_b dV of the cell with nodes X, by `rule`.
Eigen::MatrixXd mass_matrix(const fe::ReferenceCell& cell, const fe::CellNodeCoords& X,
                            const std::vector<fe::CellQuadraturePoint>& rule) {
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(cell.num_nodes(), cell.num_nodes());
  for (const auto& p : rule) {
    const fe::ShapeValues N = cell.shape(p.xi);
    const Real dV = (X.transpose() * cell.shape_grad(p.xi)).determinant() * p.weight;
    M += N * N.transpose() * dV;
  }
  return M;
}

Mat3 test_map_matrix() {
  Mat3 A;
  A << 1.2, 0.3, -0.1, -0.2, 0.9, 0.25, 0.15, -0.1, 1.4;
  return A;
}

/// The reference nodes mapped by x = A X + b.
fe::CellNodeCoords affine_instance(const fe::ReferenceCell& cell) {
  const Vec3 b(0.3, -0.2, 0.5);
  return (cell.nodes() * test_map_matrix().transpose()).rowwise() + b.transpose();
}

/// The affine instance with its corners moved by up to 6 % of the reference cell's size and
/// its mid-edge nodes moved off their edges' midpoints by half that (curved edges).
fe::CellNodeCoords distorted_instance(const fe::ReferenceCell& cell, UniformSource& random) {
  const Real amplitude = domain_of(cell) == Domain::Cube ? 0.12 : 0.06;
  auto random_offset = [&] {
    return Vec3(2 * random.next() - 1, 2 * random.next() - 1, 2 * random.next() - 1);
  };
  fe::CellNodeCoords X = affine_instance(cell);
  const int corners = corner_count(cell.type());
  for (int a = 0; a < corners; ++a)
    X.row(a) += amplitude * random_offset().transpose();
  for (int m = corners; m < cell.num_nodes(); ++m)
    for (int i = 0; i < corners; ++i)
      for (int j = i + 1; j < corners; ++j)
        if (node(cell, m) == 0.5 * (node(cell, i) + node(cell, j)))
          X.row(m) = 0.5 * (X.row(i) + X.row(j)) + 0.5 * amplitude * random_offset().transpose();
  return X;
}

/// det(dx/dxi) at the quadrature points, the nodes and 200 random points of the cell.
Real smallest_jacobian(const fe::ReferenceCell& cell, const fe::CellNodeCoords& X) {
  std::vector<Vec3> points;
  for (const auto& p : cell.rule().points)
    points.push_back(p.xi);
  for (int a = 0; a < cell.num_nodes(); ++a)
    points.push_back(node(cell, a));
  UniformSource random(21);
  for (int i = 0; i < 200; ++i)
    points.push_back(random_point<3>(domain_of(cell), random));
  Real smallest = std::numeric_limits<Real>::max();
  for (const Vec3& xi : points)
    smallest = std::min(smallest, (X.transpose() * cell.shape_grad(xi)).determinant());
  return smallest;
}

/// A facet's nodes in the cell's reference coordinates (row k = facet node k).
fe::CellNodeCoords facet_coords(const fe::ReferenceCell& cell, const fe::CellFacet& facet) {
  fe::CellNodeCoords Y(static_cast<Index>(facet.nodes.size()), 3);
  for (std::size_t k = 0; k < facet.nodes.size(); ++k)
    Y.row(static_cast<Index>(k)) = cell.nodes().row(facet.nodes[k]);
  return Y;
}

Vec2 facet_centre(fe::FacetType type) {
  const bool triangle = type == fe::FacetType::Tri3 || type == fe::FacetType::Tri6;
  return triangle ? Vec2(1.0 / 3.0, 1.0 / 3.0) : Vec2::Zero();
}

/// d x/d s1 x d x/d s2 of the facet at its centre, on the cell's reference coordinates.
Vec3 facet_normal(const fe::ReferenceCell& cell, const fe::CellFacet& facet) {
  const Eigen::Matrix<Real, 3, 2> tangents =
      facet_coords(cell, facet).transpose() *
      fe::reference_facet(facet.type).shape_grad(facet_centre(facet.type));
  return tangents.col(0).cross(tangents.col(1));
}

Vec3 cell_centroid(const fe::ReferenceCell& cell) {
  Vec3 centroid = Vec3::Zero();
  for (const auto& p : cell.rule().points)
    centroid += p.weight * p.xi;
  return centroid / cell.volume();
}

} // namespace

// ---- shape functions ---------------------------------------------------------------------

TEST(ReferenceCell, DescribesEachType) {
  struct Expected {
    fe::CellType type;
    int nodes, order, vtk_type;
    Real volume;
  };
  for (const Expected& e : {Expected{fe::CellType::Hex8, 8, 1, 12, 8.0},
                            Expected{fe::CellType::Tet4, 4, 1, 10, 1.0 / 6.0},
                            Expected{fe::CellType::Tet10, 10, 2, 24, 1.0 / 6.0},
                            Expected{fe::CellType::Penta6, 6, 1, 13, 1.0},
                            Expected{fe::CellType::Hex20, 20, 2, 25, 8.0}}) {
    SCOPED_TRACE(type_name(e.type));
    const fe::ReferenceCell& cell = fe::reference_cell(e.type);
    EXPECT_EQ(&cell, &fe::reference_cell(e.type)); // one object per type
    EXPECT_EQ(cell.type(), e.type);
    EXPECT_EQ(cell.num_nodes(), e.nodes);
    EXPECT_EQ(cell.nodes().rows(), e.nodes);
    EXPECT_EQ(cell.order(), e.order);
    EXPECT_EQ(cell.vtk_type(), e.vtk_type);
    EXPECT_DOUBLE_EQ(cell.volume(), e.volume);
  }
}

TEST(ReferenceFacet, DescribesEachType) {
  const std::array<int, 4> nodes = {3, 6, 4, 8};
  const std::array<int, 4> orders = {1, 2, 1, 2};
  const std::array<Real, 4> areas = {0.5, 0.5, 4.0, 4.0};
  for (std::size_t i = 0; i < kAllFacetTypes.size(); ++i) {
    SCOPED_TRACE(type_name(kAllFacetTypes[i]));
    const fe::ReferenceFacet& facet = fe::reference_facet(kAllFacetTypes[i]);
    EXPECT_EQ(&facet, &fe::reference_facet(kAllFacetTypes[i]));
    EXPECT_EQ(facet.type(), kAllFacetTypes[i]);
    EXPECT_EQ(facet.num_nodes(), nodes[i]);
    EXPECT_EQ(facet.order(), orders[i]);
    EXPECT_DOUBLE_EQ(facet.area(), areas[i]);
  }
}

// Gmsh's node orders (Gmsh reference manual, "Node ordering"), written out independently of
// the library's tables.
TEST(ReferenceCell, NodesFollowGmshOrder) {
  const std::vector<Vec3> tet = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  const EdgeList tet_edges = {{0, 1}, {1, 2}, {2, 0}, {3, 0}, {3, 2}, {3, 1}};
  std::vector<Vec3> hex;
  for (const auto& r : mesh::kHexNodeCoords)
    hex.emplace_back(r[0], r[1], r[2]);
  EXPECT_EQ(hex[6], Vec3(1, 1, 1));
  const EdgeList hex_edges = {{0, 1}, {0, 3}, {0, 4}, {1, 2}, {1, 5}, {2, 3},
                              {2, 6}, {3, 7}, {4, 5}, {4, 7}, {5, 6}, {6, 7}};
  const std::vector<Vec3> wedge = {Vec3(0, 0, -1), Vec3(1, 0, -1), Vec3(0, 1, -1),
                                   Vec3(0, 0, 1),  Vec3(1, 0, 1),  Vec3(0, 1, 1)};
  expect_nodes(fe::reference_cell(fe::CellType::Tet4), tet, tet_edges);
  expect_nodes(fe::reference_cell(fe::CellType::Tet10), tet, tet_edges);
  expect_nodes(fe::reference_cell(fe::CellType::Hex8), hex, hex_edges);
  expect_nodes(fe::reference_cell(fe::CellType::Hex20), hex, hex_edges);
  expect_nodes(fe::reference_cell(fe::CellType::Penta6), wedge, {});
}

TEST(ReferenceFacet, NodesFollowGmshOrder) {
  const std::vector<Vec2> triangle = {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1)};
  const std::vector<Vec2> square = {Vec2(-1, -1), Vec2(1, -1), Vec2(1, 1), Vec2(-1, 1)};
  const EdgeList triangle_edges = {{0, 1}, {1, 2}, {2, 0}};
  const EdgeList square_edges = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  expect_nodes(fe::reference_facet(fe::FacetType::Tri3), triangle, triangle_edges);
  expect_nodes(fe::reference_facet(fe::FacetType::Tri6), triangle, triangle_edges);
  expect_nodes(fe::reference_facet(fe::FacetType::Quad4), square, square_edges);
  expect_nodes(fe::reference_facet(fe::FacetType::Quad8), square, square_edges);
}

TEST(ReferenceCell, ShapeFunctionsArePartitionsOfUnity) {
  for_every_cell([](const auto& cell) { expect_partition_of_unity(cell); });
}

TEST(ReferenceFacet, ShapeFunctionsArePartitionsOfUnity) {
  for_every_facet([](const auto& facet) { expect_partition_of_unity(facet); });
}

TEST(ReferenceCell, ShapeFunctionsAreKroneckerDeltasAtTheNodes) {
  for_every_cell([](const auto& cell) { expect_kronecker_delta_at_nodes(cell); });
}

TEST(ReferenceFacet, ShapeFunctionsAreKroneckerDeltasAtTheNodes) {
  for_every_facet([](const auto& facet) { expect_kronecker_delta_at_nodes(facet); });
}

TEST(ReferenceCell, ShapeGradientsMatchCentralDifferences) {
  for_every_cell([](const auto& cell) { expect_gradients_match_central_differences(cell); });
}

TEST(ReferenceFacet, ShapeGradientsMatchCentralDifferences) {
  for_every_facet([](const auto& facet) { expect_gradients_match_central_differences(facet); });
}

TEST(ReferenceCell, ShapeFunctionsInterpolateLinearFieldsExactly) {
  for_every_cell([](const auto& cell) { expect_linear_fields_interpolated_exactly(cell); });
}

TEST(ReferenceFacet, ShapeHessiansMatchCentralDifferencesOfTheGradients) {
  constexpr Real h = 1e-6;
  UniformSource random(21);
  for_every_facet([&](const fe::ReferenceFacet& facet) {
    for (int i = 0; i < 20; ++i) {
      const Vec2 s = random_point<2>(domain_of(facet), random);
      const fe::FacetShapeHessians H = facet.shape_hessian(s);
      ASSERT_EQ(H.rows(), facet.num_nodes());
      for (int d = 0; d < 2; ++d) {
        const Vec2 step = h * Vec2::Unit(d);
        const Eigen::MatrixXd dG =
            (facet.shape_grad(s + step) - facet.shape_grad(s - step)) / (2 * h);
        // column d of dG: N_,0d and N_,1d; H holds (N_,00, N_,11, N_,01)
        EXPECT_LE((dG.col(d) - H.col(d)).cwiseAbs().maxCoeff(), 1e-8) << mesh::name(facet.type());
        EXPECT_LE((dG.col(1 - d) - H.col(2)).cwiseAbs().maxCoeff(), 1e-8)
            << mesh::name(facet.type());
      }
    }
  });
}

TEST(ReferenceFacet, ShapeFunctionsInterpolateLinearFieldsExactly) {
  for_every_facet([](const auto& facet) { expect_linear_fields_interpolated_exactly(facet); });
}

// tet10: every monomial of degree <= 2; hex20: the serendipity space (exponents <= 2, at most
// one of them 2); hex8: trilinear; tet4: linear; penta6: linear in (x, y) times linear in z.
TEST(ReferenceCell, ShapeFunctionsInterpolateTheirPolynomialSpaceExactly) {
  for_every_cell([](const auto& cell) { expect_polynomial_space_interpolated_exactly(cell); });
}

// tri6: every monomial of degree <= 2; quad8: the serendipity space; tri3 linear, quad4
// bilinear.
TEST(ReferenceFacet, ShapeFunctionsInterpolateTheirPolynomialSpaceExactly) {
  for_every_facet([](const auto& facet) { expect_polynomial_space_interpolated_exactly(facet); });
}

TEST(ReferenceCell, Hex8IsTheExistingHex8BitForBit) {
  const fe::ReferenceCell& cell = fe::reference_cell(fe::CellType::Hex8);
  std::vector<Vec3> points = {Vec3(0.3, -0.7, 0.1), Vec3(-1, 1, -1), Vec3::Zero()};
  UniformSource random(16);
  for (int i = 0; i < 10; ++i)
    points.push_back(random_point<3>(Domain::Cube, random));
  for (const Vec3& xi : points) {
    const fe::HexShape N = fe::hex8_shape(xi);
    const fe::HexShapeGrad G = fe::hex8_shape_grad(xi);
    const fe::ShapeValues cell_N = cell.shape(xi);
    const fe::ShapeGrads cell_G = cell.shape_grad(xi);
    for (int a = 0; a < 8; ++a) {
      EXPECT_EQ(cell_N[a], N[a]);
      for (int d = 0; d < 3; ++d)
        EXPECT_EQ(cell_G(a, d), G(a, d));
    }
  }
  const auto& rule = fe::hex_gauss_2x2x2();
  ASSERT_EQ(cell.rule().points.size(), rule.size());
  for (std::size_t q = 0; q < rule.size(); ++q) {
    EXPECT_EQ(cell.rule().points[q].xi, rule[q].xi);
    EXPECT_EQ(cell.rule().points[q].weight, rule[q].weight);
  }
  for (std::size_t f = 0; f < 6; ++f)
    EXPECT_EQ(cell.facets()[f].nodes,
              std::vector<int>(mesh::kHexFaces[f].begin(), mesh::kHexFaces[f].end()));
}

TEST(ReferenceFacet, Quad4IsTheExistingQuad4BitForBit) {
  const fe::ReferenceFacet& quad = fe::reference_facet(fe::FacetType::Quad4);
  UniformSource random(15);
  for (int i = 0; i < 10; ++i) {
    const Vec2 s = random_point<2>(Domain::Cube, random);
    const fe::QuadShape N = fe::quad4_shape(s);
    const fe::QuadShapeGrad G = fe::quad4_shape_grad(s);
    for (int a = 0; a < 4; ++a) {
      EXPECT_EQ(quad.shape(s)[a], N[a]);
      EXPECT_EQ(quad.shape_grad(s)(a, 0), G(a, 0));
      EXPECT_EQ(quad.shape_grad(s)(a, 1), G(a, 1));
    }
  }
  const auto& rule = fe::quad_gauss_2x2();
  ASSERT_EQ(quad.rule().points.size(), rule.size());
  for (std::size_t q = 0; q < rule.size(); ++q) {
    EXPECT_EQ(quad.rule().points[q].xi, rule[q].xi);
    EXPECT_EQ(quad.rule().points[q].weight, rule[q].weight);
  }
}

// ---- quadrature --------------------------------------------------------------------------

TEST(ReferenceCell, QuadratureWeightsSumToTheVolume) {
  for_every_cell([](const auto& cell) { expect_weights_sum_to_measure(cell); });
}

TEST(ReferenceFacet, QuadratureWeightsSumToTheArea) {
  for_every_facet([](const auto& facet) { expect_weights_sum_to_measure(facet); });
}

// hex: every x^a y^b z^c with a, b, c <= 2n - 1 (n Gauss points per direction); tet: degree
// <= 2 (tet4), <= 5 (tet10); wedge: degree <= 2 in (x, y) times <= 3 in z.
TEST(ReferenceCell, QuadratureIntegratesEveryMonomialUpToItsDegreeExactly) {
  for_every_cell([](const auto& cell) { expect_monomials_integrated_exactly(cell); });
}

// quad: x^a y^b with a, b <= 2n - 1; triangle: degree <= 2 (tri3), <= 4 (tri6).
TEST(ReferenceFacet, QuadratureIntegratesEveryMonomialUpToItsDegreeExactly) {
  for_every_facet([](const auto& facet) { expect_monomials_integrated_exactly(facet); });
}

TEST(ReferenceCell, QuadratureWeightsArePositiveAndPointsInside) {
  for_every_cell([](const auto& cell) { expect_positive_weights_inside(cell); });
}

TEST(ReferenceFacet, QuadratureWeightsArePositiveAndPointsInside) {
  for_every_facet([](const auto& facet) { expect_positive_weights_inside(facet); });
}

// The consistent mass matrix of an affine cell sums to the cell's volume, equals the one a
// finer, independently built rule gives, and is positive definite; the rows of the linear
// families sum to positive (lumped) masses.
TEST(ReferenceCell, DefaultRuleIntegratesTheMassMatrixOfAnAffineCellExactly) {
  for_every_cell([](const fe::ReferenceCell& cell) {
    const fe::CellNodeCoords X = affine_instance(cell);
    const Real volume = test_map_matrix().determinant() * cell.volume();
    const Eigen::MatrixXd M = mass_matrix(cell, X, cell.rule().points);
    EXPECT_NEAR(M.sum(), volume, 1e-14 * volume);
    const Eigen::MatrixXd fine = mass_matrix(cell, X, fine_rule(domain_of(cell)));
    EXPECT_LE((M - fine).cwiseAbs().maxCoeff(), 1e-14 * volume);
    EXPECT_EQ(M.llt().info(), Eigen::Success);
    for (int a = 0; cell.order() == 1 && a < cell.num_nodes(); ++a)
      EXPECT_GT(M.row(a).sum(), 0.0) << "row " << a;
  });
}

// Patch test of the geometry: on a distorted cell (corners moved, quadratic cells' edges
// curved; det(dx/dxi) > 0 throughout), the field u = G x + c interpolated from the nodes has
// the gradient G at every quadrature point.
TEST(ReferenceCell, LinearFieldsHaveTheirExactGradientOnDistortedCells) {
  for_every_cell([](const fe::ReferenceCell& cell) {
    UniformSource random(17);
    const fe::CellNodeCoords X = distorted_instance(cell, random);
    ASSERT_GT(smallest_jacobian(cell, X), 0.0);
    Mat3 G;
    G << 0.3, -1.2, 0.7, 2.1, 0.4, -0.5, -0.8, 0.9, 1.6;
    const Vec3 c(0.5, -1.0, 2.0);
    const fe::CellNodeCoords u = (X * G.transpose()).rowwise() + c.transpose();
    for (const auto& p : cell.rule().points) {
      const fe::ShapeGrads dN_dxi = cell.shape_grad(p.xi);
      const Mat3 J = X.transpose() * dN_dxi;
      const fe::ShapeGrads dN_dX = dN_dxi * J.inverse();
      const Mat3 grad_u = u.transpose() * dN_dX;
      EXPECT_LE((grad_u - G).norm(), 1e-12 * G.norm());
    }
  });
}

// ---- facets ------------------------------------------------------------------------------

TEST(ReferenceCell, FacetTypesAndCounts) {
  using fe::FacetType;
  const std::array<std::vector<FacetType>, 5> expected = {{
      std::vector<FacetType>(6, FacetType::Quad4), // hex8
      std::vector<FacetType>(4, FacetType::Tri3),  // tet4
      std::vector<FacetType>(4, FacetType::Tri6),  // tet10
      {FacetType::Tri3, FacetType::Tri3, FacetType::Quad4, FacetType::Quad4, FacetType::Quad4},
      std::vector<FacetType>(6, FacetType::Quad8), // hex20
  }};
  for (std::size_t i = 0; i < kAllCellTypes.size(); ++i) {
    SCOPED_TRACE(type_name(kAllCellTypes[i]));
    const fe::ReferenceCell& cell = fe::reference_cell(kAllCellTypes[i]);
    std::vector<FacetType> types;
    std::vector<int> facets_of_node(static_cast<std::size_t>(cell.num_nodes()), 0);
    for (const fe::CellFacet& facet : cell.facets()) {
      types.push_back(facet.type);
      EXPECT_EQ(static_cast<int>(facet.nodes.size()), fe::reference_facet(facet.type).num_nodes());
      for (const int a : facet.nodes) {
        ASSERT_TRUE(a >= 0 && a < cell.num_nodes());
        ++facets_of_node[static_cast<std::size_t>(a)];
      }
    }
    EXPECT_EQ(types, expected[i]);
    // every node of these cells is on the boundary: corners on 3 facets, mid-edge nodes on 2
    for (int a = 0; a < cell.num_nodes(); ++a)
      EXPECT_EQ(facets_of_node[static_cast<std::size_t>(a)], a < corner_count(cell.type()) ? 3 : 2)
          << "node " << a;
  }
}

// The facet's shape functions map it onto the cell's face: at every point of the facet, the
// cell's shape functions equal the facet's at the facet's nodes and vanish at the others; the
// face is flat and the whole cell lies behind it.
TEST(ReferenceCell, FacetsMapOntoTheCellFaces) {
  for_every_cell([](const fe::ReferenceCell& cell) {
    for (const fe::CellFacet& facet : cell.facets()) {
      const fe::ReferenceFacet& reference = fe::reference_facet(facet.type);
      const fe::CellNodeCoords Y = facet_coords(cell, facet);
      UniformSource random(18);
      for (int i = 0; i < 20; ++i) {
        const Vec2 s = random_point<2>(domain_of(reference), random);
        const fe::FacetShapeValues M = reference.shape(s);
        Eigen::VectorXd expected = Eigen::VectorXd::Zero(cell.num_nodes());
        for (std::size_t k = 0; k < facet.nodes.size(); ++k)
          expected[facet.nodes[k]] = M[static_cast<Index>(k)];
        const Vec3 x = Y.transpose() * M;
        EXPECT_LE((cell.shape(x) - expected).cwiseAbs().maxCoeff(), 1e-14);
      }
      const Vec3 n = facet_normal(cell, facet).normalized();
      const Vec3 centre = Y.transpose() * reference.shape(facet_centre(facet.type));
      for (Index k = 0; k < Y.rows(); ++k)
        EXPECT_NEAR(n.dot(Y.row(k).transpose() - centre), 0.0, 1e-14);
      for (int b = 0; b < cell.num_nodes(); ++b)
        EXPECT_LE(n.dot(node(cell, b) - centre), 1e-14) << "node " << b;
    }
  });
}

TEST(ReferenceCell, FacetNormalsPointAwayFromTheCentroid) {
  for_every_cell([](const fe::ReferenceCell& cell) {
    const Vec3 centroid = cell_centroid(cell);
    for (const fe::CellFacet& facet : cell.facets()) {
      const Vec3 centre = facet_coords(cell, facet).transpose() *
                          fe::reference_facet(facet.type).shape(facet_centre(facet.type));
      const Vec3 n = facet_normal(cell, facet);
      EXPECT_GT(n.normalized().dot(centre - centroid), 0.1);
    }
  });
}

// ---- VTK ---------------------------------------------------------------------------------

// VTK's orders (VTK file formats; vtkTetra, vtkHexahedron, vtkWedge, vtkQuadraticTetra,
// vtkQuadraticHexahedron): the normal of the triangle (0,1,2) points to node 3 in a tet, that
// of the quadrilateral (0,1,2,3) to the face (4,5,6,7) in a hex, and out of the cell, away
// from (3,4,5), in a wedge; mid-edge nodes in VTK's edge order.
TEST(ReferenceCell, VtkOrdersPlaceEachNodeWhereVtkExpectsIt) {
  const EdgeList tet10 = {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}};
  const EdgeList hex20 = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                          {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};
  for_every_cell([&](const fe::ReferenceCell& cell) {
    const std::vector<int>& order = cell.vtk_order();
    ASSERT_EQ(static_cast<int>(order.size()), cell.num_nodes());
    std::vector<int> sorted = order;
    std::sort(sorted.begin(), sorted.end());
    for (int a = 0; a < cell.num_nodes(); ++a)
      ASSERT_EQ(sorted[static_cast<std::size_t>(a)], a); // a permutation
    auto X = [&](int k) { return node(cell, order[static_cast<std::size_t>(k)]); };
    const Vec3 base_normal = (X(1) - X(0)).cross(X(2) - X(0));
    const fe::CellType type = cell.type();
    if (type == fe::CellType::Tet4 || type == fe::CellType::Tet10)
      EXPECT_GT(base_normal.dot(X(3) - X(0)), 0.0);
    else if (type == fe::CellType::Penta6)
      EXPECT_LT(base_normal.dot(X(3) - X(0)), 0.0);
    else
      EXPECT_GT(base_normal.dot(X(4) - X(0)), 0.0);
    const EdgeList* edges = type == fe::CellType::Tet10   ? &tet10
                            : type == fe::CellType::Hex20 ? &hex20
                                                          : nullptr;
    const int corners = corner_count(type);
    for (int e = 0; edges && e < static_cast<int>(edges->size()); ++e) {
      const auto& [i, j] = (*edges)[static_cast<std::size_t>(e)];
      EXPECT_EQ(X(corners + e), 0.5 * (X(i) + X(j))) << "VTK node " << corners + e;
    }
  });
}
