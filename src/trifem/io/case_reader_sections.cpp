// SPDX-License-Identifier: MIT
// Case reader, part 2: [[mesh.*]], [materials.*], [curves.*], [time], [solver], [output], and the
// order in which all sections are read. The typed access layer is in toml_table.hpp; boundary
// conditions, loads and the mixture options are read in case_reader_physics.cpp.
#include "trifem/io/probe_quantities.hpp"
#include "trifem/io/toml_table.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/solid_mixture.hpp"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <map>

namespace trifem::io::detail {
namespace {

// ---------------------------------------------------------------------------------------------
// [materials.<name>] and [curves.<name>]

constexpr std::string_view kMixtureTypes[] = {"biphasic", "triphasic"};

/// Where a solid law is read: a material ([materials.<name>], which may also be a biphasic or
/// triphasic mixture), the solid matrix of such a mixture ([<material>.solid]), or a constituent
/// of a solid mixture ([[<table>.constituent]]).
enum class LawPlace { Material, Solid, Constituent };

/// Fails on a `type` of `t` that names a law valid only elsewhere: a constituent-only law
/// (fibre) outside a solid mixture, or a solid mixture inside one.
void reject_misplaced_type(const Table& t, LawPlace place) {
  const auto type = t.get<std::string>("type");
  if (!type)
    return;
  const std::string where = fmt::format("{} = '{}'", t.path("type"), *type);
  if (place == LawPlace::Constituent && *type == material::kSolidMixtureType)
    fail(t.find("type"), where,
         "nested solid mixtures are not supported (list the constituents of the inner mixture "
         "in the outer one)");
  const auto& only = material::constituent_laws();
  if (place != LawPlace::Constituent &&
      std::any_of(only.begin(), only.end(), [&](const auto& law) { return law.type == *type; }))
    fail(t.find("type"), where,
         fmt::format("a fibre family is valid only as a constituent of a solid mixture: give {} = "
                     "\"{}\" with a ground matrix and this law as [[{}]] tables (alone it "
                     "carries no load at zero strain and none across the fibre)",
                     t.path("type"), material::kSolidMixtureType, t.path("constituent")));
}

/// The `type` key of `t`: a registered solid law; a "solid-mixture" except as a constituent; a
/// constituent-only law (fibre) only as a constituent; "biphasic"/"triphasic" only as a
/// material.
std::string read_type(const Table& t, LawPlace place, std::string_view noun) {
  reject_misplaced_type(t, place);
  Options<std::string_view> types;
  for (const auto& law : material::registered_laws())
    types.emplace_back(law.type, law.type);
  if (place == LawPlace::Constituent)
    for (const auto& law : material::constituent_laws())
      types.emplace_back(law.type, law.type);
  else
    types.emplace_back(material::kSolidMixtureType, material::kSolidMixtureType);
  if (place == LawPlace::Material)
    for (const std::string_view type : kMixtureTypes)
      types.emplace_back(type, type);
  return std::string(t.choice("type", types, std::optional<std::string_view>(), noun));
}

/// The parameter `p` of a solid law, read from `t` into `values` (a Vector as its components).
void read_law_parameter(const Table& t, const material::ParameterSchema& p,
                        material::ParameterValues& values) {
  const NumberRule rule{
      .range = p.range, .unit = p.unit, .plausible = material::parameter_plausibility(p.key)};
  if (p.kind == material::ParameterKind::Vector)
    material::set_vector(values, p.key, t.vec3(p.key, rule, std::nullopt));
  else
    values[p.key] = t.number(p.key, rule);
}

SolidSpec read_solid_mixture(const Table& t, const std::vector<std::string_view>& extra);

/// The solid law `type` read from `t`, which holds `type`, the law's parameters (or, for a solid
/// mixture, its constituents) and the material-level `extra` keys (read by the caller) only.
SolidSpec read_solid_law(const Table& t, const std::string& type,
                         std::vector<std::string_view> extra = {}) {
  if (type == material::kSolidMixtureType)
    return read_solid_mixture(t, extra);
  const material::LawEntry& law = material::find_law(type, t.path());
  std::vector<std::string_view> keys = {"type"};
  for (const auto& p : *law.parameters)
    keys.push_back(p.key);
  t.allow(keys, extra);
  material::ParameterValues values;
  for (const auto& p : *law.parameters)
    if (t.find(p.key) != nullptr)
      read_law_parameter(t, p, values);
  SolidSpec s{law.type, material::validate_parameters(*law.parameters, values, t.path()), {}};
  material::create_law(s.type, s.parameters, t.path()); // the law's own checks, if any
  return s;
}

/// The solid mixture `t`: its [[<t>.constituent]] tables, each a law with its parameters.
SolidSpec read_solid_mixture(const Table& t, const std::vector<std::string_view>& extra) {
  t.allow({"type", "constituent"}, extra);
  const std::vector<Table> parts = t.tables("constituent");
  if (parts.empty()) {
    const toml::node* given = t.find("constituent");
    fail(given ? given : t.where(), t.path("constituent"),
         fmt::format("{} (a solid mixture needs at least one constituent: a ground matrix, e.g. "
                     "neo-hookean, and fibre families; one [[{}]] table each)",
                     given ? "no constituent given" : "missing required array of tables",
                     t.path("constituent")));
  }
  SolidSpec s{std::string(material::kSolidMixtureType), {}, {}};
  for (const Table& part : parts)
    s.constituents.push_back(
        read_solid_law(part, read_type(part, LawPlace::Constituent, "constituent law")));
  material::create_law(s, t.path()); // the mixture's own checks (stiffness at zero strain)
  return s;
}

/// Rejects the keys of a triphasic material in the biphasic material `t`.
void reject_triphasic_keys(const Table& t) {
  const auto in = [](const std::vector<material::ParameterSchema>& schema, std::string_view key) {
    return std::any_of(schema.begin(), schema.end(), [&](const auto& p) { return p.key == key; });
  };
  const auto [key, node] = t.first_key([&](std::string_view k) {
    return in(material::mixture_schema(true), k) && !in(material::mixture_schema(false), k);
  });
  if (node)
    fail(node, t.path(key),
         fmt::format("only applies to triphasic materials ({} = 'biphasic' has no fixed charge "
                     "and no ions)",
                     t.path("type")));
}

/// The plausible magnitudes of a transport-law parameter of unit `unit`, if checked.
const material::Plausibility* transport_plausibility(std::string_view unit) {
  if (unit == "mm^4/(N s)")
    return &material::plausible::permeability();
  if (unit == "mm^2/s")
    return &material::plausible::diffusivity();
  return nullptr;
}

/// The law given as the table `key` of the mixture `t` ([<t>.<key>] or an inline table with
/// `type` and the law's parameters), added to `values` as material::transport_law_key entries.
void read_transport_law(const Table& t, std::string_view key, material::ParameterValues& values) {
  const Table law_table = *t.table(key);
  Options<const material::TransportLawInfo*> types;
  for (const material::TransportLawInfo* law : material::transport_laws(key))
    types.emplace_back(law->type, law);
  const std::string noun = key == "permeability" ? "permeability law" : "diffusivity law";
  const material::TransportLawInfo* law =
      law_table.choice("type", types, std::optional<const material::TransportLawInfo*>(), noun);
  std::vector<std::string_view> keys = {"type"};
  for (const auto& p : *law->parameters)
    keys.push_back(p.key);
  law_table.allow(keys);
  material::ParameterValues given;
  for (const auto& p : *law->parameters)
    if (law_table.find(p.key) != nullptr)
      given[p.key] = law_table.number(
          p.key, {.range = p.range, .unit = p.unit, .plausible = transport_plausibility(p.unit)});
  // with the defaults filled in, the law is stored even if all its parameters were defaulted
  for (const auto& [name, value] :
       material::validate_parameters(*law->parameters, given, law_table.path()))
    values[material::transport_law_key(key, law->type, name)] = value;
}

/// The mixture keys given in `t`, range-checked (fixed_charge_basis "water"/"tissue" as 0/1;
/// permeability, d_plus and d_minus given as tables as material::transport_law_key entries);
/// defaults are not filled in.
material::ParameterValues read_mixture_values(const Table& t, bool charged) {
  static const Options<Real> bases = {{"water", 0.0}, {"tissue", 1.0}};
  material::ParameterValues values;
  for (const auto& p : material::mixture_schema(charged)) {
    const toml::node* n = t.find(p.key);
    if (n == nullptr)
      continue;
    if (!material::transport_laws(p.key).empty() && !n->is_number()) {
      if (!n->is_table())
        wrong_type(*n, t.path(p.key),
                   fmt::format("a number in {} (constant) or a table with a type (a law of the "
                               "deformation)",
                               range_text(p.range, p.unit)));
      read_transport_law(t, p.key, values);
      continue;
    }
    values[p.key] = p.key == "fixed_charge_basis"
                        ? t.choice(p.key, bases, std::optional<Real>(), "basis")
                        : t.number(p.key, {.range = p.range,
                                           .unit = p.unit,
                                           .plausible = material::parameter_plausibility(p.key)});
  }
  return values;
}

/// The [<t>.solid] sub-table of the mixture `t`.
SolidSpec read_mixture_solid(const Table& t) {
  const auto solid = t.table("solid");
  if (!solid)
    fail(t.where(), t.path("solid"),
         fmt::format("missing required table [{}] (the solid matrix of a {} material: its type "
                     "(a solid law) and parameters)",
                     t.path("solid"), t.get<std::string>("type").value_or("mixture")));
  if (const toml::node* axes = solid->find("axes"))
    fail(axes, solid->path("axes"),
         fmt::format("give the material axes of a mixture as [{}] (they orient its solid)",
                     t.path("axes")));
  return read_solid_law(*solid, read_type(*solid, LawPlace::Solid, "solid law"));
}

/// The optional [<t>.axes] table of the material `t`.
std::optional<material::AxesSpec> read_material_axes(const Table& t) {
  if (const auto axes = t.table("axes"))
    return read_axes(*axes);
  return std::nullopt;
}

/// The mass density of the material `t`: optional, required in explicit analyses (in implicit
/// dynamic ones, read_dynamic checks that every material has one).
std::optional<Real> read_density(const Table& t, const CaseSpec& spec) {
  const NumberRule rule{
      .range = Range::positive(), .unit = "t/mm^3", .plausible = &material::plausible::density()};
  if (t.find("density"))
    return t.number("density", rule);
  if (spec.is_explicit())
    fail(t.where(), t.path("density"),
         fmt::format("missing required key (expected a number in {}: dynamic-explicit analyses "
                     "need the mass density of every material, e.g. 1e-9 for water-like tissue)",
                     range_text(rule.range, rule.unit)));
  return std::nullopt;
}

MaterialSpec read_mixture(const Table& t, const std::string& type, const CaseSpec& spec) {
  const bool charged = type == "triphasic";
  if (!charged)
    reject_triphasic_keys(t);
  std::vector<std::string_view> keys = {"type", "solid"};
  for (const auto& p : material::mixture_schema(charged))
    keys.push_back(p.key);
  keys.push_back("axes");
  keys.push_back("density");
  t.allow(keys);
  const material::ParameterValues values = read_mixture_values(t, charged);
  SolidSpec solid = read_mixture_solid(t);
  MaterialSpec m{type,
                 material::validate_mixture_parameters(charged, values, t.path()),
                 std::move(solid),
                 read_density(t, spec),
                 {},
                 SolidElementSpec::Auto,
                 read_material_axes(t)};
  material::make_mixture(charged, material::create_law(*m.solid, t.path("solid")), m.parameters,
                         t.path()); // the mixture's own checks
  return m;
}

/// The `element` key of the solid-law material `t` (quasi-static analyses only).
SolidElementSpec read_solid_element(const Table& t, const CaseSpec& spec) {
  static const Options<SolidElementSpec> kinds = {
      {"auto", SolidElementSpec::Auto},
      {"displacement", SolidElementSpec::Displacement},
      {"mean-dilatation", SolidElementSpec::MeanDilatation}};
  if (spec.is_explicit() && t.find("element"))
    fail(t.find("element"), t.path("element"),
         "not used in dynamic-explicit analyses (they enforce near-incompressibility with the "
         "cell multipliers of [explicit]); remove the key");
  return t.choice("element", kinds, std::optional(SolidElementSpec::Auto), "element");
}

MaterialSpec read_material(const Table& t, const CaseSpec& spec) {
  const std::string type = read_type(t, LawPlace::Material, "material type");
  if (std::find(std::begin(kMixtureTypes), std::end(kMixtureTypes), type) !=
      std::end(kMixtureTypes)) {
    if (spec.is_explicit())
      fail(t.find("type"), fmt::format("{} = '{}'", t.path("type"), type),
           "not supported in dynamic-explicit analyses (analysis.type): only solid laws");
    return read_mixture(t, type, spec);
  }
  if (const toml::node* solid = t.find("solid"))
    fail(solid, t.path("solid"),
         fmt::format("only biphasic and triphasic materials have a [solid] sub-table ({} = '{}' "
                     "is a solid law: give its parameters in [{}] itself)",
                     t.path("type"), type, t.path()));
  if (spec.is_explicit() && t.find("axes"))
    fail(t.find("axes"), t.path("axes"),
         "not supported in dynamic-explicit analyses yet (fibre directions are global there)");
  SolidSpec s = read_solid_law(t, type, {"density", "element", "axes"});
  return {std::move(s.type),     std::move(s.parameters),   std::nullopt,
          read_density(t, spec), std::move(s.constituents), read_solid_element(t, spec),
          read_material_axes(t)};
}

CurveSpec read_curve(const Table& t) {
  t.allow({"interpolation", "points", "extend"});
  static const Options<dofs::Interpolation> kinds = {
      {"linear", dofs::Interpolation::Linear},
      {"step", dofs::Interpolation::Step},
      {"smooth", dofs::Interpolation::Smooth},
      {"next", dofs::Interpolation::Next},
      {"quadratic-blend", dofs::Interpolation::QuadraticBlend}};
  static const Options<dofs::Extension> extensions = {
      {"constant", dofs::Extension::Constant},
      {"repeat", dofs::Extension::Repeat},
      {"repeat-offset", dofs::Extension::RepeatOffset}};
  CurveSpec c;
  c.interpolation = t.choice("interpolation", kinds, std::optional(c.interpolation));
  c.points = t.required<std::vector<Point>>("points");
  c.extension = t.choice("extend", extensions, std::optional(c.extension));
  const dofs::LoadCurve check(c.points, c.interpolation, t.path("points"), c.extension);
  return c;
}

void read_materials_and_curves(const Table& root, CaseSpec& spec) {
  if (const auto materials = root.table("materials"))
    for (const auto& [name, t] : materials->named_tables())
      spec.materials.emplace(name, read_material(t, spec));
  if (const auto curves = root.table("curves"))
    for (const auto& [name, t] : curves->named_tables())
      spec.curves.emplace(name, read_curve(t));
}

// ---------------------------------------------------------------------------------------------
// [time], [solver]

void read_time(const Table& root, CaseSpec& spec) {
  if (spec.is_explicit())
    return read_explicit_time(root, spec);
  const auto t = root.table("time");
  if (root.find("step")) {
    if (t)
      fail(t->where(), "time",
           "a case with [[step]] tables has its time control in each step (end_time or "
           "duration, dt, ...), not in [time]");
    return; // read_steps sets spec.time
  }
  if (!t)
    fail(nullptr, "time", "missing required table [time] (with at least end_time and dt)");
  read_time_keys(*t, spec.time, 0.0, false);
}

} // namespace

void read_time_keys(const Table& t, TimeSpec& s, Real start, bool allow_duration) {
  std::vector<std::string_view> keys = {"end_time",          "dt",     "dt_min", "dt_max",
                                        "target_iterations", "growth", "cutback"};
  if (allow_duration) {
    keys.push_back("duration");
    if (t.find("duration") && t.find("end_time"))
      fail(t.find("duration"), t.path("duration"),
           fmt::format("give either end_time or duration, not both (end_time is {})",
                       t.path("end_time")));
  }
  if (allow_duration)
    t.allow(keys, {"name", "boundary", "loads", "release_time", "analysis", "steady"});
  else
    t.allow(keys);
  const std::string after = start > 0.0 ? fmt::format("after the previous step's end, {} s", start)
                                        : "the step control resolves times to 1e-10 s";
  const bool duration = allow_duration && t.find("duration");
  if (duration)
    s.end_time = start + t.number("duration",
                                  {.range = {kMinEndTime, kUnbounded, false, false}, .unit = "s"});
  else
    s.end_time = t.number(
        "end_time",
        {.range = {start + kMinEndTime, kUnbounded, false, false}, .unit = "s", .hint = after});
  const std::string span = fmt::format("at most {}", t.path(duration ? "duration" : "end_time"));
  const std::string at_most_dt = fmt::format("at most {}", t.path("dt"));
  const std::string at_least_dt = fmt::format("at least {}", t.path("dt"));
  s.dt =
      t.number("dt", {.range = {0.0, s.end_time - start, true, false}, .unit = "s", .hint = span});
  s.dt_min = t.number("dt_min", {.range = {0.0, s.dt, true, false},
                                 .fallback = s.dt * 1e-6,
                                 .unit = "s",
                                 .hint = at_most_dt});
  s.dt_max = t.number("dt_max", {.range = {s.dt, kUnbounded, false, false},
                                 .fallback = s.dt,
                                 .unit = "s",
                                 .hint = at_least_dt});
  s.target_iterations = t.integer("target_iterations", 1, s.target_iterations);
  s.growth = t.number("growth", {.range = {1.0, kUnbounded}, .fallback = s.growth});
  s.cutback = t.number("cutback", {.range = Range::open(0.0, 1.0), .fallback = s.cutback});
}

namespace {

/// Fails at `key` of `t` (if given) unless `applies`: it does not apply to `kind`.
void check_applies(const Table& t, std::string_view key, bool applies, std::string_view to_what,
                   LinearSolverKind kind) {
  if (t.find(key) && !applies)
    fail(t.find(key), t.path(key),
         fmt::format("applies to {}, not to linear_solver = \"{}\"", to_what, to_string(kind)));
}

/// linear_solver and the keys of its backend, each checked against it.
void read_linear_solver(const Table& t, LinearSolverChoice& c) {
  using enum LinearSolverKind;
  static const Options<LinearSolverKind> kinds = {{"auto", automatic},
                                                  {"umfpack", umfpack},
                                                  {"sparselu", sparselu},
                                                  {"mumps", mumps},
                                                  {"krylov", krylov}};
  c.kind = t.choice("linear_solver", kinds, std::optional(c.kind));
  c.petsc_options = t.get<std::string>("petsc_options").value_or("");
  check_applies(t, "petsc_options", c.petsc_options.empty() || c.kind == mumps || c.kind == krylov,
                "the PETSc backends (linear_solver = \"mumps\" or \"krylov\")", c.kind);
  c.reuse_factorization = t.get<bool>("reuse_factorization").value_or(false);
  check_applies(t, "reuse_factorization", !c.reuse_factorization || c.kind == mumps,
                "linear_solver = \"mumps\"", c.kind);
  static const Options<KrylovPreconditioner> preconditioners = {{"lu", KrylovPreconditioner::lu},
                                                                {"amg", KrylovPreconditioner::amg}};
  c.preconditioner = t.choice("preconditioner", preconditioners, std::optional(c.preconditioner));
  check_applies(t, "preconditioner",
                c.preconditioner == KrylovPreconditioner::lu || c.kind == krylov,
                "linear_solver = \"krylov\"", c.kind);
  static const Options<SchurApproximation> schurs = {{"selfp", SchurApproximation::selfp},
                                                     {"drained", SchurApproximation::drained}};
  c.schur = t.choice("schur_approximation", schurs, std::optional(c.schur));
  check_applies(t, "schur_approximation", c.kind == krylov, "linear_solver = \"krylov\"", c.kind);
  static const Options<FactorPrecision> precisions = {{"single", FactorPrecision::single},
                                                      {"double", FactorPrecision::full}};
  c.precision = t.choice("factorization_precision", precisions, std::optional(c.precision));
  if (t.find("factorization_precision") && c.kind != automatic && !c.reuse_factorization)
    fail(t.find("factorization_precision"), t.path("factorization_precision"),
         "applies to reused factorizations: linear_solver = \"auto\", or \"mumps\" with "
         "reuse_factorization = true");
}

void read_solver(const Table& root, CaseSpec& spec) {
  const auto t = root.table("solver");
  if (!t)
    return;
  t->allow({"max_iterations", "residual_tolerance", "increment_tolerance", "line_search",
            "linear_solver", "petsc_options", "reuse_factorization", "preconditioner",
            "factorization_precision", "schur_approximation"});
  SolverSpec& s = spec.solver;
  s.max_iterations = t->integer("max_iterations", 1, s.max_iterations, kMaxNewtonIterations);
  s.residual_tolerance = t->number(
      "residual_tolerance", {.range = Range::open(0.0, 1.0), .fallback = s.residual_tolerance});
  s.increment_tolerance = t->number(
      "increment_tolerance", {.range = Range::open(0.0, 1.0), .fallback = s.increment_tolerance});
  s.line_search = t->get<bool>("line_search").value_or(s.line_search);
  read_linear_solver(*t, s.linear_solver);
}

// ---------------------------------------------------------------------------------------------
// [[mesh.box]], [[mesh.gmsh]]

void check_node_count(const Table& t, const std::array<int, 3>& n) {
  const std::int64_t nodes =
      (std::int64_t{n[0]} + 1) * (std::int64_t{n[1]} + 1) * (std::int64_t{n[2]} + 1);
  if (nodes > INT_MAX)
    fail(t.find("divisions"), t.path("divisions"),
         fmt::format("{} x {} x {} cells need {} nodes, more than the {} a mesh can hold", n[0],
                     n[1], n[2], nodes, INT_MAX));
}

BoxMeshSpec read_box(const Table& t, const CaseSpec& spec) {
  t.allow({"name", "origin", "size", "divisions", "grading", "cell", "material"});
  static const Options<mesh::CellType> cells = {{"hex8", mesh::CellType::Hex8},
                                                {"hex20", mesh::CellType::Hex20},
                                                {"tet4", mesh::CellType::Tet4},
                                                {"tet10", mesh::CellType::Tet10},
                                                {"penta6", mesh::CellType::Penta6}};
  BoxMeshSpec b;
  b.box.cell = t.choice("cell", cells, std::optional(mesh::CellType::Hex8), "cell type");
  b.box.name = read_identifier(t, "name", true);
  for (std::size_t i = 0; i < spec.boxes.size(); ++i)
    if (spec.boxes[i].box.name == b.box.name)
      fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), b.box.name),
           fmt::format("duplicate box name (already used by {})", element_path("mesh.box", i)));
  b.box.origin = t.vec3("origin", {.unit = "mm"}, Vec3::Zero());
  b.box.size = t.vec3(
      "size",
      {.range = Range::positive(), .unit = "mm", .plausible = &material::plausible::length()},
      std::nullopt);
  b.box.divisions = t.required<std::array<int, 3>>("divisions");
  for (std::size_t d = 0; d < 3; ++d)
    if (b.box.divisions[d] < 1)
      fail(&(*t.find("divisions")->as_array())[d],
           fmt::format("{} = {}", element_path(t.path("divisions"), d), b.box.divisions[d]),
           "out of range, expected an integer >= 1");
  check_node_count(t, b.box.divisions);
  b.box.grading = t.vec3("grading", {.range = Range::positive()}, Vec3::Ones());
  b.material = t.name("material", false); // none: the cells of a rigid body ([[rigid_body]])
  if (!b.material.empty())
    check_reference(t, "material", b.material, spec.materials, "material", "materials");
  return b;
}

