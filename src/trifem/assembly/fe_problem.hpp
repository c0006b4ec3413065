// SPDX-License-Identifier: MIT
// The assembled finite element problem: terms + DOF map + prescribed values + state.
// Implements the solver's TransientProblem; this is where elements meet the Newton solver.
#pragma once

#include "trifem/assembly/system_pattern.hpp"
#include "trifem/dofs/dirichlet.hpp"
#include "trifem/dofs/nodal_frames.hpp"
#include "trifem/dofs/rigid_map.hpp"
#include "trifem/physics/inertia_term.hpp"
#include "trifem/solver/nonlinear_problem.hpp"

#include <memory>
#include <vector>

namespace trifem::assembly {

/// Global residual over all DOFs and the two Jacobian blocks.
struct AssembledSystem {
  Vector residual;  ///< R at every DOF (reactions at constrained DOFs)
  SparseMatrix Kff; ///< dR_f/dx_f
  SparseMatrix Kfc; ///< dR_f/dx_c
};

/// Loops over terms (colour by colour, elements of a colour in parallel) and scatters.
class Assembler {
public:
  /// `frames` (optional, outlives the assembler): rotated nodal DOFs; element contributions
  /// are rotated to the local frames before scattering. `awaits_ownership`: a run on several
  /// processes, whose colours and pattern set_ownership() builds (only the stencils are
  /// collected here, for body_couplings()). `rigid` (optional, outlives the assembler): rigid
  /// bodies whose followers' contributions are condensed onto the bodies' unknowns.
  Assembler(const dofs::DofMap& map, std::vector<const physics::Term*> terms,
            const dofs::NodalFrames* frames = nullptr, bool awaits_ownership = false,
            const dofs::RigidMap* rigid = nullptr);
  /// Assembles residual and (if with_jacobian) both Jacobian blocks. False if some element
  /// reported an inadmissible state.
  bool assemble(const physics::EvalState& state, AssembledSystem& out, bool with_jacobian) const;
  /// An AssembledSystem with the right sizes and patterns (values zero). The pattern is built
  /// on the first call after a rebuild: an analysis that never asks for a Jacobian (explicit
  /// dynamics) never allocates one.
  AssembledSystem make_system();
  /// The same, moving the pattern out (the next call builds it again).
  AssembledSystem take_system();
  /// The couplings between equations of every term but those that join bodies (the graph
  /// a parallel run is partitioned by).
  SparseMatrix body_couplings() const;
  /// Recollects the stencils of every term and rebuilds the colours (after a term's
  /// element_dofs() changed); the pattern follows when next asked for.
  void rebuild();
  /// Runs on several processes: from now on only the elements of process `rank` are assembled
  /// (and only their couplings are in the pattern). An element belongs to the owner of its first
  /// equation in `equation_owner`, to rank 0 if all its DOFs are prescribed. Rebuilds.
  void set_ownership(std::vector<int> equation_owner, int rank);
  /// Scales the residual and Jacobian of every term by its weight (one per term, in the order
  /// of the constructor's terms; empty: all 1). A term of weight 0 is not evaluated.
  void set_weights(std::vector<Real> weights);
  /// Per term (same order; empty: all 0), the share σ of its condensation onto the rigid
  /// bodies taken at the step's start: (1 − σ) Λ(x)ᵀ r + σ Λ(x_old)ᵀ r. A dynamic step projects
  /// the inertia of the bodies' nodes so, as it weights their forces (docs/theory/dynamics.md).
  void set_old_projection(std::vector<Real> shares);

private:
  bool assemble_term(std::size_t t, const physics::EvalState& state, AssembledSystem& out,
                     bool with_jacobian) const;
  void build_pattern_once();

