// SPDX-License-Identifier: MIT
// Multiphasic models: FEBio's constants and solutes (Globals), its initial conditions, and its
// effective fluid pressure and concentrations on faces, mapped to trifem's bath (docs/feb.md).
#include "trifem/feb/reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>

namespace trifem::feb::detail {
namespace {

/// trifem's gas constant [mJ/(mmol K)]: the file's amount unit follows from its R.
constexpr Real kGasConstant = 8.314;

void read_constants(Reader& r, pugi::xml_node constants) {
  r.chem.constants = constants;
  for (pugi::xml_node c : elements(constants)) {
    const std::string_view name = c.name();
    if (name == "P") { // FEBio's ambient pressure (of its fluid modules): 0 changes nothing
      if (r.doc.number(c) != 0.0)
        r.doc.fail(c, "an ambient pressure P other than 0 is not supported");
      continue;
    }
    Real* target = name == "T"    ? &r.chem.T
                   : name == "R"  ? &r.chem.R
                   : name == "Fc" ? &r.chem.faraday
                                  : nullptr;
    if (!target)
      r.doc.fail(c, fmt::format("unknown constant '{}' (expected T, R, Fc, P)", name));
    *target = r.doc.number(c); // checked where used (FEBio Studio writes 0 for solid models)
  }
}

/// <Solutes>: trifem's triphasic material has exactly Na+ (charge 1) and Cl- (charge -1).
void read_solutes(Reader& r, pugi::xml_node solutes) {
  if (!r.multiphasic_module)
    r.doc.fail(solutes, "<Solutes> needs the multiphasic module");
  for (pugi::xml_node s : elements(solutes)) {
    if (std::string_view(s.name()) != "solute")
      r.doc.fail(s, "expected <solute> elements");
    const std::string id = r.doc.attribute(s, "id");
    const long z = r.doc.integer(r.doc.child(s, "charge_number"));
    if (z != 1 && z != -1)
      r.doc.fail(s.child("charge_number"),
                 fmt::format("charge number {}: trifem's triphasic model has one monovalent "
                             "cation (+1, Na) and one monovalent anion (-1, Cl)",
                             z));
    for (const auto& [ref, charge] : r.chem.charge_of)
      if (charge == z)
        r.doc.fail(s, fmt::format("a second solute of charge {} (trifem's triphasic model has "
                                  "one cation and one anion)",
                                  z));
    r.chem.charge_of[id] = static_cast<int>(z);
    if (const std::string name = s.attribute("name").value(); !name.empty())
      r.chem.charge_of[name] = static_cast<int>(z);
    for (pugi::xml_node p : s.children())
      if (is_element(p) && std::string_view(p.name()) != "charge_number" &&
          std::string_view(p.name()) != "molar_mass" && std::string_view(p.name()) != "density")
        r.doc.fail(p, fmt::format("unknown solute parameter '{}' (expected charge_number, "
                                  "molar_mass, density)",
                                  p.name()));
  }
}

/// The value of a condition (value x curve) at time t, with FEBio's interpolation.
Real value_at(const Reader& r, const EffectiveCondition& c, Real t) {
  if (c.curve.empty())
    return c.value;
  const io::CurveSpec& curve = r.spec.curves.at(c.curve);
  return c.value * dofs::LoadCurve(curve.points, curve.interpolation, c.curve, curve.extension)(t);
}

/// The value a condition holds on (0, end]: its curve must be constant there (a bath that
/// changes in time is not mapped), FEBio's value at t = 0 is that of the initial state.
Real constant_value(const Reader& r, const EffectiveCondition& c) {
  const Real end = r.spec.time.end_time;
  if (c.curve.empty())
    return c.value;
  const io::CurveSpec& curve = r.spec.curves.at(c.curve);
  std::vector<Real> times{end,
                          curve.interpolation == dofs::Interpolation::Next ? end * 1e-12 : 0.0};
  const dofs::LoadCurve lc(curve.points, curve.interpolation, c.curve, curve.extension);
  for (const Real t : lc.breakpoints(0.0, end)) // a repeating curve's in every period
    if (t > 0.0 && t < end)
      times.push_back(t);
  const Real v = value_at(r, c, end);
  for (Real t : times)
    if (std::abs(value_at(r, c, t) - v) > 1e-12 * std::max(std::abs(v), 1e-300))
      r.doc.fail(c.bc, fmt::format("the value changes in time ({} at t = {}, {} at the end): "
                                   "trifem maps a prescribed effective fluid pressure or "
                                   "concentration to a bath of constant concentration",
                                   value_at(r, c, t), t, v));
  return v;
}

/// The effective pressure and the two concentrations prescribed at each node (NaN: none).
struct NodalBath {
  std::vector<std::array<Real, 3>> values; ///< p~, c~+, c~-
  std::vector<std::array<const EffectiveCondition*, 3>> source;
};

int slot(int charge) {
  return charge == 0 ? 0 : charge > 0 ? 1 : 2;
}

NodalBath nodal_values(const Reader& r, const std::vector<EffectiveCondition>& conditions,
                       bool initial) {
  const Index n = r.mesh.mesh.num_nodes();
  NodalBath b{
      std::vector<std::array<Real, 3>>(n, {NAN, NAN, NAN}),
      std::vector<std::array<const EffectiveCondition*, 3>>(n, {nullptr, nullptr, nullptr})};
  for (const EffectiveCondition& c : conditions) {
    const Real v = initial ? c.value : constant_value(r, c);
    for (Index node : r.mesh.mesh.node_set(c.set)) {
      b.values[node][slot(c.charge)] = v;
      b.source[node][slot(c.charge)] = &c;
    }
  }
  return b;
}

/// The gauge pressure of a bath of effective pressure p~ and concentrations c~: an ideal NaCl
/// solution has p = p~ + RT (c~+ + c~-).
Real bath_pressure(const Reader& r, const std::array<Real, 3>& v) {
  return v[0] + r.chem.R * r.chem.T * (v[1] + v[2]);
}

/// The osmotic pressure scale of a bath, RT (c~+ + c~-), for tolerances.
Real osmotic_scale(const Reader& r, const std::array<Real, 3>& v) {
  return r.chem.R * r.chem.T * (std::abs(v[1]) + std::abs(v[2]));
}

constexpr const char* kSlotNames[3] = {"effective fluid pressure", "cation concentration",
                                       "anion concentration"};

/// The drained nodes of a triphasic model: p~, c~+ and c~- prescribed together; the bath
/// they define (one for the model) sets trifem's reference bath.
void map_triphasic_baths(Reader& r) {
  const NodalBath b = nodal_values(r, r.effective, false);
  const std::array<Real, 3>* bath = nullptr;
  const std::array<const EffectiveCondition*, 3>* bath_source = nullptr;
  for (Index n = 0; n < r.mesh.mesh.num_nodes(); ++n) {
    const auto& v = b.values[n];
    const int given = static_cast<int>(!std::isnan(v[0])) + !std::isnan(v[1]) + !std::isnan(v[2]);
    if (given == 0)
      continue;
    if (given < 3) {
      const int missing = std::isnan(v[0]) ? 0 : std::isnan(v[1]) ? 1 : 2;
      const EffectiveCondition* some = b.source[n][missing == 0 ? (std::isnan(v[1]) ? 2 : 1) : 0];
      r.doc.fail(some->bc, fmt::format("a node of this set has no prescribed {}: trifem drains a "
                                       "face to a bath of water and both ions at once (prescribe "
                                       "the effective fluid pressure and both concentrations "
                                       "on the same faces)",
                                       kSlotNames[missing]));
    }
    if (!bath) {
      bath = &b.values[n];
      bath_source = &b.source[n];
    } else if ((*bath)[0] != v[0] || (*bath)[1] != v[1] || (*bath)[2] != v[2]) {
      r.doc.fail(b.source[n][0]->bc,
                 fmt::format("a second bath (effective pressure {}, concentrations {} and {}; the "
                             "first has {}, {} and {}): trifem maps one bath per model",
                             v[0], v[1], v[2], (*bath)[0], (*bath)[1], (*bath)[2]));
    }
    r.drained[n] = 1;
  }
  if (!bath)
    return;
  const auto& v = *bath;
  if (!(v[1] > 0.0) || std::abs(v[1] - v[2]) > 1e-9 * v[1])
    r.doc.fail((*bath_source)[1]->bc,
               fmt::format("the bath's cation and anion concentrations are {} and {}: trifem's "
                           "bath is an electroneutral NaCl solution (equal and positive)",
                           v[1], v[2]));
  const Real p = bath_pressure(r, v), scale = osmotic_scale(r, v);
  if (std::abs(p) > 1e-3 * scale)
    r.doc.fail((*bath_source)[0]->bc,
               fmt::format("the bath's fluid pressure p~ + RT (c~+ + c~-) = {:.6g} (p~ = {}): "
                           "trifem's bath is at gauge pressure 0 (p~ = {:.6g})",
                           p, v[0], v[0] - p));
  if (p != 0.0)
    r.warn((*bath_source)[0]->bc,
           fmt::format("the bath's fluid pressure p~ + RT (c~+ + c~-) = {:.3g} "
                       "({:.2g} of its osmotic pressure) is taken as 0",
                       p, std::abs(p) / scale));
  r.spec.electrochemistry.bath_concentration = v[1] * r.chem.amount;
}

/// The drained nodes of a biphasic model: a prescribed fluid pressure of 0 drains to the
/// reference bath; any other (value x curve) is a bath at that pressure (add_impermeable_faces
/// makes its faces).
void map_biphasic_baths(Reader& r) {
  for (const EffectiveCondition& c : r.effective) {
    if (c.charge != 0)
      r.doc.fail(c.bc, "a prescribed concentration needs a triphasic material");
    if (!r.always_zero(c.value, c.curve)) {
      r.pressure_baths.push_back(&c);
      continue;
    }
    for (Index n : r.mesh.mesh.node_set(c.set))
      r.drained[n] = 1;
  }
}

/// The nodes of mixture cells.
std::vector<char> mixture_nodes(const Reader& r) {
  std::vector<char> in(r.mesh.mesh.num_nodes(), 0);
  for (const auto& [block, material] : r.mesh.materials)
    if (r.spec.materials.at(material).is_mixture())
      for (Index c : r.mesh.mesh.cell_block(block))
        for (Index n : r.mesh.mesh.cell_nodes(c))
          in[n] = 1;
  return in;
}

/// FEBio's initial values must be trifem's initial state: Donnan equilibrium with the bath, in
/// which the effective pressure and concentrations equal the bath's everywhere.
void check_initial(Reader& r) {
  const bool triphasic = r.multiphasic_module;
  const Real c = r.spec.electrochemistry.bath_concentration / r.chem.amount;
  const std::array<Real, 3> bath{triphasic ? -r.chem.R * r.chem.T * 2.0 * c : 0.0, c, c};
  const Real scale = triphasic ? osmotic_scale(r, bath) : 0.0;
  const NodalBath b = nodal_values(r, r.initial, true);
  const std::vector<char> mixture = mixture_nodes(r);
  for (int k = 0; k < (triphasic ? 3 : 1); ++k) {
    const EffectiveCondition* first = nullptr;
    for (Index n = 0; n < r.mesh.mesh.num_nodes(); ++n) {
      const Real v = b.values[n][k];
      const EffectiveCondition* source = b.source[n][k];
      if (source && !first)
        first = source;
      if (source && std::abs(v - bath[k]) > 1e-3 * scale)
        r.doc.fail(source->bc,
                   fmt::format("initial {} {}: trifem starts a mixture in Donnan equilibrium "
                               "with its bath, where it is {:.6g}",
                               kSlotNames[k], v, bath[k]));
      if (first && !source && mixture[n] && std::abs(bath[k]) > 1e-3 * scale)
        r.doc.fail(first->bc, fmt::format("the initial {} is not given at every node of the "
                                          "mixture (FEBio starts the others at 0): trifem "
                                          "starts a mixture in Donnan equilibrium with its bath",
                                          kSlotNames[k]));
    }
    if (triphasic && k > 0 && !first)
      r.warn(r.doc.root(), fmt::format("no initial {}: FEBio starts from 0, trifem from Donnan "
                                       "equilibrium with the bath ({} in the file's units)",
                                       kSlotNames[k], c));
  }
}

} // namespace

void read_globals(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node g : elements(section)) {
    const std::string_view name = g.name();
    if (name == "Constants")
      read_constants(r, g);
    else if (name == "Solutes")
      read_solutes(r, g);
    else
      r.doc.fail(g, fmt::format("<{}> is not supported (expected Constants, Solutes)", name));
  }
  if (!r.multiphasic_module)
    return;
  if (!(r.chem.R > 0.0 && r.chem.T > 0.0))
    r.doc.fail(r.chem.constants ? r.chem.constants : section,
               "a multiphasic model needs the constants R and T in <Globals>/<Constants>");
  r.chem.amount = r.chem.R / kGasConstant;
  r.spec.electrochemistry.R = kGasConstant;
  r.spec.electrochemistry.T = r.chem.T;
  if (r.chem.faraday > 0.0)
    r.spec.electrochemistry.faraday = r.chem.faraday / r.chem.amount;
}

