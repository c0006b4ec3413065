// SPDX-License-Identifier: MIT
#include "model_contact.hpp"

#include "model_conditions.hpp"
#include "trifem/contact/contact_law.hpp"
#include "trifem/contact/mixture_contact_law.hpp"

#include <cmath>

namespace trifem::app {
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
    auto term = with_context(c.key, [&] {
      return std::make_unique<contact::ContactTerm>(model.mesh, model.dofs, model.fields.u,
                                                    model.contact_fields[i], master, slave,
                                                    law(model), settings);
    });
    model.contacts.push_back(term.get());
    terms.push_back(std::move(term));
  }
  return terms;
}

} // namespace trifem::app
