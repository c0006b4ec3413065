// SPDX-License-Identifier: MIT
// Reading a history.csv back in tests: its column names and, per column, its values by row.
#pragma once

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace trifem::test {

/// The numbers of a history.csv by column, and the column names.
struct History {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  /// The values of the column `name`; std::runtime_error if there is none.
  const std::vector<double>& operator[](const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    if (it == names.end())
      throw std::runtime_error("history.csv has no column '" + name + "'");
    return columns[static_cast<std::size_t>(it - names.begin())];
  }
};

/// Reads `file` (empty if it does not exist or is empty).
inline History read_history(const std::filesystem::path& file) {
  History h;
  std::ifstream in(file);
  std::string line;
  if (!std::getline(in, line))
    return h;
  std::stringstream header(line);
  for (std::string name; std::getline(header, name, ',');)
    h.names.push_back(name);
  h.columns.resize(h.names.size());
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::size_t c = 0;
    for (std::string cell; std::getline(row, cell, ',') && c < h.columns.size(); ++c)
      h.columns[c].push_back(std::stod(cell));
  }
  return h;
}

} // namespace trifem::test
