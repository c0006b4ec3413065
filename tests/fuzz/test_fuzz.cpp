// SPDX-License-Identifier: MIT
// Mutation fuzz test of the trifem executable (contract of docs/cli.md). Every case file of
// examples/ and tests/cli/data/ and two Gmsh meshes (2.2 and 4.1) are mutated with a fixed seed
// (mutator.hpp); each mutant is checked with `trifem check` and, for small cases shortened to one
// step, `trifem run`. Every run must end by itself within the time limit, not by a signal, with
// exit code 0, 2 or 3 (never 4, an internal error); exit 2 must print exactly one stderr line
// "error: ..." naming the mutated file; a run that exits 0 or 3 must leave summary.json.
// Failing mutants are kept under <build>/tests/fuzz/work/failures/ to reproduce them.
#include "mutator.hpp"
#include "process.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace trifem::fuzz {
namespace {

namespace fs = std::filesystem;

const fs::path kExe = TRIFEM_EXE;
const fs::path kSource = TRIFEM_SOURCE_DIR;
const fs::path kWork = TRIFEM_FUZZ_WORK_DIR;

constexpr std::uint64_t kSeed = 0x7269666d2d66757aULL; ///< fixed: the same mutants every run
constexpr int kCheckMutants = 50;                      ///< `trifem check` mutants per case
constexpr int kRunMutants = 30;                        ///< `trifem run` mutants per small case
constexpr int kMshMutants = 60;                        ///< `trifem check` mutants per mesh

/// The environment variable `name` as an unsigned integer, or `fallback` if it is not set.
/// TRIFEM_FUZZ_SEED and TRIFEM_FUZZ_SCALE (a multiplier of the counts) make longer campaigns
/// with other mutants; ctest uses the defaults.
std::uint64_t from_env(const char* name, std::uint64_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 0) : fallback;
}

const std::uint64_t kSeedUsed = from_env("TRIFEM_FUZZ_SEED", kSeed);
/// Per process; a longer run is a hang. TRIFEM_FUZZ_TIMEOUT_S raises it for slow builds (the
/// sanitized one runs 3 to 30 times slower than Release).
const double kTimeoutS = static_cast<double>(from_env("TRIFEM_FUZZ_TIMEOUT_S", 10));
const int kScale = static_cast<int>(from_env("TRIFEM_FUZZ_SCALE", 1));

/// Cases small enough to run for one step in a fraction of a second.
const std::vector<std::string> kRunnable = {"cli_tiny",
                                            "cli_invert",
                                            "cli_explicit_box",
                                            "examples_cantilever",
                                            "examples_contact_patch",
                                            "examples_confined_column"};

/// A case file to mutate: its test name ("examples_cantilever", "cli_tiny") and path.
struct Base {
  std::string name;
  fs::path file;
};

std::vector<Base> bases() {
  std::vector<Base> found;
  for (const auto& entry : fs::directory_iterator(kSource / "examples"))
    if (entry.is_directory())
      for (const auto& file : fs::directory_iterator(entry.path()))
        if (file.path().extension() == ".toml")
          found.push_back({"examples_" + file.path().stem().string(), file.path()});
  for (const auto& file : fs::directory_iterator(kSource / "tests" / "cli" / "data"))
    if (file.path().extension() == ".toml")
      found.push_back({"cli_" + file.path().stem().string(), file.path()});
  std::sort(found.begin(), found.end(),
            [](const Base& a, const Base& b) { return a.name < b.name; });
  return found;
}

/// FNV-1a: a seed per case that does not depend on the standard library.
std::uint64_t fnv1a(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text)
    h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

/// `text` shortened to about one step: end_time = dt where dt is given, no output.times.
std::string shortened(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> lines;
  std::string dt;
  for (std::string line; std::getline(in, line);) {
    lines.push_back(line);
    if (line.starts_with("dt ") || line.starts_with("dt="))
      dt = line.substr(line.find('=') + 1);
  }
  std::string out;
  for (const std::string& line : lines) {
    if (line.starts_with("times"))
      continue;
    out += line.starts_with("end_time") && !dt.empty() ? "end_time =" + dt : line;
    out += '\n';
  }
  return out;
}

