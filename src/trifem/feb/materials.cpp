// SPDX-License-Identifier: MIT
// Material section: FEBio material types -> trifem laws with the same strain energy.
#include "trifem/core/error.hpp"
#include "trifem/feb/reader.hpp"
#include "trifem/material/material_axes.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/solid_mixture.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <optional>

namespace trifem::feb::detail {
namespace {

/// A FEBio solid law whose strain energy is that of a trifem law (docs/feb.md "Materials").
struct LawMapping {
  const char* febio;
  const char* trifem;
  std::vector<std::pair<const char*, const char*>> parameters; ///< FEBio name -> trifem name
  std::vector<const char*> zero; ///< FEBio parameters accepted only at 0 (terms trifem lacks)
  std::vector<const char*> ignored = {}; ///< FEBio parameters of those absent terms
  bool takes_axes = false; ///< an anisotropic law: its <mat_axis> orients the material
};

const std::vector<LawMapping>& law_mappings() {
  static const std::vector<LawMapping> laws = {
      {"neo-Hookean", "neo-hookean", {{"E", "E"}, {"v", "nu"}}, {}},
      {"isotropic elastic", "saint-venant-kirchhoff", {{"E", "E"}, {"v", "nu"}}, {}},
      {"Holmes-Mow", "holmes-mow", {{"E", "E"}, {"v", "nu"}, {"beta", "beta"}}, {}},
      {"Mooney-Rivlin", "mooney-rivlin", {{"c1", "c1"}, {"c2", "c2"}, {"k", "k"}}, {}},
      {"Ogden",
       "ogden",
       {{"c1", "c1"},
        {"c2", "c2"},
        {"c3", "c3"},
        {"m1", "m1"},
        {"m2", "m2"},
        {"m3", "m3"},
        {"k", "k"}},
       {"c4", "c5", "c6"},
       {"m4", "m5", "m6"}},
      {"Ogden unconstrained",
       "ogden-unconstrained",
       {{"c1", "c1"},
        {"c2", "c2"},
        {"c3", "c3"},
        {"c4", "c4"},
        {"c5", "c5"},
        {"c6", "c6"},
        {"m1", "m1"},
        {"m2", "m2"},
        {"m3", "m3"},
        {"m4", "m4"},
        {"m5", "m5"},
        {"m6", "m6"},
        {"cp", "cp"}},
       {}},
      {"Veronda-Westmann", "veronda-westmann", {{"c1", "c1"}, {"c2", "c2"}, {"k", "k"}}, {}},
      {"porous neo-Hookean", "porous-neo-hookean", {{"E", "E"}, {"phi0", "phi0"}}, {}},
      {"uncoupled Holmes-Mow",
       "holmes-mow-uncoupled",
       {{"mu", "mu"}, {"beta", "beta"}, {"k", "k"}},
       {}},
      {"Yeoh",
       "yeoh",
       {{"c1", "c1"},
        {"c2", "c2"},
        {"c3", "c3"},
        {"c4", "c4"},
        {"c5", "c5"},
        {"c6", "c6"},
        {"k", "k"}},
       {}},
      {"orthotropic elastic",
       "orthotropic-elastic",
       {{"E1", "E1"},
        {"E2", "E2"},
        {"E3", "E3"},
        {"G12", "G12"},
        {"G23", "G23"},
        {"G31", "G31"},
        {"v12", "v12"},
        {"v23", "v23"},
        {"v31", "v31"}},
       {},
       {},
       true},
  };
  return laws;
}

/// Parameters FEBio reads that do not change a quasi-static solution without body forces.
bool ignored_parameter(std::string_view name) {
  return name == "density";
}

std::string known_types() {
  std::string s;
  for (const auto& m : law_mappings())
    s += fmt::format("{}{}", s.empty() ? "" : ", ", m.febio);
  return s + ", trans iso Mooney-Rivlin, trans iso Veronda-Westmann, Arruda-Boyce, EFD "
             "neo-Hookean, solid "
             "mixture and uncoupled solid mixture (of these and the fibres fiber-exp-pow, "
             "fiber-exp-linear, uncoupled fiber-exp-linear, ellipsoidal fiber distribution, EFD "
             "uncoupled), "
             "biphasic, triphasic, multiphasic (Na and Cl)";
}

/// The value of a material parameter element (a plain number: no load curve, no map).
Real parameter_value(const Reader& r, pugi::xml_node p) {
  if (p.attribute("lc"))
    r.doc.fail(p, "a load curve on a material parameter is not supported");
  if (p.attribute("type"))
    r.doc.fail(p, "only a constant material parameter is supported (no map or math)");
  return r.doc.number(p);
}

/// `law`, validated by trifem's schema: returned as it is, or the validation's InputError
/// located at `node`.
material::LawSpec validated(const Reader& r, pugi::xml_node node, material::LawSpec law,
                            const std::string& context = "") {
  try {
    material::create_law(law, context.empty() ? fmt::format("trifem {}", law.type) : context);
  } catch (const InputError& e) {
    r.doc.fail(node, e.what());
  }
  return law;
}

/// A density element `name` of `node`, or FEBio's default for it.
Real density_child(const Reader& r, pugi::xml_node node, const char* name, Real fallback) {
  const pugi::xml_node d = node.child(name);
  return d ? parameter_value(r, d) : fallback;
}

/// The mass per reference volume of a FEBio material: a solid's <density> (FEBio's default 1);
/// of a mixture φ0 ρ_s + (1 − φ0) ρ_w, with ρ_s the solid's density (or <solid_density>) and ρ_w
/// its <fluid_density> (FEBio's default 0).
Real material_density(const Reader& r, pugi::xml_node node, const io::MaterialSpec& m) {
  if (!m.is_mixture())
    return density_child(r, node, "density", 1.0);
  const Real solid = density_child(r, node, "solid_density",
                                   density_child(r, node.child("solid"), "density", 1.0));
  const Real fluid = density_child(r, node, "fluid_density", 0.0);
  const Real phi = m.parameters.at("phi_s0");
  return phi * solid + (1.0 - phi) * fluid;
}

/// <pressure_model> of an uncoupled law: only FEBio's default, U = k/2 (ln J)^2.
void check_pressure_model(const Reader& r, pugi::xml_node p) {
  const std::string model = r.doc.text(p);
  if (model != "default" && model != "0")
    r.doc.fail(p, fmt::format("pressure_model '{}' is not supported (trifem's volumetric energy "
                              "is FEBio's default, U = k/2 (ln J)^2)",
                              model));
}

/// <fiber type="vector"><vector>x,y,z</vector></fiber> (or the vector as the element's text),
/// or <fiber type="angles"><theta>..</theta><phi>..</phi></fiber> (degrees; FEBio's
/// (cos θ sin φ, sin θ sin φ, cos φ)): a constant fibre direction.
Vec3 fibre_vector(const Reader& r, pugi::xml_node fiber) {
  const std::string type = fiber.attribute("type").as_string("vector");
  if (type == "angles") {
    const Real degree = std::numbers::pi / 180.0;
    const Real theta = r.doc.number(r.doc.child(fiber, "theta")) * degree;
    const Real phi = r.doc.number(r.doc.child(fiber, "phi")) * degree;
    return {std::cos(theta) * std::sin(phi), std::sin(theta) * std::sin(phi), std::cos(phi)};
  }
  if (type != "vector")
    r.doc.fail(fiber, "type",
               fmt::format("fiber of type '{}' is not supported (supported: vector and angles, "
                           "a constant direction, and local in trans iso laws)",
                           type));
  const pugi::xml_node vector = fiber.child("vector");
  return r.doc.vector(vector ? vector : fiber);
}

/// FEBio's "trans iso Mooney-Rivlin" and "trans iso Veronda-Westmann": the uncoupled ground
/// matrix `ground` (c1, c2, k) plus an uncoupled exponential-linear fibre family (c3, c4, c5,
/// lam_max, fiber), as a trifem solid mixture of the two.
/// <fiber type="local"><local>n1,n2</local></fiber>: FEBio's fibre along each element's edge
/// from its node n1 to its node n2 (1-based, FEBio's node order; 0,0: 1,2). The material gets
/// per-cell axes whose e1 is that direction (a cell data view the reader makes once the mesh is
/// read: local_fibre_view) and the fibre is e1. InputError where the material cannot take axes.
void local_fibre(const Reader& r, pugi::xml_node fiber, std::optional<material::AxesSpec>* axes,
                 material::LawSpec& fibre) {
  if (axes == nullptr)
    r.doc.fail(fiber, "a local fibre here is not supported (trifem orients a material as a whole)");
  const std::vector<long> n = r.doc.ids(r.doc.child(fiber, "local"));
  if (n.size() != 2 || n[0] < 0 || n[1] < 0 || (n[0] == 0) != (n[1] == 0) ||
      (n[0] > 0 && n[0] == n[1]))
    r.doc.fail(fiber, "local: expected two different element node numbers (1-based), or 0,0");
  material::AxesSpec local;
  local.kind = material::AxesKind::Mesh;
  local.view = local_fibre_view(n[0] == 0 ? 1 : n[0], n[0] == 0 ? 2 : n[1]);
  *axes = local;
  material::set_vector(fibre.parameters, "fibre", Vec3::UnitX());
}

material::LawSpec trans_iso_law(const Reader& r, pugi::xml_node node, const char* ground,
                                std::optional<material::AxesSpec>* axes) {
  material::LawSpec matrix{ground, {}, {}}, fibre{"fibre-exp-linear", {}, {}};
  bool has_fibre = false;
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "pressure_model") {
      check_pressure_model(r, p);
    } else if (name == "c1" || name == "c2" || name == "k") {
      matrix.parameters[name] = parameter_value(r, p);
    } else if (name == "c3" || name == "c4" || name == "c5" || name == "lam_max") {
      fibre.parameters[name] = parameter_value(r, p);
    } else if (name == "fiber") {
      if (std::string_view(p.attribute("type").value()) == "local")
        local_fibre(r, p, axes, fibre);
      else
        material::set_vector(fibre.parameters, "fibre", fibre_vector(r, p));
      has_fibre = true;
    } else if (name == "active_contraction") {
      r.doc.fail(p, "an active contraction is not supported (trifem's fibres are passive)");
    } else if (!ignored_parameter(name)) {
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type '{}' (expected one of: "
                                "c1, c2, c3, c4, c5, lam_max, k, fiber, density)",
                                name, r.doc.attribute(node, "type")));
    }
  }
  if (!has_fibre)
    r.doc.fail(node, "the fibre direction <fiber> is required");
  material::LawSpec mixture{std::string(material::kSolidMixtureType), {}, {matrix, fibre}};
  return validated(r, node, std::move(mixture));
}