GmshMeshSpec read_gmsh(const Table& t, const CaseSpec& spec) {
  t.allow({"file", "materials"});
  GmshMeshSpec g;
  const std::string file = t.name("file");
  std::error_code ec;
  g.file = std::filesystem::absolute(spec.file.parent_path() / file, ec).lexically_normal();
  if (!std::filesystem::is_regular_file(g.file, ec))
    fail(t.find("file"), fmt::format("{} = '{}'", t.path("file"), file),
         fmt::format("{} (looked for '{}')",
                     std::filesystem::exists(g.file, ec) ? "not a regular file" : "file not found",
                     g.file.string()));
  const auto volumes = t.table("materials");
  if (!volumes)
    t.missing("materials", "a table { <physical volume name> = \"<material>\", ... }");
  // (empty: every volume is the cells of a rigid body, which have no material)
  for (const auto& [key, node] : volumes->raw()) {
    const std::string volume(key.str());
    const std::string material = volumes->name(volume);
    check_reference(*volumes, volume, material, spec.materials, "material", "materials");
    g.materials.emplace(volume, material);
  }
  return g;
}

void read_mesh(const Table& root, CaseSpec& spec) {
  if (const auto mesh = root.table("mesh")) {
    mesh->allow({"box", "gmsh", "refine"});
    spec.mesh_refinement = mesh->integer("refine", 0, 0, kMaxMeshRefinement);
    for (const Table& t : mesh->tables("box"))
      spec.boxes.push_back(read_box(t, spec));
    for (const Table& t : mesh->tables("gmsh"))
      spec.gmsh.push_back(read_gmsh(t, spec));
  }
  if (spec.boxes.empty() && spec.gmsh.empty())
    fail(nullptr, "mesh", "no mesh defined (expected at least one [[mesh.box]] or [[mesh.gmsh]])");
}

