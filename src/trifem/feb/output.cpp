// SPDX-License-Identifier: MIT
// Output section: logfile node and element data -> history.csv reactions and probes.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <set>

namespace trifem::feb::detail {
namespace {

/// Logfile data of more items than this are not turned into probes (one column group each).
constexpr std::size_t kMaxProbes = 16;

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t end = std::min(s.find(';', start), s.size());
    if (end > start)
      out.push_back(s.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

/// True if every variable of `data` is in `names`.
bool all_in(const std::vector<std::string>& data, std::initializer_list<std::string_view> names) {
  for (const std::string& d : data)
    if (std::find(names.begin(), names.end(), d) == names.end())
      return false;
  return !data.empty();
}

/// The FEBio ids of the items of a logfile entry: its set attribute, its text, or all.
std::vector<long> item_ids(const Reader& r, pugi::xml_node d, bool nodes) {
  const std::map<long, Index>& index = nodes ? r.node_index : r.cell_index;
  std::vector<long> ids;
  const char* set_key = nodes ? "node_set" : "elem_set";
  if (d.attribute(set_key)) {
    const std::vector<Index>& members = nodes ? r.mesh.mesh.node_set(r.node_set(d, set_key))
                                              : r.mesh.mesh.cell_block(r.doc.attribute(d, set_key));
    const std::set<Index> wanted(members.begin(), members.end());
    for (const auto& [id, i] : index)
      if (wanted.contains(i))
        ids.push_back(id);
  } else if (!r.doc.text(d).empty()) {
    ids = r.doc.ids(d);
  } else {
    for (const auto& entry : index)
      ids.push_back(entry.first);
  }
  return ids;
}

/// The mean of the cell's corners.
Vec3 centroid(const mesh::Mesh& mesh, Index cell) {
  Vec3 c = Vec3::Zero();
  const std::span<const Index> corners = mesh.cell_nodes(cell).first(
      static_cast<std::size_t>(mesh::num_corners(mesh.cell_type(cell))));
  for (Index n : corners)
    c += mesh.node(n) / static_cast<Real>(corners.size());
  return c;
}

/// Probes of `quantity` at the items of a logfile entry.
void add_probes(Reader& r, pugi::xml_node d, bool nodes, const std::string& quantity) {
  const std::vector<long> ids = item_ids(r, d, nodes);
  if (ids.size() > kMaxProbes) {
    r.warn(d, fmt::format("{} items: more than {} are not written to history.csv (ignored; "
                          "give a smaller set)",
                          ids.size(), kMaxProbes));
    return;
  }
  for (long id : ids) {
    const auto& index = nodes ? r.node_index : r.cell_index;
    const auto it = index.find(id);
    if (it == index.end())
      r.doc.fail(d, fmt::format("{} id {} is not defined", nodes ? "node" : "element", id));
    io::ProbeSpec p;
    p.name = fmt::format("{}{}_{}", nodes ? "node" : "elem", id, quantity);
    p.quantity = quantity;
    p.point = nodes ? r.mesh.mesh.node(it->second) : centroid(r.mesh.mesh, it->second);
    const bool seen = std::any_of(r.spec.output.probes.begin(), r.spec.output.probes.end(),
                                  [&](const io::ProbeSpec& q) { return q.name == p.name; });
    if (!seen)
      r.spec.output.probes.push_back(std::move(p));
  }
}

void read_log_entry(Reader& r, pugi::xml_node d) {
  const std::string_view kind = d.name();
  const std::vector<std::string> data = split(d.attribute("data").value());
  if (kind == "node_data" && all_in(data, {"Rx", "Ry", "Rz"}) && d.attribute("node_set")) {
    const std::string set = r.node_set(d);
    const bool seen = std::any_of(r.spec.output.reactions.begin(), r.spec.output.reactions.end(),
                                  [&](const io::ReactionSpec& s) { return s.set == set; });
    if (!seen)
      r.spec.output.reactions.push_back({set});
  } else if (kind == "node_data" && all_in(data, {"ux", "uy", "uz"})) {
    add_probes(r, d, true, "displacement");
  } else if (kind == "node_data" && all_in(data, {"x", "y", "z"})) {
    add_probes(r, d, true, "position");
  } else if (kind == "element_data" && all_in(data, {"sx", "sy", "sz", "sxy", "syz", "sxz"})) {
    add_probes(r, d, false, "stress");
  } else if (kind == "element_data" && all_in(data, {"p"})) {
    add_probes(r, d, false, "fluid_pressure");
  } else if (kind == "element_data" && all_in(data, {"J"})) {
    add_probes(r, d, false, "relative_volume");
  } else {
    r.warn(d, "this logfile data has no history.csv equivalent yet (ignored)");
  }
}

} // namespace

void read_output(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node c : elements(section)) {
    const std::string_view kind = c.name();
    if (kind == "plotfile")
      continue; // trifem writes its own VTU files
    if (kind != "logfile") {
      r.warn(c, fmt::format("<{}> output is not supported (ignored)", kind));
      continue;
    }
    for (pugi::xml_node d : c.children())
      if (d.type() == pugi::node_element)
        read_log_entry(r, d);
  }
}

} // namespace trifem::feb::detail
