// SPDX-License-Identifier: MIT
// trifem command-line interface: run, check, convert, --version.
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"

#include <CLI/CLI.hpp>
#include <iostream>
#include <new>

using namespace trifem;

namespace {

/// Runs `action`, mapping exceptions to exit codes with one clear message.
template <class F>
int guarded(F&& action) {
  try {
    return action();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return analysis::kInvalidInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "error: out of memory: the model is too large for the memory available\n";
    return analysis::kAnalysisFailed;
  } catch (const std::exception& e) {
    std::cerr << "internal error: " << e.what() << '\n';
    return analysis::kInternalError;
  }
}

/// The first argument that is not a flag must be a known command.
void check_command_name(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.starts_with("-"))
      continue;
    if (arg != "run" && arg != "check" && arg != "convert")
      throw CLI::ParseError("unknown command '" + arg + "' (expected run, check or convert)",
                            CLI::ExitCodes::ExtrasError);
    return;
  }
}

} // namespace

int main(int argc, char** argv) {
  CLI::App cli{"trifem: finite elements for charged-hydrated soft tissues"};
  cli.set_version_flag("--version", std::string("trifem ") + TRIFEM_VERSION);
  cli.require_subcommand(1);
  bool quiet = false, verbose = false;
  cli.add_flag("-q,--quiet", quiet, "only warnings and errors");
  cli.add_flag("-v,--verbose", verbose, "also Newton iterations");

  std::string case_file, output_dir;
  auto* run = cli.add_subcommand("run", "run an analysis");
  run->add_option("case", case_file, "case file (.toml, or an FEBio .feb file)")->required();
  run->add_option("-o,--output", output_dir, "output directory (default: results/<case name>)");
  analysis::RunOptions options;
  run->add_option("--restart", options.restart_file,
                  "continue from a restart file (restart_NNNN.bin) written by a run of this case");
  run->add_flag("--write-restart", options.write_restart,
                "write a restart file with every VTU state (as [output] restart = true)");
  auto* check = cli.add_subcommand("check", "validate a case without solving");
  check->add_option("case", case_file, "case file (.toml, or an FEBio .feb file)")->required();
  analysis::Refinement refinement;
  for (CLI::App* command : {run, check}) {
    command->add_option("--refine-mesh", refinement.mesh_levels,
                        "split every cell into eight this many times (mesh convergence)");
    command->add_option("--refine-time", refinement.time_levels,
                        "halve the time steps this many times (time-step convergence)");
  }
  std::string converted;
  auto* convert = cli.add_subcommand("convert", "write a case as a TOML case and a Gmsh mesh");
  convert->add_option("case", case_file, "case file (an FEBio .feb file, or .toml)")->required();
  convert
      ->add_option("-o,--output", converted,
                   "TOML case to write (its mesh: the same name "
                   "with .msh)")
      ->required();

  try {
    check_command_name(argc, argv);
    cli.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return cli.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << " (see 'trifem --help')\n";
    return analysis::kUsage;
  }
  log::configure(quiet ? log::Level::Quiet : verbose ? log::Level::Verbose : log::Level::Normal);
  return guarded([&] {
    if (convert->parsed()) {
      for (const auto& file : analysis::convert_case(case_file, converted))
        log::info("wrote {}", file.string());
      return static_cast<int>(analysis::kSuccess);
    }
    io::CaseSpec spec = analysis::read_case_file(case_file);
    analysis::refine_case(spec, refinement);
    if (check->parsed())
      return analysis::check_case(spec);
    interrupt::install_handler(); // Ctrl-C ends the run cleanly, with its summary
    const std::filesystem::path out = output_dir.empty()
                                          ? std::filesystem::path("results") / spec.file.stem()
                                          : std::filesystem::path(output_dir);
    return analysis::run_case(spec, out, options);
  });
}
