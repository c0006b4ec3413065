// SPDX-License-Identifier: MIT
// Writer of TOML case files: the inverse of read_case for what the front ends produce (the
// FEBio reader), e.g. for `trifem convert model.feb -o case.toml`.
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace trifem::io {

/// The TOML text of `spec`, which read_case reads back into the same case: mesh references
/// ([[mesh.gmsh]]), materials (solid laws, solid mixtures, biphasic and triphasic mixtures with
/// their transport laws), curves, boundary conditions, loads, [analysis] and [electrochemistry]
/// where they differ from the defaults, [time] or the [[step]]s, [solver] and [output]. Numbers
/// are written in the shortest form that reads back bitwise. `spec.meshes` must be empty (the
/// inline meshes are written by write_case). InputError naming the member for what the writer
/// does not support (boxes, contact, rigid bodies, material axes, dynamic-explicit analyses),
/// rather than a case that would differ.
std::string case_toml(const CaseSpec& spec);

/// Writes `spec` as the TOML case `file` (created or overwritten). Each inline mesh is written
/// next to it as a Gmsh MSH 4.1 file (mesh::write_gmsh), `<stem>.msh` (several meshes:
/// `<stem>_1.msh`, `<stem>_2.msh`, ...), referenced by a [[mesh.gmsh]] table with the block ->
/// material map. Existing Gmsh meshes of `spec` keep their files, referenced by absolute path.
/// Returns the files written, the case file first.
std::vector<std::filesystem::path> write_case(const CaseSpec& spec,
                                              const std::filesystem::path& file);

} // namespace trifem::io
