// SPDX-License-Identifier: MIT
// CSV table writer for spreadsheets: header once, then rows flushed one by one.
#pragma once

#include <filesystem>
#include <fstream>
#include <span>
#include <string>
#include <vector>

namespace trifem::io {

/// A CSV table written row by row and flushed after every row (results survive a crash).
/// The header is written once; numbers are written in shortest round-trip form (std::strtod
/// reads back the exact double; NaN and infinities as "nan", "inf", "-inf").
class CsvWriter {
public:
  /// Creates (truncates) the file and writes the header; column names containing a comma,
  /// quote or line break are quoted. Throws InputError naming the path if the file cannot be
  /// created.
  CsvWriter(std::filesystem::path file, std::vector<std::string> columns);

  /// Appends one row and flushes it. TRIFEM_VERIFY(values.size() == columns().size()).
  /// Throws InputError naming the path if the write fails (e.g. disk full).
  void write_row(std::span<const double> values);

  /// The column names, in order.
  const std::vector<std::string>& columns() const { return columns_; }
  /// Path of the CSV file.
  const std::filesystem::path& file() const { return file_; }

private:
  void flush_checked();

  std::filesystem::path file_;
  std::vector<std::string> columns_;
  std::ofstream out_;
};

} // namespace trifem::io
