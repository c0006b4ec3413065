// SPDX-License-Identifier: MIT
#include "trifem/assembly/fe_problem.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>

namespace trifem::assembly {
namespace {

/// Colours with fewer elements are assembled by one thread (a parallel region costs more).
constexpr Index kMinParallelElements = 32;

/// The entry of `row` in the sorted row indices [from, end) of a column whose pattern contains
/// it, found by galloping forward from `from`: the rows of an element are scattered in
/// ascending order, so consecutive ones are usually a few entries apart (a node's DOFs are
/// consecutive equations).
inline const Index* find_row(const Index* from, const Index* end, Index row) {
  std::ptrdiff_t step = 1;
  const Index* lo = from;
  while (lo + step < end && lo[step] <= row) {
    lo += step;
    step *= 2;
  }
  const Index* it = std::lower_bound(lo, std::min(lo + step, end), row);
  TRIFEM_ASSERT(it != end && *it == row, "row {} is not in the pattern", row);
  return it;
}

/// Thread-private buffers of one element evaluation.
struct Scratch {
  physics::LocalVector r;
  physics::LocalMatrix K;
  dofs::CondensedElement condensed; ///< r and K on the rigid bodies' unknowns
  dofs::CondensedElement at_start;  ///< r condensed at the step's start (old projection)
  std::vector<Index> rows;          ///< equation of each local DOF (-1: constrained)
  std::vector<Index> order;         ///< the local DOFs with an equation, by ascending equation
};

/// Rotates an element contribution to the local frames of its rotated nodal DOFs:
/// r_i <- Q^T r_i for every rotated triple i, K <- T^T K T (T block-diagonal with the Q).
void rotate(const dofs::NodalFrames& frames, std::span<const Index> dofs, Scratch& s,
            bool with_jacobian) {
  const Index n = static_cast<Index>(dofs.size());
  for (Index i = 0; i < n; ++i) {
    const int f = frames.frame_of(dofs[i]);
    if (f < 0)
      continue;
    const dofs::NodalFrame& frame = frames.frames()[f];
    if (dofs[i] != frame.dofs[0])
      continue; // handle each triple once, from its first DOF
    std::array<Index, 3> at{};
    for (int k = 0; k < 3; ++k) {
      const auto it = std::find(dofs.begin(), dofs.end(), frame.dofs[k]);
      TRIFEM_VERIFY(it != dofs.end(), "an element holds part of a rotated triple");
      at[k] = static_cast<Index>(it - dofs.begin());
    }
    const Mat3 Qt = frame.Q.transpose();
    const Vec3 r(s.r[at[0]], s.r[at[1]], s.r[at[2]]);
    const Vec3 rl = Qt * r;
    for (int k = 0; k < 3; ++k)
      s.r[at[k]] = rl[k];
    if (!with_jacobian)
      continue;
    const Eigen::Map<const Eigen::Array<Index, 3, 1>> idx(at.data());
    Eigen::MatrixXd rows = s.K(idx, Eigen::all);
    s.K(idx, Eigen::all) = Qt * rows;
    Eigen::MatrixXd cols = s.K(Eigen::all, idx);
    s.K(Eigen::all, idx) = cols * frame.Q;
  }
}

/// Adds an element tangent K on `dofs` (none dependent) to the system. Each column is added
/// along the matrix column in one forward walk, its rows taken in ascending order.
void scatter_jacobian(const dofs::DofMap& map, std::span<const Index> dofs,
                      const physics::LocalMatrix& K, Scratch& s, AssembledSystem& out) {
  const Index n = static_cast<Index>(dofs.size());
  s.rows.resize(n);
  s.order.clear();
  for (Index i = 0; i < n; ++i) {
    s.rows[i] = map.equation(dofs[i]);
    if (s.rows[i] >= 0)
      s.order.push_back(i);
  }
  std::sort(s.order.begin(), s.order.end(),
            [&](Index a, Index b) { return s.rows[a] < s.rows[b]; });
  for (Index j = 0; j < n; ++j) {
    const Index eq = s.rows[j];
    SparseMatrix& A = eq >= 0 ? out.Kff : out.Kfc;
    const Index col = eq >= 0 ? eq : map.constrained_index(dofs[j]);
    const Index* inner = A.innerIndexPtr();
    const Index* at = inner + A.outerIndexPtr()[col];
    const Index* end = inner + A.outerIndexPtr()[col + 1];
    Real* values = A.valuePtr();
    for (Index i : s.order) {
      const Real v = K(i, j);
      if (v == 0.0)
        continue;
      at = find_row(at, end, s.rows[i]);
      values[at - inner] += v;
    }
  }
}

/// Adds the element residual and tangent to the system. The residual of DOFs that follow a
/// rigid body stays at them (the force on the node) and its condensation goes to the body's
/// unknowns, with the condensed tangent.
/// A share `old_share` = σ of the condensation is taken at the step's start:
/// (1 − σ) Λ(x)ᵀ r + σ Λ(x_old)ᵀ r, with the Jacobian (1 − σ)(Λ(x)ᵀ K Λ(x) + G) + σ Λ(x_old)ᵀ K
/// Λ(x).
void scatter(const dofs::DofMap& map, const dofs::RigidMap* rigid, const physics::EvalState& state,
             std::span<const Index> dofs, Scratch& s, AssembledSystem& out, bool with_jacobian,
             Real old_share) {
  const Index n = static_cast<Index>(dofs.size());
  for (Index i = 0; i < n; ++i)
    out.residual[dofs[i]] += s.r[i];
  if (rigid && rigid->condense(dofs, state.x, s.r, with_jacobian ? &s.K : nullptr, s.condensed)) {
    auto& condensed = s.condensed;
    if (old_share != 0.0) {
      rigid->condense(dofs, state.x_old, s.r, nullptr, s.at_start);
      condensed.residual = (1.0 - old_share) * condensed.residual + old_share * s.at_start.residual;
      if (with_jacobian)
        condensed.jacobian = (1.0 - old_share) * condensed.jacobian +
                             old_share * s.at_start.lambda.transpose() * s.K * condensed.lambda;
    }
    for (Index i = condensed.first_body_dof; i < static_cast<Index>(condensed.dofs.size()); ++i)
      out.residual[condensed.dofs[i]] += condensed.residual[i];
    if (with_jacobian)
      scatter_jacobian(map, condensed.dofs, condensed.jacobian, s, out);
    return;
  }
  if (with_jacobian)
    scatter_jacobian(map, dofs, s.K, s, out);
}

/// The elements of `stencils` that process `rank` assembles: those whose first equation it
/// owns, and on rank 0 those without an equation (all DOFs prescribed: reactions only).
std::vector<Index> owned_elements(const Stencils& stencils, const dofs::DofMap& map,
                                  const std::vector<int>& equation_owner, int rank) {
  std::vector<Index> mine;
  for (Index e = 0; e < stencils.size(); ++e) {
    int owner = 0;
    for (Index d : stencils.of(e))
      if (const Index eq = map.equation(d); eq >= 0) {
        owner = equation_owner[eq];
        break;
      }
    if (owner == rank)
      mine.push_back(e);
  }
  return mine;
}

/// The stencils of the elements `which` of `stencils`, renumbered 0, 1, ...
Stencils subset(const Stencils& stencils, const std::vector<Index>& which) {
  Stencils s;
  s.offsets.reserve(which.size() + 1);
  s.offsets.push_back(0);
  for (Index e : which) {
    const auto dofs = stencils.of(e);
    s.dofs.insert(s.dofs.end(), dofs.begin(), dofs.end());
    s.offsets.push_back(static_cast<Index>(s.dofs.size()));
  }
  return s;
}

/// The stencils of `stencils` after condensation onto the rigid bodies' unknowns.
Stencils condense(const Stencils& stencils, const dofs::RigidMap& rigid) {
  Stencils out;
  out.offsets.reserve(stencils.offsets.size());
  out.offsets.push_back(0);
  std::vector<Index> dofs;
  for (Index e = 0; e < stencils.size(); ++e) {
    rigid.expand(stencils.of(e), dofs);
    out.dofs.insert(out.dofs.end(), dofs.begin(), dofs.end());
    out.offsets.push_back(static_cast<Index>(out.dofs.size()));
  }
  return out;
}

} // namespace

Assembler::Assembler(const dofs::DofMap& map, std::vector<const physics::Term*> terms,
                     const dofs::NodalFrames* frames, bool awaits_ownership,
                     const dofs::RigidMap* rigid)
    : map_(map), terms_(std::move(terms)), frames_(frames),
      rigid_(rigid && !rigid->empty() ? rigid : nullptr), awaits_ownership_(awaits_ownership) {
  TRIFEM_VERIFY(map.finalized(), "the DOF map must be finalized before assembly");
  rebuild();
}

void Assembler::set_ownership(std::vector<int> equation_owner, int rank) {
  equation_owner_ = std::move(equation_owner);
  rank_ = rank;
  awaits_ownership_ = false;
  rebuild();
}

void Assembler::rebuild() {
  stencils_.clear();
  condensed_.clear();
  colours_.clear();
  owned_.clear();
  pattern_built_ = false;
  pattern_ = {};
  for (const physics::Term* t : terms_) {
    stencils_.push_back(collect_stencils(*t));
    if (rigid_)
      condensed_.push_back(condense(stencils_.back(), *rigid_));
    const Stencils& coupled = rigid_ ? condensed_.back() : stencils_.back();
    if (awaits_ownership_)
      continue;
    if (equation_owner_.empty()) {
      colours_.push_back(colour_elements(coupled, map_));
      continue;
    }
    const std::vector<Index> mine = owned_elements(coupled, map_, equation_owner_, rank_);
    owned_.push_back(subset(coupled, mine));
    std::vector<std::vector<Index>> colours = colour_elements(owned_.back(), map_);
    for (auto& colour : colours)
      for (Index& e : colour)
        e = mine[e];
    colours_.push_back(std::move(colours));
  }
}

void Assembler::build_pattern_once() {
  TRIFEM_VERIFY(!awaits_ownership_, "the pattern of a parallel run needs the equation owners");
  if (pattern_built_)
    return;
  std::vector<const Stencils*> sets;
  for (const auto& s : !equation_owner_.empty() ? owned_ : rigid_ ? condensed_ : stencils_)
    sets.push_back(&s);
  pattern_ = build_pattern(map_, sets);
  pattern_built_ = true;
}

SparseMatrix Assembler::body_couplings() const {
  std::vector<const Stencils*> sets;
  for (std::size_t t = 0; t < terms_.size(); ++t)
    if (!terms_[t]->joins_bodies())
      sets.push_back(rigid_ ? &condensed_[t] : &stencils_[t]);
  return build_pattern(map_, sets).Kff;
}

AssembledSystem Assembler::make_system() {
  build_pattern_once();
  return {Vector::Zero(map_.num_dofs()), pattern_.Kff, pattern_.Kfc};
}

AssembledSystem Assembler::take_system() {
  build_pattern_once();
  AssembledSystem system{Vector::Zero(map_.num_dofs()), {}, {}};
  system.Kff.swap(pattern_.Kff);
  system.Kfc.swap(pattern_.Kfc);
  pattern_built_ = false;
  return system;
}

bool Assembler::assemble_term(std::size_t t, const physics::EvalState& state, AssembledSystem& out,
                              bool with_jacobian) const {
  const physics::Term& term = *terms_[t];
  const Stencils& stencils = stencils_[t];
  const Real weight = weights_.empty() ? 1.0 : weights_[t];
  const Real old_share = old_projection_.empty() ? 0.0 : old_projection_[t];
  bool admissible = true;
  for (const auto& colour : colours_[t]) {
    const Index count = static_cast<Index>(colour.size());
#pragma omp parallel reduction(&& : admissible) if (count >= kMinParallelElements)
    {
      Scratch s;
#pragma omp for schedule(static)
      for (Index k = 0; k < count; ++k) {
        const Index e = colour[k];
        if (!term.evaluate(e, state, s.r, with_jacobian ? &s.K : nullptr)) {
          admissible = false;
          continue;
        }
        if (weight != 1.0) {
          s.r *= weight;
          if (with_jacobian)
            s.K *= weight;
        }
        if (frames_ && !frames_->empty())
          rotate(*frames_, stencils.of(e), s, with_jacobian);
        scatter(map_, rigid_, state, stencils.of(e), s, out, with_jacobian, old_share);
      }
    }
  }
  return admissible;
}

bool Assembler::assemble(const physics::EvalState& state, AssembledSystem& out,
                         bool with_jacobian) const {
  out.residual.setZero(map_.num_dofs());
  if (with_jacobian) {
    out.Kff.coeffs().setZero();
    out.Kfc.coeffs().setZero();
  }
  bool admissible = true;
  for (std::size_t t = 0; t < terms_.size() && admissible; ++t)
    if (weights_.empty() || weights_[t] != 0.0)
      admissible = assemble_term(t, state, out, with_jacobian);
  return admissible;
}

void Assembler::set_weights(std::vector<Real> weights) {
  TRIFEM_VERIFY(weights.empty() || weights.size() == terms_.size(), "one weight per term");
  weights_ = std::move(weights);
}

void Assembler::set_old_projection(std::vector<Real> shares) {
  TRIFEM_VERIFY(shares.empty() || shares.size() == terms_.size(), "one share per term");
  old_projection_ = std::move(shares);
}

} // namespace trifem::assembly
