// SPDX-License-Identifier: MIT
// trifem command-line interface: run, check, convert, --version.
#include "trifem/analysis/case_file.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/digest.hpp"
#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/core/log.hpp"
#include "trifem/core/printable.hpp"
#include "trifem/core/standard_streams.hpp"
#include "trifem/parallel/communicator.hpp"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <new>

using namespace trifem;

namespace {

/// Prints `line` (one message of a failure) and returns `code`. On several processes, rank 0
/// prints it once if all failed together (an input error, read by all); a failure of this
/// process alone is printed with its rank and stops the others (parallel::agree_on_failure).
int fail(const std::string& line, int code) {
  const std::string shown = printable(line); // no control characters of the input
  if (parallel::agree_on_failure(shown, code))
    std::cerr << shown << '\n';
  return code;
}

/// Runs `action`, mapping exceptions to exit codes with one clear message.
template <class F>
int guarded(F&& action) {
  try {
    return action();
  } catch (const InputError& e) {
    return fail(std::string("error: ") + e.what(), analysis::kInvalidInput);
  } catch (const std::bad_alloc&) {
    return fail("error: out of memory: the model is too large for the memory available",
                analysis::kAnalysisFailed);
  } catch (const std::exception& e) {
    return fail(std::string("internal error: ") + e.what(), analysis::kInternalError);
  }
}

/// Under mpirun without OMP_NUM_THREADS: the cores shared between the processes of a machine
/// (OMPI_COMM_WORLD_LOCAL_SIZE), so that they do not oversubscribe them.
void share_cores() {
  if (!parallel::active() || std::getenv("OMP_NUM_THREADS") != nullptr)
    return;
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  const int processes = local != nullptr ? std::max(1, std::atoi(local)) : parallel::size();
  omp_set_num_threads(std::max(1, omp_get_num_procs() / processes));
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

/// Under mpirun every process must run the same command on the same case: processes that read
/// different models (an MPMD launch with other options, a stale copy of the case on one host)
/// would wait for each other forever or exchange messages of different sizes. InputError on
/// every process if one differs from process 0 (its command line or its case file's bytes).
void check_processes_agree(int argc, char** argv, const std::string& case_file) {
  if (!parallel::active())
    return;
  Fnv1a64 digest;
  for (int i = 1; i < argc; ++i)
    digest.add(argv[i], std::strlen(argv[i]) + 1); // with its NUL: "ab" "c" differs from "a" "bc"
  std::ifstream in(case_file, std::ios::binary);
  std::string text(std::size_t{1} << 16, '\0');
  while (in && in.read(text.data(), static_cast<std::streamsize>(text.size())).gcount() > 0)
    digest.add(text.data(), static_cast<std::size_t>(in.gcount()));
  const int other = parallel::first_rank_differing(digest.value());
  TRIFEM_CHECK(other < 0,
               "the processes disagree: process {} of {} was started with another command line "
               "than process 0, or reads another case file {} (every process of mpirun must run "
               "the same command on the same files)",
               other, parallel::size(), case_file);
}

} // namespace

int main(int argc, char** argv) {
  guard_standard_streams();         // before anything opens a file
  parallel::initialize(argc, argv); // under mpirun: one analysis shared by the processes
  share_cores();
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
    if (parallel::is_root())
      std::cerr << "error: " << e.what() << " (see 'trifem --help')\n";
    return analysis::kUsage;
  }
  log::configure(!parallel::is_root() ? log::Level::Silent
                 : quiet              ? log::Level::Quiet
                 : verbose            ? log::Level::Verbose
                                      : log::Level::Normal);
  return guarded([&] {
    if (convert->parsed()) {
      for (const auto& file : analysis::convert_case(case_file, converted))
        log::info("wrote {}", file.string());
      return static_cast<int>(analysis::kSuccess);
    }
    check_processes_agree(argc, argv, case_file);
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