/// A fibre constituent of a FEBio solid mixture: fiber-exp-pow (its toe stretch lam0 = 1 and
/// fibre modulus mu = 0 only), fiber-exp-linear (coupled) or uncoupled fiber-exp-linear, with a
/// constant <fiber>; nullopt for other types.
std::optional<material::LawSpec> fibre_constituent(const Reader& r, pugi::xml_node node) {
  const std::string type = r.doc.attribute(node, "type");
  std::vector<std::pair<const char*, const char*>> names;
  std::vector<std::pair<const char*, Real>> fixed; // FEBio parameters trifem has at one value
  material::LawSpec law;
  if (type == "fiber-exp-pow") {
    law.type = "fibre-exp-pow";
    names = {{"ksi", "ksi"}, {"alpha", "alpha"}, {"beta", "beta"}};
    fixed = {{"lam0", 1.0}, {"mu", 0.0}};
  } else if (type == "fiber-exp-linear" || type == "uncoupled fiber-exp-linear") {
    law.type = type == "fiber-exp-linear" ? "fibre-exp-linear-coupled" : "fibre-exp-linear";
    names = {
        {"c3", "c3"}, {"c4", "c4"}, {"c5", "c5"}, {"lambda", "lam_max"}, {"lam_max", "lam_max"}};
  } else {
    return std::nullopt;
  }
  bool has_fibre = false;
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "fiber") {
      material::set_vector(law.parameters, "fibre", fibre_vector(r, p));
      has_fibre = true;
      continue;
    }
    if (name == "k") { // an uncoupled fibre's: its mixture sums it with the others'
      law.parameters["k"] = parameter_value(r, p);
      continue;
    }
    if (ignored_parameter(name) || name == "pressure_model")
      continue;
    if (const auto it = std::find_if(fixed.begin(), fixed.end(),
                                     [&](const auto& q) { return name == q.first; });
        it != fixed.end()) {
      if (parameter_value(r, p) != it->second)
        r.doc.fail(p, fmt::format("{} = {} only (trifem's {} has no such term)", name, it->second,
                                  law.type));
      continue;
    }
    const auto it =
        std::find_if(names.begin(), names.end(), [&](const auto& q) { return name == q.first; });
    if (it == names.end())
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type '{}'", name, type));
    law.parameters[it->second] = parameter_value(r, p);
  }
  if (!has_fibre)
    r.doc.fail(node, "the fibre direction <fiber> is required");
  return law;
}

