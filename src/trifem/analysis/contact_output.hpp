// SPDX-License-Identifier: MIT
// Contact output of a run: per [[contact]] pair a VTU series of the slave surface in the
// current configuration (contact<i>.pvd), a CSV of the interface quantities along the surface
// at the same output times, and the pair's history.csv columns. On several processes each
// writes its piece of the surface (the facets of its nodes), listed by rank 0's .pvtu file.
#pragma once

#include "trifem/io/pvd_writer.hpp"
#include "trifem/io/vtu_writer.hpp"
#include "trifem/model/model.hpp"

#include <filesystem>
#include <memory>

namespace trifem::analysis {

/// Nodal arrays of one contact pair in physical units, one value (or vector) per slave node in
/// the order of `states` (= ContactTerm::slave_states of the model's state): gap, traction,
/// potentials and normal fluxes (mixtures), active and projected flags, friction traction and
/// slipping flag (friction), slave normal and nodal
/// area (docs/input.md, "Contact output").
std::vector<io::DataArray> contact_arrays(const model::Model& model,
                                          const std::vector<contact::SlaveNodeState>& states);

/// Positions in `nodes` (mesh nodes) ordered along the surface they form: by the reference
/// coordinate with the largest extent over the nodes, ties by the next largest, then the last
/// (coordinates equal to 1e-9 of the largest extent count as ties).
std::vector<Index> surface_order(const mesh::Mesh& mesh, const std::vector<Index>& nodes);

/// history.csv columns of every pair i (from 1): slave force contact<i>.Fx/Fy/Fz [N], master
/// force contact<i>.master_Fx/Fy/Fz [N], contact<i>.area [mm^2], contact<i>.active_nodes.
std::vector<std::string> contact_history_columns(const model::Model& model);

/// Appends the values of contact_history_columns() in the model's current state to `row`.
void append_contact_history(const model::Model& model, std::vector<double>& row);

/// Writes the surface files of every contact pair i at the output states of a run:
/// contact<i>_NNNN.vtu listed in contact<i>.pvd, and contact<i>_surface_NNNN.csv. On several
/// processes the VTU state is contact<i>_NNNN.pvtu, whose pieces contact<i>_NNNN_P.vtu each
/// process P writes.
class ContactOutput {
public:
  /// In `directory` (which must exist). `writes_files`: this process writes the .pvd, .pvtu
  /// and CSV files (it starts an empty contact<i>.pvd per pair); the others write only their
  /// pieces.
  ContactOutput(const model::Model& model, std::filesystem::path directory, bool writes_files);

  /// Writes the files numbered `number` of the model's current state at `time`; the VTU file
  /// only if `vtu` is set.
  void write(Real time, int number, bool vtu);

private:
  void write_vtu(const std::filesystem::path& stem, Real time, std::size_t pair,
                 io::UnstructuredGrid grid);

  void write_csv(const std::filesystem::path& file, Real time, const contact::ContactTerm& pair,
                 const std::vector<contact::SlaveNodeState>& states,
                 const std::vector<io::DataArray>& arrays) const;

  const model::Model& model_;
  std::filesystem::path directory_;
  bool writes_files_;
  std::vector<std::unique_ptr<io::PvdWriter>> pvd_;
  /// On several processes: per pair, this process's slave facets (positions in the slave
  /// surface's facet list); empty on one process.
  std::vector<std::vector<Index>> piece_facets_;
};

} // namespace trifem::analysis