// ---------------------------------------------------------------------------------------------
// [output], [[output.reaction]], [[output.probe]], [[output.average]]

std::vector<Real> read_output_times(const Table& t, Real end_time) {
  const toml::node* n = t.find("times");
  if (!n)
    return {};
  std::vector<Real> times = t.required<std::vector<Real>>("times");
  const NumberRule rule{
      .range = Range::closed(0.0, end_time), .unit = "s", .hint = "between 0 and time.end_time"};
  for (std::size_t i = 0; i < times.size(); ++i)
    check_range(&(*n->as_array())[i], element_path(t.path("times"), i), times[i], rule);
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  return times;
}

/// The `quantity` key: one of the probe quantities (`fallback` if absent; required if none).
const ProbeQuantity& read_quantity(const Table& t, std::optional<std::string_view> fallback) {
  static const Options<std::string_view> quantities = [] {
    Options<std::string_view> o;
    for (const ProbeQuantity& q : probe_quantities())
      o.emplace_back(q.name, q.name);
    return o;
  }();
  return *find_probe_quantity(t.choice("quantity", quantities, fallback, "quantity"));
}

ProbeSpec read_probe(const Table& t, const std::vector<ProbeSpec>& earlier) {
  t.allow({"name", "quantity", "point"});
  ProbeSpec p;
  p.name = read_identifier(t, "name", false);
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].name == p.name)
      fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), p.name),
           fmt::format("duplicate probe name (already used by {})",
                       element_path("output.probe", i)));
  p.quantity = std::string(read_quantity(t, p.quantity).name);
  p.point = t.vec3("point", {.unit = "mm"}, std::nullopt);
  return p;
}

