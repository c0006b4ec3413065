// SPDX-License-Identifier: MIT
// The output directory of a run: stale result files of an earlier run are removed at the start,
// summary.json says "running" until the run ends, and is written atomically at the end.
#pragma once

#include "trifem/io/case_spec.hpp"

#include <filesystem>
#include <nlohmann/json.hpp>

namespace trifem::analysis {

/// Creates `directory`, removes the result files an earlier run left there (only trifem's own
/// file names: results.pvd, volume_NNNN.vtu, contact files, history.csv, summary.json, run.log)
/// and writes a summary.json with "status": "running", so that the files of a run that is
/// killed are never mistaken for those of a completed one. Until write_final_summary or
/// abandon_summary, a signal that requests a stop rewrites it at once as "interrupted" (the
/// process may be killed before the run reaches its next poll, as mpirun does after forwarding
/// SIGTERM). OutputError if impossible.
void start_output_directory(const std::filesystem::path& directory, const io::CaseSpec& spec);

/// Writes the summary a run ends with (after stopping the signal notice of
/// start_output_directory, which must not overwrite it); OutputError if it cannot be written.
void write_final_summary(const std::filesystem::path& file, const nlohmann::json& summary);

/// For a run ended by an error that no summary describes (an exception after
/// start_output_directory): summary.json gets "status": "failed" with `why`. Does nothing if
/// the final summary was written; never throws.
void abandon_summary(const std::string& why) noexcept;

/// True for the names of the files a run writes into its output directory.
bool is_result_file_name(const std::string& name);

/// Writes `summary` to `file` atomically (a temporary file renamed onto it); OutputError if it
/// cannot be written.
void write_summary_file(const std::filesystem::path& file, const nlohmann::json& summary);

/// Peak resident memory of the process so far [MB] (0 if the system does not say).
double peak_memory_mb();

/// The status fields every summary.json starts with ("status": completed, failed, interrupted)
/// and the peak memory so far.
nlohmann::json summary_header(const io::CaseSpec& spec, const std::string& status,
                              const std::string& failure);

} // namespace trifem::analysis
