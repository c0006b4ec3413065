// SPDX-License-Identifier: MIT
// The `run` and `check` commands for dynamic-explicit analyses ([analysis] type =
// "dynamic-explicit"); run_case and check_case dispatch here.
#pragma once

#include "trifem/io/case_spec.hpp"
#include "trifem/model/model.hpp"

#include <filesystem>

namespace trifem::analysis {

/// Runs a dynamic-explicit case to time.end_time; results (VTU series, results.pvd,
/// history.csv, summary.json, run.log) go to `output_dir`. Returns an ExitCode: kSuccess, or
/// kAnalysisFailed with one "error:" line on stderr naming the step, cell or node and quantity
/// (the results written until then are kept). Invalid input throws InputError before anything
/// is written.
int run_explicit_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir);

/// Validates a dynamic-explicit case (mesh, sets, materials, settings) and logs the stable time
/// step estimate, without stepping.
int check_explicit_case(const io::CaseSpec& spec);

/// Runs a mixed case (spec.has_explicit_step()) on one model: its quasi-static steps, then its
/// dynamic-explicit last step from their final displacement, at rest, from their end time. One
/// results.pvd (VTU numbering continued), history.csv for the quasi-static steps and
/// history_step<k>.csv for the explicit step k, one summary.json. Returns an ExitCode.
int run_mixed_case(const io::CaseSpec& spec, const std::filesystem::path& output_dir);

/// Validates the dynamic-explicit step of a mixed case on its model (loads, outputs and
/// settings); InputError naming the case file and step otherwise.
void check_explicit_step(const io::CaseSpec& spec, const model::Model& model);

} // namespace trifem::analysis
