// SPDX-License-Identifier: MIT
// Typed contents of a case file. The case reader fills it (every key validated); the
// application turns it into a model. No TOML types leak past the reader.
#pragma once

#include "trifem/core/solver_choice.hpp"
#include "trifem/dofs/load_curve.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/mesh/box.hpp"
#include "trifem/mesh/mesh.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::io {

/// [[mesh.box]]: a structured box; `material` assigns its cell block (empty: the cells of a
/// rigid body, named in its `blocks`).
struct BoxMeshSpec {
  mesh::BoxSpec box;
  std::string material;
};

/// [[mesh.gmsh]]: a Gmsh .msh file (path relative to the case file).
struct GmshMeshSpec {
  std::filesystem::path file;
  /// Physical volume name -> material name.
  std::map<std::string, std::string> materials;
};

/// A mesh given in full by a front end that reads its own mesh format (the FEBio reader):
/// nodes, hex8 cells, named node sets, surfaces and cell blocks, with the material of each
/// block it assigns.
struct InlineMeshSpec {
  mesh::Mesh mesh;
  std::map<std::string, std::string> materials; ///< cell block -> material name
};

/// A solid law and its parameters ([materials.<name>] or [materials.<name>.solid]), or a
/// "solid-mixture" and its constituents ([[<table>.constituent]], each a law with its
/// parameters). material::create_law(spec, context) makes the law.
using SolidSpec = material::LawSpec;

/// The hex8 formulation of a solid-law material ([materials.X] element = ...).
enum class SolidElementSpec {
  Auto,           ///< mean dilatation if the law is nearly incompressible, else displacement
  Displacement,   ///< "displacement"
  MeanDilatation, ///< "mean-dilatation"
};

/// [materials.<name>]: a solid law, or a "biphasic"/"triphasic" mixture whose solid matrix is
/// the sub-table [materials.<name>.solid]. For mixtures, `parameters` holds the mixture keys of
/// material::mixture_schema() (fixed_charge_basis "water"/"tissue" is stored as 0/1), with the
/// defaults filled in. permeability, d_plus and d_minus given as a number are stored under their
/// key; given as a law table, their parameters are stored as material::transport_law_key()
/// entries, e.g. "permeability.holmes-mow.k0" (see material::validate_mixture_parameters).
struct MaterialSpec {
  std::string type;
  material::ParameterValues parameters;
  std::optional<SolidSpec> solid; ///< set exactly for mixtures
  /// Mass density ρ [t/mm³] per reference volume (optional key, > 0; of a mixture: of the
  /// saturated mixture); required in dynamic analyses, unused by quasi-static ones.
  std::optional<Real> density;
  /// The constituents of a solid-law material of type "solid-mixture" ([[<name>.constituent]]);
  /// empty otherwise.
  std::vector<SolidSpec> constituents;
  /// The element of a solid-law material in quasi-static analyses (key `element`).
  SolidElementSpec element = SolidElementSpec::Auto;
  /// The material axes ([<name>.axes]): the local basis in which the directions of its solid
  /// law (or of a mixture's solid) are given; absent: the global basis.
  std::optional<material::AxesSpec> axes;
  bool is_mixture() const { return type == "biphasic" || type == "triphasic"; }
  /// The solid law of a material that is not a mixture (type, parameters, constituents).
  SolidSpec solid_law() const { return {type, parameters, constituents}; }
};

/// [curves.<name>]
struct CurveSpec {
  dofs::Interpolation interpolation = dofs::Interpolation::Linear;
  std::vector<std::pair<Real, Real>> points;
  dofs::Extension extension = dofs::Extension::Constant; ///< key `extend`
};

/// Vector component selector: 0 = x, 1 = y, 2 = z.
using Component = int;

/// Nodal vector fields a boundary condition can act on.
enum class FieldKind {
  Displacement, ///< u [mm]
  FluidFlux,    ///< w [mm/s]
  CationFlux,   ///< j+ [mmol/(mm^2 s)]
  AnionFlux,    ///< j- [mmol/(mm^2 s)]
};