/// A fresh directory for one fuzz test, with copies of the Gmsh files next to `source`. Runs
/// use one OpenMP thread (ctest runs several tests at once) unless OMP_NUM_THREADS is set.
fs::path work_dir(const std::string& name, const fs::path& source) {
  ::setenv("OMP_NUM_THREADS", "1", 0);
  const fs::path dir = kWork / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& file : fs::directory_iterator(source.parent_path()))
    if (file.path().extension() == ".msh")
      fs::copy_file(file.path(), dir / file.path().filename());
  return dir;
}

/// One mutant to run: the command, the mutated file and what was done to it.
struct Trial {
  std::vector<std::string> argv;
  fs::path mutated;   ///< the file that was mutated (case or mesh)
  fs::path case_file; ///< the case file passed to trifem
  fs::path output;    ///< -o directory of `run` ("" for check)
  std::string description;
};

/// What `r` violates of the contract, or "" if nothing.
std::string violation(const Trial& t, const ProcessResult& r) {
  if (r.timed_out)
    return "did not finish within " + std::to_string(kTimeoutS) + " s (hang)";
  if (r.signal != 0)
    return "killed by signal " + std::to_string(r.signal);
  if (r.exit_code == 4 || r.err.find("internal error") != std::string::npos)
    return "internal error (exit 4)";
  if (r.exit_code != 0 && r.exit_code != 2 && r.exit_code != 3)
    return "unexpected exit code " + std::to_string(r.exit_code);
  if (r.exit_code == 2) {
    std::vector<std::string> errors; // a TOML syntax error quotes its line below the error
    std::istringstream in(r.err);
    for (std::string line; std::getline(in, line);)
      if (line.starts_with("error:"))
        errors.push_back(line);
    if (errors.size() != 1 || !r.err.starts_with("error: "))
      return "exit 2 without exactly one 'error: ' line (first) on stderr";
    const bool names = errors[0].find(t.mutated.filename().string()) != std::string::npos ||
                       errors[0].find(t.case_file.filename().string()) != std::string::npos;
    if (!names)
      return "the error line does not name the mutated file";
  }
  if (!t.output.empty() && (r.exit_code == 0 || r.exit_code == 3) &&
      !fs::exists(t.output / "summary.json"))
    return "exit " + std::to_string(r.exit_code) + " without summary.json";
  return "";
}

/// Runs `t`; reports a violation with a reproducer kept under work/failures/.
void run_trial(const Trial& t, const fs::path& dir) {
  const ProcessResult r = run_process(t.argv, dir, kTimeoutS);
  const std::string why = violation(t, r);
  if (!why.empty()) {
    const fs::path keep = kWork / "failures" / dir.filename();
    fs::create_directories(keep);
    for (const auto& file : fs::directory_iterator(dir))
      if (file.is_regular_file())
        fs::copy_file(file.path(), keep / file.path().filename(),
                      fs::copy_options::overwrite_existing);
    std::string command;
    for (const std::string& a : t.argv)
      command += a + ' ';
    ADD_FAILURE() << why << "\n  mutation: " << t.description << "\n  kept in " << keep.string()
                  << "\n  $ " << command << "\n  exit " << r.exit_code << ", signal " << r.signal
                  << ", " << r.seconds << " s\n  stderr: " << r.err.substr(0, 2000);
  }
  if (!t.output.empty())
    fs::remove_all(t.output);
}

void PrintTo(const Base& base, std::ostream* os) {
  *os << base.name;
}

/// One line per mutated input, which scripts/fuzz-campaign.sh adds up.
void report_count(const std::string& name, int checks, int runs) {
  std::printf("[ fuzz ] %s: %d check and %d run mutants (seed %#llx)\n", name.c_str(), checks, runs,
              static_cast<unsigned long long>(kSeedUsed));
}

