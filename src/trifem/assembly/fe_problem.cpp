// SPDX-License-Identifier: MIT
#include "trifem/assembly/fe_problem.hpp"

#include "trifem/core/error.hpp"
#include "trifem/linalg/nested_dissection.hpp"
#include "trifem/parallel/communicator.hpp"

#include <algorithm>
#include <cmath>

namespace trifem::assembly {

FeProblem::FeProblem(dofs::DofMap map, std::vector<dofs::DirichletCondition> conditions,
                     std::vector<std::unique_ptr<physics::Term>> terms,
                     std::vector<solver::FieldScale> scales, dofs::NodalFrames frames,
                     dofs::RigidMap rigid)
    : map_(std::move(map)), conditions_(std::move(conditions)), terms_(std::move(terms)),
      scales_(std::move(scales)), frames_(std::move(frames)), rigid_(std::move(rigid)) {
  TRIFEM_VERIFY(static_cast<int>(scales_.size()) == map_.num_fields(), "one scale per field");
  for (Index d = 0; d < map_.num_dofs() && !rigid_.empty(); ++d)
    TRIFEM_VERIFY((rigid_.body_of(d) >= 0) == map_.is_dependent(d) &&
                      (rigid_.body_of(d) < 0 || frames_.frame_of(d) < 0),
                  "DOF {}: the followers of rigid bodies must be the dependent DOFs, in no "
                  "rotated frame",
                  d);
  build_assembler();
  x_ = x_old_ = saved_ = target_ = Vector::Zero(map_.num_dofs());
  dofs::prescribed_values(conditions_, time_, x_);
  x_old_ = target_ = x_;
  sync();
  x_old_global_ = x_global_;
}

void FeProblem::set_node_positions(dofs::FieldId displacement, std::vector<Vec3> positions) {
  TRIFEM_VERIFY(displacement.valid() &&
                    map_.field(displacement).num_entities == static_cast<Index>(positions.size()),
                "one position per node of the displacement field");
  displacement_ = displacement;
  node_positions_ = std::move(positions);
}

std::vector<Vector> FeProblem::rigid_body_modes() const {
  if (!displacement_.valid() || map_.field(displacement_).components != 3)
    return {};
  Vec3 centre = Vec3::Zero(); // rotations about the centroid keep the modes well scaled
  for (const Vec3& x : node_positions_)
    centre += x;
  centre /= std::max<Real>(1.0, static_cast<Real>(node_positions_.size()));
  std::vector<Vector> modes;
  for (int mode = 0; mode < 6; ++mode) {
    Vector all = Vector::Zero(map_.num_dofs()); // global components at every DOF
    for (Index node = 0; node < static_cast<Index>(node_positions_.size()); ++node) {
      const Vec3 r = node_positions_[node] - centre;
      const Vec3 motion = mode < 3 ? Vec3(Vec3::Unit(mode)) : Vec3(Vec3::Unit(mode - 3).cross(r));
      for (int c = 0; c < 3; ++c)
        all[map_.dof(displacement_, node, c)] = motion[c];
    }
    for (const dofs::RigidBodyDofs& body : rigid_.bodies()) { // u_c and Θ of the motion
      const Vec3 rotation = mode < 3 ? Vec3::Zero() : Vec3(Vec3::Unit(mode - 3));
      const Vec3 motion = mode < 3 ? Vec3(Vec3::Unit(mode)) : rotation.cross(body.centre - centre);
      for (int c = 0; c < 3; ++c) {
        all[body.translation[c]] = motion[c];
        all[body.rotation[c]] = rotation[c];
      }
    }
    frames_.to_local(all);
    Vector mode_vector = Vector::Zero(map_.num_equations());
    for (Index dof = 0; dof < map_.num_dofs(); ++dof)
      if (const Index eq = map_.equation(dof);
          eq >= 0 && map_.leader(dof) == dof &&
          (map_.field_of(dof) == displacement_ ||
           map_.field(map_.field_of(dof)).role == FieldRole::rigid_motion))
        mode_vector[eq] = all[dof];
    modes.push_back(std::move(mode_vector));
  }
  return modes;
}

void FeProblem::to_equations(const physics::CellTransport& cell, Real weight,
                             linalg::TransportCell& out) const {
  const auto equation = [&](Index dof) { return dof >= 0 ? map_.equation(dof) : Index(-1); };
  for (int i = 0; i < 2; ++i)
    out.potential[i] = equation(cell.potential[i]);
  out.divergence.setZero();
  out.flux_rate.setZero();
  for (int a = 0; a < 8; ++a)
    for (int field = 0; field < cell.flux_dof.cols(); ++field) {
      const Vec3 g = cell.area.row(a).transpose();
      for (int k = 0; k < 3; ++k) {
        const Index dof = cell.flux_dof(3 * a + k, field);
        out.flux_equation(3 * a + k, field) = equation(dof);
        // in a rotated frame (global = Q local) the local component k enters v · Q e_k, for
        // the area vector as for the rates of the equations of node a
        Vec3 axis = Vec3::Unit(k);
        if (const int frame = dof >= 0 ? frames_.frame_of(dof) : -1; frame >= 0) {
          const dofs::NodalFrame& f = frames_.frames()[frame];
          axis = f.Q.col(std::find(f.dofs.begin(), f.dofs.end(), dof) - f.dofs.begin());
        }
        out.divergence(3 * a + k, field) = g.dot(axis);
        for (int other = 0; other < 3; ++other)
          out.flux_rate(3 * a + k, 3 * field + other) =
              weight * cell.flux_rate.block<3, 1>(3 * a, 3 * field + other).dot(axis);
      }
    }
  out.coupling = weight * cell.coupling;
  out.friction = weight * cell.friction; // the flux block is m_ab ⊗ friction: m unweighted
  out.gamma = weight * cell.gamma;
  out.node = cell.node;
  out.lumped_mass = cell.lumped_mass;
}

linalg::TransportCells FeProblem::transport_cells() const {
  if (parallel::active()) // each process holds only its part of the matrix
    return {};
  std::vector<physics::CellTransport> cells;
  for (const auto& t : terms_)
    t->transport_cells(eval_state(), cells);
  // a dynamic step weights the Jacobian of every term but the inertia by 1 − α_f
  const Real weight = dynamic_ ? 1.0 - inertia_->method().alpha_f : 1.0;
  linalg::TransportCells out(cells.size());
  for (std::size_t c = 0; c < cells.size(); ++c)
    to_equations(cells[c], weight, out[c]);
  return out;
}

void FeProblem::reclaim_jacobian(solver::Linearization& lin) {
  if (!jacobian_lent_)
    return;
  jacobian_lent_ = false;
  const SparseMatrix& lent = lin.jacobian;
  if (lin.lender == this && lin.lent_pattern == pattern_id_ &&
      lent.rows() == map_.num_equations() && lent.cols() == map_.num_equations() &&
      lent.nonZeros() == lent_nonzeros_ && lent.isCompressed()) {
    system_.Kff.swap(lin.jacobian);
    lin.lender = nullptr;
    return;
  }
  // lent to a linearization that is gone: the same pattern once more (from the stencils, which
  // have not changed)
  system_ = assembler_->take_system();
}

void FeProblem::build_assembler() {
  equation_fields_.resize(map_.num_equations());
  for (Index eq = 0; eq < map_.num_equations(); ++eq)
    equation_fields_[eq] = map_.field_of(map_.dof_of_equation(eq)).index;
  std::vector<const physics::Term*> views;
  for (const auto& t : terms_)
    views.push_back(t.get());
  // on several processes the whole pattern is never built: each builds its part once the
  // equations are split (partition)
  assembler_ =
      std::make_unique<Assembler>(map_, std::move(views), &frames_, parallel::active(), &rigid_);
  apply_weights();
  partition();
  reset_system();
}

std::vector<FieldRole> FeProblem::field_roles() const {
  std::vector<FieldRole> roles;
  for (int f = 0; f < map_.num_fields(); ++f)
    roles.push_back(map_.field(dofs::FieldId{f}).role);
  return roles;
}

std::string FeProblem::equation_name(Index eq) const {
  const Index dof = map_.dof_of_equation(eq);
  const dofs::FieldInfo& f = map_.field(map_.field_of(dof));
  const Index local = dof - f.offset;
  const char* entity = f.role == FieldRole::potential      ? "cell"
                       : f.role == FieldRole::multiplier   ? "slave node"
                       : f.role == FieldRole::rigid_motion ? "body"
                                                           : "node";
  return fmt::format("component {} of {} {} (0-based, in trifem's order) of the field '{}'",
                     local % f.components, entity, local / f.components, f.name);
}

void FeProblem::reset_system() {
  system_ = AssembledSystem{Vector::Zero(map_.num_dofs()), {}, {}};
  pattern_pending_ = true;
  jacobian_lent_ = false;
  ++pattern_id_;
}

void FeProblem::partition() {
  equation_owner_.clear();
  if (!parallel::active())
    return;
  equation_owner_.assign(map_.num_equations(), 0);
  if (parallel::is_root()) {
    const SparseMatrix K = assembler_->body_couplings(); // bodies may be cut at contacts
    equation_owner_ = linalg::partition_rows(
        {static_cast<Index>(K.rows()), K.outerIndexPtr(), K.innerIndexPtr()}, parallel::size());
  }
  parallel::broadcast(equation_owner_);
  assembler_->set_ownership(equation_owner_, parallel::rank());
}

void FeProblem::set_conditions(std::vector<dofs::DirichletCondition> conditions) {
  conditions_ = std::move(conditions);
  map_.reset_constraints();
  dofs::constrain_all(conditions_, map_);
  map_.finalize();
  build_assembler();
  target_ = x_;
  dofs::prescribed_values(conditions_, time_, target_);
}

void FeProblem::add_term(std::unique_ptr<physics::Term> term) {
  terms_.push_back(std::move(term));
  build_assembler();
}

void FeProblem::add_inertia(std::unique_ptr<physics::InertiaTerm> inertia) {
  TRIFEM_VERIFY(inertia_ == nullptr, "the problem has an inertia term already");
  inertia_ = inertia.get();
  add_term(std::move(inertia));
}

void FeProblem::apply_weights() {
  if (!inertia_) {
    assembler_->set_weights({});
    return;
  }
  const Real alpha_f = inertia_->method().alpha_f;
  const Real others = dynamic_ ? 1.0 - alpha_f : 1.0;
  std::vector<Real> weights, old_projection;
  for (const auto& t : terms_) {
    weights.push_back(t.get() == inertia_ ? (dynamic_ ? 1.0 : 0.0) : others);
    // the inertia of rigid bodies' nodes is projected at both ends of the step, as the other
    // terms' residual is weighted: (1 − α_f) Λ(x_{n+1})ᵀ + α_f Λ(x_n)ᵀ
    old_projection.push_back(t.get() == inertia_ && dynamic_ && !rigid_.empty() ? alpha_f : 0.0);
  }
  assembler_->set_weights(std::move(weights));
  assembler_->set_old_projection(std::move(old_projection));
}

void FeProblem::set_dynamic(bool dynamic, bool start, const Vector& velocity) {
  TRIFEM_VERIFY(!dynamic || inertia_ != nullptr, "a dynamic step needs the inertia term");
  if (dynamic && !dynamic_ && start)
    start_motion(velocity);
  if (dynamic && !dynamic_) // the support forces of the state the step starts from
    committed_residual_ = system_.residual;
  dynamic_ = dynamic;
  apply_weights();
}

Vector FeProblem::velocity() const {
  if (!dynamic_)
    return {};
  Vector v = Vector::Zero(map_.num_dofs());
  for (std::size_t i = 0; i < inertia_->dofs().size(); ++i)
    v[inertia_->dofs()[i]] = inertia_->velocity()[static_cast<Index>(i)];
  return v;
}

Vector FeProblem::static_residual() {
  std::vector<Real> weights;
  for (const auto& t : terms_)
    weights.push_back(t.get() == inertia_ ? 0.0 : 1.0);
  assembler_->set_weights(std::move(weights));
  AssembledSystem out;
  const bool admissible = parallel::all(assembler_->assemble(eval_state(), out, false));
  apply_weights();
  TRIFEM_VERIFY(admissible, "the static residual of an accepted state is inadmissible");
  parallel::sum(out.residual);
  return out.residual;
}

void FeProblem::sync() {
  rigid_.apply(x_);
  x_global_ = x_;
  frames_.to_global(x_global_);
}

void FeProblem::set_state(const Vector& x) {
  TRIFEM_VERIFY(x.size() == map_.num_dofs(), "state size mismatch");
  x_ = x;
  frames_.to_local(x_);
  rigid_.apply(x_);
  x_old_ = target_ = x_;
  sync();
  x_old_global_ = x_global_;
}

solver::SolveStatus FeProblem::linearize(solver::Linearization& lin, bool with_jacobian) {
  bool changed = false;
  for (auto& t : terms_)
    changed = t->prepare(eval_state()) || changed;
  if (changed) {
    assembler_->rebuild();
    reset_system();
  }
  if (with_jacobian && pattern_pending_) { // the first Jacobian of this pattern
    AssembledSystem pattern = assembler_->take_system();
    system_.Kff.swap(pattern.Kff);
    system_.Kfc.swap(pattern.Kfc);
    pattern_pending_ = false;
  } else if (with_jacobian) {
    reclaim_jacobian(lin);
  }
  // on several processes each assembles its elements: the parts are summed (and every
  // process must agree that the state is admissible before any returns)
  if (!parallel::all(assembler_->assemble(eval_state(), system_, with_jacobian)))
    return solver::SolveStatus::Inadmissible;
  parallel::sum(system_.residual);
  if (dynamic_) { // α_f g(x_n): the other terms' residual of the last step
    const Real alpha_f = inertia_->method().alpha_f;
    for (std::size_t i = 0; i < inertia_->dofs().size(); ++i)
      system_.residual[inertia_->dofs()[i]] +=
          alpha_f * inertia_->residual_history()[static_cast<Index>(i)];
  }
  const Index neq = map_.num_equations();
  lin.residual.setZero(neq);
  for (Index d = 0; d < map_.num_dofs(); ++d) // tied DOFs add their rows
    if (const Index eq = map_.equation(d); eq >= 0)
      lin.residual[eq] += system_.residual[d];
  if (!with_jacobian)
    return solver::SolveStatus::Converged;
  Vector pending(map_.num_constrained());
  for (Index c = 0; c < map_.num_constrained(); ++c) {
    const Index d = map_.dof_of_constrained(c);
    pending[c] = target_[d] - x_[d];
  }
  lin.constraint_rhs = system_.Kfc * pending;
  parallel::sum(lin.constraint_rhs);
  // the caller gets the assembled matrix itself, not a copy; the next linearize takes it back
  lin.jacobian.swap(system_.Kff);
  SparseMatrix().swap(system_.Kff);
  jacobian_lent_ = true;
  lent_nonzeros_ = lin.jacobian.nonZeros();
  lin.lender = this;
  lin.lent_pattern = pattern_id_;
  return solver::SolveStatus::Converged;
}

solver::SolveStatus FeProblem::update(const Vector& dx, Real step) {
  for (Index d = 0; d < map_.num_dofs(); ++d) // tied DOFs move together
    if (const Index eq = map_.equation(d); eq >= 0)
      x_[d] += step * dx[eq];
  for (Index c = 0; c < map_.num_constrained(); ++c) {
    const Index d = map_.dof_of_constrained(c);
    x_[d] = step == 1.0 ? target_[d] : x_[d] + step * (target_[d] - x_[d]); // exact at s = 1
  }
  sync();
  return solver::SolveStatus::Converged;
}

std::vector<Real> FeProblem::field_magnitudes() const {
  std::vector<Real> magnitudes(scales_.size(), 0.0);
  for (Index eq = 0; eq < map_.num_equations(); ++eq) {
    Real& m = magnitudes[equation_fields_[eq]];
    m = std::max(m, std::abs(x_[map_.dof_of_equation(eq)]));
  }
  return magnitudes;
}

bool FeProblem::constraints_satisfied() const {
  for (Index c = 0; c < map_.num_constrained(); ++c) {
    const Index d = map_.dof_of_constrained(c);
    if (x_[d] != target_[d])
      return false;
  }
  return true;
}

void FeProblem::begin_step(Real time, Real dt) {
  time_ = time;
  dt_ = dt;
  dofs::prescribed_values(conditions_, time_, target_);
}

std::string FeProblem::step_rejection() const {
  for (const auto& t : terms_)
    if (std::string why = t->step_rejection(eval_state()); !why.empty())
      return t->name() + ": " + why;
  return {};
}

std::string FeProblem::step_caution() const {
  for (const auto& t : terms_)
    if (std::string why = t->step_caution(eval_state()); !why.empty())
      return t->name() + ": " + why;
  return {};
}

void FeProblem::commit_step() {
  Vector g;
  if (dynamic_) {
    g = static_residual(); // g(x_{n+1}, t_{n+1}) before the terms commit
    Vector history(static_cast<Index>(inertia_->dofs().size()));
    for (std::size_t i = 0; i < inertia_->dofs().size(); ++i)
      history[static_cast<Index>(i)] = g[inertia_->dofs()[i]];
    inertia_->set_residual_history(std::move(history));
  }
  for (auto& t : terms_)
    if (t.get() != inertia_ || dynamic_) // the motion is that of the last dynamic step
      t->commit(eval_state());
  if (dynamic_) { // the reactions of the accepted state: g + M a_{n+1}
    Vector a = Vector::Zero(map_.num_dofs());
    for (std::size_t i = 0; i < inertia_->dofs().size(); ++i)
      a[inertia_->dofs()[i]] = inertia_->acceleration()[static_cast<Index>(i)];
    Vector inertial = inertia_->mass_times(a);
    rigid_.add_condensed(x_global_, inertial, inertial);
    frames_.to_local(inertial);
    committed_residual_ = g + inertial;
  }
  if (rigid_.wrap_rotations(x_, map_)) // a body that turned past π: the same rotation below it
    sync();
  x_old_ = x_;
  x_old_global_ = x_global_;
  time_old_ = time_;
}

void FeProblem::reject_step() {
  for (auto& t : terms_)
    t->reject();
  x_ = x_old_;
  sync();
  time_ = time_old_;
  dofs::prescribed_values(conditions_, time_, target_);
}

std::vector<Real> FeProblem::step_change() const {
  std::vector<Real> change(scales_.size(), 0.0);
  for (Index eq = 0; eq < map_.num_equations(); ++eq) {
    const Index d = map_.dof_of_equation(eq);
    Real& c = change[equation_fields_[eq]];
    c = std::max(c, std::abs(x_[d] - x_old_[d]));
  }
  return change;
}

void FeProblem::mark_committed() {
  mark_.x = x_old_;
  mark_.time = time_old_;
  mark_.histories.clear();
  for (const auto& t : terms_)
    mark_.histories.push_back(t->history());
}

void FeProblem::return_to_mark() {
  for (std::size_t k = 0; k < terms_.size(); ++k) {
    terms_[k]->reject();
    terms_[k]->restore_history(mark_.histories[k]);
  }
  x_ = mark_.x;
  sync();
  x_old_ = x_;
  x_old_global_ = x_global_;
  time_ = time_old_ = mark_.time;
  dofs::prescribed_values(conditions_, time_, target_);
}

} // namespace trifem::assembly