/// The case-file name of a field ([[boundary.fixed]] and [[boundary.prescribed]] `field`).
constexpr std::string_view field_name(FieldKind kind) {
  switch (kind) {
  case FieldKind::Displacement:
    return "displacement";
  case FieldKind::FluidFlux:
    return "fluid_flux";
  case FieldKind::CationFlux:
    return "cation_flux";
  case FieldKind::AnionFlux:
    return "anion_flux";
  }
  return "displacement";
}

/// [[boundary.fixed]]: zero components of one or more fields on a node set. Case keys:
/// field = "displacement" (default) | "fluid_flux" | "cation_flux" | "anion_flux" |
/// "fluxes" (fluid + both ions). [[boundary.impermeable]] (set, normal) is stored as fixed
/// fluxes on the normal component; [[boundary.bonded]] (set) as fixed displacement and fluxes.
struct FixedSpec {
  std::string key; ///< case key it came from, e.g. "boundary.impermeable[1]" (for messages)
  std::string set;
  std::vector<Component> components;
  std::vector<FieldKind> fields = {FieldKind::Displacement};
};

/// [[boundary.impermeable]] with `surface` (and no `normal`): no normal flux through a face
/// of any orientation. The flux DOFs of its nodes are rotated to the (reference) nodal normal
/// and the normal components are fixed.
struct ImpermeableSurfaceSpec {
  std::string key; ///< e.g. "boundary.impermeable[2]"
  std::string surface;
};

/// [[boundary.prescribed]]: field_component = value * curve(t) on a node set.
struct PrescribedSpec {
  std::string set;
  Component component = 0;
  Real value = 0.0;
  std::string curve; ///< empty: constant 1
  FieldKind field = FieldKind::Displacement;
  /// value * curve(t) is added to the DOF's value at the start of the condition's step (of the
  /// run for a case-level condition), instead of replacing it.
  bool relative = false;
};

/// [[loads.pressure]]: pressure on a surface (positive pushes into the body) [MPa], along the
/// current normal per current area (a follower load) or, with `follower = false`, along the
/// reference normal per reference area (a dead load).
struct PressureSpec {
  std::string surface;
  Real value = 0.0;
  std::string curve;
  bool follower = true;
};

/// [[boundary.bath]]: a surface in a NaCl bath whose concentration moves from the reference
/// (electrochemistry.bath_concentration) to `concentration`, and its pressure from 0 to
/// `pressure`, following `curve` (0 -> 1).
/// Surfaces without conditions are free-draining to the reference bath.
struct BathSpec {
  std::string surface;
  Real concentration = 0.0; ///< [mmol/mm^3], > 0; 0: the reference bath's (biphasic models)
  Real pressure = 0.0;      ///< gauge pressure of the bath's water [MPa]
  std::string curve;        ///< empty: the new bath applies from t = 0
};

/// [[contact]]: a contact pair (one pass: the slave's nodes carry the contact pressure, the
/// friction traction of solids with friction and, between mixtures, the potentials).
struct ContactSpec {
  std::string key;            ///< "contact[1]" (for messages)
  std::string master;         ///< master surface (the coarser one)
  std::string slave;          ///< slave surface (the finer one)
  bool both_surfaces = true;  ///< integration "both-surfaces" (default) or "slave-nodes"
  Real scale = 0.0;           ///< c_N [MPa/mm]; 0: (lambda + 2 mu)_max / h
  Real search_distance = 0.0; ///< [mm]; 0: half the mean facet size
  /// Largest initial penetration accepted [mm]; < 0 (absent): 1e-3 x the mean facet size.
  Real penetration_tolerance = -1.0;
  Real friction = 0.0; ///< Coulomb friction coefficient μ (0: frictionless)
};

/// How one translation (rotation) component of a rigid body is driven.
enum class RigidDrive {
  Free,         ///< no prescribed value, no applied force (moment)
  Displacement, ///< translation [mm] (rotation [rad]) = value * curve(t)
  Force,        ///< applied force [N] (moment [N mm]) = value * curve(t)
};

/// One component of a [[rigid_body]] (the keys x, y, z, and rx, ry, rz of a rotating body).
struct RigidComponentSpec {
  RigidDrive drive = RigidDrive::Free;
  Real value = 0.0;
  std::string curve; ///< empty: constant 1
};