/// The `name` of an average: an identifier that no probe and no earlier average uses (both
/// prefix history columns).
std::string read_average_name(const Table& t, const OutputSpec& s) {
  const std::string name = read_identifier(t, "name", false);
  const auto taken = [&](std::string_view array, std::size_t i) {
    fail(t.find("name"), fmt::format("{} = '{}'", t.path("name"), name),
         fmt::format("duplicate name (already used by {}; probes and averages share the column "
                     "prefixes of history.csv)",
                     element_path(array, i)));
  };
  for (std::size_t i = 0; i < s.probes.size(); ++i)
    if (s.probes[i].name == name)
      taken("output.probe", i);
  for (std::size_t i = 0; i < s.averages.size(); ++i)
    if (s.averages[i].name == name)
      taken("output.average", i);
  return name;
}

/// The cell blocks a case names itself, each with its material: the [[mesh.box]] names and the
/// physical volumes the [[mesh.gmsh]] tables assign a material to.
std::map<std::string, std::string> named_blocks(const CaseSpec& spec) {
  std::map<std::string, std::string> blocks;
  for (const BoxMeshSpec& b : spec.boxes)
    if (!b.material.empty()) // the cells of a rigid body otherwise
      blocks.emplace(b.box.name, b.material);
  for (const GmshMeshSpec& g : spec.gmsh)
    blocks.insert(g.materials.begin(), g.materials.end());
  return blocks;
}

