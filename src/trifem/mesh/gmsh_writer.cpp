// SPDX-License-Identifier: MIT
// Gmsh MSH 4.1 ASCII writer: the inverse of read_gmsh for trifem's meshes of any cell family.
#include "trifem/mesh/gmsh_writer.hpp"

#include "trifem/core/error.hpp"
#include "trifem/mesh/gmsh_element_types.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace trifem::mesh {
namespace {

using Buffer = fmt::memory_buffer;

/// Fails on a name that read_gmsh would not read back as it is.
void check_name(std::string_view kind, const std::string& name) {
  const bool blank_edge = !name.empty() && (name.front() == ' ' || name.front() == '\t' ||
                                            name.back() == ' ' || name.back() == '\t');
  TRIFEM_CHECK(!name.empty() && !blank_edge && name.find_first_of("\r\n") == std::string::npos,
               "{} '{}' cannot be written to a Gmsh file (a physical name must be non-empty, "
               "on one line and without surrounding blanks)",
               kind, name);
}

/// Consecutive cells of one type in the same cell blocks: one volume entity with those physical
/// tags.
struct CellRun {
  Index first = 0;
  Index end = 0;
  std::vector<int> physicals;
};

/// Gmsh's element type of a cell type (its node order is trifem's).
int gmsh_type(CellType type) {
  switch (type) {
  case CellType::Hex8:
    return kGmshHex8;
  case CellType::Tet4:
    return kGmshTet4;
  case CellType::Tet10:
    return kGmshTet10;
  case CellType::Penta6:
    return kGmshPrism6;
  case CellType::Hex20:
    return kGmshHex20;
  }
  return kGmshHex8;
}

/// Gmsh's element type of a facet of a cell (a free facet, cell -1, is written as a quad4 whose
/// fourth node may repeat its third: a triangle of a surface mesh).
int gmsh_type(const Facet& f) {
  if (f.cell < 0)
    return kGmshQuad4;
  switch (f.type) {
  case FacetType::Tri3:
    return kGmshTri3;
  case FacetType::Tri6:
    return kGmshTri6;
  case FacetType::Quad4:
    return kGmshQuad4;
  case FacetType::Quad8:
    return kGmshQuad8;
  }
  return kGmshQuad4;
}

/// The nodes of facet f as its Gmsh element lists them.
std::vector<Index> facet_nodes(const Facet& f) {
  if (f.cell < 0)
    return {f.nodes.begin(), f.nodes.end()};
  std::vector<Index> nodes;
  for (int a = 0; a < f.num_nodes(); ++a)
    nodes.push_back(f.node(a));
  return nodes;
}

/// The facets of a surface grouped by Gmsh element type, in facet order within each type.
std::vector<std::pair<int, std::vector<const Facet*>>> facet_blocks(const Surface& surface) {
  std::vector<std::pair<int, std::vector<const Facet*>>> blocks;
  for (const Facet& f : surface.facets) {
    const int type = gmsh_type(f);
    auto it = std::find_if(blocks.begin(), blocks.end(),
                           [&](const auto& block) { return block.first == type; });
    if (it == blocks.end())
      it = blocks.insert(blocks.end(), {type, {}});
    it->second.push_back(&f);
  }
  return blocks;
}

/// The runs of cells with equal block membership, blocks tagged 1, 2, ... in name order.
std::vector<CellRun> cell_runs(const Mesh& mesh) {
  std::vector<std::vector<int>> physicals(static_cast<std::size_t>(mesh.num_cells()));
  int tag = 0;
  for (const auto& [name, cells] : mesh.cell_blocks()) {
    ++tag;
    check_name("cell block", name);
    TRIFEM_CHECK(!cells.empty(),
                 "cell block '{}' is empty: an empty physical volume cannot be "
                 "written to a Gmsh file",
                 name);
    for (Index c : cells)
      physicals[static_cast<std::size_t>(c)].push_back(tag);
  }
  std::vector<CellRun> runs;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    std::vector<int>& p = physicals[static_cast<std::size_t>(c)];
    TRIFEM_CHECK(!p.empty(),
                 "cell {} is in no cell block: a Gmsh file would put it into a block "
                 "'unassigned'",
                 c);
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (runs.empty() || runs.back().physicals != p ||
        mesh.cell_type(runs.back().first) != mesh.cell_type(c))
      runs.push_back({c, c, p});
    runs.back().end = c + 1;
  }
  return runs;
}

