// SPDX-License-Identifier: MIT
#include "trifem/feb/document.hpp"

#include "trifem/core/error.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fmt/format.h>

namespace trifem::feb {
namespace {

std::string_view trim(std::string_view s) {
  const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; };
  while (!s.empty() && blank(s.front()))
    s.remove_prefix(1);
  while (!s.empty() && blank(s.back()))
    s.remove_suffix(1);
  return s;
}

/// The comma-separated fields of `s` (trimmed; a trailing comma ends the list).
std::vector<std::string_view> fields(std::string_view s) {
  std::vector<std::string_view> out;
  s = trim(s);
  while (!s.empty()) {
    const std::size_t comma = s.find(',');
    out.push_back(trim(s.substr(0, comma)));
    if (comma == std::string_view::npos)
      break;
    s.remove_prefix(comma + 1);
    s = trim(s);
  }
  return out;
}

bool parse_real(std::string_view s, Real& value) {
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  return ec == std::errc() && end == s.data() + s.size() && std::isfinite(value);
}

/// The attribute of `node` that names it in a path: name, then id (sol: a material's solute).
pugi::xml_attribute identity(pugi::xml_node node) {
  for (const char* key : {"name", "id", "lid", "sol"})
    if (auto a = node.attribute(key))
      return a;
  return {};
}

} // namespace

Document::Document(std::string text, std::filesystem::path file)
    : text_(std::move(text)), file_(std::move(file)) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i)
    if (text_[i] == '\n')
      line_starts_.push_back(static_cast<std::ptrdiff_t>(i + 1));
  const pugi::xml_parse_result r =
      xml_.load_buffer(text_.data(), text_.size(), pugi::parse_default, pugi::encoding_utf8);
  if (!r) {
    const auto line =
        std::upper_bound(line_starts_.begin(), line_starts_.end(), r.offset) - line_starts_.begin();
    throw InputError(fmt::format("{}:{}: XML syntax error: {} (the file is not well-formed XML)",
                                 name(), line, r.description()));
  }
}

std::string Document::name() const {
  return file_.empty() ? std::string("<feb>") : file_.string();
}

int Document::line(pugi::xml_node node) const {
  const std::ptrdiff_t offset = node.offset_debug();
  if (offset < 0)
    return 0;
  return static_cast<int>(std::upper_bound(line_starts_.begin(), line_starts_.end(), offset) -
                          line_starts_.begin());
}

std::string Document::path(pugi::xml_node node) const {
  std::vector<std::string> parts;
  for (pugi::xml_node n = node; n && n.type() == pugi::node_element; n = n.parent()) {
    std::string part = n.name();
    if (auto t = n.attribute("type"))
      part += fmt::format("[@type='{}']", t.value());
    if (auto a = identity(n))
      part += fmt::format("[@{}='{}']", a.name(), a.value());
    parts.push_back(std::move(part));
  }
  std::reverse(parts.begin(), parts.end());
  return fmt::format("{}", fmt::join(parts, "/"));
}

std::string Document::where(pugi::xml_node node) const {
  return fmt::format("{}:{}: {}", name(), line(node), path(node));
}

void Document::fail(pugi::xml_node node, std::string_view what) const {
  throw InputError(fmt::format("{}: {}", where(node), what));
}

void Document::fail(pugi::xml_node node, const char* attribute, std::string_view what) const {
  throw InputError(fmt::format("{}/@{}: {}", where(node), attribute, what));
}

std::string Document::text(pugi::xml_node node) const {
  return std::string(trim(node.child_value()));
}

Real Document::number(pugi::xml_node node) const {
  const std::string s = text(node);
  Real value = 0.0;
  if (!parse_real(s, value))
    fail(node, fmt::format("expected a number, got '{}'", s));
  return value;
}

std::vector<Real> Document::numbers(pugi::xml_node node, std::size_t count) const {
  const std::string s = text(node);
  std::vector<Real> out;
  for (std::string_view f : fields(s)) {
    Real value = 0.0;
    if (!parse_real(f, value))
      fail(node, fmt::format("expected comma-separated numbers, got '{}'", s));
    out.push_back(value);
  }
  if (count > 0 && out.size() != count)
    fail(node, fmt::format("expected {} comma-separated numbers, got '{}'", count, s));
  return out;
}

Vec3 Document::vector(pugi::xml_node node) const {
  const std::vector<Real> v = numbers(node, 3);
  return {v[0], v[1], v[2]};
}

std::vector<long> Document::ids(pugi::xml_node node) const {
  const std::string s = text(node);
  std::vector<long> out;
  for (std::string_view f : fields(s)) {
    long id = 0;
    const auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), id);
    if (ec != std::errc() || end != f.data() + f.size() || f.empty())
      fail(node, fmt::format("expected comma-separated integer ids, got '{}'", f));
    out.push_back(id);
  }
  return out;
}

long Document::integer(pugi::xml_node node) const {
  const std::vector<long> v = ids(node);
  if (v.size() != 1)
    fail(node, fmt::format("expected one integer, got '{}'", text(node)));
  return v.front();
}

std::string Document::attribute(pugi::xml_node node, const char* name) const {
  const std::string value(trim(node.attribute(name).value()));
  if (value.empty())
    fail(node, fmt::format("the attribute '{}' is required", name));
  return value;
}

pugi::xml_node Document::child(pugi::xml_node node, const char* name) const {
  pugi::xml_node c = node.child(name);
  if (!c)
    fail(node, fmt::format("the element <{}> is required", name));
  return c;
}

} // namespace trifem::feb