/// The `block` of an average: a block the case names. With Gmsh meshes it may also be another
/// physical volume of their files, which the model checks against the mesh.
std::string read_average_block(const Table& t, const std::map<std::string, std::string>& blocks,
                               const CaseSpec& spec) {
  const std::string block = t.name("block");
  if (blocks.contains(block) || !spec.gmsh.empty())
    return block;
  std::vector<std::string> names;
  for (const auto& entry : blocks)
    names.push_back(entry.first);
  fail(t.find("block"), fmt::format("{} = '{}'", t.path("block"), block),
       fmt::format("unknown cell block (expected the name of a [[mesh.box]]: {}){}", join(names),
                   did_you_mean(block, names)));
}

/// Fails if the material of `block` (when the case names it) does not have the quantity `q`.
void check_block_material(const Table& t, const ProbeQuantity& q, const std::string& block,
                          const std::map<std::string, std::string>& blocks, const CaseSpec& spec) {
  const auto it = blocks.find(block);
  if (it == blocks.end())
    return; // a physical volume of a Gmsh file: the model checks its cells
  const MaterialSpec& m = spec.materials.at(it->second);
  if (material_has(q, m.is_mixture(), m.type == "triphasic"))
    return;
  fail(t.find("quantity"), fmt::format("{} = '{}'", t.path("quantity"), q.name),
       fmt::format("cell block '{}' has the material '{}' ({}), which has no {} (it needs a {} "
                   "material)",
                   block, it->second, m.type, q.name, required_material(q)));
}

