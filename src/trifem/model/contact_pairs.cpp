// SPDX-License-Identifier: MIT
#include "trifem/model/contact_pairs.hpp"

#include "trifem/contact/contact_law.hpp"
#include "trifem/contact/mixture_contact_law.hpp"
#include "trifem/core/log.hpp"
#include "trifem/model/conditions.hpp"

#include <cmath>

namespace trifem::model {
namespace {

/// Mean facet size sqrt(area) of a surface in the reference configuration.
Real mean_facet_size(const mesh::Mesh& mesh, const mesh::Surface& surface) {
  Real sum = 0.0;
  for (const mesh::Facet& f : surface.facets) {
    const Vec3 d1 = mesh.node(f.nodes[2]) - mesh.node(f.nodes[0]);
    const Vec3 d2 = mesh.node(f.nodes[3]) - mesh.node(f.nodes[1]);
    sum += std::sqrt(0.5 * d1.cross(d2).norm());
  }
  return sum / static_cast<Real>(surface.facets.size());
}

/// Frictionless solid contact, or the mixture law (pressure and potential continuity).
std::shared_ptr<const contact::ContactLaw> law(const Model& model) {
  if (!model.fields.w.valid())
    return std::make_shared<contact::FrictionlessLaw>(model.fields.u);
  const physics::MixtureFields& f = model.fields;
  return std::make_shared<contact::MixtureContactLaw>(
      contact::MixtureContactFields{f.u, f.w, f.j_plus, f.j_minus});
}

/// "contact[i] (master 'a', slave 'b')": the key and the surfaces it names, for messages.
std::string pair_context(const io::ContactSpec& c) {
  return fmt::format("{} (master '{}', slave '{}')", c.key, c.master, c.slave);
}

/// The slave and master outward normals of the projected slave nodes must be opposed; an error
/// if most are not, a warning if no slave node projects (the bodies may touch later).
void check_facing(const io::ContactSpec& c, const std::vector<contact::SlaveNodeState>& states,
                  Real search_distance) {
  Index projected = 0, same_side = 0;
  for (const contact::SlaveNodeState& s : states) {
    projected += s.projected ? 1 : 0;
    same_side += s.projected && s.normal.dot(s.master_normal) >= 0 ? 1 : 0;
  }
  if (projected == 0) {
    log::warn("warning: {}: no slave node lies within the search distance ({:.4g} mm) of the "
              "master surface in the initial configuration; the bodies are not in contact yet",
              pair_context(c), search_distance);
    return;
  }
  TRIFEM_CHECK(2 * same_side <= projected,
               "the surfaces '{}' (master) and '{}' (slave) do not face each other: at {} of the "
               "{} slave nodes that project onto the master surface both outward normals point "
               "the same way (n_s.n_m >= 0); check that master and slave are the touching faces "
               "of the two bodies",
               c.master, c.slave, same_side, projected);
}

/// No projected slave node may lie deeper than `tolerance` behind the master surface.
void check_penetration(const io::ContactSpec& c, const Model& model,
                       const std::vector<contact::SlaveNodeState>& states, Real tolerance) {
  Index count = 0;
  const contact::SlaveNodeState* worst = nullptr;
  for (const contact::SlaveNodeState& s : states) {
    if (!s.projected || s.gap >= -tolerance)
      continue;
    ++count;
    if (!worst || s.gap < worst->gap)
      worst = &s;
  }
  if (count == 0)
    return;
  const Vec3& X = model.mesh.node(worst->node);
  throw InputError(fmt::format(
      "{} node(s) of the slave surface '{}' penetrate the master surface '{}' by more than "
      "penetration_tolerance = {:.4g} mm in the initial configuration; the deepest, at ({:.6g}, "
      "{:.6g}, {:.6g}) mm, has the gap {:.6g} mm (move the bodies apart or raise the tolerance)",
      count, c.slave, c.master, tolerance, X.x(), X.y(), X.z(), worst->gap));
}

/// Geometry checks of a pair in the reference configuration (zero displacement).
void check_initial_geometry(const io::ContactSpec& c, const contact::ContactTerm& term,
                            const Model& model, Real h) {
  const Vector x = Vector::Zero(model.dofs.num_dofs());
  const std::vector<contact::SlaveNodeState> states = term.slave_states(x);
  const Real tolerance = c.penetration_tolerance >= 0 ? c.penetration_tolerance : 1e-3 * h;
  with_context(pair_context(c), [&] {
    check_facing(c, states, term.settings().search_distance);
    check_penetration(c, model, states, tolerance);
    return 0;
  });
}

} // namespace

void add_contact_fields(const io::CaseSpec& spec, Model& model) {
  for (std::size_t i = 0; i < spec.contacts.size(); ++i) {
    const io::ContactSpec& c = spec.contacts[i];
    const auto& slave = with_context(
        c.key + ".slave", [&]() -> const mesh::Surface& { return model.mesh.surface(c.slave); });
    const auto nodes = static_cast<Index>(mesh::surface_nodes(slave).size());
    // components: contact pressure [+ water potential [+ c_ref x ion potentials]]
    const int components = model.fields.j_plus.valid() ? 4 : model.fields.w.valid() ? 2 : 1;
    model.contact_fields.push_back(
        model.dofs.add_field(fmt::format("contact_multipliers_{}", i + 1), nodes, components));
  }
}

std::vector<std::unique_ptr<physics::Term>> contact_terms(const io::CaseSpec& spec, Model& model) {
  std::vector<std::unique_ptr<physics::Term>> terms;
  for (std::size_t i = 0; i < spec.contacts.size(); ++i) {
    const io::ContactSpec& c = spec.contacts[i];
    const mesh::Surface& master = with_context(
        c.key + ".master", [&]() -> const mesh::Surface& { return model.mesh.surface(c.master); });
    const mesh::Surface& slave = model.mesh.surface(c.slave);
    contact::ContactSettings settings;
    settings.integration =
        c.both_surfaces ? contact::Integration::BothSurfaces : contact::Integration::SlaveNodes;
    const Real h = 0.5 * (mean_facet_size(model.mesh, master) + mean_facet_size(model.mesh, slave));
    settings.scale = c.scale > 0 ? c.scale : model.modulus_scale / h;
    settings.search_distance = c.search_distance;
    auto term = with_context(pair_context(c), [&] {
      return std::make_unique<contact::ContactTerm>(model.mesh, model.dofs, model.fields.u,
                                                    model.contact_fields[i], master, slave,
                                                    law(model), settings);
    });
    check_initial_geometry(c, *term, model, h);
    model.contacts.push_back(term.get());
    terms.push_back(std::move(term));
  }
  return terms;
}

} // namespace trifem::model