/// [[rigid_body.follower]]: a force at a point of a rotating body and a moment, given in the
/// reference configuration and turning with the body.
struct RigidFollowerSpec {
  Vec3 force = Vec3::Zero();  ///< [N]
  std::optional<Vec3> point;  ///< where the force acts [mm]; none: the body's center
  Vec3 moment = Vec3::Zero(); ///< [N mm]
  std::string curve;          ///< empty: constant 1
};

/// [[rigid_body]]: the nodes of `set` move with one rigid translation (rotation fixed), the
/// unknown of the body, e.g. a bone bonded to cartilage. Only the listed `components` are tied
/// (default all; the others stay per node, e.g. for plane strain); each is free, driven by a
/// displacement or by a force. A rotating body (rotation = "free") has six unknowns, the
/// translation of its `center` and its rotation vector (rx, ry, rz), each free or driven.
struct RigidBodySpec {
  std::string key; ///< "rigid_body[1]" (for messages)
  std::string name;
  std::string set;
  std::vector<Component> components = {0, 1, 2};
  std::array<RigidComponentSpec, 3> drives; ///< by component (Free unless given)
  bool rotates = false;
  std::optional<Vec3> center; ///< of a rotating body [mm]; none: the centroid of its nodes
  std::array<RigidComponentSpec, 3> rotation_drives; ///< rx, ry, rz of a rotating body
  /// Prescribed Euler angles of a rotating body instead (x, y, z: rotation = angle [rad] with
  /// its curve): R = R_z R_y R_x, about the fixed axes, x first (FEBio's rigid_euler_angles).
  std::optional<std::array<RigidComponentSpec, 3>> euler_angles;
  /// Cell blocks that move with the body (rigid cells: no material, no unknowns of their own);
  /// a body with blocks rotates. Their nodes, and those of `set` (may then be empty), follow it.
  std::vector<std::string> blocks;
  std::vector<RigidFollowerSpec> followers; ///< of a rotating body
  /// Mass per reference volume of the body's cells or shells [t/mm³] (none: massless; the
  /// tissue cells at its nodes still carry their mass).
  std::optional<Real> density;
  /// The thickness [mm] of the shells of a body whose `set` is a surface mesh (facets bounding
  /// no cell): with `density`, its facets carry the mass ρ t per reference area.
  std::optional<Real> shell_thickness;
  /// Velocity of the center [mm/s] and angular velocity [rad/s] at the start of the first
  /// dynamic step, if it starts the analysis.
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
};

/// The kind of a [[connector]].
enum class ConnectorKind {
  Spherical,   ///< the origins coincide
  Revolute,    ///< and the axes: one rotation about the axis is free
  Prismatic,   ///< one translation along the axis is free
  Cylindrical, ///< the rotation about the axis and the translation along it are free
  Planar,      ///< the plane normal to the axis slides and turns in itself
  Lock,        ///< the bodies move as one
  Spring,      ///< a linear spring between two points
  Cable,       ///< a spring in tension only (a ligament bundle)
  Damper,      ///< a force proportional to the relative velocity of two points
  Contractile  ///< a given force pulling two points together
};

/// [[connector]]: a joint or a link between two rigid bodies (or a body and "ground").
struct ConnectorSpec {
  std::string key; ///< "connector[1]" (for messages)
  std::string name;
  ConnectorKind kind = ConnectorKind::Spherical;
  std::string body_a, body_b; ///< names of rotating [[rigid_body]]s, or "ground"
  // joints
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  std::optional<Vec3> transverse;
  RigidComponentSpec rotation;    ///< about the axis: rotation [rad] or moment [N mm]
  RigidComponentSpec translation; ///< along the axis: displacement [mm] or force [N]
  Real torsion_stiffness = 0.0;   ///< [N mm/rad]
  // links
  Vec3 point_a = Vec3::Zero(), point_b = Vec3::Zero();
  Real stiffness = 0.0;            ///< [N/mm] (spring, cable) or [N s/mm] (damper)
  std::optional<Real> free_length; ///< [mm]; none: the reference distance
  Real force = 0.0;                ///< [N] (contractile)
  std::string curve;               ///< of the contractile force
};

