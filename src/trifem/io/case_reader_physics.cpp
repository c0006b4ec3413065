// SPDX-License-Identifier: MIT
// Case reader, part 3: [[boundary.*]], [[loads.*]], [analysis] and [electrochemistry]. The
// fields a condition may act on depend on the materials (read before these sections).
#include "trifem/io/toml_table.hpp"

#include <algorithm>

namespace trifem::io::detail {
namespace {

/// Which fields the materials of the case create.
struct ModelFields {
  bool fluxes = false; ///< w (some material is biphasic or triphasic)
  bool ions = false;   ///< j+, j- (some material is triphasic)
};

ModelFields model_fields(const CaseSpec& spec) {
  ModelFields m;
  for (const auto& [name, material] : spec.materials) {
    m.fluxes = m.fluxes || material.is_mixture();
    m.ions = m.ions || material.type == "triphasic";
  }
  return m;
}

constexpr std::string_view kNoFluxFields =
    "the model has no flux fields (no biphasic or triphasic material)";
constexpr std::string_view kNoIonFields = "the model has no ion fields (no triphasic material)";

const std::vector<FieldKind> kAllFluxes = {FieldKind::FluidFlux, FieldKind::CationFlux,
                                           FieldKind::AnionFlux};

/// The unit of a prescribed value of `kind`.
std::string_view field_unit(FieldKind kind) {
  switch (kind) {
  case FieldKind::Displacement:
    return "mm";
  case FieldKind::FluidFlux:
    return "mm/s";
  case FieldKind::CationFlux:
  case FieldKind::AnionFlux:
    return "mmol/(mm^2 s)";
  }
  return "";
}

/// A value of a `field` key: the fields it stands for and what the model must have for it.
struct FieldChoice {
  std::vector<FieldKind> fields;
  bool needs_fluxes = false;
  bool needs_ions = false;
};

/// The choices of `field`; "fluxes" (every flux field of the model) only if `groups`.
Options<FieldChoice> field_options(bool groups) {
  Options<FieldChoice> options = {
      {"displacement", {{FieldKind::Displacement}}},
      {"fluid_flux", {{FieldKind::FluidFlux}, true}},
      {"cation_flux", {{FieldKind::CationFlux}, true, true}},
      {"anion_flux", {{FieldKind::AnionFlux}, true, true}},
  };
  if (groups)
    options.push_back({"fluxes", {kAllFluxes, true}});
  return options;
}

/// The optional `field` key of `t` (default "displacement"), checked against the model.
std::vector<FieldKind> read_field(const Table& t, const ModelFields& model, bool groups) {
  static const FieldChoice displacement{{FieldKind::Displacement}};
  const FieldChoice f =
      t.choice("field", field_options(groups), std::optional(displacement), "field");
  const bool missing_fluxes = f.needs_fluxes && !model.fluxes;
  if (missing_fluxes || (f.needs_ions && !model.ions))
    fail(t.find("field"),
         fmt::format("{} = '{}'", t.path("field"), t.required<std::string>("field")),
         missing_fluxes ? kNoFluxFields : kNoIonFields);
  return f.fields;
}

// ---------------------------------------------------------------------------------------------
// [[boundary.fixed]], [[boundary.impermeable]], [[boundary.bonded]], [[boundary.prescribed]]

FixedSpec read_fixed(const Table& t, const ModelFields& model) {
  t.allow({"set", "field", "components"});
  FixedSpec f;
  f.set = t.name("set");
  f.fields = read_field(t, model, true);
  f.components = read_components(t);
  return f;
}

FixedSpec read_impermeable(const Table& t, const ModelFields& model) {
  if (!model.fluxes)
    fail(t.where(), t.path(), kNoFluxFields);
  t.allow({"set", "normal"});
  FixedSpec f;
  f.set = t.name("set");
  f.components = {t.choice("normal", component_options(), std::optional<Component>(), "axis")};
  f.fields = kAllFluxes;
  return f;
}

FixedSpec read_bonded(const Table& t) {
  t.allow({"set"});
  FixedSpec f;
  f.set = t.name("set");
  f.components = {0, 1, 2};
  f.fields = {FieldKind::Displacement};
  f.fields.insert(f.fields.end(), kAllFluxes.begin(), kAllFluxes.end());
  return f;
}

/// Rejects a second constraint on the same (node set, field, component). `fixed_keys[i]` is the
/// table that produced spec.fixed[i].
void check_unconstrained(const Table& t, const PrescribedSpec& p, const CaseSpec& spec,
                         const std::vector<std::string>& fixed_keys) {
  const auto conflict = [&](std::string_view by) {
    const std::string field =
        p.field == FieldKind::Displacement ? "" : fmt::format("{} ", field_name(p.field));
    fail(t.where(), t.path(),
         fmt::format("{}component {} of node set '{}' is already constrained by {}", field,
                     kAxis[p.component], p.set, by));
  };
  for (std::size_t i = 0; i < spec.fixed.size(); ++i) {
    const FixedSpec& f = spec.fixed[i];
    const bool field = std::find(f.fields.begin(), f.fields.end(), p.field) != f.fields.end();
    const auto& c = f.components;
    if (f.set == p.set && field && std::find(c.begin(), c.end(), p.component) != c.end())
      conflict(fixed_keys[i]);
  }
  for (std::size_t i = 0; i < spec.prescribed.size(); ++i) {
    const PrescribedSpec& q = spec.prescribed[i];
    if (q.set == p.set && q.field == p.field && q.component == p.component)
      conflict(element_path("boundary.prescribed", i));
  }
}

PrescribedSpec read_prescribed(const Table& t, const CaseSpec& spec,
                               const std::vector<std::string>& fixed_keys) {
  t.allow({"set", "field", "component", "value", "curve", "relative"});
  PrescribedSpec p;
  p.relative = t.get<bool>("relative").value_or(false);
  p.set = t.name("set");
  p.field = read_field(t, model_fields(spec), false).front();
  p.component = t.choice("component", component_options(), std::optional<Component>(), "component");
  p.value = t.number("value", {.unit = field_unit(p.field)});
  p.curve = read_curve_reference(t, spec);
  check_unconstrained(t, p, spec, fixed_keys);
  return p;
}

/// Throws unless some material is a mixture (`t` only applies to those).
void require_mixture(const Table& t, const CaseSpec& spec) {
  if (!model_fields(spec).fluxes)
    fail(t.where(), t.path(),
         "only applies to biphasic/triphasic materials (no [materials.<name>] has type = "
         "'biphasic' or 'triphasic')");
}

/// The [analysis] keys of mixture models (`type`, read first, applies to every model).
void check_analysis_keys(const Table& t, const CaseSpec& spec) {
  static const std::vector<std::string_view> mixture_keys = {"initial_state", "fixed_charge_curve",
                                                             "flux_mass"};
  t.allow(mixture_keys, {"type"});
  const auto [key, node] = t.first_key([](std::string_view k) { return k != "type"; });
  if (node && !model_fields(spec).fluxes)
    fail(t.where(), t.path(),
         fmt::format("only applies to biphasic/triphasic materials (no [materials.<name>] has "
                     "type = 'biphasic' or 'triphasic'); of its keys only 'type' applies to "
                     "every model, {} does not",
                     t.path(key)));
}

} // namespace

void read_boundary(const Table& root, CaseSpec& spec) {
  const auto boundary = root.table("boundary");
  if (!boundary)
    return;
  boundary->allow({"fixed", "impermeable", "bonded", "prescribed", "bath"});
  const ModelFields model = model_fields(spec);
  std::vector<std::string> fixed_keys; // where each entry of spec.fixed comes from
  const auto add = [&](const Table& t, FixedSpec f) {
    f.key = t.path();
    spec.fixed.push_back(std::move(f));
    fixed_keys.push_back(t.path());
  };
  for (const Table& t : boundary->tables("fixed"))
    add(t, read_fixed(t, model));
  for (const Table& t : boundary->tables("impermeable")) {
    if (t.find("surface")) { // any orientation: rotated frames on the surface's normals
      if (!model.fluxes)
        fail(t.where(), t.path(), kNoFluxFields);
      t.allow({"surface"});
      spec.impermeable_surfaces.push_back({t.path(), t.name("surface")});
      continue;
    }
    add(t, read_impermeable(t, model));
  }
  for (const Table& t : boundary->tables("bonded"))
    add(t, read_bonded(t));
  for (const Table& t : boundary->tables("prescribed"))
    spec.prescribed.push_back(read_prescribed(t, spec, fixed_keys));
  for (const Table& t : boundary->tables("bath")) {
    t.allow({"surface", "concentration", "pressure", "curve"});
    if (!model.fluxes)
      fail(t.where(), t.path(), "a bath needs a biphasic or triphasic material");
    if (!t.find("concentration") && !t.find("pressure"))
      fail(t.where(), t.path(), "a bath needs its concentration, its pressure or both");
    if (t.find("concentration") && !model.ions)
      fail(t.find("concentration"), t.path("concentration"),
           "a bath concentration needs a triphasic material (a biphasic bath has a pressure only)");
    BathSpec b;
    b.surface = t.name("surface");
    if (t.find("concentration"))
      b.concentration =
          t.number("concentration", {.range = material::Range::positive(),
                                     .unit = "mmol/mm^3",
                                     .plausible = &material::plausible::concentration()});
    b.pressure = t.number("pressure", {.fallback = 0.0, .unit = "MPa"});
    b.curve = read_curve_reference(t, spec);
    spec.baths.push_back(b);
  }
}

// ---------------------------------------------------------------------------------------------
// [[loads.pressure]], [[loads.traction]], [[loads.body_force]]

namespace {

/// [[loads.body_force]] `t` (case level only; the model checks the blocks and their materials).
BodyForceSpec read_body_force(const Table& t, const CaseSpec& spec) {
  t.allow({"force", "blocks", "curve"});
  BodyForceSpec b;
  b.key = t.path();
  b.force = t.vec3("force", {.unit = "mm/s^2"}, std::nullopt);
  b.blocks = t.get<std::vector<std::string>>("blocks").value_or(std::vector<std::string>{});
  if (const toml::node* n = t.find("blocks"); n && b.blocks.empty())
    fail(n, t.path("blocks"), "no cell block given (leave the key out to load every cell)");
  for (std::size_t i = 0; i < b.blocks.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (b.blocks[j] == b.blocks[i])
        fail(&(*t.find("blocks")->as_array())[i],
             fmt::format("{} = '{}'", element_path(t.path("blocks"), i), b.blocks[i]),
             fmt::format("the block is named twice (also {})", element_path(t.path("blocks"), j)));
  b.curve = read_curve_reference(t, spec);
  return b;
}

/// [[loads.nodal_force]] `t` (case level only; the model checks the node set).
NodalForceSpec read_nodal_force(const Table& t, const CaseSpec& spec) {
  t.allow({"set", "value", "curve"});
  NodalForceSpec f;
  f.key = t.path();
  f.set = t.name("set");
  f.value = t.vec3("value", {.unit = "N"}, std::nullopt);
  f.curve = read_curve_reference(t, spec);
  return f;
}

} // namespace

void read_loads(const Table& root, CaseSpec& spec) {
  const auto loads = root.table("loads");
  if (!loads)
    return;
  loads->allow({"pressure", "traction", "body_force", "nodal_force"});
  if (const toml::node* n = loads->find("body_force"); n && !root.path().empty())
    fail(n, loads->path("body_force"),
         "a body force acts in every step: give it in the case's [[loads.body_force]] (with a "
         "curve to change it in time)");
  if (const toml::node* n = loads->find("nodal_force"); n && !root.path().empty())
    fail(n, loads->path("nodal_force"),
         "a nodal force acts in every step: give it in the case's [[loads.nodal_force]] (with a "
         "curve to change it in time)");
  for (const Table& t : loads->tables("body_force"))
    spec.body_forces.push_back(read_body_force(t, spec));
  for (const Table& t : loads->tables("nodal_force"))
    spec.nodal_forces.push_back(read_nodal_force(t, spec));
  for (const Table& t : loads->tables("pressure")) {
    t.allow({"surface", "value", "curve", "follower"});
    spec.pressures.push_back({t.name("surface"), t.number("value", {.unit = "MPa"}),
                              read_curve_reference(t, spec),
                              t.get<bool>("follower").value_or(true)});
  }
  static const Options<bool> areas = {{"reference", false}, {"current", true}};
  for (const Table& t : loads->tables("traction")) {
    t.allow({"surface", "value", "force", "curve", "area"});
    const bool total = t.find("force") != nullptr;
    if (total == (t.find("value") != nullptr))
      fail(t.where(), t.path(),
           fmt::format("give either value (a traction [MPa]) or force (a total force [N] "
                       "spread over the surface's reference area), not {}",
                       total ? "both" : "neither"));
    TractionSpec load{t.name("surface"),
                      total ? t.vec3("force", {.unit = "N"}, std::nullopt)
                            : t.vec3("value", {.unit = "MPa"}, std::nullopt),
                      read_curve_reference(t, spec),
                      t.choice("area", areas, std::optional(false), "traction area"), total};
    if (total && load.per_current_area)
      fail(t.find("area"), fmt::format("{} = \"current\"", t.path("area")),
           "a force is spread over the reference area (remove area, or give a traction value "
           "per current area)");
    spec.tractions.push_back(std::move(load));
  }
}

// ---------------------------------------------------------------------------------------------
// [analysis], [electrochemistry]

void read_analysis(const Table& root, CaseSpec& spec) {
  const auto t = root.table("analysis");
  if (!t)
    return;
  check_analysis_keys(*t, spec);
  if (!model_fields(spec).fluxes)
    return; // only `type`, read by read_analysis_type
  static const Options<InitialStateKind> states = {
      {"donnan", InitialStateKind::Donnan},
      {"donnan-prestressed", InitialStateKind::DonnanPrestressed}};
  AnalysisSpec& a = spec.analysis;
  a.initial_state =
      t->choice("initial_state", states, std::optional(a.initial_state), "initial state");
  static const Options<FluxMass> masses = {{"consistent", FluxMass::Consistent},
                                           {"lumped", FluxMass::Lumped}};
  a.flux_mass = t->choice("flux_mass", masses, std::optional(a.flux_mass), "flux mass");
  a.fixed_charge_curve = t->name("fixed_charge_curve", false);
  if (a.fixed_charge_curve.empty())
    return;
  check_reference(*t, "fixed_charge_curve", a.fixed_charge_curve, spec.curves, "curve", "curves");
  if (!model_fields(spec).ions)
    fail(t->find("fixed_charge_curve"),
         fmt::format("{} = '{}'", t->path("fixed_charge_curve"), a.fixed_charge_curve),
         "only applies to triphasic materials (no material has a fixed charge)");
}

void read_electrochemistry(const Table& root, CaseSpec& spec) {
  const auto t = root.table("electrochemistry");
  if (!t)
    return;
  require_mixture(*t, spec);
  t->allow({"R", "T", "faraday", "bath_concentration", "bath_activity", "bath_osmotic"});
  ElectrochemistrySpec& e = spec.electrochemistry; // holds the defaults until overwritten
  const auto positive = [&](std::string_view key, Real fallback, std::string_view unit) {
    return t->number(key, {.range = Range::positive(), .fallback = fallback, .unit = unit});
  };
  e.R = positive("R", e.R, "mJ/(mmol K)");
  e.T = positive("T", e.T, "K");
  e.faraday = positive("faraday", e.faraday, "C/mmol");
  e.bath_concentration =
      t->number("bath_concentration", {.range = Range::positive(),
                                       .fallback = e.bath_concentration,
                                       .unit = "mmol/mm^3",
                                       .plausible = &material::plausible::concentration()});
  e.bath_activity = positive("bath_activity", e.bath_activity, "");
  e.bath_osmotic = positive("bath_osmotic", e.bath_osmotic, "");
}

} // namespace trifem::io::detail

namespace trifem::io::detail {

/// [[contact]] pairs.
void read_contacts(const Table& root, CaseSpec& spec) {
  const Options<bool> integration = {{"both-surfaces", true}, {"slave-nodes", false}};
  for (const Table& t : root.tables("contact")) {
    t.allow({"master", "slave", "integration", "scale", "search_distance", "penetration_tolerance",
             "friction"});
    ContactSpec c;
    c.key = t.path();
    c.master = t.name("master");
    c.slave = t.name("slave");
    if (c.master == c.slave)
      fail(t.find("slave"), t.path("slave"),
           fmt::format("'{}' is also the master surface; a pair needs two surfaces", c.slave));
    for (const ContactSpec& other : spec.contacts)
      if ((other.master == c.master && other.slave == c.slave) ||
          (other.master == c.slave && other.slave == c.master))
        fail(t.find("slave"), c.key,
             fmt::format("the surfaces '{}' and '{}' are already a pair in {}; each pair of "
                         "surfaces is one [[contact]] entry (remove the duplicate)",
                         c.master, c.slave, other.key));
    c.both_surfaces = t.choice("integration", integration, std::optional<bool>(true));
    c.scale = t.number(
        "scale", {.range = material::Range::non_negative(), .fallback = 0.0, .unit = "MPa/mm"});
    c.search_distance =
        t.number("search_distance",
                 {.range = material::Range::non_negative(), .fallback = 0.0, .unit = "mm"});
    c.penetration_tolerance =
        t.number("penetration_tolerance",
                 {.range = material::Range::non_negative(), .fallback = -1.0, .unit = "mm"});
    c.friction = t.number("friction", {.range = material::Range::non_negative(), .fallback = 0.0});
    spec.contacts.push_back(std::move(c));
  }
}

/// The optional `components` key of `t` (default: all three).
std::vector<Component> read_components(const Table& t) {
  const toml::node* n = t.find("components");
  if (!n)
    return {0, 1, 2};
  const toml::array& a = array_of(*n, t.path("components"), "an array of components");
  if (a.empty())
    fail(n, t.path("components"), "expected at least one of \"x\", \"y\", \"z\", got []");
  std::vector<Component> components;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string path = element_path(t.path("components"), i);
    const Component c = component_of(a[i], path);
    if (std::find(components.begin(), components.end(), c) != components.end())
      fail(&a[i], fmt::format("{} = '{}'", path, kAxis[c]), "duplicate component");
    components.push_back(c);
  }
  return components;
}

} // namespace trifem::io::detail
