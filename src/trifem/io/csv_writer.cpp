// SPDX-License-Identifier: MIT
// CSV table writer.
#include "trifem/io/csv_writer.hpp"

#include "trifem/core/error.hpp"

#include <cerrno>
#include <fmt/format.h>
#include <iterator>
#include <string_view>
#include <system_error>

namespace trifem::io {

namespace {

/// `text` as a CSV field (RFC 4180): quoted, with doubled quotes, if it needs to be.
std::string csv_field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos)
    return std::string(text);
  std::string field = "\"";
  for (const char c : text) {
    if (c == '"')
      field += '"';
    field += c;
  }
  return field + '"';
}

} // namespace

CsvWriter::CsvWriter(std::filesystem::path file, std::vector<std::string> columns)
    : file_(std::move(file)), columns_(std::move(columns)) {
  TRIFEM_VERIFY(!columns_.empty(), "CSV file '{}' needs at least one column", file_.string());
  out_.open(file_, std::ios::out | std::ios::trunc);
  TRIFEM_CHECK_OUTPUT(out_.is_open(), "cannot create CSV file '{}' ({})", file_.string(),
                      std::generic_category().message(errno));
  std::string header;
  for (std::size_t i = 0; i < columns_.size(); ++i) {
    if (i > 0)
      header += ',';
    header += csv_field(columns_[i]);
  }
  out_ << header << '\n';
  flush_checked();
}

void CsvWriter::write_row(std::span<const double> values) {
  TRIFEM_VERIFY(values.size() == columns_.size(), "CSV row of {} values for {} columns in '{}'",
                values.size(), columns_.size(), file_.string());
  fmt::memory_buffer row;
  for (std::size_t i = 0; i < values.size(); ++i)
    fmt::format_to(std::back_inserter(row), "{}{}", i == 0 ? "" : ",", values[i]);
  row.push_back('\n');
  out_.write(row.data(), static_cast<std::streamsize>(row.size()));
  flush_checked();
}

void CsvWriter::flush_checked() {
  out_.flush();
  TRIFEM_CHECK_OUTPUT(out_.good(), "cannot write to CSV file '{}'", file_.string());
}

} // namespace trifem::io
