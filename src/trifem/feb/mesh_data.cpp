// SPDX-License-Identifier: MIT
// MeshData section: the shell thickness of the shell parts of rigid bodies (their mass); data
// trifem does not use yet is refused naming its type.
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

/// The rigid body whose shell part is `part` (nullptr if none).
RigidBodyInput* rigid_shell_body(Reader& r, const std::string& part) {
  for (auto& [name, body] : r.rigid_bodies)
    if (body.shell && body.set == part)
      return &body;
  return nullptr;
}

/// <ElementData type="shell thickness" elem_set="..."> on the shell part of a rigid body: one
/// thickness for the part (a rigid body's mass is its density times its volume).
void read_shell_thickness(Reader& r, pugi::xml_node data) {
  const std::string part = r.doc.attribute(data, "elem_set");
  if (!r.shell_parts.contains(part))
    r.doc.fail(data, "elem_set", fmt::format("no quad4 or tri3 part is named '{}'", part));
  RigidBodyInput* body = rigid_shell_body(r, part);
  if (body == nullptr)
    r.doc.fail(data, "elem_set",
               fmt::format("the shells of '{}' are no rigid body's (trifem has shells as rigid "
                           "bodies only)",
                           part));
  std::vector<Real> values;
  for (pugi::xml_node e : elements(data)) {
    if (std::string_view(e.name()) != "e")
      r.doc.fail(e, "expected <e> elements");
    for (const Real t : r.doc.numbers(e)) {
      if (!(t >= 0.0))
        r.doc.fail(e, "a shell thickness must not be negative");
      values.push_back(t);
    }
  }
  if (values.empty())
    r.doc.fail(data, "the shell thickness data has no <e> elements");
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  if (*hi - *lo > 1e-12 * *hi)
    r.doc.fail(data, fmt::format("the shell thickness of a rigid body varies from {} to {}: "
                                 "trifem takes one thickness per rigid shell part",
                                 *lo, *hi));
  body->mesh_data_thickness = *hi;
}

} // namespace

void read_mesh_data(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node data : elements(section)) {
    const std::string_view kind = data.name();
    if (kind != "ElementData")
      r.doc.fail(data, fmt::format("<{}> is not supported (trifem reads the shell thickness of "
                                   "rigid bodies from <MeshData>)",
                                   kind));
    const std::string type = data.attribute("type").as_string();
    if (type != "shell thickness")
      r.doc.fail(data, fmt::format("element data {} is not supported (trifem reads the shell "
                                   "thickness of rigid bodies from <MeshData>)",
                                   type.empty() ? std::string("without a type")
                                                : fmt::format("of type '{}'", type)));
    read_shell_thickness(r, data);
  }
}

} // namespace trifem::feb::detail
