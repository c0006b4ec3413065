// SPDX-License-Identifier: MIT
// ParaView .pvd collection writer.
#include "trifem/io/pvd_writer.hpp"

#include "trifem/core/error.hpp"
#include "trifem/io/vtu_writer.hpp"

#include <cmath>
#include <fmt/format.h>
#include <ostream>

namespace trifem::io {

namespace fs = std::filesystem;

namespace {

/// `dataset` (relative to the current directory or absolute) relative to `directory` (absolute).
std::string relative_to(const fs::path& dataset, const fs::path& directory) {
  const fs::path absolute = fs::absolute(dataset).lexically_normal();
  const fs::path relative = absolute.lexically_relative(directory);
  return (relative.empty() ? absolute : relative).generic_string();
}

} // namespace

PvdWriter::PvdWriter(fs::path pvd_file)
    : file_(std::move(pvd_file)), directory_(fs::absolute(file_).lexically_normal().parent_path()) {
  write();
}

void PvdWriter::add(double time, const fs::path& dataset, int part, std::string_view name) {
  TRIFEM_VERIFY(std::isfinite(time), "time {} of dataset '{}' is not finite", time,
                dataset.string());
  TRIFEM_VERIFY(part >= 0, "negative part {} for dataset '{}'", part, dataset.string());
  entries_.push_back({time, relative_to(dataset, directory_), part, std::string(name)});
  write();
}

void PvdWriter::write() const {
  write_file_atomically(file_, [this](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const Entry& e : entries_) {
      out << fmt::format(R"(    <DataSet timestep="{}" group="" part="{}" file="{}")", e.time,
                         e.part, xml_escape(e.file));
      if (!e.name.empty())
        out << fmt::format(R"( name="{}")", xml_escape(e.name));
      out << "/>\n";
    }
    out << "  </Collection>\n</VTKFile>\n";
  });
}

} // namespace trifem::io