/// The kind of a [[constraint]].
enum class ConstraintKind {
  Linear,             ///< sum_i c_i u_{n_i, k_i} = value * curve(t) (one equation)
  SymmetryPlane,      ///< the nodes of a flat surface stay in its plane: n.u_a = 0
  NormalDisplacement, ///< each node of a surface moves tangentially: N_a.u_a = 0 (reference
                      ///< nodal normal N_a, area-weighted)
  RigidWall,          ///< the nodes of a surface stay on one side of a moving plane (contact)
};

/// One coefficient of a linear constraint: `coefficient` times component `component` of the
/// displacement of mesh node `node` (0-based, the point id of the VTU output).
struct LinearConstraintEntry {
  Index node = -1;
  Component component = 0;
  Real coefficient = 0.0;
};

/// [[constraint]]: constraints imposed exactly with Lagrange multipliers (equations) or by a
/// primal-dual active set (the rigid wall).
struct ConstraintSpec {
  std::string key; ///< "constraint[1]" (for messages)
  std::string name;
  ConstraintKind kind = ConstraintKind::SymmetryPlane;
  std::string surface;                        ///< symmetry plane, normal displacement, wall
  std::vector<LinearConstraintEntry> entries; ///< linear
  Real value = 0.0;          ///< linear: right-hand side [mm]; wall: offset of the plane along its
                             ///< normal [mm] (the plane moves by value * curve(t))
  std::string curve;         ///< of `value`; empty: constant 1
  Vec3 point = Vec3::Zero(); ///< wall: a point of the plane at t = 0 [mm]
  Vec3 normal = Vec3::UnitZ(); ///< wall: unit normal pointing to the side the surface keeps to
};

/// [[loads.traction]]: traction in a fixed direction on a surface [MPa], per reference area (a
/// dead load) or per current area (key `area`).
struct TractionSpec {
  std::string surface;
  Vec3 value = Vec3::Zero(); ///< per unit area [MPa]; the total force [N] if total_force
  std::string curve;
  bool per_current_area = false; ///< `area = "current"`
  /// `force = [...]`: value is a total force spread uniformly over the surface's reference
  /// area, a traction value / A0 per reference area (FEBio's surface force load).
  bool total_force = false;
};

/// [[loads.body_force]]: a dead body force per unit mass (gravity) on the solid and rigid cells
/// of cell blocks: f = ρ force curve(t) per reference volume, ρ the density of the cell's
/// material (of its rigid body).
struct BodyForceSpec {
  std::string key;           ///< "loads.body_force[1]" (for messages)
  Vec3 force = Vec3::Zero(); ///< per unit mass [mm/s² = N/t], e.g. (0, 0, −9810) for gravity
  std::vector<std::string> blocks; ///< cell blocks; empty: every cell
  std::string curve;               ///< empty: constant 1
};

/// [[loads.nodal_force]]: a dead force on every node of a node set (each node gets the whole
/// value): f = value curve(t) [N].
struct NodalForceSpec {
  std::string key;           ///< "loads.nodal_force[1]" (for messages)
  std::string set;           ///< node set
  Vec3 value = Vec3::Zero(); ///< per node [N]
  std::string curve;         ///< empty: constant 1
};

/// [[initial_velocity]]: the velocity of the nodes of a node set when a dynamic analysis (implicit
/// or explicit) starts [mm/s].
struct InitialVelocitySpec {
  std::string key;           ///< "initial_velocity[1]" (for messages)
  std::string set;           ///< node set
  Vec3 value = Vec3::Zero(); ///< [mm/s]
};

/// Initial state of mixture models ([analysis] initial_state).
enum class InitialStateKind {
  Donnan,            ///< "donnan": Donnan equilibrium with the bath, stress-free solid (IC-1)
  DonnanPrestressed, ///< "donnan-prestressed": as IC-1 with a Cauchy prestress Pi0 (IC-3a)
};

/// The kind of analysis ([analysis] type).
enum class AnalysisType {
  QuasiStatic,     ///< "quasi-static": implicit Newton steps, no inertia (default)
  DynamicExplicit, ///< "dynamic-explicit": central differences with a multiplier pressure
  Dynamic          ///< "dynamic": implicit Newton steps with inertia (generalized-α)
};

