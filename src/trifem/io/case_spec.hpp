// SPDX-License-Identifier: MIT
// Typed contents of a case file. The case reader fills it (every key validated); the
// application turns it into a model. No TOML types leak past the reader.
#pragma once

#include "trifem/dofs/load_curve.hpp"
#include "trifem/material/schema.hpp"
#include "trifem/mesh/box.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace trifem::io {

/// [[mesh.box]]: a structured box; `material` assigns its cell block.
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

/// [materials.<name>]: a solid law and its parameters.
struct MaterialSpec {
  std::string type;
  material::ParameterValues parameters;
};

/// [curves.<name>]
struct CurveSpec {
  dofs::Interpolation interpolation = dofs::Interpolation::Linear;
  std::vector<std::pair<Real, Real>> points;
};

/// Displacement component selector: 0 = x, 1 = y, 2 = z.
using Component = int;

/// [[boundary.fixed]]: zero displacement components on a node set.
struct FixedSpec {
  std::string set;
  std::vector<Component> components;
};

/// [[boundary.prescribed]]: u_component = value * curve(t) on a node set.
struct PrescribedSpec {
  std::string set;
  Component component = 0;
  Real value = 0.0;
  std::string curve; ///< empty: constant 1
};

/// [[loads.pressure]]: follower pressure on a surface (positive pushes into the body) [MPa].
struct PressureSpec {
  std::string surface;
  Real value = 0.0;
  std::string curve;
};

/// [[loads.traction]]: dead traction per reference area on a surface [MPa].
struct TractionSpec {
  std::string surface;
  Vec3 value = Vec3::Zero();
  std::string curve;
};

/// [time]
struct TimeSpec {
  Real end_time = 1.0;  ///< end of the analysis [s]
  Real dt = 0.1;        ///< initial step [s]
  Real dt_min = 0.0;    ///< smallest step before the run fails [s]; 0 means dt * 1e-6
  Real dt_max = 0.0;    ///< largest step [s]; 0 means dt
  int target_iterations = 6; ///< steps that converge in at most this many iterations grow dt
  Real growth = 1.5;    ///< step growth factor (>= 1)
  Real cutback = 0.5;   ///< step cutback factor in (0, 1)
};

/// [solver]
struct SolverSpec {
  int max_iterations = 20;
  Real residual_tolerance = 1e-8;  ///< relative to the characteristic residual of each field
  Real increment_tolerance = 1e-8; ///< relative to the characteristic size of each field
  bool line_search = true;
  std::string linear_solver = "umfpack"; ///< "umfpack" or "sparselu"
};

/// [[output.reaction]]: total reaction force on a node set, in history.csv.
struct ReactionSpec {
  std::string set;
};

/// [[output.probe]]: a nodal quantity at the node nearest to `point`, in history.csv.
struct ProbeSpec {
  std::string name;
  std::string quantity = "displacement"; ///< "displacement" or "position"
  Vec3 point = Vec3::Zero();
};

/// [output]
struct OutputSpec {
  Real interval = 0.0;       ///< VTU output every `interval` s (0: every step)
  std::vector<Real> times;   ///< extra output times (must points)
  bool vtu = true;
  std::vector<ReactionSpec> reactions;
  std::vector<ProbeSpec> probes;
};

/// A whole case file.
struct CaseSpec {
  std::filesystem::path file; ///< the case file itself (for messages and relative paths)
  std::string title;
  std::vector<BoxMeshSpec> boxes;
  std::vector<GmshMeshSpec> gmsh;
  std::map<std::string, MaterialSpec> materials;
  std::map<std::string, CurveSpec> curves;
  std::vector<FixedSpec> fixed;
  std::vector<PrescribedSpec> prescribed;
  std::vector<PressureSpec> pressures;
  std::vector<TractionSpec> tractions;
  TimeSpec time;
  SolverSpec solver;
  OutputSpec output;
};

} // namespace trifem::io