/// An [[output.average]]: its name, quantity and cell block.
AverageSpec read_average(const Table& t, const CaseSpec& spec) {
  t.allow({"name", "quantity", "block"});
  AverageSpec a;
  a.name = read_average_name(t, spec.output);
  const ProbeQuantity& q = read_quantity(t, std::nullopt);
  a.quantity = std::string(q.name);
  const std::map<std::string, std::string> blocks = named_blocks(spec);
  a.block = read_average_block(t, blocks, spec);
  check_block_material(t, q, a.block, blocks, spec);
  return a;
}

/// The history of a dynamic-explicit run has nodal probes only: [[output.average]] is refused
/// there.
void reject_explicit_averages(const Table& output, const CaseSpec& spec) {
  const std::vector<Table> averages = output.tables("average");
  if (!spec.is_explicit() || averages.empty())
    return;
  fail(averages.front().where(), averages.front().path(),
       "[[output.average]] is not supported in dynamic-explicit analyses (analysis.type); use "
       "[[output.probe]] with quantity 'displacement' or 'position'");
}

ReactionSpec read_reaction(const Table& t, const std::vector<ReactionSpec>& earlier) {
  t.allow({"set"});
  ReactionSpec r{t.name("set")};
  for (std::size_t i = 0; i < earlier.size(); ++i)
    if (earlier[i].set == r.set)
      fail(t.find("set"), fmt::format("{} = '{}'", t.path("set"), r.set),
           fmt::format("node set already listed in {}", element_path("output.reaction", i)));
  return r;
}