class CaseFuzz : public ::testing::TestWithParam<Base> {};

TEST_P(CaseFuzz, MutantsKeepTheContract) {
  const Base& base = GetParam();
  const fs::path dir = work_dir(base.name, base.file);
  const std::string text = read_file(base.file);
  const bool runnable = std::find(kRunnable.begin(), kRunnable.end(), base.name) != kRunnable.end();
  const std::string short_text = shortened(text);
  Mutator mutator(kSeedUsed ^ fnv1a(base.name));
  const int checks = kScale * kCheckMutants;
  const int total = checks + (runnable ? kScale * kRunMutants : 0);
  for (int k = 0; k < total; ++k) {
    const bool run = k >= checks;
    const Mutant m = mutator.mutate_case(run ? short_text : text);
    const fs::path file = dir / ("mutant_" + std::to_string(k) + ".toml");
    write_file(file, m.text);
    Trial t{{kExe.string(), run ? "run" : "check", file.string()}, file, file, {}, m.description};
    if (run) {
      t.output = dir / "out";
      t.argv.insert(t.argv.end(), {"-o", t.output.string()});
    }
    run_trial(t, dir);
    fs::remove(file);
  }
  report_count(base.name, checks, total - checks);
}

std::string base_name(const ::testing::TestParamInfo<Base>& info) {
  std::string name = info.param.name;
  std::replace_if(
      name.begin(), name.end(),
      [](char c) { return std::isalnum(static_cast<unsigned char>(c)) == 0; }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cases, CaseFuzz, ::testing::ValuesIn(bases()), base_name);

/// A Gmsh mesh and the case that reads it (the case refers to the mesh by its file name).
struct MeshBase {
  std::string name;
  fs::path mesh;
  std::string case_text;
};

std::vector<MeshBase> mesh_bases() {
  const fs::path sliding = kSource / "examples" / "sliding_layers";
  return {
      {"sliding_layers_v22", sliding / "sliding_layers_coarse.msh",
       read_file(sliding / "sliding_layers.toml")},
      {"two_hex_v41", kSource / "tests" / "unit" / "mesh" / "data" / "two_hex_v41.msh",
       R"([[mesh.gmsh]]
file = "two_hex_v41.msh"
materials = { cartilage = "soft" }
[materials.soft]
type = "neo-hookean"
E = 1.0
[[boundary.fixed]]
set = "top"
[[boundary.fixed]]
set = "corner"
[[boundary.fixed]]
set = "edge"
[time]
end_time = 1.0
dt = 0.5
)"},
  };
}

void PrintTo(const MeshBase& base, std::ostream* os) {
  *os << base.name;
}

class MeshFuzz : public ::testing::TestWithParam<MeshBase> {};

TEST_P(MeshFuzz, MutantsKeepTheContract) {
  const MeshBase& base = GetParam();
  const fs::path dir = work_dir("mesh_" + base.name, base.mesh);
  const fs::path case_file = dir / "case.toml";
  write_file(case_file, base.case_text);
  const std::string text = read_file(base.mesh);
  const fs::path mesh = dir / base.mesh.filename();
  Mutator mutator(kSeedUsed ^ fnv1a(base.name));
  for (int k = 0; k < kScale * kMshMutants; ++k) {
    const Mutant m = mutator.mutate_msh(text);
    write_file(mesh, m.text);
    run_trial({{kExe.string(), "check", case_file.string()}, mesh, case_file, {}, m.description},
              dir);
  }
  report_count("mesh_" + base.name, kScale * kMshMutants, 0);
}

std::string mesh_name(const ::testing::TestParamInfo<MeshBase>& info) {
  return info.param.name;
}

INSTANTIATE_TEST_SUITE_P(Meshes, MeshFuzz, ::testing::ValuesIn(mesh_bases()), mesh_name);

} // namespace
} // namespace trifem::fuzz