  const dofs::DofMap& map_;
  std::vector<const physics::Term*> terms_;
  std::vector<Real> weights_;        ///< per term (empty: all 1)
  std::vector<Real> old_projection_; ///< per term (empty: all 0)
  const dofs::NodalFrames* frames_;
  const dofs::RigidMap* rigid_;     ///< nullptr: no rigid bodies
  std::vector<int> equation_owner_; ///< empty: this process assembles every element
  int rank_ = 0;
  bool awaits_ownership_ = false;   ///< until set_ownership(): stencils only
  std::vector<Stencils> stencils_;  ///< per term: what its elements evaluate
  std::vector<Stencils> condensed_; ///< with rigid bodies: what they couple (RigidMap::expand)
  std::vector<std::vector<std::vector<Index>>> colours_;
  std::vector<Stencils> owned_; ///< on several processes: the stencils of this one's elements
  SystemPattern pattern_;
  bool pattern_built_ = false; ///< pattern_ is that of the current stencils
};

/// A transient/quasi-static problem: R(x, t) = 0 with prescribed DOFs.
class FeProblem final : public solver::TransientProblem {
public:
  /// `map` (the problem keeps its own copy: the constraints of its current conditions) must be
  /// finalized with the constrained DOFs of `conditions`. `scales` gives one FieldScale per
  /// field of `map`.
  /// `frames`: rotated nodal DOFs (their values and prescribed values are local components).
  /// `rigid`: rigid bodies, whose followers must be the dependent DOFs of `map` (and in no
  /// rotated frame).
  FeProblem(dofs::DofMap map, std::vector<dofs::DirichletCondition> conditions,
            std::vector<std::unique_ptr<physics::Term>> terms,
            std::vector<solver::FieldScale> scales, dofs::NodalFrames frames = {},
            dofs::RigidMap rigid = {});
  FeProblem(const FeProblem&) = delete; // its assembler refers to its DOF map
  FeProblem& operator=(const FeProblem&) = delete;

  // NonlinearProblem
  Index num_equations() const override { return map_.num_equations(); }
  const std::vector<int>& equation_fields() const override { return equation_fields_; }
  /// "field 'displacement', entity (node) 12, component 1" of the equation's leader DOF.
  std::string equation_name(Index eq) const override;
  const std::vector<solver::FieldScale>& field_scales() const override { return scales_; }
  std::vector<FieldRole> field_roles() const override;
  int pattern_id() const override { return pattern_id_; }
  const std::vector<int>& equation_owners() const override { return equation_owner_; }
  std::vector<Vector> rigid_body_modes() const override;
  /// Empty on several processes (each holds only its part of the matrix).
  linalg::TransportCells transport_cells() const override;
  solver::SolveStatus linearize(solver::Linearization& lin, bool with_jacobian) override;
  solver::SolveStatus update(const Vector& dx, Real step) override;
  bool constraints_satisfied() const override;
  std::vector<Real> field_magnitudes() const override;
  void save_iterate() override { saved_ = x_; }
  void restore_iterate() override {
    x_ = saved_;
    sync();
  }

  // TransientProblem
  void begin_step(Real time, Real dt) override;
  /// The first term's rejection of the converged state ("<term>: <reason>"), or empty.
  std::string step_rejection() const override;
  /// The first term's caution about the converged state ("<term>: <reason>"), or empty.
  std::string step_caution() const override;
  void commit_step() override;
  void reject_step() override;
  std::vector<Real> step_change() const override;
  void mark_committed() override;
  void return_to_mark() override;

