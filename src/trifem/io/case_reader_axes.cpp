// SPDX-License-Identifier: MIT
// Case reader: the material axes of a material ([materials.<name>.axes]).
#include "trifem/core/error.hpp"
#include "trifem/io/toml_table.hpp"
#include "trifem/material/material_axes.hpp"

namespace trifem::io::detail {
namespace {

using material::AxesKind;

/// A nonzero vector `key` of `t` (`fallback` if absent, required if none).
Vec3 nonzero_vector(const Table& t, std::string_view key, std::optional<Vec3> fallback,
                    std::string_view what) {
  const Vec3 v = t.vec3(key, NumberRule{}, fallback);
  if (v.norm() == 0.0)
    fail(t.find(key), t.path(key), fmt::format("must be a nonzero vector ({})", what));
  return v;
}

} // namespace

material::AxesSpec read_axes(const Table& t) {
  static const Options<AxesKind> kinds = {{"vector", AxesKind::Vector},
                                          {"cylindrical", AxesKind::Cylindrical},
                                          {"spherical", AxesKind::Spherical},
                                          {"mesh", AxesKind::Mesh}};
  material::AxesSpec axes;
  axes.kind = t.choice("type", kinds, std::optional<AxesKind>(), "axes type");
  switch (axes.kind) {
  case AxesKind::Vector:
    t.allow({"type", "a", "d"});
    axes.a = nonzero_vector(t, "a", std::nullopt, "the direction of the local axis e1");
    axes.d = nonzero_vector(t, "d", std::nullopt, "a direction of the local (e1, e2) plane");
    try {
      material::vector_basis(axes.a, axes.d, t.path());
    } catch (const InputError&) {
      fail(t.find("d"), t.path("d"),
           "must not be parallel to a (d fixes the local (e1, e2) plane; e.g. a = [1, 0, 0], "
           "d = [0, 1, 0] is the global basis)");
    }
    break;
  case AxesKind::Cylindrical:
    t.allow({"type", "center", "axis"});
    axes.center = t.vec3("center", NumberRule{}, std::nullopt);
    axes.axis = nonzero_vector(t, "axis", std::nullopt, "the direction of the cylinder axis");
    break;
  case AxesKind::Spherical:
    t.allow({"type", "center", "axis"});
    axes.center = t.vec3("center", NumberRule{}, std::nullopt);
    axes.axis = nonzero_vector(t, "axis", Vec3::UnitZ(), "the pole axis of the azimuthal e2");
    break;
  case AxesKind::Mesh:
    t.allow({"type", "view", "d_view"});
    axes.view = t.name("view");
    axes.d_view = t.name("d_view", false);
    if (axes.d_view == axes.view)
      fail(t.find("d_view"), t.path("d_view"),
           "must name another view than view (d_view fixes the local (e1, e2) plane; omit it "
           "for the completed basis)");
    break;
  }
  return axes;
}

} // namespace trifem::io::detail