/// The mass matrix of an implicit dynamic analysis ([dynamic] mass).
enum class MassMatrixSpec {
  Consistent, ///< "consistent": m_ab = ∫ ρ N_a N_b dV (default)
  Lumped      ///< "lumped": its row sums
};

/// [dynamic]: options of implicit dynamic steps.
struct DynamicSpec {
  /// Spectral radius of the generalized-α method at infinite frequency, in [0, 1]: 1 (default)
  /// is the trapezoidal rule without numerical dissipation; smaller values damp the highest
  /// frequencies.
  Real rho_inf = 1.0;
  MassMatrixSpec mass = MassMatrixSpec::Consistent;
};

/// [analysis]: the analysis type (any model) and the options of mixture models.
/// The mass of the mixture's friction terms ([analysis] flux_mass).
enum class FluxMass {
  Consistent, ///< m_ab = ∫ N_a N_b dv (default)
  Lumped      ///< diag(∫ N_a dv): the drained preconditioner's flux block is then exact
};

struct AnalysisSpec {
  AnalysisType type = AnalysisType::QuasiStatic;
  InitialStateKind initial_state = InitialStateKind::Donnan;
  FluxMass flux_mass = FluxMass::Consistent;
  std::string fixed_charge_curve; ///< curve scaling every fixed charge in time (free swelling)
};

/// [electrochemistry]: constants and the reference bath (mm-N-s-mmol-K units).
struct ElectrochemistrySpec {
  Real R = 8.314;                   ///< gas constant [mJ/(mmol K)], > 0
  Real T = 298.0;                   ///< temperature [K], > 0
  Real faraday = 96.485;            ///< Faraday constant [C/mmol], > 0
  Real bath_concentration = 1.5e-4; ///< NaCl bath c* [mmol/mm^3], > 0
  Real bath_activity = 1.0;         ///< bath activity coefficient gamma*, > 0
  Real bath_osmotic = 1.0;          ///< bath osmotic coefficient Phi*, > 0
};

/// Which forces the per-step iteration of an explicit analysis re-evaluates ([explicit] reading).
enum class ExplicitReading {
  A, ///< "A": all forces at t + Δt (first order, dissipative)
  B  ///< "B": forces at t_n, only the multiplier iterated (second order; default)
};

/// The volume constraint Ψ(C) of the multiplier term ([explicit] constraint).
enum class VolumeConstraint {
  JMinusOne, ///< "J-1": Ψ = J − 1 (σ = λ I)
  LogJ       ///< "lnJ": Ψ = ln J (τ = λ I)
};

/// How an explicit analysis estimates its critical step ([explicit] stable_step).
enum class StableStepEstimate {
  PowerIteration, ///< "power-iteration": isochoric ω by power iteration (default)
  ElementBound,   ///< "element-bound": max over cells of the element frequency (upper bound)
  None            ///< "none": use time.dt as given
};

/// [explicit]: options of a dynamic-explicit analysis (with the requested step, the settings of
/// explicit_dynamics::ExplicitSolver).
struct ExplicitSpec {
  ExplicitReading reading = ExplicitReading::B;
  VolumeConstraint constraint = VolumeConstraint::JMinusOne;
  bool multiplier = true; ///< false: pure-displacement Q1 (the law carries the bulk stiffness)
  Real penalty = std::numeric_limits<Real>::infinity(); ///< α [MPa]; inf: exact constraint
  Real damping = 0.0;                                   ///< mass-proportional damping c [1/s]
  std::optional<Real> safety_factor; ///< of the critical step; default 0.8 (B) or 0.5 (A)
  StableStepEstimate stable_step = StableStepEstimate::PowerIteration;
  int stable_step_interval = 0;        ///< re-estimate every this many steps (0: at t = 0 only)
  int max_iterations = 50;             ///< multiplier iterations per step before Δt is halved
  int max_halvings = 8;                ///< consecutive halvings before the run stops
  int factorization_age = 1;           ///< steps one factorization may serve (reading B)
  Real displacement_tolerance = 1e-10; ///< relative increment that ends the iteration
  Real constraint_tolerance = 1e-11;   ///< max_e |Ψ_e − V_e Λ_e/α| / V_e that ends it
};

