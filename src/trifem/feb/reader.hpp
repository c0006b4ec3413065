// SPDX-License-Identifier: MIT
// Shared state of the .feb section readers (internal to the feb library).
#pragma once

#include "trifem/core/error.hpp"
#include "trifem/feb/document.hpp"
#include "trifem/io/case_spec.hpp"

#include <array>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::feb::detail {

/// The FEBio format versions read.
enum class Version { V3, V4 };

/// A load curve as FEBio extends it beyond its points; checked against the run's span once the
/// steps are known.
struct CurveExtent {
  pugi::xml_node node;
  bool extrapolate = false; ///< extend EXTRAPOLATE (the same as CONSTANT inside its points)
  Real first = 0.0;         ///< time of the first point [s]
  Real last = 0.0;          ///< time of the last point [s]
};

/// The solutes and constants of a multiphasic model (<Globals>), in the file's units.
struct Electrochemistry {
  std::map<std::string, int> charge_of; ///< solute id and name -> charge number (+1 Na, -1 Cl)
  pugi::xml_node constants;             ///< <Constants> (empty: none)
  Real R = 0.0;                         ///< gas constant of the file
  Real T = 0.0;                         ///< temperature [K]
  Real faraday = 0.0;                   ///< Faraday constant of the file
  /// trifem's amount (mmol) per amount unit of the file: R / 8.314 mJ/(mmol K) (nmol: 1e-6).
  Real amount = 1.0;
  /// The charge number of the solute `ref` (id or name) named at `node`; error if unknown.
  int charge(const Document& doc, pugi::xml_node node, const std::string& ref) const;
};

/// A prescribed effective fluid pressure (charge 0) or effective concentration (the solute's
/// charge number) on a node set: the bath a face is drained to.
struct EffectiveCondition {
  pugi::xml_node bc;
  std::string set;
  int charge = 0;
  Real value = 0.0;
  std::string curve; ///< FEBio load controller name ("" : constant)
};

/// A "rigid body" material: its attachment (bc type rigid) and the <Rigid> conditions on it.
struct RigidBodyInput {
  pugi::xml_node material;
  pugi::xml_node attachment;
  /// The thickness of its shell part from <MeshData><ElementData type="shell thickness">
  /// (checked uniform and not negative)
  std::optional<Real> mesh_data_thickness;
  std::string set;                 ///< the attached node set
  std::vector<std::string> blocks; ///< the parts (solid domains) of the body
  bool shell = false; ///< made of a shell part (a surface mesh): `set` is its nodes; it rotates
  std::array<bool, 6> fixed{};                  ///< rigid_fixed: x, y, z, then the rotations
  std::array<io::RigidComponentSpec, 3> drives; ///< rigid_displacement, rigid_force
  std::array<io::RigidComponentSpec, 3> rotation_drives; ///< rigid_rotation, rigid_moment
  bool connected = false;                                ///< a rigid_connector names it: it rotates
  static constexpr std::string_view kComponentNames[6] = {"x", "y", "z", "Ru", "Rv", "Rw"};
  /// The drive of component k (0-2 translations, 3-5 rotations).
  io::RigidComponentSpec& drive(int k) { return k < 3 ? drives[k] : rotation_drives[k - 3]; }
  const io::RigidComponentSpec& drive(int k) const {
    return k < 3 ? drives[k] : rotation_drives[k - 3];
  }
  /// Per component (x, y, z, then the rotations): the order of the rigid condition that last
  /// fixed or drove it (0: none). As in FEBio, a later condition replaces an earlier one.
  std::array<int, 6> order{};
  /// rigid_euler_angles: Ex, Ey, Ez in radians with their curves
  std::optional<std::array<io::RigidComponentSpec, 3>> euler_angles;
  pugi::xml_node euler_node;
  Vec3 velocity = Vec3::Zero();         ///< rigid_ic initial_rigid_velocity
  Vec3 angular_velocity = Vec3::Zero(); ///< rigid_ic initial_rigid_angular_velocity
  pugi::xml_node initial;               ///< the last rigid_ic (for messages)
};

/// Everything the section readers share while a file is read.
struct Reader {
  Reader(const Document& d, io::CaseSpec& s) : doc(d), spec(s) {}

