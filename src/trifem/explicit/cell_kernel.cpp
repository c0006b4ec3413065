// SPDX-License-Identifier: MIT
#include "trifem/explicit/cell_kernel.hpp"

#include "trifem/explicit/parallel.hpp"
#include "trifem/parallel/communicator.hpp"

#include <cmath>
#include <limits>

namespace trifem::explicit_dynamics {
namespace {

/// The nodal values of a cell as rows, over its slice of a CellVectors (Nodes = 8 for a hex8,
/// Eigen::Dynamic for the other families).
template <int Nodes>
using NodeRows = Eigen::Map<Eigen::Matrix<Real, Nodes, 3, Eigen::RowMajor>>;

/// Quantity codes of a failed cell (index into kQuantities).
enum Quantity : int { kOk = 0, kDetF, kDisplacement, kInternal, kGradient, kPsi, kEnergy };
constexpr const char* kQuantities[] = {"",
                                       "det F",
                                       "displacement",
                                       "internal force Q_V",
                                       "constraint gradient H",
                                       "constraint integral Psi",
                                       "strain energy"};

/// One cell of geometry `geo` (fe::HexGeometry with Nodes = 8, or physics::CellGeometry) at the
/// nodal displacements u, its vectors written to q and h (3 values per node); returns a
/// Quantity code (kOk on success).
template <int Nodes, class Geometry, class Coords>
int evaluate_cell(const Geometry& geo, const Coords& u, const material::ElasticLaw& law,
                  Constraint constraint, const CellRequest& req, Real* q, Real* h, Real& psi,
                  Real& W, Real& dJ, Real& dev) {
  if (!u.allFinite())
    return kDisplacement;
  NodeRows<Nodes> qm(q, u.rows(), 3), hm(h, u.rows(), 3);
  if (req.internal)
    qm.setZero();
  if (req.gradient)
    hm.setZero();
  if (req.psi)
    psi = 0.0;
  W = dJ = dev = 0.0;
  Real volume = 0.0;
  for (std::size_t q_point = 0; q_point < geo.dV.size(); ++q_point) {
    const auto& g = geo.dN_dX[q_point];
    const Real dV = geo.dV[q_point];
    const Mat3 F = Mat3::Identity() + u.transpose() * g;
    const Real J = F.determinant();
    if (!(J > 0.0))
      return std::isfinite(J) ? kDetF : kDisplacement;
    dev = std::max(dev, std::abs(J - 1.0));
    dJ += (J - 1.0) * dV;
    volume += dV;
    const bool jm1 = constraint == Constraint::JMinusOne;
    if (req.internal || req.energy) {
      const Mat3 C = F.transpose() * F;
      if (req.internal)
        qm.noalias() += g * (F * law.stress(C)).transpose() * dV;
      if (req.energy)
        W += law.energy(C) * dV;
    }
    if (req.gradient)
      hm.noalias() += g * ((jm1 ? J : 1.0) * F.inverse().transpose()).transpose() * dV;
    if (req.psi)
      psi += (jm1 ? J - 1.0 : std::log(J)) * dV;
  }
  dJ /= volume;
  if (req.internal && !qm.allFinite())
    return kInternal;
  if (req.gradient && !hm.allFinite())
    return kGradient;
  if (req.psi && !std::isfinite(psi))
    return kPsi;
  if (req.energy && !std::isfinite(W))
    return kEnergy;
  return kOk;
}

/// evaluate_cell on cell c of `model` at the displacement U.
int evaluate_cell(const ExplicitView& model, Index c, Constraint constraint, const Vector& U,
                  const CellRequest& req, Real* q, Real* h, Real& psi, Real& W, Real& dJ,
                  Real& dev) {
  const material::ElasticLaw& law = model.law(c);
  if (const auto* hex = std::get_if<fe::HexGeometry>(&model.geometry()[c]))
    return evaluate_cell<8>(*hex, model.hex8_values(c, U), law, constraint, req, q, h, psi, W, dJ,
                            dev);
  return evaluate_cell<Eigen::Dynamic>(std::get<physics::CellGeometry>(model.geometry()[c]),
                                       model.node_values(c, U), law, constraint, req, q, h, psi, W,
                                       dJ, dev);
}

/// The cell scalars of evaluate_cells whole on every process: each process's own cells, the
/// others taken as 0, summed over the processes in one sum.
void sum_cell_scalars(const ExplicitView& model, const CellRequest& request, CellFields& out) {
  std::vector<Vector*> parts = {&out.volume_change, &out.gauss_volume_change};
  if (request.psi)
    parts.push_back(&out.psi);
  if (request.energy)
    parts.push_back(&out.energy);
  const Index n = model.num_cells();
  Vector all(n * static_cast<Index>(parts.size()));
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (Index c = 0; c < n; ++c)
      all[static_cast<Index>(i) * n + c] = model.owns_cell(c) ? (*parts[i])[c] : 0.0;
  parallel::sum(all);
  for (std::size_t i = 0; i < parts.size(); ++i)
    *parts[i] = all.segment(static_cast<Index>(i) * n, n);
}

} // namespace

void CellFields::resize(const ExplicitView& model) {
  const Index n = model.num_cells();
  internal.resize(model.cell_offsets().back());
  gradient.resize(model.cell_offsets().back());
  psi.resize(n);
  energy.resize(n);
  volume_change.resize(n);
  gauss_volume_change.resize(n);
}

CellStatus evaluate_cells(const ExplicitView& model, Constraint constraint, const Vector& U,
                          const CellRequest& request, CellFields& out) {
  const Index n = model.num_cells();
  if (out.internal.size() != model.cell_offsets().back() || out.psi.size() != n)
    out.resize(model);
  const std::vector<Index>& offsets = model.cell_offsets();
  Index first_bad = n; // none
#pragma omp parallel for schedule(static) reduction(min : first_bad) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.evaluates(c))
      continue;
    const Index begin = offsets[c], size = offsets[c + 1] - begin;
    if (!model.deformable(c)) { // moves rigidly: no forces, no strain
      out.internal.segment(begin, size).setZero();
      out.gradient.segment(begin, size).setZero();
      out.psi[c] = out.energy[c] = out.volume_change[c] = out.gauss_volume_change[c] = 0.0;
      continue;
    }
    Real W = 0.0;
    const int code =
        evaluate_cell(model, c, constraint, U, request, &out.internal[begin], &out.gradient[begin],
                      out.psi[c], W, out.volume_change[c], out.gauss_volume_change[c]);
    if (request.energy)
      out.energy[c] = W;
    if (code != kOk)
      first_bad = std::min(first_bad, c);
  }
  if (model.distributed()) {
    sum_cell_scalars(model, request, out);
    for (const Real bad : parallel::gather(static_cast<Real>(first_bad)))
      first_bad = std::min(first_bad, static_cast<Index>(bad));
  }
  if (first_bad == n)
    return {};
  // Re-evaluate the first failing cell serially to name the quantity (deterministic; every
  // process holds every cell).
  physics::CellVectorX q(offsets[first_bad + 1] - offsets[first_bad]), h(q.size());
  Real psi = 0.0, W = 0.0, dJ = 0.0, dev = 0.0;
  const int code =
      evaluate_cell(model, first_bad, constraint, U, request, q.data(), h.data(), psi, W, dJ, dev);
  const CellFailure failure =
      code == kDetF ? CellFailure::NegativeJacobian : CellFailure::NonFinite;
  return {failure, first_bad, kQuantities[code]};
}