/// FEBio's "ellipsoidal fiber distribution" (beta and ksi, three values each) as trifem's
/// ellipsoidal-fibre-distribution (of the deviatoric deformation if `uncoupled`: FEBio's "EFD
/// uncoupled"); other elements of `node` but those in `also` are errors.
material::LawSpec efd_law(const Reader& r, pugi::xml_node node,
                          const std::vector<std::string>& also = {}, bool uncoupled = false) {
  material::LawSpec law{uncoupled ? "ellipsoidal-fibre-distribution-uncoupled"
                                  : "ellipsoidal-fibre-distribution",
                        {},
                        {}};
  for (const char* name : {"beta", "ksi"})
    material::set_vector(law.parameters, name, r.doc.vector(r.doc.child(node, name)));
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name != "beta" && name != "ksi" && !ignored_parameter(name) &&
        std::find(also.begin(), also.end(), name) == also.end()) {
      std::string expected;
      for (const std::string& a : also)
        expected += ", " + a;
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type '{}' (expected: beta, "
                                "ksi{}, density)",
                                name, r.doc.attribute(node, "type"), expected));
    }
  }
  return law;
}

material::LawSpec solid_law(const Reader& r, pugi::xml_node node,
                            std::optional<material::AxesSpec>* axes, bool validate = true);