/// Most levels of [mesh] refine (each multiplies the cells by eight).
inline constexpr int kMaxMeshRefinement = 6;

/// Most steps a run may need: end_time / (largest step) above this is refused (by the reader,
/// and by the explicit analysis once its stability estimate is known).
inline constexpr Real kMaxSteps = 1e8;

/// [time]
struct TimeSpec {
  Real end_time = 1.0; ///< end of the analysis [s]
  /// Initial step [s]. Dynamic-explicit: the requested step, 0 (time.dt absent) = the stability
  /// estimate; a request above the estimate is reduced to it.
  Real dt = 0.1;
  Real dt_min = 0.0;         ///< smallest step before the run fails [s]; 0 means dt * 1e-6
  Real dt_max = 0.0;         ///< largest step [s]; 0 means dt
  int target_iterations = 6; ///< steps that converge in at most this many iterations grow dt
  Real growth = 1.5;         ///< step growth factor (>= 1)
  Real cutback = 0.5;        ///< step cutback factor in (0, 1)
};

/// [solver]
struct SolverSpec {
  int max_iterations = 20;
  Real residual_tolerance = 1e-8;  ///< relative to the characteristic residual of each field
  Real increment_tolerance = 1e-8; ///< relative to the characteristic size of each field
  bool line_search = true;
  LinearSolverChoice linear_solver; ///< linear_solver and the keys of its backend
};

/// [[output.reaction]]: total reaction force on a node set, in history.csv.
struct ReactionSpec {
  std::string set;
};

/// [[output.probe]]: a quantity at `point` (reference configuration), in history.csv.
struct ProbeSpec {
  std::string name;
  std::string quantity = "displacement"; ///< one of io::probe_quantities()
  Vec3 point = Vec3::Zero();
};

/// [[output.average]]: the volume average of a quantity over the cells of a cell block, in
/// history.csv (weighted by the reference, current or water volume: io::AverageWeight).
struct AverageSpec {
  std::string name;     ///< column prefix, unique among probes and averages
  std::string quantity; ///< one of io::probe_quantities()
  std::string block;    ///< a cell block: a [[mesh.box]] name or a Gmsh physical volume
};

/// VTU states a quasi-static run without output.interval writes at most (plus the initial
/// state, the step ends and output.times).
inline constexpr int kDefaultOutputCount = 100;

/// [output]
struct OutputSpec {
  Real interval = 0.0; ///< VTU output every `interval` s (0: every step)
  /// `interval` was given; without it a quasi-static run writes a VTU file at the first step at
  /// or after each of kDefaultOutputCount equal parts of the run (and at every step end).
  bool interval_given = false;
  std::vector<Real> times; ///< extra output times (must points)
  /// history.csv rows of dynamic-explicit steps every this many seconds (the first step at or
  /// after each multiple, every VTU state and the step's end); 0: every step
  Real history_interval = 0.0;
  bool vtu = true;
  bool restart = false; ///< write a restart file with every VTU state (quasi-static runs)
  std::vector<ReactionSpec> reactions;
  std::vector<ProbeSpec> probes;
  std::vector<AverageSpec> averages;
};

/// [[step]]: one stage of a quasi-static analysis, from the end of the previous step (or 0) to
/// `time.end_time`, with its own time control and the conditions and loads that act during it
/// only (in addition to the case's [boundary] and [loads], which act in every step).
struct StepSpec {
  std::string name;
  std::string key; ///< "step[i]" (for messages)
  TimeSpec time;   ///< end_time is absolute (a `duration` key is converted)
  std::vector<FixedSpec> fixed;
  std::vector<PrescribedSpec> prescribed;
  std::vector<PressureSpec> pressures;
  std::vector<TractionSpec> tractions;
  /// Conditions of the previous step that this step does not repeat are released: their
  /// reactions act as loads decreasing linearly to zero over this time [s] (0: at once).
  Real release_time = 0.0;
  /// The analysis of this step (default: the case's [analysis] type). A dynamic-explicit step
  /// follows at least one other step and starts from its final state (with its velocity after
  /// a dynamic step, at rest otherwise); its time.dt is optional (0: the stability estimate).
  AnalysisType analysis = AnalysisType::QuasiStatic;
  /// A steady-state step of a mixture model (key `steady`): at each of its times the state is
  /// the steady state under that time's loads (the transport is done in a pseudo-time step).
  bool steady = false;
  bool is_explicit() const { return analysis == AnalysisType::DynamicExplicit; }
  bool is_dynamic() const { return analysis == AnalysisType::Dynamic; }
};