void gather(const ExplicitView& model, const CellVectors& v, const Vector* weights, Vector& y) {
  const NodeIncidence& inc = model.incidence();
  const std::vector<Index>& offsets = model.cell_offsets();
  const Index nn = model.mesh().num_nodes();
  y.resize(3 * nn);
#pragma omp parallel for schedule(static) if (nn >= kMinParallelLoop)
  for (Index a = 0; a < nn; ++a) {
    if (!model.owns_node(a)) {
      y.segment<3>(3 * a).setZero();
      continue;
    }
    Vec3 sum = Vec3::Zero();
    for (Index i = inc.offsets[a]; i < inc.offsets[a + 1]; ++i) {
      const auto [c, l] = inc.entries[i];
      sum += (weights ? (*weights)[c] : 1.0) * v.segment<3>(offsets[c] + 3 * l);
    }
    y.segment<3>(3 * a) = sum;
  }
  if (model.distributed())
    parallel::sum(y);
}

void cell_dot(const ExplicitView& model, const CellVectors& v, const Vector& x, Vector& z) {
  const Index n = model.num_cells();
  const std::vector<Index>& offsets = model.cell_offsets();
  z.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    const std::span<const Index> nodes = model.mesh().cell_nodes(c);
    Real s = 0.0;
    if (model.owns_cell(c))
      for (std::size_t a = 0; a < nodes.size(); ++a)
        s += v.segment<3>(offsets[c] + 3 * static_cast<Index>(a)).dot(x.segment<3>(3 * nodes[a]));
    z[c] = s;
  }
  if (model.distributed())
    parallel::sum(z);
}

} // namespace trifem::explicit_dynamics