/// Whether the trifem law `type` has a bulk modulus k (an uncoupled law).
bool has_bulk_modulus(const std::string& type) {
  const auto& schema = *material::find_law(type, type).parameters;
  return std::any_of(schema.begin(), schema.end(), [](const auto& p) { return p.key == "k"; });
}

/// FEBio's "solid mixture" and "uncoupled solid mixture": the sum of its <solid> constituents
/// (laws or fibres), as a trifem solid mixture. The bulk modulus of an uncoupled mixture is its
/// own k plus its constituents' (FEBio sums them), carried by the first constituent with a k.
material::LawSpec solid_mixture_law(const Reader& r, pugi::xml_node node, bool uncoupled) {
  material::LawSpec mixture{std::string(material::kSolidMixtureType), {}, {}};
  Real k = 0.0;
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "solid") {
      const std::string type = r.doc.attribute(p, "type");
      if (type == "solid mixture" || type == "uncoupled solid mixture")
        r.doc.fail(p, "a solid mixture inside a solid mixture is not supported (list its "
                      "constituents in the outer one)");
      std::optional<material::LawSpec> fibre = fibre_constituent(r, p);
      if (type == "ellipsoidal fiber distribution" || type == "EFD uncoupled") {
        fibre = efd_law(r, p, {"k", "pressure_model"}, type == "EFD uncoupled");
        if (const pugi::xml_node k = p.child("k")) // summed with the mixture's below
          fibre->parameters["k"] = parameter_value(r, k);
      }
      mixture.constituents.push_back(fibre ? *fibre : solid_law(r, p, nullptr, false));
    } else if (uncoupled && name == "k") {
      k = parameter_value(r, p);
    } else if (uncoupled && name == "pressure_model") {
      check_pressure_model(r, p);
    } else if (!ignored_parameter(name)) {
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type '{}' (expected: solid, "
                                "density{})",
                                name, r.doc.attribute(node, "type"), uncoupled ? ", k" : ""));
    }
  }
  if (mixture.constituents.empty())
    r.doc.fail(node, "a solid mixture needs at least one <solid>");
  if (uncoupled) { // FEBio: k of the mixture plus those of its constituents, on the first
    const auto carrier = std::find_if(mixture.constituents.begin(), mixture.constituents.end(),
                                      [](const auto& c) { return has_bulk_modulus(c.type); });
    if (carrier == mixture.constituents.end())
      r.doc.fail(node, "no constituent of the uncoupled mixture has a bulk modulus k to carry "
                       "the volume (an uncoupled law such as Mooney-Rivlin)");
    for (auto& c : mixture.constituents)
      if (&c != &*carrier && c.parameters.contains("k")) {
        k += c.parameters.at("k");
        c.parameters.erase("k");
      }
    carrier->parameters["k"] += k; // (absent: 0)
  }
  return validated(r, node, std::move(mixture));
}

