// SPDX-License-Identifier: MIT
// Rigid connectors (docs/theory/rigid.md §5): joints, springs, dampers and forces between two
// rigid bodies, or a body and space. A connector is a set of measures of the pair's relative
// motion (rigid_measure.hpp) that are either
//   - constrained, g(q) = g_p(t), each with a Lagrange multiplier λ:
//       R_q += λ ∇g,   R_λ = g − g_p,   K_qq += λ ∇²g,   K_qλ = K_λqᵀ = ∇g;
//   - or given an energy ψ(g): R_q += ψ'(g) ∇g,   K_qq += ψ'' ∇g ∇gᵀ + ψ' ∇²g.
// The multipliers are unknowns of the state: exact joints with no penalty to choose.
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/physics/rigid_measure.hpp"
#include "trifem/physics/term.hpp"

#include <optional>
#include <string>

namespace trifem::physics {

/// The unknowns and reference center of one rotating rigid body.
struct RigidBodyUnknowns {
  std::array<Index, 3> translation{};
  std::array<Index, 3> rotation{};
  Vec3 centre = Vec3::Zero();
};

/// g(q) = value · curve(t), enforced by the multiplier DOF `multiplier`. For an angle the
/// difference g − g_p is taken in (−π, π], so that a prescribed angle may grow past π.
struct ConnectorConstraint {
  rigid::Measure measure;
  Real value = 0.0;
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
  Index multiplier = -1;
  bool angular = false; ///< a multiplier that is a moment (else a force)
};

/// The energy of a measure g.
enum class ConnectorEnergyKind {
  Spring, ///< ½ k (g − rest)²
  Cable,  ///< ½ k (g − rest)² where g > rest, else 0 (tension only)
  Force,  ///< −F(t) g: a force (moment) F = value · curve(t) that does work on g
  Viscous ///< ½ (c/Δt) (g − g_old)²: a damper, force c ġ with ġ = (g − g_old)/Δt
};

struct ConnectorEnergy {
  rigid::Measure measure;
  ConnectorEnergyKind kind = ConnectorEnergyKind::Spring;
  Real stiffness = 0.0; ///< k (Spring, Cable) or c (Viscous)
  Real rest = 0.0;      ///< Spring, Cable
  Real value = 0.0;     ///< Force
  dofs::LoadCurve curve = dofs::LoadCurve::constant(1.0);
};

/// A measure reported in the output (e.g. the angle of a revolute joint).
struct ReportedMeasure {
  std::string name; ///< "angle", "translation", "length"
  std::string unit; ///< "rad", "mm"
  rigid::Measure measure;
};

/// One connector between body a and body b (none: space).
struct Connector {
  std::string name;
  std::array<std::optional<RigidBodyUnknowns>, 2> bodies;
  std::vector<rigid::Attachment> attachments;
  std::vector<ConnectorConstraint> constraints;
  std::vector<ConnectorEnergy> energies;
  std::vector<ReportedMeasure> reported;
  int origin_b = -1; ///< attachment: the point of body b about which its moment is reported
};

/// The force and moment a connector applies to its body b [N, N mm], the moment about the
/// current position of attachment origin_b (its center without one). Body a carries the
/// opposite: a connector's own forces balance.
struct ConnectorWrench {
  Vec3 force = Vec3::Zero();
  Vec3 moment = Vec3::Zero();
};

class RigidConnectorTerm final : public Term {
public:
  explicit RigidConnectorTerm(std::vector<Connector> connectors);
  std::string name() const override { return "rigid connector"; }
  Index num_elements() const override { return static_cast<Index>(connectors_.size()); }
  void element_dofs(Index e, std::vector<Index>& dofs) const override;
  bool evaluate(Index e, const EvalState& state, LocalVector& r, LocalMatrix* K) const override;

  const std::vector<Connector>& connectors() const { return connectors_; }
  /// The pair's motion of connector `e` in `x` (every DOF).
  rigid::PairState pair_state(Index e, const Vector& x) const;
  /// The value of measure `m` of connector `e` at `x`.
  Real measure(Index e, const rigid::Measure& m, const Vector& x) const;
  /// ∂g/∂q of each constraint of connector `e` at `x` (a column each; rows: the body unknowns
  /// of element_dofs(e), in order). Empty columns for a measure without derivatives there.
  Eigen::MatrixXd constraint_gradients(Index e, const Vector& x) const;
  /// What connector `e` applies to its body b at `state`.
  ConnectorWrench wrench(Index e, const EvalState& state) const;
  /// The wrench of each connector in the last committed state (zero before the first commit).
  const std::vector<ConnectorWrench>& committed_wrenches() const { return committed_; }
  void commit(const EvalState& state) override;
  std::vector<double> history() const override;
  void restore_history(const std::vector<double>& values) override;

private:
  /// R_q (12) of the pair and, if K is given, K_qq, with the constraint rows R_λ, K_qλ.
  bool pair_residual(Index e, const EvalState& state, rigid::PairVector& rq, Eigen::VectorXd& rl,
                     rigid::PairMatrix* Kqq, Eigen::MatrixXd* Kql) const;

  std::vector<Connector> connectors_;
  std::vector<ConnectorWrench> committed_;
};

} // namespace trifem::physics
