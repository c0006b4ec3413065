// SPDX-License-Identifier: MIT
// The parsed XML of a .feb file: element lookup, line numbers and one-line error messages.
#pragma once

#include "trifem/core/types.hpp"
#include "trifem/tensor/tensor.hpp"

#include <pugixml.hpp>

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::feb {

/// A parsed .feb file. Every error is one InputError "<file>:<line>: <XML path>: <what>", with
/// the line of the element concerned (pugixml reports byte offsets; the lines are counted here).
class Document {
public:
  /// Parses `text`; InputError "<file>:<line>: XML syntax error: ..." if it is not well formed.
  Document(std::string text, std::filesystem::path file);
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;

  pugi::xml_node root() const { return xml_.document_element(); }
  const std::filesystem::path& file() const { return file_; }
  /// The file as messages name it.
  std::string name() const;

  /// 1-based line of the start of `node`.
  int line(pugi::xml_node node) const;
  /// The element path from the root, with the name, id and type attributes that identify each
  /// element: febio_spec/Mesh/Elements[@type='tet4'][@name='Part1'].
  std::string path(pugi::xml_node node) const;
  /// "<file>:<line>: <path>" of `node`.
  std::string where(pugi::xml_node node) const;
  /// Throws InputError "<file>:<line>: <path>: <what>".
  [[noreturn]] void fail(pugi::xml_node node, std::string_view what) const;
  /// Throws InputError "<file>:<line>: <path>/@<attribute>: <what>".
  [[noreturn]] void fail(pugi::xml_node node, const char* attribute, std::string_view what) const;

  /// The text of `node`, without leading and trailing blanks.
  std::string text(pugi::xml_node node) const;
  /// The number in the text of `node` (InputError if it is not one finite number).
  Real number(pugi::xml_node node) const;
  /// The comma-separated numbers in the text of `node`; exactly `count` of them if count > 0.
  std::vector<Real> numbers(pugi::xml_node node, std::size_t count = 0) const;
  /// Three comma-separated numbers.
  Vec3 vector(pugi::xml_node node) const;
  /// The comma-separated integer ids in the text of `node`.
  std::vector<long> ids(pugi::xml_node node) const;
  /// The integer in the text of `node`.
  long integer(pugi::xml_node node) const;
  /// The required attribute `name` of `node` (InputError if missing or empty).
  std::string attribute(pugi::xml_node node, const char* name) const;
  /// The required child `name` of `node`.
  pugi::xml_node child(pugi::xml_node node, const char* name) const;

private:
  std::string text_;
  std::filesystem::path file_;
  pugi::xml_document xml_;
  std::vector<std::ptrdiff_t> line_starts_; ///< byte offset of the start of each line
};

} // namespace trifem::feb