  /// Current state (all DOFs, global components) and time.
  const Vector& state() const { return x_global_; }
  /// Current state with rotated DOFs in their local frames (the solver's unknowns).
  const Vector& local_state() const { return x_; }
  Real time() const { return time_; }
  /// Sets the current (and last converged) time, e.g. when a run continues from a restart file.
  void set_time(Real time) { time_ = time_old_ = time; }
  /// Sets the state (global components; e.g. initial conditions) at the current time.
  void set_state(const Vector& x);
  /// Replaces the prescribed conditions (between steps): the DOF map's constraints become
  /// theirs, the equations and the pattern are rebuilt and the state is kept.
  void set_conditions(std::vector<dofs::DirichletCondition> conditions);
  /// The displacement field and the reference position of every node, from which
  /// rigid_body_modes() builds the solid's rigid motions.
  void set_node_positions(dofs::FieldId displacement, std::vector<Vec3> positions);
  /// Adds a term (between steps), e.g. the loads that replace released conditions.
  void add_term(std::unique_ptr<physics::Term> term);
  /// Adds the inertia of the model (once; left out of quasi-static steps).
  void add_inertia(std::unique_ptr<physics::InertiaTerm> inertia);
  const physics::InertiaTerm* inertia() const { return inertia_; }
  /// Makes the following steps dynamic (generalized-α with the inertia term: the other terms'
  /// residual g enters as (1 − α_f) g(x_{n+1}) + α_f g(x_n)) or quasi-static. Entering dynamics
  /// with `start` (after a quasi-static or dynamic-explicit step, or at the start), the body
  /// starts with `velocity` (every DOF, global components; empty: at rest) and the acceleration
  /// M⁻¹(−g) of the current state (zero at prescribed DOFs); otherwise (a run continued from a
  /// restart file) with the motion the inertia term holds.
  void set_dynamic(bool dynamic, bool start = true, const Vector& velocity = {});
  bool dynamic() const { return dynamic_; }
  /// The velocity of the last accepted state at every DOF (global components) in a dynamic
  /// step; empty outside them.
  Vector velocity() const;
  const std::vector<dofs::DirichletCondition>& conditions() const { return conditions_; }
  /// Residual at every DOF of the last evaluation: reactions at constrained DOFs. In dynamic
  /// steps, that of the last accepted state, g + M a (the support forces).
  const Vector& full_residual() const { return dynamic_ ? committed_residual_ : system_.residual; }
  /// The DOFs with the constraints of the current conditions.
  const dofs::DofMap& dof_map() const { return map_; }
  const dofs::RigidMap& rigid_map() const { return rigid_; }
  const std::vector<std::unique_ptr<physics::Term>>& terms() const { return terms_; }

private:
  physics::EvalState eval_state() const { return {x_global_, x_old_global_, time_, dt_, &map_}; }
  /// Refreshes the follower DOFs of rigid bodies and the global-component copy of the state
  /// after x_ changed.
  void sync();
  /// On several processes: splits the equations between them (METIS on the pattern, computed
  /// on rank 0 and broadcast) and restricts the assembler to this process's elements.
  void partition();
  /// Before an assembly of the Jacobian: takes back the matrix storage lent to `lin` by the
  /// last linearize, or builds the pattern anew if `lin` does not hold it.
  void reclaim_jacobian(solver::Linearization& lin);
  /// Numbers the equations' fields and builds the assembler and its pattern.
  void build_assembler();
  /// A term's cell over the equations (divergences in the rotated frames' components), its
  /// Jacobian parts multiplied by the term's `weight`.
  void to_equations(const physics::CellTransport& cell, Real weight,
                    linalg::TransportCell& out) const;
  /// Term weights of the assembly: dynamic, (1 − α_f) for every term but the inertia (1);
  /// quasi-static, 1 for every term but the inertia (0).
  void apply_weights();
  /// The residual g of every term but the inertia at the current state (every DOF, in the
  /// assembled components).
  Vector static_residual();
  /// The motion a dynamic step starts with: `velocity` (every DOF, global components; empty:
  /// at rest) and the acceleration of the equation of motion (dynamic_start.cpp).
  void start_motion(const Vector& velocity);
  void reset_system();

  dofs::DofMap map_;
  std::vector<dofs::DirichletCondition> conditions_;
  std::vector<std::unique_ptr<physics::Term>> terms_;
  physics::InertiaTerm* inertia_ = nullptr; ///< among terms_ (nullptr: none)
  bool dynamic_ = false;
  Vector committed_residual_; ///< dynamic: g + M a of the last accepted state
  std::vector<solver::FieldScale> scales_;
  std::vector<int> equation_fields_;
  dofs::FieldId displacement_;       ///< for rigid_body_modes()
  std::vector<Vec3> node_positions_; ///< reference positions of the displacement's nodes
  std::vector<int> equation_owner_;  ///< on several processes: the owner of each equation
  std::unique_ptr<Assembler> assembler_;
  AssembledSystem system_;
  bool pattern_pending_ = false; ///< system_ has no Jacobian pattern yet (none asked for)
  bool jacobian_lent_ = false;   ///< system_.Kff's storage is with a Linearization (linearize)
  Index lent_nonzeros_ = 0;      ///< the lent matrix's nonzeros
  dofs::NodalFrames frames_;
  dofs::RigidMap rigid_;
  Vector x_, x_old_, saved_, target_;
  Vector x_global_, x_old_global_;
  Real time_ = 0.0, time_old_ = 0.0, dt_ = 0.0;
  int pattern_id_ = 0;
  /// The committed state remembered by mark_committed().
  struct Mark {
    Vector x;
    Real time = 0.0;
    std::vector<std::vector<double>> histories; ///< per term
  } mark_;
};

} // namespace trifem::assembly
