// SPDX-License-Identifier: MIT
// Unstructured mesh of hex8, tet4, tet10, penta6 and hex20 cells (cell_type.hpp) with named
// node sets, surfaces and cell blocks.
// The mesh knows geometry and topology only: no DOFs, no fields.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/mesh/cell_type.hpp"
#include "trifem/tensor/tensor.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace trifem::mesh {

/// Hex8 connectivity (VTK/Gmsh order, see hex_faces.hpp).
using Hex8 = std::array<Index, 8>;

/// A boundary facet: a face of `cell` (its face `local_face` of cell_faces(); for a hex8 that of
/// kHexFaces) or, with cell −1, a facet of a surface mesh that bounds no cell (a rigid bone
/// surface), whose normal comes from its node order. `nodes` are its corners, ordered so that
/// the right-hand rule gives the normal pointing out of `cell`; a triangle's fourth corner
/// repeats its third (a surface mesh's triangles are such quads, of type Quad4). A quadratic
/// facet (tri6, quad8: faces of tet10 and hex20 cells) also has its mid-edge nodes.
struct Facet {
  std::array<Index, 4> nodes{};
  Index cell = -1;
  int local_face = -1;
  FacetType type = FacetType::Quad4;
  std::array<Index, 4> mid_edge_nodes{-1, -1, -1, -1}; ///< tri6: 3, quad8: 4, else none

  bool bounds_cell() const { return cell >= 0; }
  /// A quad4 facet (or a triangle of a surface mesh as a quad): what the facet kernels of
  /// contact, baths, fluxes and frames take so far.
  bool is_quad4() const { return type == FacetType::Quad4; }
  int num_nodes() const { return mesh::num_nodes(type); }
  int num_corners() const { return mesh::num_corners(type); }
  /// Node i in the order of its type: the corners, then the mid-edge nodes.
  Index node(int i) const {
    const int corners = num_corners();
    return i < corners ? nodes[static_cast<std::size_t>(i)]
                       : mid_edge_nodes[static_cast<std::size_t>(i - corners)];
  }
};

/// A named surface: a list of oriented facets.
struct Surface {
  std::vector<Facet> facets;
};

/// Named per-cell data (e.g. a Gmsh $ElementData view): `components` numbers per cell, NaN for
/// the cells the data does not cover.
struct CellData {
  int components = 1;
  std::vector<Real> values; ///< cell-major: component k of cell c is values[c * components + k]

  /// True if cell c has a value (its components are not NaN).
  bool covers(Index c) const;
  /// Component k of cell c (NaN if the cell is not covered).
  Real value(Index c, int k) const {
    return values[static_cast<std::size_t>(c) * static_cast<std::size_t>(components) +
                  static_cast<std::size_t>(k)];
  }
};

/// Where a run of cells came from, for messages: cell `first` + i was read from `file` as its
/// element `tags[i]` (a Gmsh element tag, a .feb element id), called there a `what`.
struct CellSource {
  std::string file;
  std::string what = "element";
  Index first = 0;
  std::vector<long long> tags;
};

/// A mesh with named sets. Names are unique per kind.
class Mesh {
public:
  /// Appends a node at reference position x; returns its index.
  Index add_node(const Vec3& x);
  /// Appends a hex8 cell; returns its index. Nodes must exist. The cell has no cell data (NaN).
  Index add_cell(const Hex8& nodes);
  /// Appends a cell of `type` whose num_nodes(type) nodes are in the order of cell_type.hpp;
  /// returns its index. Nodes must exist. The cell has no cell data (NaN).
  Index add_cell(CellType type, std::span<const Index> nodes);

  Index num_nodes() const { return static_cast<Index>(nodes_.size()); }
  Index num_cells() const { return static_cast<Index>(cell_types_.size()); }
  const Vec3& node(Index i) const { return nodes_[i]; }
  const std::vector<Vec3>& nodes() const { return nodes_; }
  CellType cell_type(Index c) const { return cell_types_[static_cast<std::size_t>(c)]; }
  /// The nodes of cell c in the order of its type.
  std::span<const Index> cell_nodes(Index c) const {
    const auto first = static_cast<std::size_t>(cell_offsets_[static_cast<std::size_t>(c)]);
    const auto last = static_cast<std::size_t>(cell_offsets_[static_cast<std::size_t>(c) + 1]);
    return {cell_node_list_.data() + first, last - first};
  }
  /// The nodes of hex8 cell c (a program error if cell c is of another type: code that takes
  /// any cell reads cell_nodes()).
  Hex8 cell(Index c) const;
  /// True if every cell is a hex8 (so for a mesh without cells).
  bool all_hex8() const { return std::ranges::all_of(cell_types_, is_hex8); }
  /// The first cell that is not a hex8, −1 if none.
  Index first_non_hex8() const;

  /// Registers a named node set (sorted, duplicates removed). Throws InputError on a name clash.
  void add_node_set(const std::string& name, std::vector<Index> nodes);
  /// Registers a named surface and, under the same name, the node set of its nodes.
  void add_surface(const std::string& name, Surface surface);
  /// Registers a named cell block.
  void add_cell_block(const std::string& name, std::vector<Index> cells);

