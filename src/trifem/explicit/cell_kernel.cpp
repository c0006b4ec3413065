// SPDX-License-Identifier: MIT
#include "trifem/explicit/cell_kernel.hpp"

#include "trifem/explicit/parallel.hpp"
#include "trifem/parallel/communicator.hpp"

#include <cmath>
#include <limits>

namespace trifem::explicit_dynamics {
namespace {

using RowMajor83 = Eigen::Matrix<Real, 8, 3, Eigen::RowMajor>;

/// Quantity codes of a failed cell (index into kQuantities).
enum Quantity : int { kOk = 0, kDetF, kDisplacement, kInternal, kGradient, kPsi, kEnergy };
constexpr const char* kQuantities[] = {"",
                                       "det F",
                                       "displacement",
                                       "internal force Q_V",
                                       "constraint gradient H",
                                       "constraint integral Psi",
                                       "strain energy"};

/// One cell; returns a Quantity code (kOk on success).
int evaluate_cell(const fe::HexGeometry& geo, const fe::HexCoords& u,
                  const material::ElasticLaw& law, Constraint constraint, const CellRequest& req,
                  CellVector& q, CellVector& h, Real& psi, Real& W, Real& dJ, Real& dev) {
  if (!u.allFinite())
    return kDisplacement;
  Eigen::Map<RowMajor83> qm(q.data()), hm(h.data());
  if (req.internal)
    qm.setZero();
  if (req.gradient)
    hm.setZero();
  if (req.psi)
    psi = 0.0;
  W = dJ = dev = 0.0;
  Real volume = 0.0;
  for (int q_point = 0; q_point < 8; ++q_point) {
    const fe::HexShapeGrad& g = geo.dN_dX[q_point];
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
  if (req.internal && !q.allFinite())
    return kInternal;
  if (req.gradient && !h.allFinite())
    return kGradient;
  if (req.psi && !std::isfinite(psi))
    return kPsi;
  if (req.energy && !std::isfinite(W))
    return kEnergy;
  return kOk;
}

/// The cell scalars of evaluate_cells whole on every process: each process's own cells, the
/// others taken as 0, summed over the processes in one sum.
void sum_cell_scalars(const ExplicitModel& model, const CellRequest& request, CellFields& out) {
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

void CellFields::resize(Index n) {
  internal.resize(n);
  gradient.resize(n);
  psi.resize(n);
  energy.resize(n);
  volume_change.resize(n);
  gauss_volume_change.resize(n);
}

CellStatus evaluate_cells(const ExplicitModel& model, Constraint constraint, const Vector& U,
                          const CellRequest& request, CellFields& out) {
  const Index n = model.num_cells();
  if (static_cast<Index>(out.internal.size()) != n)
    out.resize(n);
  Index first_bad = n; // none
#pragma omp parallel for schedule(static) reduction(min : first_bad) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    if (!model.evaluates(c))
      continue;
    if (!model.deformable(c)) { // moves rigidly: no forces, no strain
      out.internal[c].setZero();
      out.gradient[c].setZero();
      out.psi[c] = out.energy[c] = out.volume_change[c] = out.gauss_volume_change[c] = 0.0;
      continue;
    }
    Real W = 0.0;
    const int code = evaluate_cell(model.geometry()[c], model.cell_values(c, U), model.law(c),
                                   constraint, request, out.internal[c], out.gradient[c],
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
  CellVector q, h;
  Real psi = 0.0, W = 0.0, dJ = 0.0, dev = 0.0;
  const int code = evaluate_cell(model.geometry()[first_bad], model.cell_values(first_bad, U),
                                 model.law(first_bad), constraint, request, q, h, psi, W, dJ, dev);
  const CellFailure failure =
      code == kDetF ? CellFailure::NegativeJacobian : CellFailure::NonFinite;
  return {failure, first_bad, kQuantities[code]};
}

void gather(const ExplicitModel& model, const std::vector<CellVector>& v, const Vector* weights,
            Vector& y) {
  const NodeIncidence& inc = model.incidence();
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
      sum += (weights ? (*weights)[c] : 1.0) * v[c].segment<3>(3 * l);
    }
    y.segment<3>(3 * a) = sum;
  }
  if (model.distributed())
    parallel::sum(y);
}

void cell_dot(const ExplicitModel& model, const std::vector<CellVector>& v, const Vector& x,
              Vector& z) {
  const Index n = model.num_cells();
  z.resize(n);
#pragma omp parallel for schedule(static) if (n >= kMinParallelLoop)
  for (Index c = 0; c < n; ++c) {
    const mesh::Hex8& nodes = model.mesh().cell(c);
    Real s = 0.0;
    if (model.owns_cell(c))
      for (int a = 0; a < 8; ++a)
        s += v[c].segment<3>(3 * a).dot(x.segment<3>(3 * nodes[a]));
    z[c] = s;
  }
  if (model.distributed())
    parallel::sum(z);
}

} // namespace trifem::explicit_dynamics
