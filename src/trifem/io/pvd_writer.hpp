// SPDX-License-Identifier: MIT
// ParaView .pvd collection writer (time series of datasets), rewritten atomically on every add.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace trifem::io {

/// A ParaView .pvd collection (time series). Every add() rewrites the .pvd file completely
/// (atomic temp+rename), so results written before a crash stay readable.
class PvdWriter {
public:
  /// Starts a new, empty collection and writes it at once (replacing an existing file).
  /// Throws InputError naming the path if the file cannot be written.
  explicit PvdWriter(std::filesystem::path pvd_file);

  /// Adds a dataset at `time` and rewrites the .pvd file. `dataset` is a path as seen from the
  /// current directory (e.g. the one given to write_vtu); it is stored relative to the .pvd
  /// directory. `part` is for multi-block series (0 = volume, 1 = contact surface, ...),
  /// `name` an optional block name shown by ParaView.
  void add(double time, const std::filesystem::path& dataset, int part = 0,
           std::string_view name = {});

  /// Path of the .pvd file.
  const std::filesystem::path& file() const { return file_; }

private:
  /// One DataSet entry of the collection.
  struct Entry {
    double time;
    std::string file; ///< relative to the .pvd directory, '/' separated
    int part;
    std::string name;
  };

  void write() const;

  std::filesystem::path file_;
  std::filesystem::path directory_; ///< absolute directory of file_
  std::vector<Entry> entries_;
};

} // namespace trifem::io