  bool has_node_set(const std::string& name) const { return node_sets_.contains(name); }
  bool has_surface(const std::string& name) const { return surfaces_.contains(name); }
  bool has_cell_block(const std::string& name) const { return cell_blocks_.contains(name); }

  /// Named lookups; throw InputError naming the missing set and listing the available ones.
  const std::vector<Index>& node_set(const std::string& name) const;
  const Surface& surface(const std::string& name) const;
  const std::vector<Index>& cell_block(const std::string& name) const;

  const std::map<std::string, std::vector<Index>>& node_sets() const { return node_sets_; }
  const std::map<std::string, Surface>& surfaces() const { return surfaces_; }
  const std::map<std::string, std::vector<Index>>& cell_blocks() const { return cell_blocks_; }

  /// Registers named cell data; `data.values` holds num_cells() * components numbers
  /// (components >= 1). Throws InputError on a name clash or a wrong size.
  void add_cell_data(const std::string& name, CellData data);
  bool has_cell_data(const std::string& name) const { return cell_data_.contains(name); }
  /// Named lookup; throws InputError naming the missing data and listing the available ones.
  const CellData& cell_data(const std::string& name) const;
  const std::map<std::string, CellData>& cell_data() const { return cell_data_; }

  /// Records where the cells [source.first, source.first + source.tags.size()) came from.
  void add_cell_source(CellSource source);
  /// "element 12 of 'cube.msh'" for a cell read from a file; empty for a cell made otherwise (a
  /// box, a refinement).
  std::string cell_origin(Index c) const;
  /// How messages name cell c: "element 12 of 'cube.msh'" (cell_origin), or "cell 3" for a
  /// cell of no file.
  std::string describe(Index c) const;

  /// Moves every node: x <- A x + b (e.g. to rotate or translate a part). Cell data is kept as
  /// it is (it is not known to be a vector).
  void transform(const Mat3& A, const Vec3& b = Vec3::Zero());

  /// Appends another mesh (nodes and cells renumbered; names kept, clashes are errors).
  /// Nodes are not merged: separate bodies stay separate (contact later joins them).
  /// Cell data of the same name in both meshes is joined (InputError if the numbers of
  /// components differ); the cells of a mesh without some data get NaN in it.
  void append(const Mesh& other);

  /// For each quad (four node indices, any order), the outward-oriented facet of the hex8 face
  /// with exactly these nodes. Throws InputError naming the first quad that is no cell face.
  std::vector<Facet> find_facets(const std::vector<std::array<Index, 4>>& quads) const;

  /// For each quad (its node order is its orientation; a triangle's fourth node repeats its
  /// third), the facet of the cell face with these corners, oriented outward (with the cell
  /// face's own type and mid-edge nodes): of the cells that have the quad as a face, the one
  /// whose face lists its corners in the same cyclic order (an interior face names its side by
  /// its orientation), else the first; a quad that is no cell's face stays as given (cell −1,
  /// type Quad4: a surface mesh). Only the quads are hashed, so this stays cheap for large
  /// meshes.
  std::vector<Facet> orient_quads(const std::vector<std::array<Index, 4>>& quads) const;

  /// Facets of all cell faces that belong to exactly one cell (the mesh boundary), ordered by
  /// cell and local face.
  std::vector<Facet> boundary_facets() const;
  /// The same for the region of the cells c with inside[c] != 0: the faces of its cells that no
  /// other cell of the region shares.
  std::vector<Facet> boundary_facets(const std::vector<char>& inside) const;

private:
  /// Joins the cell data of `other`, whose cells were appended from `cell_offset` on.
  void append_cell_data(const Mesh& other, Index cell_offset);

  static bool is_hex8(CellType type) { return type == CellType::Hex8; }

  std::vector<Vec3> nodes_;
  std::vector<CellType> cell_types_;
  std::vector<Index> cell_offsets_ = {0}; ///< cell c's nodes: cell_node_list_[offsets c..c+1)
  std::vector<Index> cell_node_list_;
  std::map<std::string, std::vector<Index>> node_sets_;
  std::map<std::string, Surface> surfaces_;
  std::map<std::string, std::vector<Index>> cell_blocks_;
  std::map<std::string, CellData> cell_data_;
  std::vector<CellSource> cell_sources_; ///< in increasing `first`
};

/// Sorted, unique node indices of a surface.
std::vector<Index> surface_nodes(const Surface& surface);

/// The area vector of a facet's corners in the reference configuration, ½ (x2 − x0) × (x3 − x1)
/// (exact for a flat quad; for a triangle, whose last corner repeats the third, its area
/// vector; a curved quadratic facet's is that of its corners).
Vec3 facet_area_vector(const Mesh& mesh, const Facet& facet);

/// The mean facet size √(area) of a surface in the reference configuration [length].
Real mean_facet_size(const Mesh& mesh, const Surface& surface);

/// Shortest and longest cell edge of a mesh [length].
struct EdgeRange {
  Real min = 0.0;
  Real max = 0.0;
};

/// The range of the lengths of the cells' edges between corners in the reference mesh.
EdgeRange edge_length_range(const Mesh& mesh);

} // namespace trifem::mesh
