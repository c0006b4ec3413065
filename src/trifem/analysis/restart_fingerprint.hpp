// SPDX-License-Identifier: MIT
// The fingerprint of a case that a restart file carries: one hash per part of the case the
// state of a run depends on (mesh, degrees of freedom, materials, conditions, ...), so that a
// restart of another case is refused with the parts that differ named. Settings that do not
// change the state up to a restart time (title, output, solver, time steps, the end of the run)
// are not part of it: a run may be continued with other output or a later end time.
#pragma once

#include "trifem/core/digest.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace trifem::analysis {

/// The parts of a case fingerprint, in the order a restart file stores them.
enum class CasePart : std::size_t {
  Mesh,               ///< nodes, cells, cell blocks, node sets, surfaces, cell data
  DegreesOfFreedom,   ///< fields, numbering, ties, the DOFs of the case's and steps' conditions
  Materials,          ///< every material (law, parameters, constituents, axes, element) and
                      ///< the material of every cell block
  BoundaryConditions, ///< [boundary] conditions, [loads], baths and [curves]
  Contact,            ///< [[contact]] pairs
  RigidBodies,        ///< [[rigid_body]] tables
  Steps,              ///< [[step]] conditions, loads, release times and start times
  AnalysisOptions,    ///< [analysis], [electrochemistry] and the model of [explicit]
};
inline constexpr std::size_t kCaseParts = 8;

/// The part's name in messages, e.g. "materials" (BoundaryConditions: "boundary conditions",
/// which covers the loads and curves too; AnalysisOptions: "analysis options").
std::string_view case_part_name(CasePart part);

/// One hash per CasePart.
using CaseFingerprint = std::array<std::uint64_t, kCaseParts>;

/// The fingerprint of `spec` and of `model`, built from it. It does not depend on the state,
/// the active step or the time: the model of a run and that of its restart give the same.
CaseFingerprint case_fingerprint(const io::CaseSpec& spec, const model::Model& model);

} // namespace trifem::analysis
