// SPDX-License-Identifier: MIT
// TOML case writer, part 2: the TOML text helpers and the [materials.<name>] tables (solid
// laws, solid mixtures, biphasic and triphasic mixtures with their transport laws).
#include "trifem/core/error.hpp"
#include "trifem/io/case_spec.hpp"
#include "trifem/io/case_writer_text.hpp"
#include "trifem/material/mixture.hpp"
#include "trifem/material/registry.hpp"
#include "trifem/material/solid_mixture.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>

namespace trifem::io::detail {

std::string TomlText::key(std::string_view k) {
  const bool bare = !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  });
  return bare ? std::string(k) : quoted(k);
}

std::string TomlText::quoted(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\')
      out += fmt::format("\\{}", c);
    else if (u < 0x20 || u == 0x7f)
      out += fmt::format("\\u{:04X}", u);
    else
      out += c;
  }
  return out + "\"";
}

std::string TomlText::number(Real v) {
  if (std::isnan(v))
    return "nan";
  if (std::isinf(v))
    return v > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".e") == std::string::npos)
    s += ".0";
  return s;
}

void TomlText::inline_table(std::string_view k,
                            const std::vector<std::pair<std::string, std::string>>& e) {
  std::string s = "{";
  for (std::size_t i = 0; i < e.size(); ++i)
    s += fmt::format("{} {} = {}", i ? "," : "", e[i].first, e[i].second);
  raw(k, s + (e.empty() ? "}" : " }"));
}

namespace {

/// Writes the parameters of a law of registered_laws() or constituent_laws() (after its
/// `type`); InputError for a value the law's schema does not name.
void write_law_parameters(const SolidSpec& law, const std::string& where, TomlText& t) {
  const material::LawEntry& entry = material::find_law(law.type, where);
  std::set<std::string> written;
  for (const material::ParameterSchema& p : *entry.parameters) {
    if (p.kind == material::ParameterKind::Vector) {
      const auto keys = material::vector_keys(p.key);
      if (!law.parameters.contains(keys[0]))
        continue;
      t.vector(p.key, material::vector_value(law.parameters, p.key));
      written.insert(keys.begin(), keys.end());
    } else if (const auto it = law.parameters.find(p.key); it != law.parameters.end()) {
      t.number(p.key, it->second);
      written.insert(p.key);
    }
  }
  for (const auto& entry_value : law.parameters)
    TRIFEM_CHECK(written.contains(entry_value.first),
                 "{}: parameter '{}' is not one of law '{}' and cannot be written", where,
                 entry_value.first, law.type);
}

/// `type` and the parameters of a law, then (a solid mixture) its [[<path>.constituent]]
/// tables, after the caller's `extra` keys of the same table.
void write_law(const SolidSpec& law, const std::string& path, TomlText& t,
               const std::function<void()>& extra = {}) {
  t.string("type", law.type);
  if (law.type != material::kSolidMixtureType)
    write_law_parameters(law, path, t);
  if (extra)
    extra();
  for (const SolidSpec& part : law.constituents) {
    t.header(fmt::format("[[{}.constituent]]", path));
    write_law(part, path + ".constituent", t);
  }
}

/// A transport law stored as transport_law_key entries "<key>.<type>.<parameter>", as an
/// inline table { type = ..., <parameter> = ... }; false if there is none.
bool write_transport_law(const material::ParameterValues& values, const std::string& key,
                         const std::string& where, std::set<std::string>& written, TomlText& t) {
  std::string type;
  std::vector<std::pair<std::string, std::string>> entries;
  const std::string prefix = key + ".";
  for (const auto& [name, value] : values) {
    if (!name.starts_with(prefix))
      continue;
    const std::string rest = name.substr(prefix.size());
    const std::size_t dot = rest.rfind('.');
    TRIFEM_CHECK(dot != std::string::npos && (type.empty() || rest.substr(0, dot) == type),
                 "{}: parameter '{}' cannot be written", where, name);
    type = rest.substr(0, dot);
    entries.emplace_back(TomlText::key(rest.substr(dot + 1)), TomlText::number(value));
    written.insert(name);
  }
  if (type.empty())
    return false;
  entries.insert(entries.begin(), {"type", TomlText::quoted(type)});
  t.inline_table(key, entries);
  return true;
}

/// The mixture keys of a biphasic or triphasic material (after its `type`).
void write_mixture_parameters(const MaterialSpec& m, const std::string& where, TomlText& t) {
  std::set<std::string> written;
  for (const material::ParameterSchema& p : material::mixture_schema(m.type == "triphasic")) {
    const auto it = m.parameters.find(p.key);
    if (it == m.parameters.end()) {
      write_transport_law(m.parameters, p.key, where, written, t);
      continue;
    }
    if (p.key == "fixed_charge_basis")
      t.string(p.key, it->second == 0.0 ? "water" : "tissue");
    else
      t.number(p.key, it->second);
    written.insert(p.key);
  }
  for (const auto& entry : m.parameters)
    TRIFEM_CHECK(written.contains(entry.first), "{}: parameter '{}' cannot be written", where,
                 entry.first);
}

void write_material(const std::string& name, const MaterialSpec& m, TomlText& t) {
  const std::string path = fmt::format("materials.{}", TomlText::key(name));
  TRIFEM_CHECK(!m.axes, "{}.axes: writing material axes to a TOML case is not supported yet", path);
  t.header(fmt::format("[{}]", path));
  if (m.is_mixture()) {
    TRIFEM_CHECK(m.element == SolidElementSpec::Auto && m.constituents.empty(),
                 "{}: a mixture with an element or constituents cannot be written", path);
    t.string("type", m.type);
    if (m.density)
      t.number("density", *m.density);
    write_mixture_parameters(m, path, t);
    t.header(fmt::format("[{}.solid]", path));
    return write_law(*m.solid, path + ".solid", t);
  }
  write_law(m.solid_law(), path, t, [&] {
    if (m.density)
      t.number("density", *m.density);
    if (m.element == SolidElementSpec::Displacement)
      t.string("element", "displacement");
    else if (m.element == SolidElementSpec::MeanDilatation)
      t.string("element", "mean-dilatation");
  });
}

} // namespace

void write_materials(const CaseSpec& spec, TomlText& t) {
  for (const auto& [name, m] : spec.materials)
    write_material(name, m, t);
}

} // namespace trifem::io::detail
