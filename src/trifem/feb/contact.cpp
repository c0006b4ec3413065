// SPDX-License-Identifier: MIT
// FEBio contact interfaces as trifem's contact pairs (docs/feb.md): sliding contact of solids
// (frictionless or with Coulomb friction) and frictionless contact of biphasic bodies; FEBio's
// penalty and augmentation settings are read and ignored, since trifem enforces contact and
// friction with Lagrange multipliers.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <span>
#include <string_view>

namespace trifem::feb::detail {
namespace {

/// FEBio's sliding interfaces of solids.
constexpr std::string_view kSolidContacts[] = {"sliding-elastic", "sliding-facet-on-facet",
                                               "sliding-node-on-facet"};

/// Parameters of the enforcement (penalty, augmentation, search, stiffness symmetry, and the
/// penalty of friction): they do not change the contact conditions, which trifem's multipliers
/// hold exactly.
constexpr std::string_view kEnforcement[] = {"laugon",
                                             "fric_penalty",
                                             "ktmult",
                                             "tolerance",
                                             "gaptol",
                                             "ptol",
                                             "penalty",
                                             "auto_penalty",
                                             "update_penalty",
                                             "two_pass",
                                             "minaug",
                                             "maxaug",
                                             "search_tol",
                                             "search_radius",
                                             "symmetric_stiffness",
                                             "seg_up",
                                             "smooth_aug",
                                             "node_reloc",
                                             "knmult",
                                             "pressure_penalty",
                                             "dual_proj",
                                             "offset",
                                             "shell_bottom_primary",
                                             "shell_bottom_secondary",
                                             "max_traction"};

/// Parameters that must keep FEBio's default (the value trifem's contact has).
const std::map<std::string_view, Real> kFixedDefaults = {{"tension", 0.0},
                                                         {"flip_primary", 0.0},
                                                         {"flip_secondary", 0.0},
                                                         {"contact_frac", 0.0},
                                                         {"smooth_fls", 0.0}};

bool contains(std::span<const std::string_view> list, std::string_view s) {
  return std::find(list.begin(), list.end(), s) != list.end();
}

/// The surfaces of each <SurfacePair name=...> of the mesh: primary and secondary.
struct Pair {
  std::string primary, secondary;
};

std::map<std::string, Pair> surface_pairs(const Reader& r, pugi::xml_node mesh) {
  std::map<std::string, Pair> pairs;
  for (pugi::xml_node p : mesh.children("SurfacePair")) {
    const std::string name = r.doc.attribute(p, "name");
    Pair pair;
    pair.primary = r.doc.text(r.doc.child(p, "primary"));
    pair.secondary = r.doc.text(r.doc.child(p, "secondary"));
    for (const auto& [role, surface] :
         {std::pair{"primary", pair.primary}, std::pair{"secondary", pair.secondary}})
      if (!r.mesh.mesh.has_surface(surface))
        r.doc.fail(p.child(role), fmt::format("surface '{}' is not defined", surface));
    if (pair.primary == pair.secondary)
      r.doc.fail(p, fmt::format("the primary and secondary surfaces are both '{}'", pair.primary));
    pairs.emplace(name, pair);
  }
  return pairs;
}

/// The type of a contact interface is one trifem maps for this model, or an error saying why.
void check_type(const Reader& r, pugi::xml_node c, const std::string& type) {
  const bool solid_type = contains(kSolidContacts, type);
  if (type == "sliding-biphasic") {
    if (!r.biphasic_module)
      r.doc.fail(c, "type", "'sliding-biphasic' needs the biphasic module");
    return;
  }
  if (solid_type) {
    if (r.biphasic_module)
      r.doc.fail(c, "type",
                 fmt::format("'{}' in a biphasic model keeps the contact faces impermeable to the "
                             "fluid, which trifem's contact of mixtures does not (its fluid "
                             "pressure and normal flux are continuous across the contact): use "
                             "'sliding-biphasic'",
                             type));
    return;
  }
  if (type.starts_with("tied") || type == "sticky")
    r.doc.fail(c, "type",
               fmt::format("contact type '{}' is not supported (trifem has no tied contact: "
                           "merge the nodes of the two surfaces instead)",
                           type));
  r.doc.fail(c, "type",
             fmt::format("contact type '{}' is not supported (supported: sliding-elastic, "
                         "sliding-facet-on-facet, sliding-node-on-facet; sliding-biphasic in "
                         "the biphasic module)",
                         type));
}

/// The parameters of an interface: enforcement settings are ignored, the friction coefficient
/// of solids is returned, the others must keep the defaults that describe trifem's contact.
Real check_parameters(Reader& r, pugi::xml_node c, bool& noted) {
  Real friction = 0.0;
  for (pugi::xml_node p : elements(c)) {
    const std::string_view name = p.name();
    if (name == "fric_coeff") {
      friction = r.doc.number(p);
      if (friction < 0.0 || !std::isfinite(friction))
        r.doc.fail(p, fmt::format("'fric_coeff' must be >= 0, not {}", friction));
      if (friction > 0.0 && r.doc.attribute(c, "type") == "sliding-biphasic")
        r.doc.fail(p, "friction between biphasic bodies is not implemented yet (trifem's "
                      "contact of mixtures is frictionless; fric_coeff must be 0)");
      continue;
    }
    if (contains(kEnforcement, name)) {
      if (!noted)
        r.warn(c, "FEBio's penalty, augmentation and search settings of contact interfaces "
                  "are ignored: trifem enforces contact with Lagrange multipliers (one pass, "
                  "slave = the primary surface)");
      noted = true;
      continue;
    }
    const auto fixed = kFixedDefaults.find(name);
    if (fixed == kFixedDefaults.end())
      r.doc.fail(p, fmt::format("contact parameter '{}' is not supported", name));
    if (r.doc.number(p) != fixed->second)
      r.doc.fail(p, fmt::format("'{}' must be {} (trifem's contact is compressive, with the "
                                "surfaces' own normals)",
                                name, fixed->second));
  }
  return friction;
}

/// The mean reference facet size sqrt(area) of two surfaces.
Real mean_facet_size(const mesh::Mesh& mesh, const std::string& a, const std::string& b) {
  Real sum = 0.0;
  std::size_t count = 0;
  for (const std::string& name : {a, b})
    for (const mesh::Facet& f : mesh.surface(name).facets) {
      const Vec3 n = (mesh.node(f.nodes[2]) - mesh.node(f.nodes[0]))
                         .cross(mesh.node(f.nodes[3]) - mesh.node(f.nodes[1]));
      sum += std::sqrt(0.5 * n.norm());
      ++count;
    }
  return count ? sum / static_cast<Real>(count) : 0.0;
}

/// FEBio resolves an initial overlap of the surfaces through the contact itself; trifem's
/// multipliers close it in the first step, so an overlap up to this fraction of the facet size
/// is accepted (trifem's own default is 1e-3).
constexpr Real kInitialOverlap = 0.05;

} // namespace

void read_contact(Reader& r, pugi::xml_node section, pugi::xml_node mesh) {
  const std::map<std::string, Pair> pairs = surface_pairs(r, mesh);
  bool noted = false;
  for (pugi::xml_node c : elements(section)) {
    if (std::string_view(c.name()) != "contact")
      r.doc.fail(c, fmt::format("<{}> is not supported in <Contact>", c.name()));
    check_type(r, c, r.doc.attribute(c, "type"));
    const std::string pair_name = r.doc.attribute(c, "surface_pair");
    const auto pair = pairs.find(pair_name);
    if (pair == pairs.end())
      r.doc.fail(c, "surface_pair",
                 fmt::format("surface pair '{}' is not defined in <Mesh>", pair_name));
    io::ContactSpec spec;
    spec.friction = check_parameters(r, c, noted);
    spec.key = fmt::format("contact '{}'",
                           c.attribute("name") ? c.attribute("name").value() : pair_name.c_str());
    spec.slave = pair->second.primary; // FEBio's primary surface is the former slave
    spec.master = pair->second.secondary;
    spec.penetration_tolerance =
        kInitialOverlap * mean_facet_size(r.mesh.mesh, spec.slave, spec.master);
    for (const io::ContactSpec& other : r.spec.contacts)
      if ((other.master == spec.master && other.slave == spec.slave) ||
          (other.master == spec.slave && other.slave == spec.master))
        r.doc.fail(c, fmt::format("the surfaces '{}' and '{}' are already a pair in {}", spec.slave,
                                  spec.master, other.key));
    r.spec.contacts.push_back(std::move(spec));
  }
}

} // namespace trifem::feb::detail