/// FEBio's "Arruda-Boyce" (mu, N, k): W = mu sum_i a_i (I1~^i - 3^i)/N^(i-1) + k/2 (ln J)^2 with
/// FEBio's a = (1/2, 1/10, 11/350, 19/1750, 519/134750), a polynomial of degree 5 in I1~ and so
/// trifem's Yeoh law with c_j = mu sum_(i>=j) a_i/N^(i-1) C(i, j) 3^(i-j).
material::LawSpec arruda_boyce_law(const Reader& r, pugi::xml_node node) {
  Real mu = 0.0, N = 0.0;
  material::LawSpec law{"yeoh", {}, {}};
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "mu")
      mu = parameter_value(r, p);
    else if (name == "N")
      N = parameter_value(r, p);
    else if (name == "k")
      law.parameters["k"] = parameter_value(r, p);
    else if (name == "pressure_model")
      check_pressure_model(r, p);
    else if (!ignored_parameter(name))
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type 'Arruda-Boyce' "
                                "(expected one of: mu, N, k, density)",
                                name));
  }
  if (!(mu > 0.0) || !(N > 0.0))
    r.doc.fail(node,
               fmt::format("Arruda-Boyce needs mu > 0 and N > 0 (got mu = {}, N = {})", mu, N));
  constexpr std::array<Real, 5> a = {0.5, 0.1, 11.0 / 350.0, 19.0 / 1750.0, 519.0 / 134750.0};
  std::array<Real, 6> c{};
  for (int i = 1; i <= 5; ++i) {
    const Real A = mu * a[static_cast<std::size_t>(i - 1)] / std::pow(N, i - 1);
    Real binomial = 1.0; // C(i, j), j from i down to 1
    for (int j = i; j >= 1; --j) {
      c[static_cast<std::size_t>(j - 1)] += A * binomial * std::pow(3.0, i - j);
      binomial = binomial * j / (i - j + 1);
    }
  }
  for (int j = 1; j <= 5; ++j)
    law.parameters[fmt::format("c{}", j)] = c[static_cast<std::size_t>(j - 1)];
  return validated(r, node, std::move(law), "trifem yeoh (Arruda-Boyce)");
}

/// FEBio's "EFD neo-Hookean" (neo-Hookean E, v), "EFD Mooney-Rivlin" and "EFD Veronda-Westmann"
/// (uncoupled c1, c2, k) plus an ellipsoidal fibre distribution (beta, ksi; the uncoupled one
/// with the uncoupled grounds), as a trifem solid mixture of the two.
material::LawSpec efd_ground_law(const Reader& r, pugi::xml_node node, const std::string& type) {
  const bool neo = type == "EFD neo-Hookean";
  material::LawSpec matrix{neo                           ? "neo-hookean"
                           : type == "EFD Mooney-Rivlin" ? "mooney-rivlin"
                                                         : "veronda-westmann",
                           {},
                           {}};
  using Names = std::vector<std::pair<std::string, std::string>>;
  const Names names =
      neo ? Names{{"E", "E"}, {"v", "nu"}} : Names{{"c1", "c1"}, {"c2", "c2"}, {"k", "k"}};
  std::vector<std::string> also = {"pressure_model"};
  for (const auto& [febio, trifem] : names) {
    also.push_back(febio);
    if (const pugi::xml_node p = node.child(febio.c_str()))
      matrix.parameters[trifem] = parameter_value(r, p);
  }
  if (const pugi::xml_node p = node.child("pressure_model"))
    check_pressure_model(r, p);
  material::LawSpec mixture{
      std::string(material::kSolidMixtureType), {}, {matrix, efd_law(r, node, also, !neo)}};
  return validated(r, node, std::move(mixture));
}

/// <mat_axis type="vector"><a>..</a><d>..</d></mat_axis>: FEBio's constant material axes,
/// e1 along a, e2 in the plane of a and d (trifem's axes of type vector).
material::AxesSpec material_axes(const Reader& r, pugi::xml_node node) {
  const std::string type = r.doc.attribute(node, "type");
  if (type != "vector")
    r.doc.fail(node, "type",
               fmt::format("mat_axis of type '{}' is not supported (supported: vector)", type));
  for (pugi::xml_node c : elements(node))
    if (std::string_view(c.name()) != "a" && std::string_view(c.name()) != "d")
      r.doc.fail(
          c, fmt::format("unknown parameter '{}' of a vector mat_axis (expected: a, d)", c.name()));
  material::AxesSpec axes;
  axes.kind = material::AxesKind::Vector;
  axes.a = r.doc.vector(r.doc.child(node, "a"));
  axes.d = r.doc.vector(r.doc.child(node, "d"));
  try {
    (void)material::vector_basis(axes.a, axes.d, "mat_axis");
  } catch (const InputError& e) {
    r.doc.fail(node, e.what());
  }
  return axes;
}