void read_initial(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node ic : elements(section)) {
    if (std::string_view(ic.name()) != "ic")
      r.doc.fail(ic, fmt::format("<{}> is not supported in <Initial> (expected <ic>)", ic.name()));
    const std::string type = r.doc.attribute(ic, "type");
    if (type == "velocity") {
      const pugi::xml_node value = r.doc.child(ic, "value");
      if (value.attribute("lc") || value.attribute("type"))
        r.doc.fail(value, "an initial velocity must be a constant vector");
      r.spec.initial_velocities.push_back({fmt::format("ic '{}'", ic.attribute("name").value()),
                                           r.node_set(ic), r.doc.vector(value)});
      continue;
    }
    EffectiveCondition c{ic, r.node_set(ic), 0, 0.0, ""};
    if (type == "initial concentration") {
      const pugi::xml_node dof = r.doc.child(ic, "dof");
      const std::string name = r.doc.text(dof);
      if (!name.starts_with("c"))
        r.doc.fail(dof, fmt::format("dof '{}': expected c<solute id>", name));
      c.charge = r.chem.charge(r.doc, dof, name.substr(1));
    } else if (type != "initial fluid pressure") {
      r.doc.fail(ic, "type",
                 fmt::format("initial condition type '{}' is not supported (supported: initial "
                             "fluid pressure, initial concentration, velocity)",
                             type));
    }
    const pugi::xml_node value = r.doc.child(ic, "value");
    if (value.attribute("lc") || value.attribute("type"))
      r.doc.fail(value, "an initial value must be a number");
    c.value = r.doc.number(value);
    r.initial.push_back(c);
  }
}

void map_baths(Reader& r) {
  if (r.multiphasic_module)
    map_triphasic_baths(r);
  else
    map_biphasic_baths(r);
  if (r.multiphasic_module && r.effective.empty()) {
    // no drained face: the bath only sets the initial state, given by the initial conditions
    for (const EffectiveCondition& c : r.initial)
      if (c.charge > 0)
        r.spec.electrochemistry.bath_concentration = c.value * r.chem.amount;
  }
  check_initial(r);
}

} // namespace trifem::feb::detail