/// The sorted, unique nodes of the cells of a block.
std::vector<Index> block_nodes(const Mesh& mesh, const std::vector<Index>& cells) {
  std::vector<Index> nodes;
  for (Index c : cells)
    nodes.insert(nodes.end(), mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

/// A node set written as a physical point group.
struct NamedNodes {
  const std::string* name;
  const std::vector<Index>* nodes;
};

/// The node sets read_gmsh does not re-create: all but those of the surfaces and those equal to
/// the nodes of the cell block of their name.
std::vector<NamedNodes> point_groups(const Mesh& mesh) {
  std::vector<NamedNodes> groups;
  for (const auto& [name, nodes] : mesh.node_sets()) {
    if (mesh.has_surface(name))
      continue;
    if (mesh.has_cell_block(name) && block_nodes(mesh, mesh.cell_block(name)) == nodes)
      continue;
    check_name("node set", name);
    TRIFEM_CHECK(!nodes.empty(),
                 "node set '{}' is empty: an empty physical group cannot be "
                 "written to a Gmsh file",
                 name);
    groups.push_back({&name, &nodes});
  }
  return groups;
}

/// Bounding box "xmin ymin zmin xmax ymax zmax" of some nodes.
template <class Nodes>
std::string bounding_box(const Mesh& mesh, const Nodes& nodes) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = -lo;
  for (Index n : nodes) {
    lo = lo.cwiseMin(mesh.node(n));
    hi = hi.cwiseMax(mesh.node(n));
  }
  return fmt::format("{} {} {} {} {} {}", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

/// Everything to write, with the physical tags of each kind numbered from 1.
struct Layout {
  std::vector<CellRun> runs;
  std::vector<NamedNodes> points;
};

void write_physical_names(const Mesh& mesh, const Layout& l, Buffer& b) {
  const std::size_t count = mesh.cell_blocks().size() + mesh.surfaces().size() + l.points.size();
  fmt::format_to(std::back_inserter(b), "$PhysicalNames\n{}\n", count);
  int tag = 0;
  for (const NamedNodes& p : l.points)
    fmt::format_to(std::back_inserter(b), "0 {} \"{}\"\n", ++tag, *p.name);
  tag = 0;
  for (const auto& [name, surface] : mesh.surfaces()) {
    check_name("surface", name);
    TRIFEM_CHECK(!surface.facets.empty(),
                 "surface '{}' is empty: an empty physical surface "
                 "cannot be written to a Gmsh file",
                 name);
    fmt::format_to(std::back_inserter(b), "2 {} \"{}\"\n", ++tag, name);
  }
  tag = 0;
  for (const auto& entry : mesh.cell_blocks())
    fmt::format_to(std::back_inserter(b), "3 {} \"{}\"\n", ++tag, entry.first);
  fmt::format_to(std::back_inserter(b), "$EndPhysicalNames\n");
}

void write_entities(const Mesh& mesh, const Layout& l, Buffer& b) {
  auto out = std::back_inserter(b);
  fmt::format_to(out, "$Entities\n{} 0 {} {}\n", l.points.size(), mesh.surfaces().size(),
                 l.runs.size());
  int tag = 0;
  for (const NamedNodes& p : l.points) {
    const Vec3& x = mesh.node(p.nodes->front());
    ++tag;
    fmt::format_to(out, "{} {} {} {} 1 {}\n", tag, x[0], x[1], x[2], tag);
  }
  tag = 0;
  for (const auto& [name, surface] : mesh.surfaces()) {
    std::vector<Index> nodes = surface_nodes(surface);
    ++tag;
    fmt::format_to(out, "{} {} 1 {} 0\n", tag, bounding_box(mesh, nodes), tag);
  }
  tag = 0;
  for (const CellRun& run : l.runs) {
    std::vector<Index> nodes;
    for (Index c = run.first; c < run.end; ++c)
      nodes.insert(nodes.end(), mesh.cell_nodes(c).begin(), mesh.cell_nodes(c).end());
    fmt::format_to(out, "{} {} {}", ++tag, bounding_box(mesh, nodes), run.physicals.size());
    for (int p : run.physicals)
      fmt::format_to(out, " {}", p);
    fmt::format_to(out, " 0\n");
  }
  fmt::format_to(out, "$EndEntities\n");
}

void write_nodes(const Mesh& mesh, Buffer& b) {
  auto out = std::back_inserter(b);
  const Index n = mesh.num_nodes();
  fmt::format_to(out, "$Nodes\n1 {} 1 {}\n3 1 0 {}\n", n, n, n);
  for (Index i = 0; i < n; ++i)
    fmt::format_to(out, "{}\n", i + 1);
  for (const Vec3& x : mesh.nodes())
    fmt::format_to(out, "{} {} {}\n", x[0], x[1], x[2]);
  fmt::format_to(out, "$EndNodes\n");
}

void write_elements(const Mesh& mesh, const Layout& l, Buffer& b) {
  auto out = std::back_inserter(b);
  std::size_t count = static_cast<std::size_t>(mesh.num_cells()), blocks = l.runs.size();
  for (const auto& entry : mesh.surfaces()) {
    count += entry.second.facets.size();
    blocks += facet_blocks(entry.second).size();
  }
  for (const NamedNodes& p : l.points)
    count += p.nodes->size();
  fmt::format_to(out, "$Elements\n{} {} 1 {}\n", blocks + l.points.size(), count, count);
  std::size_t tag = 0;
  int entity = 0;
  for (const CellRun& run : l.runs) {
    fmt::format_to(out, "3 {} {} {}\n", ++entity, gmsh_type(mesh.cell_type(run.first)),
                   run.end - run.first);
    for (Index c = run.first; c < run.end; ++c) {
      fmt::format_to(out, "{}", ++tag);
      for (Index node : mesh.cell_nodes(c))
        fmt::format_to(out, " {}", node + 1);
      fmt::format_to(out, "\n");
    }
  }
  entity = 0;
  for (const auto& entry : mesh.surfaces()) {
    ++entity;
    for (const auto& [type, facets] : facet_blocks(entry.second)) {
      fmt::format_to(out, "2 {} {} {}\n", entity, type, facets.size());
      for (const Facet* f : facets) {
        fmt::format_to(out, "{}", ++tag);
        for (Index node : facet_nodes(*f))
          fmt::format_to(out, " {}", node + 1);
        fmt::format_to(out, "\n");
      }
    }
  }
  entity = 0;
  for (const NamedNodes& p : l.points) {
    fmt::format_to(out, "0 {} {} {}\n", ++entity, kGmshPoint, p.nodes->size());
    for (Index node : *p.nodes)
      fmt::format_to(out, "{} {}\n", ++tag, node + 1);
  }
  fmt::format_to(out, "$EndElements\n");
}

} // namespace

void write_gmsh(const Mesh& mesh, std::ostream& out) {
  TRIFEM_CHECK(mesh.num_cells() > 0, "the mesh has no cells: nothing to write to a Gmsh file");
  const Layout layout{cell_runs(mesh), point_groups(mesh)};
  Buffer b;
  fmt::format_to(std::back_inserter(b), "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  write_physical_names(mesh, layout, b);
  write_entities(mesh, layout, b);
  write_nodes(mesh, b);
  write_elements(mesh, layout, b);
  out.write(b.data(), static_cast<std::streamsize>(b.size()));
}

void write_gmsh(const Mesh& mesh, const std::filesystem::path& file) {
  std::ofstream out(file, std::ios::binary);
  TRIFEM_CHECK(out.is_open(), "{}: cannot write the mesh file", file.string());
  write_gmsh(mesh, out);
  out.close();
  TRIFEM_CHECK(out.good(), "{}: error while writing the mesh file", file.string());
}

} // namespace trifem::mesh