/// The solid law of a FEBio solid material element (type attribute), validated; `axes`
/// receives the <mat_axis> of an anisotropic law (that of an isotropic one has no effect).
material::LawSpec solid_law(const Reader& r, pugi::xml_node node,
                            std::optional<material::AxesSpec>* axes, bool validate) {
  const std::string type = r.doc.attribute(node, "type");
  if (type == "solid mixture" || type == "uncoupled solid mixture")
    return solid_mixture_law(r, node, type == "uncoupled solid mixture");
  if (type == "EFD neo-Hookean" || type == "EFD Mooney-Rivlin" || type == "EFD Veronda-Westmann")
    return efd_ground_law(r, node, type);
  if (type == "Arruda-Boyce")
    return arruda_boyce_law(r, node);
  if (type == "trans iso Mooney-Rivlin")
    return trans_iso_law(r, node, "mooney-rivlin", axes);
  if (type == "trans iso Veronda-Westmann")
    return trans_iso_law(r, node, "veronda-westmann", axes);
  const LawMapping* law = nullptr;
  for (const auto& m : law_mappings())
    if (type == m.febio)
      law = &m;
  if (!law)
    r.doc.fail(
        node, "type",
        fmt::format("material type '{}' is not supported (supported: {})", type, known_types()));
  material::LawSpec spec{law->trifem, {}, {}};
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "pressure_model") {
      check_pressure_model(r, p);
      continue;
    }
    if (ignored_parameter(name) ||
        std::find(law->ignored.begin(), law->ignored.end(), name) != law->ignored.end())
      continue;
    if (name == "mat_axis") {
      if (!law->takes_axes) // an isotropic law: the axes change nothing
        continue;
      if (axes == nullptr)
        r.doc.fail(p, "a mat_axis here is not supported (trifem orients a material as a whole)");
      *axes = material_axes(r, p);
      continue;
    }
    if (std::find(law->zero.begin(), law->zero.end(), name) != law->zero.end()) {
      if (parameter_value(r, p) != 0.0)
        r.doc.fail(p, fmt::format("{} != 0: trifem's {} law has at most 3 terms", name, type));
      continue;
    }
    const auto it = std::find_if(law->parameters.begin(), law->parameters.end(),
                                 [&](const auto& q) { return name == q.first; });
    if (it == law->parameters.end()) {
      std::string known;
      for (const auto& q : law->parameters)
        known += fmt::format("{}{}", known.empty() ? "" : ", ", q.first);
      r.doc.fail(p, fmt::format("unknown parameter '{}' of material type '{}' (expected one of: "
                                "{}, density)",
                                name, type, known));
    }
    spec.parameters[it->second] = parameter_value(r, p);
  }
  if (!validate) // a constituent: validated with its mixture (after its k is set)
    return spec;
  return validated(r, node, std::move(spec));
}

/// The permeability element of a biphasic material as mixture parameters.
void permeability(const Reader& r, pugi::xml_node node, material::ParameterValues& values) {
  const std::string type = r.doc.attribute(node, "type");
  std::string law;
  std::vector<std::pair<const char*, const char*>> names;
  if (type == "perm-const-iso") {
    names = {{"perm", "k0"}};
  } else if (type == "perm-Holmes-Mow") {
    law = "holmes-mow";
    names = {{"perm", "k0"}, {"M", "M"}, {"alpha", "alpha"}};
  } else if (type == "perm-exp-iso") {
    law = "exponential";
    names = {{"perm", "k0"}, {"M", "M"}};
  } else {
    r.doc.fail(node, "type",
               fmt::format("permeability type '{}' is not supported (supported: perm-const-iso, "
                           "perm-Holmes-Mow, perm-exp-iso)",
                           type));
  }
  for (pugi::xml_node p : elements(node)) {
    const auto it = std::find_if(names.begin(), names.end(), [&](const auto& q) {
      return std::string_view(p.name()) == q.first;
    });
    if (it == names.end())
      r.doc.fail(p,
                 fmt::format("unknown parameter '{}' of permeability type '{}'", p.name(), type));
    const std::string key = law.empty()
                                ? std::string("permeability")
                                : material::transport_law_key("permeability", law, it->second);
    values[key] = parameter_value(r, p);
  }
}

/// The solid and phi0 every mixture needs, and its parameters validated by trifem's schema
/// (errors located at the material element). The solid, read unvalidated, is validated here: a
/// porous neo-Hookean solid with phi0 = 1 takes the mixture's phi0 (FEBio's rule).
void validate_mixture(const Reader& r, pugi::xml_node node, io::MaterialSpec& m) {
  if (!m.solid)
    r.doc.fail(node, fmt::format("a {} material needs a <solid>", m.type));
  if (!m.parameters.contains("phi_s0"))
    r.doc.fail(node, fmt::format("a {} material needs <phi0> (the solid volume fraction)", m.type));
  if (m.solid->type == "porous-neo-hookean" && m.solid->parameters.contains("phi0") &&
      m.solid->parameters.at("phi0") == 1.0)
    m.solid->parameters["phi0"] = m.parameters.at("phi_s0");
  (void)validated(r, node.child("solid"), *m.solid);
  try {
    m.parameters =
        material::validate_mixture_parameters(m.type == "triphasic", m.parameters, m.type);
  } catch (const InputError& e) {
    r.doc.fail(node, e.what());
  }
}