  const Document& doc;
  io::CaseSpec& spec;
  Version version = Version::V4;
  bool biphasic_module = false;    ///< a mixture module (biphasic or multiphasic)
  bool multiphasic_module = false; ///< the multiphasic module (triphasic materials)
  Electrochemistry chem;
  io::InlineMeshSpec mesh;
  std::map<long, Index> node_index;                  ///< FEBio node id -> mesh node
  std::map<long, Index> cell_index;                  ///< FEBio element id -> mesh cell
  std::map<std::string, std::string> material_by_id; ///< FEBio material id -> name
  std::map<std::string, pugi::xml_node> parts;       ///< Elements name -> its element
  /// quad4 and tri3 Elements (shells), kept as surfaces of the same name: only a rigid body may
  /// use one
  std::map<std::string, pugi::xml_node> shell_parts;
  std::map<std::string, std::string> curve_by_id; ///< load controller id -> curve name
  std::vector<CurveExtent> curve_extents;
  std::vector<EffectiveCondition> effective;          ///< top-level fluid pressure, concentrations
  std::vector<EffectiveCondition> initial;            ///< <Initial> fluid pressure, concentrations
  std::map<std::string, RigidBodyInput> rigid_bodies; ///< by material name
  /// The rigid connectors, their bodies named by material name until map_rigid_bodies
  std::vector<io::ConnectorSpec> connectors;
  /// The prescribed rotation or the moments of a spherical joint: the rotation vector of body b
  /// relative to body a (or the moment on b), which map_rigid_bodies gives to the body that
  /// moves when the other is the ground.
  struct JointRotation {
    pugi::xml_node where;
    std::string body_a, body_b;                   ///< material names
    std::array<io::RigidComponentSpec, 3> drives; ///< on body b
  };
  std::vector<JointRotation> joint_rotations;
  int rigid_conditions = 0;               ///< rigid_bc and rigid_load elements read so far
  std::vector<std::string> flux_surfaces; ///< surfaces with a prescribed normal fluid flux
  /// prescribed fluid pressures other than 0 of a biphasic model: baths at that pressure
  std::vector<const EffectiveCondition*> pressure_baths;
  /// <fixed_charge_density> of each triphasic material (name), mapped once the curves are known
  std::vector<std::pair<std::string, pugi::xml_node>> fixed_charges;
  std::vector<char> drained; ///< per mesh node: in a "zero fluid pressure" node set
  /// Mass density per reference volume of each material (name) with FEBio's defaults, given to
  /// the materials once the analysis is known to be dynamic (map_densities)
  std::map<std::string, Real> densities;

  void warn(pugi::xml_node node, const std::string& what);
  /// The curve name of the attribute lc of `node` ("" without one).
  std::string curve_of(pugi::xml_node node) const;
  /// True if value x curve (a curve name, "" for none) is 0 at every time.
  bool always_zero(Real value, const std::string& curve) const;
  /// The node set named by the attribute `attribute` ("@surface:S" names the nodes of S).
  std::string node_set(pugi::xml_node node, const char* attribute = "node_set") const;
  /// The surface named by the attribute `attribute`.
  std::string surface(pugi::xml_node node, const char* attribute = "surface") const;
  /// The mesh nodes of the FEBio node ids in the text of `node`.
  std::vector<Index> nodes_of(pugi::xml_node node, const std::vector<long>& ids) const;
};

/// True for an XML element (not text, a comment or another kind of node).
inline bool is_element(pugi::xml_node n) {
  return n.type() == pugi::node_element;
}

/// The element children of `node` in document order (those for which is_element holds).
std::vector<pugi::xml_node> elements(pugi::xml_node node);

/// Runs `f` (a mesh operation), turning its InputError into one located at `node`.
template <class F>
void with_mesh_errors(const Reader& r, pugi::xml_node node, F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    r.doc.fail(node, e.what());
  }
}

/// Globals: Constants and Solutes (multiphasic models).
void read_globals(Reader& r, pugi::xml_node section);
/// Materials (before the mesh: 3.0 files assign them by id in Elements).
void read_materials(Reader& r, pugi::xml_node section);
/// The fixed charge densities of the triphasic materials (after LoadData): magnitude in trifem's
/// units and, with a load curve, [analysis] fixed_charge_curve.
void map_fixed_charges(Reader& r);
/// Mesh (Nodes, Elements, NodeSet, Surface, ElementSet) and MeshDomains.
void read_mesh(Reader& r, pugi::xml_node mesh, pugi::xml_node domains);
/// The name of the cell data of FEBio's local fibres from element node n1 to n2 (1-based).
std::string local_fibre_view(long n1, long n2);
/// Makes the cell data of every local fibre view the materials' axes name (the unit vector from
/// each cell's FEBio node n1 to its node n2 in the reference configuration); InputError at the
/// material if a cell has fewer nodes.
void add_local_fibre_views(Reader& r);
/// MeshData: the shell thickness of the rigid bodies' shell parts (after read_mesh).
void read_mesh_data(Reader& r, pugi::xml_node section);
/// LoadData: the load controllers as curves.
void read_load_data(Reader& r, pugi::xml_node section);
/// The conditions of a Boundary section into `fixed` and `prescribed`; zero fluid pressure
/// marks drained nodes (top level only: `step` false).
void read_boundary(Reader& r, pugi::xml_node section, std::vector<io::FixedSpec>& fixed,
                   std::vector<io::PrescribedSpec>& prescribed, bool step);