/// A whole case file.
struct CaseSpec {
  std::filesystem::path file; ///< the case file itself (for messages and relative paths)
  std::string title;
  std::vector<BoxMeshSpec> boxes;
  std::vector<GmshMeshSpec> gmsh;
  std::vector<InlineMeshSpec> meshes; ///< meshes read with the case (not from TOML)
  /// Uniform refinement levels of the whole mesh ([mesh] refine, or `trifem run --refine-mesh`):
  /// each level splits every cell into eight (mesh::refine_uniformly).
  int mesh_refinement = 0;
  std::map<std::string, MaterialSpec> materials;
  std::map<std::string, CurveSpec> curves;
  std::vector<FixedSpec> fixed;
  std::vector<PrescribedSpec> prescribed;
  std::vector<ImpermeableSurfaceSpec> impermeable_surfaces;
  std::vector<PressureSpec> pressures;
  std::vector<TractionSpec> tractions;
  std::vector<BodyForceSpec> body_forces;
  std::vector<NodalForceSpec> nodal_forces;
  std::vector<InitialVelocitySpec> initial_velocities;
  std::vector<BathSpec> baths;
  std::vector<ContactSpec> contacts;
  std::vector<RigidBodySpec> rigid_bodies;
  std::vector<ConnectorSpec> connectors;
  std::vector<ConstraintSpec> constraints;
  AnalysisSpec analysis;
  ElectrochemistrySpec electrochemistry;
  TimeSpec time;
  SolverSpec solver;              ///< quasi-static analyses
  ExplicitSpec explicit_dynamics; ///< dynamic-explicit analyses ([explicit])
  DynamicSpec dynamics;           ///< implicit dynamic analyses and steps ([dynamic])
  OutputSpec output;
  /// The [[step]]s in order; empty: one step with [time] and no step-level conditions.
  std::vector<StepSpec> steps;
  /// Values far outside the range of soft tissues, most likely in another unit (the reader also
  /// logs them): "<key> = <value> <unit> is far outside ... (line N)".
  std::vector<std::string> warnings;

  bool is_explicit() const { return analysis.type == AnalysisType::DynamicExplicit; }
  /// A case with a dynamic-explicit [[step]] (among quasi-static ones).
  bool has_explicit_step() const {
    return std::any_of(steps.begin(), steps.end(),
                       [](const StepSpec& s) { return s.is_explicit(); });
  }
  /// The analysis or one of its [[step]]s is quasi-static: its bodies must be supported (in a
  /// dynamic step a body may fly).
  bool has_static_step() const {
    if (steps.empty())
      return analysis.type == AnalysisType::QuasiStatic;
    return std::any_of(steps.begin(), steps.end(),
                       [](const StepSpec& s) { return s.analysis == AnalysisType::QuasiStatic; });
  }
  /// The analysis or one of its [[step]]s is implicit dynamic (the model has inertia).
  bool has_dynamic_step() const {
    return analysis.type == AnalysisType::Dynamic ||
           std::any_of(steps.begin(), steps.end(),
                       [](const StepSpec& s) { return s.is_dynamic(); });
  }
  /// The analysis or one of its steps is dynamic, implicit or explicit: the bodies start with
  /// their initial velocities.
  bool has_motion() const { return has_dynamic_step() || is_explicit() || has_explicit_step(); }
  /// The dynamics lump the mass: always in dynamic-explicit analyses and steps, in implicit ones
  /// if [dynamic] mass = "lumped" (body forces are then lumped alike).
  bool lumps_the_mass() const {
    return is_explicit() || has_explicit_step() ||
           (has_dynamic_step() && dynamics.mass == MassMatrixSpec::Lumped);
  }
};

} // namespace trifem::io