/// A biphasic material: solid, permeability and solid volume fraction.
io::MaterialSpec biphasic(const Reader& r, pugi::xml_node node) {
  io::MaterialSpec m;
  m.type = "biphasic";
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    if (name == "solid")
      m.solid = solid_law(r, p, &m.axes, false); // validated with the mixture
    else if (name == "permeability")
      permeability(r, p, m.parameters);
    else if (name == "phi0")
      m.parameters["phi_s0"] = parameter_value(r, p);
    else if (name == "tau" && parameter_value(r, p) != 0.0)
      r.doc.fail(p, "tau != 0 is not supported");
    else if (name != "tau" && name != "fluid_density" && name != "solid_density")
      r.doc.fail(p, fmt::format("unknown parameter '{}' of a biphasic material (expected one of: "
                                "phi0, solid, permeability, fluid_density, tau)",
                                name));
  }
  validate_mixture(r, node, m);
  return m;
}

/// <solute sol="..."> of a triphasic material: the constant diffusivity d and free diffusivity
/// d0 (d < d0: the ion also drags on the solid, trifem's free_d_plus/minus) and the constant
/// solubility (trifem's activity coefficient is its inverse).
void triphasic_solute(const Reader& r, pugi::xml_node node, io::MaterialSpec& m) {
  const std::string ref = r.doc.attribute(node, "sol");
  const int charge = r.chem.charge(r.doc, node, ref);
  const char* sign = charge > 0 ? "plus" : "minus";
  for (pugi::xml_node p : elements(node)) {
    const std::string name = p.name();
    const std::string type = r.doc.attribute(p, "type");
    if (name == "diffusivity") {
      if (type != "diff-const-iso")
        r.doc.fail(p, "type",
                   fmt::format("diffusivity type '{}' is not supported (supported: "
                               "diff-const-iso)",
                               type));
      const Real d = parameter_value(r, r.doc.child(p, "diff"));
      const Real d0 = parameter_value(r, r.doc.child(p, "free_diff"));
      if (d > d0 * (1.0 + 1e-12))
        r.doc.fail(p, fmt::format("diff = {} exceeds free_diff = {}: the diffusivity in the "
                                  "tissue cannot exceed the free one (the friction of the solute "
                                  "with the solid would be negative)",
                                  d, d0));
      m.parameters[fmt::format("d_{}", sign)] = d;
      if (d < d0 * (1.0 - 1e-12))
        m.parameters[fmt::format("free_d_{}", sign)] = d0;
    } else if (name == "solubility") {
      if (type != "solub-const")
        r.doc.fail(
            p, "type",
            fmt::format("solubility type '{}' is not supported (supported: solub-const)", type));
      const Real k = parameter_value(r, r.doc.child(p, "solub"));
      if (!(k > 0.0))
        r.doc.fail(p, "the solubility must be positive");
      m.parameters[fmt::format("gamma_{}", sign)] = 1.0 / k;
    } else {
      r.doc.fail(p, fmt::format("unknown parameter '{}' of a solute (expected diffusivity, "
                                "solubility)",
                                name));
    }
  }
}