/// The surface loads of a Loads section: follower pressures and dead tractions, mixture normal
/// tractions (as pressures) and normal fluid fluxes (as prescribed fluxes, top level only); its
/// body loads (top level only) go to r.spec.body_forces.
void read_loads(Reader& r, pugi::xml_node section, std::vector<io::PressureSpec>& pressures,
                std::vector<io::TractionSpec>& tractions,
                std::vector<io::PrescribedSpec>& prescribed, bool step);
/// The analysis of a Control section.
enum class FebAnalysis { Static, SteadyState, Transient, Dynamic };
/// The time control of a Control section; `start` is the step's start time [s]; `analysis` (if
/// given) is set to the analysis (a dynamic one also sets r.spec.dynamics).
io::TimeSpec read_control(Reader& r, pugi::xml_node control, Real start,
                          FebAnalysis* analysis = nullptr);
/// The densities of the materials when some step is dynamic or a body load acts (after
/// read_steps).
void map_densities(Reader& r);
/// Control or Step: the time of the run and its steps with their conditions.
void read_steps(Reader& r, pugi::xml_node root);
/// Output: logfile data as reactions and probes where they map directly.
void read_output(Reader& r, pugi::xml_node section);
/// Initial: initial fluid pressure and concentrations of mixtures (checked by map_baths).
void read_initial(Reader& r, pugi::xml_node section);
/// The prescribed effective fluid pressures and concentrations as drained nodes and the bath
/// (electrochemistry), and the initial conditions checked against trifem's Donnan initial state.
void map_baths(Reader& r);
/// A material of type "rigid body" (no elements: its nodes are attached by bc type rigid).
void add_rigid_material(Reader& r, pugi::xml_node node, const std::string& name);
/// bc type "rigid": the node set a rigid body moves.
void attach_rigid(Reader& r, pugi::xml_node bc, bool step);
/// <Rigid>: rigid_fixed, rigid_displacement and rigid_force on the bodies.
void read_rigid(Reader& r, pugi::xml_node section);
/// The <step> of a file whose <Step> has exactly one (null otherwise): its <Rigid>, <Contact>
/// and <Constraints> act over the whole run, as the file's own sections do.
pugi::xml_node only_step(pugi::xml_node root);
/// The rigid bodies as [[rigid_body]]s (translating if attached by nodes with their rotations
/// fixed and joined by no connector, else rotating), then the connectors as [[connector]]s.
void map_rigid_bodies(Reader& r);
/// A node set of the nodes of sets `a` and `b` (its name, "<a>_and_<b>").
std::string union_node_sets(Reader& r, const std::string& a, const std::string& b);
/// Merges the rigid bodies whose elements share nodes into the one of the lowest material id
/// (elements, attached nodes, conditions in FEBio's order, connectors), with a warning each,
/// until none do (rigid_merge.cpp).
void merge_touching_bodies(Reader& r);
/// In a static analysis the rigid bodies' initial velocities (rigid_ic) are dropped, with a
/// warning: they act in dynamic analyses only. Call once the steps are read.
void drop_static_rigid_velocities(Reader& r);

/// The sorted nodes of the cells of cell block `block`.
std::vector<Index> block_nodes(const mesh::Mesh& mesh, const std::string& block);
/// <rigid_connector> of <Rigid>: joints, springs, dampers and contractile forces
/// (connectors.cpp).
void read_rigid_connector(Reader& r, pugi::xml_node node);
/// <Constraints>: rigid walls, symmetry planes, fixed normal displacements and linear constraint
/// sets as [[constraint]]s (constraints.cpp).
void read_constraints(Reader& r, pugi::xml_node section);
/// bc type "linear constraint" of a Boundary section: one linear [[constraint]] (constraints.cpp;
/// refused inside a step).
void read_linear_constraint_bc(Reader& r, pugi::xml_node bc, bool step);
/// The name of a [[rigid_body]] for FEBio's body `name` (letters, digits and _ only).
std::string rigid_body_name(std::string name);
/// Contact: each <contact> of a supported type as a contact pair of its <SurfacePair> (in
/// `mesh`): slave = the primary surface, master = the secondary one.
void read_contact(Reader& r, pugi::xml_node section, pugi::xml_node mesh);
/// FEBio's natural condition of mixtures (no flux through a face without a condition): every
/// boundary face of the mixture cells whose nodes are not all drained, and that is not a face
/// of a contact surface (the contact couples the fluid there), becomes part of an impermeable
/// surface (one per smooth patch).
void add_impermeable_faces(Reader& r);

} // namespace trifem::feb::detail
