// SPDX-License-Identifier: MIT
#include "trifem/feb/feb_reader.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/log.hpp"
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <system_error>

namespace trifem::feb {
namespace {

using detail::Reader;
using detail::Version;

std::string display_name(const std::filesystem::path& file) {
  return file.empty() ? std::string("<feb>") : file.string();
}

std::string read_text(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError(
        fmt::format("{}: cannot open the FEBio file (it is a directory)", display_name(file)));
  std::ifstream in(file, std::ios::binary);
  if (!in)
    throw InputError(
        fmt::format("{}: cannot open the FEBio file ({})", display_name(file),
                    std::error_code(errno ? errno : ENOENT, std::generic_category()).message()));
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The format version of the root element: 4.0 or 3.0; older ones are refused.
Version version(const Document& doc, pugi::xml_node root) {
  if (std::string_view(root.name()) != "febio_spec")
    doc.fail(root, "not an FEBio file: the root element must be <febio_spec>");
  const std::string v = doc.attribute(root, "version");
  if (v == "4.0")
    return Version::V4;
  if (v == "3.0")
    return Version::V3;
  doc.fail(root, "version",
           fmt::format("FEBio format version '{}' is not supported (trifem reads 4.0 and 3.0; "
                       "FEBio Studio converts older files: open it and save it as .feb 4.0)",
                       v));
}

/// Module type: solid or biphasic.
void read_module(Reader& r, pugi::xml_node root) {
  const pugi::xml_node module = root.child("Module");
  if (!module)
    return; // FEBio's default: solid
  const std::string type = r.doc.attribute(module, "type");
  if (type == "biphasic") {
    r.biphasic_module = true;
  } else if (type == "multiphasic") {
    r.biphasic_module = true;
    r.multiphasic_module = true;
  } else if (type != "solid") {
    r.doc.fail(module, "type",
               fmt::format("module '{}' is not supported (supported: solid, biphasic, "
                           "multiphasic with the triphasic material)",
                           type));
  }
}

/// Sections that are refused with a reason (everything else unknown is refused too).
void check_sections(const Reader& r, pugi::xml_node root) {
  for (pugi::xml_node s : detail::elements(root)) {
    const std::string_view name = s.name();
    static constexpr std::string_view known[] = {
        "Module",   "Globals", "Control", "Material", "Mesh",  "MeshDomains",
        "Boundary", "Initial", "Rigid",   "Contact",  "Loads", "Constraints",
        "LoadData", "Output",  "Step",    "MeshData"};
    if (std::find(std::begin(known), std::end(known), name) == std::end(known))
      r.doc.fail(s, fmt::format("the section <{}> is not supported (trifem reads Module, Globals, "
                                "Control, Material, Mesh, MeshDomains, MeshData, Boundary, "
                                "Initial, Rigid, Contact, Loads, Constraints, LoadData, Output "
                                "and Step)",
                                name));
  }
}

/// FEBio reads every section it meets, so a model may split its conditions over several
/// <Boundary>, <Loads> or <Contact> sections (all read here, in order); the sections that
/// define the model once are refused when repeated, rather than one of them being ignored.
void check_single_sections(const Reader& r, pugi::xml_node root) {
  for (const char* name : {"Module", "Globals", "Control", "Material", "Mesh", "MeshDomains",
                           "MeshData", "Rigid", "Initial", "LoadData", "Output"}) {
    const pugi::xml_node first = root.child(name);
    if (const pugi::xml_node second = first.next_sibling(name))
      r.doc.fail(second, fmt::format("a second <{}> section (the first is at line {}): trifem "
                                     "reads one <{}> section; merge them",
                                     name, r.doc.line(first), name));
  }
}

/// Curves extended by EXTRAPOLATE must cover the run (then they equal CONSTANT ones).
void check_curve_extents(const Reader& r) {
  for (const auto& e : r.curve_extents)
    if (e.extrapolate && (e.first > 0.0 || e.last < r.spec.time.end_time))
      r.doc.fail(e.node, fmt::format("extend EXTRAPOLATE is used at times outside its points [{}, "
                                     "{}] (the run lasts to {}): trifem holds curves constant "
                                     "outside their points",
                                     e.first, e.last, r.spec.time.end_time));
}

void read_sections(Reader& r) {
  const pugi::xml_node root = r.doc.root();
  r.version = version(r.doc, root);
  check_sections(r, root);
  check_single_sections(r, root);
  read_module(r, root);
  if (const pugi::xml_node globals = root.child("Globals"))
    detail::read_globals(r, globals);
  detail::read_materials(r, r.doc.child(root, "Material"));
  detail::read_mesh(r, r.doc.child(root, "Mesh"), root.child("MeshDomains"));
  detail::add_local_fibre_views(r);
  if (r.version == Version::V4 && !root.child("MeshDomains"))
    r.doc.fail(root, "the element <MeshDomains> is required");
  if (const pugi::xml_node data = root.child("MeshData"))
    detail::read_mesh_data(r, data);
  if (const pugi::xml_node data = root.child("LoadData"))
    detail::read_load_data(r, data);
  detail::map_fixed_charges(r);
  for (const pugi::xml_node b : root.children("Boundary"))
    detail::read_boundary(r, b, r.spec.fixed, r.spec.prescribed, false);
  for (const pugi::xml_node l : root.children("Loads"))
    detail::read_loads(r, l, r.spec.pressures, r.spec.tractions, r.spec.prescribed, false);
  // the sections of a file's only step act over the whole run, as the file's own do
  const pugi::xml_node only_step = detail::only_step(root);
  for (const pugi::xml_node owner : {root, only_step})
    if (const pugi::xml_node rigid = owner.child("Rigid"))
      detail::read_rigid(r, rigid);
  detail::map_rigid_bodies(r);
  if (const pugi::xml_node i = root.child("Initial"))
    detail::read_initial(r, i);
  detail::read_steps(r, root);
  detail::map_densities(r);
  detail::drop_static_rigid_velocities(r);
  check_curve_extents(r);
  detail::map_baths(r);
  for (const pugi::xml_node owner : {root, only_step}) {
    for (const pugi::xml_node c : owner.children("Contact"))
      detail::read_contact(r, c, root.child("Mesh"));
    for (const pugi::xml_node c : owner.children("Constraints"))
      detail::read_constraints(r, c);
  }
  if (const pugi::xml_node o = root.child("Output"))
    detail::read_output(r, o);
  detail::add_impermeable_faces(r);
  r.spec.output.vtu = true;
}

} // namespace

io::CaseSpec parse_feb(std::string_view text, const std::filesystem::path& file) {
  const Document doc(std::string(text), file);
  io::CaseSpec spec;
  spec.file = file;
  Reader r{doc, spec};
  read_sections(r);
  spec.title = doc.text(doc.root().child("Control").child("title"));
  spec.meshes.push_back(std::move(r.mesh));
  for (const std::string& warning : spec.warnings)
    log::warn("warning: {}", warning);
  return spec;
}

io::CaseSpec read_feb(const std::filesystem::path& file) {
  return parse_feb(read_text(file), file);
}

bool is_feb_file(const std::filesystem::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".feb";
}

} // namespace trifem::feb