/// A triphasic material (or a multiphasic one with exactly the two ions of <Solutes>): a
/// biphasic one with a fixed charge and a cation and an anion.
io::MaterialSpec triphasic(Reader& r, pugi::xml_node node, const std::string& name) {
  if (!r.multiphasic_module)
    r.doc.fail(
        node, "type",
        fmt::format("a {} material needs the multiphasic module", r.doc.attribute(node, "type")));
  io::MaterialSpec m;
  m.type = "triphasic";
  int solutes = 0;
  for (pugi::xml_node p : elements(node)) {
    const std::string key = p.name();
    if (key == "solid") {
      m.solid = solid_law(r, p, &m.axes, false); // validated with the mixture
    } else if (key == "permeability") {
      permeability(r, p, m.parameters);
    } else if (key == "phi0") {
      m.parameters["phi_s0"] = parameter_value(r, p);
    } else if (key == "fixed_charge_density") {
      r.fixed_charges.emplace_back(name, p);
      m.parameters["fixed_charge"] = 0.0; // set by map_fixed_charges
    } else if (key == "osmotic_coefficient") {
      const std::string type = r.doc.attribute(p, "type");
      if (type != "osm-coef-const")
        r.doc.fail(p, "type",
                   fmt::format("osmotic coefficient type '{}' is not supported (supported: "
                               "osm-coef-const)",
                               type));
      m.parameters["osmotic"] = parameter_value(r, r.doc.child(p, "osmcoef"));
    } else if (key == "solute") {
      triphasic_solute(r, p, m);
      ++solutes;
    } else if (key != "fluid_density" && key != "solid_density" && key != "penalty") {
      r.doc.fail(p, fmt::format("unknown parameter '{}' of a triphasic material (expected one "
                                "of: phi0, fixed_charge_density, solid, permeability, "
                                "osmotic_coefficient, solute, fluid_density, penalty)",
                                key));
    }
  }
  if (solutes != 2)
    r.doc.fail(node, fmt::format("a triphasic material needs two <solute>s (the cation and the "
                                 "anion), found {}",
                                 solutes));
  if (!m.parameters.contains("fixed_charge"))
    m.parameters["fixed_charge"] = 0.0;
  validate_mixture(r, node, m);
  return m;
}

} // namespace

void map_fixed_charges(Reader& r) {
  std::string shared_curve;
  pugi::xml_node first;
  for (const auto& [name, node] : r.fixed_charges) {
    // FEBio: c^F(t) = value x curve(t) per reference water volume, negative for the negative
    // charge trifem models; trifem: fixed_charge x fixed_charge_curve(t), magnitude in mmol
    const Real value = r.doc.number(node);
    const std::string curve = r.curve_of(node);
    if (node.attribute("type"))
      r.doc.fail(node, "only a constant fixed charge density is supported (no map or math)");
    if (!first) {
      first = node;
      shared_curve = curve;
    } else if (curve != shared_curve) {
      r.doc.fail(node, "lc",
                 "the triphasic materials have different fixed-charge load curves: trifem "
                 "scales every fixed charge by one curve");
    }
    Real magnitude = -value;
    if (!curve.empty()) {
      const std::string scaled = curve + "_fixed_charge";
      io::CurveSpec c = r.spec.curves.at(curve);
      const Real sign = value < 0.0 ? 1.0 : -1.0;
      for (auto& [t, v] : c.points) {
        v = sign * v + 0.0; // + 0.0: no -0 in the curve
        if (v < 0.0)
          r.doc.fail(node, fmt::format("the fixed charge density value x curve is positive ({} "
                                       "at t = {}): trifem's fixed charge is negative",
                                       -v * std::abs(value), t));
      }
      r.spec.curves[scaled] = c;
      r.spec.analysis.fixed_charge_curve = scaled;
      magnitude = std::abs(value);
    }
    if (magnitude < 0.0)
      r.doc.fail(node, fmt::format("fixed_charge_density = {} is positive: trifem's fixed charge "
                                   "is negative (FEBio's sign convention: negative values)",
                                   value));
    r.spec.materials.at(name).parameters["fixed_charge"] = magnitude * r.chem.amount;
  }
}

void read_materials(Reader& r, pugi::xml_node section) {
  for (pugi::xml_node node : elements(section)) {
    if (std::string_view(node.name()) != "material")
      r.doc.fail(node, "expected <material> elements");
    const std::string id = node.attribute("id").value();
    std::string name = node.attribute("name").value();
    if (name.empty())
      name = "material" + id;
    const std::string type = r.doc.attribute(node, "type");
    io::MaterialSpec m;
    if (type == "biphasic") {
      m = biphasic(r, node);
    } else if (type == "triphasic" || type == "multiphasic") {
      m = triphasic(r, node, name);
    } else if (type == "rigid body") {
      add_rigid_material(r, node, name);
      continue;
    } else {
      const material::LawSpec law = solid_law(r, node, &m.axes);
      m.type = law.type;
      m.parameters = law.parameters;
      m.constituents = law.constituents;
    }
    if (r.spec.materials.contains(name))
      r.doc.fail(node, "name", fmt::format("a second material named '{}'", name));
    r.densities[name] = material_density(r, node, m);
    r.spec.materials[name] = std::move(m);
    if (!id.empty())
      r.material_by_id[id] = name;
  }
  if (r.spec.materials.empty() && r.rigid_bodies.empty())
    r.doc.fail(section, "the file defines no material");
}

} // namespace trifem::feb::detail