void read_output(const Table& root, CaseSpec& spec) {
  const auto t = root.table("output");
  if (!t)
    return;
  t->allow(
      {"interval", "history_interval", "times", "vtu", "restart", "reaction", "probe", "average"});
  OutputSpec& s = spec.output;
  s.interval_given = t->find("interval") != nullptr;
  s.interval =
      t->number("interval", {.range = Range::non_negative(), .fallback = s.interval, .unit = "s"});
  s.times = read_output_times(*t, spec.time.end_time);
  if (const toml::node* node = t->find("history_interval")) {
    if (!spec.is_explicit() && !spec.has_explicit_step())
      fail(node, t->path("history_interval"),
           "only dynamic-explicit steps thin their history rows (a quasi-static or implicit "
           "dynamic step writes one per step); remove the key");
    s.history_interval =
        t->number("history_interval",
                  {.range = Range::non_negative(), .fallback = s.history_interval, .unit = "s"});
  }
  s.vtu = t->get<bool>("vtu").value_or(s.vtu);
  s.restart = t->get<bool>("restart").value_or(s.restart);
  for (const Table& r : t->tables("reaction"))
    s.reactions.push_back(read_reaction(r, s.reactions));
  for (const Table& p : t->tables("probe"))
    s.probes.push_back(read_probe(p, s.probes));
  reject_explicit_averages(*t, spec);
  for (const Table& a : t->tables("average"))
    s.averages.push_back(read_average(a, spec));
}

} // namespace

void read_sections(const toml::table& document, CaseSpec& spec) {
  const Table root(document, "", &spec.warnings);
  root.allow({"title", "mesh", "materials", "curves", "boundary", "loads", "contact", "rigid_body",
              "connector", "constraint", "analysis", "electrochemistry", "time", "step", "solver",
              "explicit", "dynamic", "initial_velocity", "output"});
  spec.title = root.get<std::string>("title").value_or("");
  read_analysis_type(root, spec); // the other sections depend on it
  check_analysis_sections(root, spec);
  read_materials_and_curves(root, spec);
  read_time(root, spec);
  read_mesh(root, spec);
  read_boundary(root, spec);
  read_loads(root, spec);
  read_contacts(root, spec);
  read_rigid_bodies(root, spec);
  read_connectors(root, spec);
  read_constraints(root, spec);
  read_analysis(root, spec);
  read_electrochemistry(root, spec);
  read_solver(root, spec);
  read_explicit(root, spec);
  read_steps(root, spec);
  read_dynamic(root, spec);
  read_output(root, spec);
  check_time_limits(&root, spec);
  check_model_size(&root, spec);
}

} // namespace trifem::io::detail
