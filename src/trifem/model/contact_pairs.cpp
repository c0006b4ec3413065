// SPDX-License-Identifier: MIT
#include "trifem/model/contact_pairs.hpp"

#include "trifem/contact/contact_law.hpp"
#include "trifem/contact/frictional_law.hpp"
#include "trifem/contact/mixture_contact_law.hpp"
#include "trifem/core/log.hpp"
#include "trifem/model/conditions.hpp"

#include <cmath>

namespace trifem::model {
namespace {

/// Solid contact, frictionless or with Coulomb friction, or the mixture law (pressure and
/// potential continuity).
std::shared_ptr<const contact::ContactLaw> law(const io::ContactSpec& c, const Model& model) {
  if (!model.fields.w.valid() && c.friction > 0.0)
    return std::make_shared<contact::FrictionalLaw>(model.fields.u, c.friction);
  if (!model.fields.w.valid())
    return std::make_shared<contact::FrictionlessLaw>(model.fields.u);
  TRIFEM_CHECK(c.friction == 0.0,
               "friction = {} in a model with biphasic or triphasic materials: friction between "
               "mixtures is not implemented yet (contact between mixtures is frictionless; "
               "remove the key)",
               c.friction);
  const physics::MixtureFields& f = model.fields;
  return std::make_shared<contact::MixtureContactLaw>(
      contact::MixtureContactFields{f.u, f.w, f.j_plus, f.j_minus});
}

/// A slave surface whose facets are this much larger than the master's is warned about.
constexpr Real kCoarseSlave = 1.2;

/// "contact[i] (master 'a', slave 'b')": the key and the surfaces it names, for messages.
std::string pair_context(const io::ContactSpec& c) {
  return fmt::format("{} (master '{}', slave '{}')", c.key, c.master, c.slave);
}

/// Area-weighted mean outward normal of a surface in the reference configuration: a unit
/// vector for a flat surface, shorter for a curved one (zero for a closed one).
Vec3 mean_normal(const mesh::Mesh& mesh, const mesh::Surface& surface) {
  Vec3 sum = Vec3::Zero();
  Real area = 0.0;
  for (const mesh::Facet& f : surface.facets) {
    const Vec3 a = mesh::facet_area_vector(mesh, f);
    sum += a;
    area += a.norm();
  }
  return area > 0.0 ? Vec3(sum / area) : Vec3::Zero();
}

/// Two flat surfaces (mean normals of length > 0.99, curved by less than about 8 degrees): a
/// conforming contact, over which a slave surface coarser than the master lets master nodes in
/// between pass (a curved indenter on a layer, such as examples/indentation's spherical cap,
/// touches the slave at few nodes and is not warned about).
bool conforming(const mesh::Mesh& mesh, const mesh::Surface& master, const mesh::Surface& slave) {
  return mean_normal(mesh, master).norm() > 0.99 && mean_normal(mesh, slave).norm() > 0.99;
}

/// The slave and master outward normals of the projected slave nodes must be opposed; an error
/// if most are not. If no slave node projects (the bodies may touch later), two nearly flat
/// surfaces whose outward normals point the same way can never touch face to face (e.g. the
/// top faces of two stacked blocks): an error; otherwise a warning.
void check_facing(const io::ContactSpec& c, const Model& model,
                  const std::vector<contact::SlaveNodeState>& states, Real search_distance) {
  Index projected = 0, same_side = 0;
  for (const contact::SlaveNodeState& s : states) {
    projected += s.projected ? 1 : 0;
    same_side += s.projected && s.normal.dot(s.master_normal) >= 0 ? 1 : 0;
  }
  if (projected == 0) {
    const Vec3 n_m = mean_normal(model.mesh, model.mesh.surface(c.master));
    const Vec3 n_s = mean_normal(model.mesh, model.mesh.surface(c.slave));
    TRIFEM_CHECK(n_m.dot(n_s) <= 0.5,
                 "the surfaces '{}' (master) and '{}' (slave) do not face each other: their mean "
                 "outward normals ({:.3g}, {:.3g}, {:.3g}) and ({:.3g}, {:.3g}, {:.3g}) point the "
                 "same way, so they cannot touch face to face; check that master and slave are "
                 "the touching faces of the two bodies",
                 c.master, c.slave, n_m.x(), n_m.y(), n_m.z(), n_s.x(), n_s.y(), n_s.z());
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
    check_facing(c, model, states, term.settings().search_distance);
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
    // components: contact pressure [+ water potential [+ c_ref x ion potentials]], or
    // contact pressure + friction traction (solids with friction)
    const int components = model.fields.j_plus.valid() ? 4
                           : model.fields.w.valid()    ? 2
                           : c.friction > 0.0          ? 4
                                                       : 1;
    model.contact_fields.push_back(model.dofs.add_field(
        fmt::format("contact_multipliers_{}", i + 1), FieldRole::multiplier, nodes, components));
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
    const Real h_master = mesh::mean_facet_size(model.mesh, master);
    const Real h_slave = mesh::mean_facet_size(model.mesh, slave);
    if (h_slave > kCoarseSlave * h_master && conforming(model.mesh, master, slave))
      log::warn("warning: {}: the slave surface is coarser than the master surface (mean facet "
                "size {:.4g} mm against {:.4g} mm): master nodes between the slave nodes are not "
                "held back, so the contact is too soft (20 % measured on two blocks of 2 and 3 "
                "cells); make the finer surface the slave",
                pair_context(c), h_slave, h_master);
    const Real h = 0.5 * (h_master + h_slave);
    settings.scale = c.scale > 0 ? c.scale : model.modulus_scale / h;
    settings.search_distance = c.search_distance;
    auto term = with_context(pair_context(c), [&] {
      return std::make_unique<contact::ContactTerm>(model.mesh, model.dofs, model.fields.u,
                                                    model.contact_fields[i], master, slave,
                                                    law(c, model), settings);
    });
    check_initial_geometry(c, *term, model, h);
    model.contacts.push_back(term.get());
    terms.push_back(std::move(term));
  }
  return terms;
}

} // namespace trifem::model
