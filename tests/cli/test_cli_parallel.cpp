// SPDX-License-Identifier: MIT
// Runs on several processes (mpirun -np 2 and -np 3, oversubscribed on small machines): every
// quasi-static example (sliding_layers through its first stroke and back, with MUMPS), and a
// biphasic one as an implicit dynamic analysis, gives the one-process history to 1e-8 of the
// largest magnitude of each unit, with one log, one set of
// result files and its VTU states (volume and contact surfaces) in one piece per process; a
// contact interface split between processes gives the same answer; bad input and an unwritable
// output directory fail with one error line; a write error or an input error of one process
// alone stops them all, with one error line, and so does a signal to one process; the explicit
// analysis, alone, restarted or between quasi-static steps, gives the one-process histories to
// 1e-10; the Krylov backend is refused.
#include "cli_harness.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <functional>
#include <map>
#include <regex>

namespace trifem::cli_test {
namespace {

const fs::path kMpiexec = TRIFEM_MPIEXEC;

class CliParallel : public Cli {
protected:
  void SetUp() override {
    Cli::SetUp();
    // OpenMPI refuses to start as root (containers, CI) without these
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
    ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  }

  /// Runs trifem with `args` on `processes` processes through mpirun.
  Result mpirun(int processes, std::initializer_list<std::string> args) const {
    return run(shell_quoted(kMpiexec.string()) + " --oversubscribe -np " +
                   std::to_string(processes) + " " + shell_quoted(kExe.string()),
               args);
  }

  /// Runs `file` on one process, then on 2 and 3: each history must be the one-process history
  /// to `relative` of each unit's scale (iterations aside); `check` looks at each parallel run.
  void expect_the_one_process_history(const fs::path& file, double relative,
                                      const std::function<void(const Result&)>& check = {}) const {
    const Result one = trifem({"run", file.string(), "-o", (output() / "1").string()});
    ASSERT_EQ(one.exit_code, kSuccess) << one;
    const History serial = read_history(output() / "1" / "history.csv");
    for (const int processes : {2, 3}) {
      SCOPED_TRACE(std::to_string(processes) + " processes");
      const fs::path out = output() / std::to_string(processes);
      const Result r = mpirun(processes, {"run", file.string(), "-o", out.string()});
      ASSERT_EQ(r.exit_code, kSuccess) << r;
      if (check)
        check(r);
      expect_the_same_history(serial, read_history(out / "history.csv"), relative, {"iterations"});
    }
  }

  /// The example `name` as a case file of the working directory (its mesh file, if any, read
  /// from the example's folder), each line that begins with a key of `lines` replaced by its
  /// value.
  fs::path example(const std::string& name,
                   const std::map<std::string, std::string>& lines = {}) const {
    std::string text = read_text(kExamples / name / (name + ".toml"));
    const std::string mesh = "\nfile = \"";
    if (const auto at = text.find(mesh); at != std::string::npos)
      text.insert(at + mesh.size(), (kExamples / name).string() + "/");
    for (const auto& [key, line] : lines) {
      const auto at = text.find("\n" + key);
      EXPECT_NE(at, std::string::npos) << name << " has no line " << key;
      if (at != std::string::npos)
        text.replace(at + 1, text.find('\n', at + 1) - at - 1, line);
    }
    return write_file(name + ".toml", text);
  }

  /// The output states of `parallel` (a run on `processes` processes) in the collection
  /// `pvd` are those of `serial`, each as a .pvtu file whose pieces, one per process, hold all
  /// the cells between them.
  static void expect_the_same_states_in_pieces(const fs::path& serial, const fs::path& parallel,
                                               int processes, const std::string& pvd) {
    SCOPED_TRACE(pvd);
    const std::regex dataset(R"re(timestep="([^"]*)"[^>]*file="([^"]*)")re");
    const auto states = [&](const fs::path& dir) {
      std::vector<std::pair<std::string, std::string>> found; // (time, file)
      const std::string text = read_text(dir / pvd);
      for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
           it != std::sregex_iterator(); ++it)
        found.emplace_back((*it)[1].str(), (*it)[2].str());
      return found;
    };
    const auto cells = [](const std::string& vtu) { // NumberOfCells of a .vtu file
      const std::regex count(R"re(NumberOfCells="(\d+)")re");
      std::smatch m;
      return std::regex_search(vtu, m, count) ? std::stol(m[1].str()) : -1L;
    };
    const auto one = states(serial), many = states(parallel);
    ASSERT_EQ(one.size(), many.size()) << "the same output states";
    ASSERT_FALSE(one.empty());
    for (std::size_t k = 0; k < one.size(); ++k) {
      EXPECT_EQ(many[k].first, one[k].first);
      const std::string stem = fs::path(one[k].second).stem().string(); // volume_NNNN
      EXPECT_EQ(many[k].second, stem + ".pvtu");
      const std::string pvtu = read_text(parallel / (stem + ".pvtu"));
      long total = 0;
      for (int p = 0; p < processes; ++p) {
        const std::string piece = stem + "_" + std::to_string(p) + ".vtu";
        EXPECT_TRUE(contains(pvtu, "Source=\"" + piece + "\"")) << piece;
        total += cells(read_text(parallel / piece));
      }
      EXPECT_EQ(total, cells(read_text(serial / one[k].second))) << stem;
    }
  }

  /// The VTU collections of the one-process run in `serial`: results.pvd and one contact<i>.pvd
  /// per contact pair.
  static std::vector<std::string> collections(const fs::path& serial) {
    std::vector<std::string> names = {"results.pvd"};
    for (int i = 1; fs::exists(serial / ("contact" + std::to_string(i) + ".pvd")); ++i)
      names.push_back("contact" + std::to_string(i) + ".pvd");
    return names;
  }

  /// Runs the case `file` on one process and on two, both writing restart files (`files` of
  /// them on two), continues it on two processes from the file `restart_at` (time
  /// `restart_time`) and expects every row after the restart to be the uninterrupted one-process
  /// run's to 1e-10 of each unit's scale. The continued run's history.
  History expect_a_two_process_restart_to_continue(const fs::path& file, std::size_t files,
                                                   std::size_t restart_at,
                                                   double restart_time) const {
    const fs::path one = output() / "one", two = output() / "two", resumed = output() / "resumed";
    Result r = trifem({"-q", "run", file.string(), "-o", one.string(), "--write-restart"});
    EXPECT_EQ(r.exit_code, kSuccess) << r;
    r = mpirun(2, {"-q", "run", file.string(), "-o", two.string(), "--write-restart"});
    EXPECT_EQ(r.exit_code, kSuccess) << r;
    const std::vector<fs::path> written = restart_files(two);
    EXPECT_EQ(written.size(), files) << "one per output time";
    if (written.size() <= restart_at)
      return {};
    r = mpirun(2, {"-q", "run", file.string(), "-o", resumed.string(), "--restart",
                   written[restart_at].string()});
    EXPECT_EQ(r.exit_code, kSuccess) << r;
    const History a = read_history(one / "history.csv");
    History b = read_history(resumed / "history.csv");
    EXPECT_EQ(a.names, b.names);
    if (a.names != b.names || b.columns.empty() || b.columns[0].size() > a.columns[0].size())
      return b;
    EXPECT_NEAR(b["time [s]"].front(), restart_time, 1e-15);
    const std::size_t offset = a.columns[0].size() - b.columns[0].size();
    const std::map<std::string, double> scale = unit_scales(a);
    for (std::size_t c = 0; c < a.names.size(); ++c) {
      if (a.names[c] == "iterations")
        continue;
      double worst = 0.0; // row 0: the restart state itself
      for (std::size_t i = 1; i < b.columns[c].size(); ++i)
        worst = std::max(worst, std::abs(b.columns[c][i] - a.columns[c][offset + i]));
      EXPECT_LE(worst, 1e-10 * scale.at(unit_of(a.names[c]))) << a.names[c];
    }
    return b;
  }

  /// Runs `name` (its lines replaced by `lines`: example()) on 1, 2 and 3 processes: the same
  /// steps and the same history to `relative` of each unit's scale; rank 0 alone writes the
  /// files and the log.
  void expect_the_one_process_history(const std::string& name,
                                      const std::map<std::string, std::string>& lines = {},
                                      double relative = 1e-8) const {
    SCOPED_TRACE(name);
    expect_the_one_process_results(example(name, lines), relative, {"history.csv"});
  }

  /// Runs the case `file` on 1, 2 and 3 processes: the same steps and the same `histories` (of
  /// the output directory) to `relative` of each unit's scale; rank 0 alone writes the files
  /// and the log.
  void expect_the_one_process_results(const fs::path& file, double relative,
                                      std::initializer_list<std::string> histories) const {
    const Result one = trifem({"run", file.string(), "-o", (output() / "1").string()});
    ASSERT_EQ(one.exit_code, kSuccess) << one;
    for (const int processes : {2, 3}) {
      SCOPED_TRACE(std::to_string(processes) + " processes");
      const fs::path out = output() / std::to_string(processes);
      const Result r = mpirun(processes, {"run", file.string(), "-o", out.string()});
      ASSERT_EQ(r.exit_code, kSuccess) << r;
      EXPECT_EQ(count_of(r.out, "completed: "), 1u) << "one log, from rank 0" << r;
      EXPECT_TRUE(contains(r.out, "on each of " + std::to_string(processes) + " processes")) << r;
      EXPECT_TRUE(lines_of(r.err).empty()) << r;
      for (const std::string& history : histories) {
        SCOPED_TRACE(history);
        const History serial = read_history(output() / "1" / history);
        ASSERT_GT(serial.names.size(), 4u);
        expect_the_same_history(serial, read_history(out / history), relative, {"iterations"});
      }
      for (const std::string& pvd : collections(output() / "1"))
        expect_the_same_states_in_pieces(output() / "1", out, processes, pvd);
    }
  }
};

TEST_F(CliParallel, BiphasicAndSolidExamplesGiveTheOneProcessHistory) {
  for (const std::string name : {"biphasic_creep", "cantilever", "fibre_reinforced_unconfined"})
    expect_the_one_process_history(name);
}

TEST_F(CliParallel, TriphasicExamplesGiveTheOneProcessHistory) {
  for (const std::string name : {"confined_column", "free_swelling", "swell_then_compress"})
    expect_the_one_process_history(name);
}

TEST_F(CliParallel, ContactExamplesGiveTheOneProcessHistory) {
  for (const std::string name : {"contact_patch", "contact_column"})
    expect_the_one_process_history(name);
}

TEST_F(CliParallel, TheIndentationExampleGivesTheOneProcessHistory) {
  expect_the_one_process_history("indentation"); // 3-D, contact, a rigid indenter
}

TEST_F(CliParallel, TheSlidingLayersExampleGivesTheOneProcessHistory) {
  // large sliding under load, through the first stroke (0 -> +A) and a quarter of the way back
  // (39 steps of the 160 of the whole example); MUMPS: 10 s instead of SparseLU's 18 s
  expect_the_one_process_history("sliding_layers",
                                 {{"end_time", "end_time = 0.152"},
                                  {"times", "times = [0.002, 0.102, 0.152]"},
                                  {"linear_solver", "linear_solver = \"mumps\""}});
}

TEST_F(CliParallel, AnImplicitDynamicMixtureGivesTheOneProcessHistory) {
  // generalized-alpha steps of a biphasic layer (the creep example) whose mass, 10^11 times the
  // tissue's, changes its settlement by 1.6e-3 of its peak (against the quasi-static creep)
  expect_the_one_process_history(
      "biphasic_creep",
      {{"nu", "nu = 0.0\n[analysis]\ntype = \"dynamic\"\n[dynamic]\nrho_inf = 0.0"},
       {"permeability", "permeability = 1.07e-3\ndensity = 1e2"}});
}

TEST_F(CliParallel, AContactInterfaceSplitBetweenProcessesGivesTheOneProcessAnswer) {
  // the paper's §4.1 column split at mid-height by a contact interface, both halves meshed
  // alike: the partition (by the couplings of the bodies, not of the contact) puts the slave
  // and the master side on different processes, and the answer is the one-process answer
  std::string text = read_text(kExamples / "contact_column" / "contact_column.toml");
  const std::string upper = "divisions = [3, 3, 5]";
  ASSERT_NE(text.find(upper), std::string::npos);
  text.replace(text.find(upper), upper.size(), "divisions = [2, 2, 5]");
  expect_the_one_process_history(write_file("halves.toml", text), 1e-8, [](const Result& r) {
    // "contact 1: slave nodes on processes [a], master nodes on processes [b]" with a != b
    const std::regex sides(
        R"(contact 1: slave nodes on processes \[(\d)\], master nodes on processes \[(\d)\])");
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, sides)) << r;
    EXPECT_NE(m[1].str(), m[2].str()) << "the interface must lie between processes" << r;
  });
}

TEST_F(CliParallel, BadInputFailsWithOneErrorLine) {
  std::string text = read_text(kExamples / "cantilever" / "cantilever.toml");
  text += "\n[bogus]\nkey = 1\n";
  const fs::path file = write_file("bad.toml", text);
  const Result r = mpirun(3, {"run", file.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "bogus")) << r;
  EXPECT_FALSE(fs::exists(output() / "history.csv")) << r;
}

TEST_F(CliParallel, AnUnwritableOutputDirectoryFailsWithOneErrorLine) {
  // rank 0 alone creates the output directory; every process learns that it could not
  const fs::path blocker = write_file("not_a_directory", "");
  const Result r =
      mpirun(2, {"run", example("cantilever").string(), "-o", (blocker / "out").string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "cannot create the output directory")) << r;
}

TEST_F(CliParallel, AWriteErrorOfOneProcessStopsEveryProcessWithOneErrorLine) {
  // process 1 alone cannot write its piece of the first VTU state (a directory stands in its
  // way): every process learns it, and the run fails as on one process, with a summary
  fs::create_directories(output() / "volume_0000_1.vtu");
  const Result r = mpirun(2, {"run", example("cantilever").string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kAnalysisFailed) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "the initial state could not be written")) << r;
  EXPECT_TRUE(contains(errors[0], "volume_0000_1.vtu")) << r;
  EXPECT_TRUE(contains(read_text(output() / "summary.json"), "\"status\": \"failed\"")) << r;
  // no list names the state whose piece is missing
  EXPECT_FALSE(fs::exists(output() / "volume_0000.pvtu")) << r;
  if (fs::exists(output() / "results.pvd")) {
    EXPECT_FALSE(contains(read_text(output() / "results.pvd"), "volume_0000")) << r;
  }
}

TEST_F(CliParallel, ProcessesThatReadDifferentCasesAreRefused) {
  // process 1 alone reads another case (two programs under one mpirun, or a stale copy of the
  // case on one host): the processes compare their command lines and case files first, and
  // all refuse the run instead of waiting for each other in different places
  const fs::path good = example("cantilever");
  const fs::path bad = write_file("bad.toml", read_text(good) + "\n[bogus]\nkey = 1\n");
  const std::string exe = shell_quoted(kExe.string());
  const Result r = run(shell_quoted(kMpiexec.string()) + " --oversubscribe -np 1 " + exe + " run " +
                           shell_quoted(good.string()) + " -o " + shell_quoted(output().string()) +
                           " : -np 1 " + exe,
                       {"run", bad.string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "the processes disagree: process 1 of 2")) << r;
  EXPECT_FALSE(fs::exists(output())) << "nothing is written";
}

TEST_F(CliParallel, AnErrorOfOneProcessAloneStopsEveryProcess) {
  // the same command on the same case file, run from another directory by each process: the
  // Gmsh mesh the case names exists for process 0 only. Process 0 goes on and waits for
  // process 1 in the next collective operation; process 1 reports its error with its rank and
  // stops them both, with the exit code of invalid input
  const std::string text = "[[mesh.gmsh]]\nfile = \"mesh.msh\"\nmaterials = { cartilage = "
                           "\"soft\" }\n\n[materials.soft]\ntype = \"neo-hookean\"\nE = 1.0\n\n"
                           "[[boundary.fixed]]\nset = \"cartilage\"\n\n[time]\nend_time = 1.0\n"
                           "dt = 0.5\n";
  const fs::path dir =
      write_file("rank.sh", "cd r${OMPI_COMM_WORLD_RANK:-$PMI_RANK} && exec \"$@\"\n")
          .parent_path();
  for (const char* rank : {"r0", "r1"}) {
    fs::create_directories(dir / rank);
    write_file(std::string(rank) + "/case.toml", text);
  }
  fs::copy_file(fs::path(TRIFEM_SOURCE_DIR) / "tests/unit/mesh/data/two_hex_v22.msh",
                dir / "r0" / "mesh.msh");
  const Result r = run(shell_quoted(kMpiexec.string()) + " --oversubscribe -np 2 sh rank.sh " +
                           shell_quoted(kExe.string()),
                       {"run", "case.toml", "-o", "out"});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  std::vector<std::string> errors = lines_of(r.err);
  std::erase_if(errors, [](const std::string& line) { return !line.starts_with("error"); });
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(errors[0].starts_with("error (process 1 of 2): case.toml")) << r;
  EXPECT_TRUE(contains(errors[0], "mesh.msh")) << r;
  EXPECT_TRUE(contains(errors[0], "the other processes are stopped")) << r;
  EXPECT_EQ(count_of(r.out, "completed: "), 0u) << r;
}

TEST_F(CliParallel, ASignalToOneProcessStopsEveryProcessAtTheSameIteration) {
  // SIGTERM to process 1 alone, after a few steps of a long run: every process stops, rank 0
  // reports the interruption and keeps the results (without the agreement process 0 would wait
  // for process 1 for ever: the run is killed after 120 s)
  const fs::path file = example("confined_column", {{"end_time", "end_time = 1e5"}});
  const fs::path history = output() / "history.csv";
  write_file("rank.sh", "echo $$ > pid_${OMPI_COMM_WORLD_RANK:-$PMI_RANK}\nexec \"$@\"\n");
  const std::string script =
      "timeout -s KILL 120 " + shell_quoted(kMpiexec.string()) +
      " --oversubscribe -np 2 sh rank.sh " + shell_quoted(kExe.string()) + " -q run " +
      shell_quoted(file.string()) + " -o " + shell_quoted(output().string()) +
      " 2>err.txt & job=$!; for i in $(seq 1200); do n=$(cat " + shell_quoted(history.string()) +
      " 2>/dev/null | wc -l); [ \"$n\" -ge 5 ] && break; sleep 0.05; done; kill -TERM $(cat "
      "pid_1); wait $job; exit $?";
  const int status = std::system(
      ("cd " + shell_quoted(dir_.string()) + " && sh -c " + shell_quoted(script)).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_NE(WEXITSTATUS(status), 0);
  EXPECT_NE(WEXITSTATUS(status), 137) << "killed after 120 s: a process was left waiting";
  const std::string summary = read_text(output() / "summary.json");
  EXPECT_TRUE(contains(summary, "\"status\": \"interrupted\"")) << summary;
  EXPECT_GE(lines_of(read_text(history)).size(), 5u);
  const std::string err = read_text(dir_ / "err.txt");
  EXPECT_EQ(error_lines(err).size(), 1u) << err;
  EXPECT_TRUE(contains(err, "interrupted")) << err;
}

TEST_F(CliParallel, TheExplicitCantileverGivesTheOneProcessHistory) {
  // the multiplier's pressure (solved by MUMPS on the processes), a follower pressure and the
  // clamp's reaction, through the first quarter of the bending period (440 steps)
  expect_the_one_process_history("explicit_cantilever", {{"end_time", "end_time = 0.005"}}, 1e-10);
}

TEST_F(CliParallel, AnExplicitRunRestartedOnTwoProcessesContinuesTheOneProcessRun) {
  // restart files written on 2 processes hold the integrator's state of every process (the
  // same bits everywhere): continued on 2 processes from the middle of the run, the rows after
  // the restart are those of the uninterrupted one-process run (both write restart files, so
  // both factorize the multiplier matrix afresh at the same steps)
  const fs::path file = example("explicit_cantilever", {{"end_time", "end_time = 0.005"}});
  const History b = expect_a_two_process_restart_to_continue(file, 10, 4, 2.5e-3);
  EXPECT_GT(b.columns[0].size(), 100u);
}

TEST_F(CliParallel, QuasiStaticExplicitQuasiStaticStepsGiveTheOneProcessHistories) {
  // a bar stretched quasi-statically, then pulled further by its moving end in a
  // dynamic-explicit step, then brought back quasi-statically: one mesh, one state, on every
  // process
  const std::string text = R"(
[[mesh.box]]
name = "bar"
size = [10.0, 1.0, 1.0]
divisions = [20, 2, 2]
material = "rubber"

[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.3
density = 1e-9

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0], [1.001, 1.5], [2.001, 1.0]]

[[boundary.fixed]]
set = "bar.xmin"

[explicit]
multiplier = false  # the law's own bulk response, as in the quasi-static steps

[[step]]
name = "stretch"
end_time = 1.0
dt = 0.25
[[step.boundary.prescribed]]
set = "bar.xmax"
component = "x"
value = 0.1
curve = "ramp"

[[step]]
name = "pull"
analysis = "dynamic-explicit"
duration = 1e-3
[[step.boundary.prescribed]]
set = "bar.xmax"
component = "x"
value = 0.1
curve = "ramp"

[[step]]
name = "return"
duration = 1.0
dt = 0.25
[[step.boundary.prescribed]]
set = "bar.xmax"
component = "x"
value = 0.1
curve = "ramp"

[[output.reaction]]
set = "bar.xmax"
[[output.probe]]
name = "middle"
point = [5.0, 1.0, 1.0]
)";
  expect_the_one_process_results(write_file("steps.toml", text), 1e-10,
                                 {"history.csv", "history_step2.csv"});
}

/// A nearly incompressible bar (the multiplier's system on MUMPS) fixed at one end, carrying a
/// heavy free block that starts moving and turning at the other, in a dynamic-explicit analysis
/// (2 ms, 80 steps; restart files every 0.25 ms).
constexpr const char* kBarAndBlock = R"(
[[mesh.box]]
name = "bar"
size = [10.0, 1.0, 1.0]
divisions = [10, 2, 2]
material = "rubber"
[[mesh.box]]
name = "weight"
origin = [10.0, 0.0, 0.0]
size = [1.0, 1.0, 1.0]
divisions = [1, 1, 1]
[materials.rubber]
type = "neo-hookean"
E = 1.0
nu = 0.0
density = 1e-9
[[boundary.fixed]]
set = "bar.xmin"
[[rigid_body]]
name = "weight"
set = "bar.xmax"
blocks = ["weight"]
density = 1e-7
velocity = [100.0, 20.0, 0.0]
angular_velocity = [10.0, 0.0, 5.0]
[analysis]
type = "dynamic-explicit"
[time]
end_time = 2e-3
dt = 2.5e-5
[output]
interval = 2.5e-4
)";

TEST_F(CliParallel, ABarCarryingAFreeBodyExplicitlyGivesTheOneProcessHistory) {
  expect_the_one_process_results(write_file("bar_and_block.toml", kBarAndBlock), 1e-10,
                                 {"history.csv"});
}

TEST_F(CliParallel, AnExplicitRunWithAFreeBodyRestartedOnTwoProcessesContinuesTheOneProcessRun) {
  // the body's motion (its pivot, rotation, momenta) is in the restart file
  const History b = expect_a_two_process_restart_to_continue(
      write_file("bar_and_block.toml", kBarAndBlock), 8, 3, 1e-3);
  EXPECT_GT(b.columns[0].size(), 30u);
  EXPECT_GT(std::abs(b["weight.rz [rad]"].back()), 1e-3) << "the body turns";
}

/// A 2 x 1 x 1 mm bar of tet10 cells (a box split into Kuhn's tets) pulled by a dead traction on
/// its tri6 end face and pushed sideways by a follower pressure, with probes and an average.
std::string tet10_bar_case() {
  return R"(
[[mesh.box]]
name = "bar"
size = [2.0, 1.0, 1.0]
divisions = [4, 2, 2]
cell = "tet10"
material = "tissue"
[materials.tissue]
type = "neo-hookean"
E = 1.0
nu = 0.3
[[boundary.fixed]]
set = "bar.xmin"
[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]
[[loads.traction]]
surface = "bar.xmax"
value = [0.1, 0.0, 0.02]
curve = "ramp"
[[loads.pressure]]
surface = "bar.ymax"
value = 0.01
curve = "ramp"
[time]
end_time = 1.0
dt = 0.25
[output]
interval = 0.25
[[output.reaction]]
set = "bar.xmin"
[[output.probe]]
name = "tip"
point = [2.0, 0.5, 0.5]
[[output.average]]
name = "bar"
quantity = "displacement"
block = "bar"
)";
}

TEST_F(CliParallel, ATet10BarGivesTheOneProcessHistory) {
  expect_the_one_process_results(write_file("tet10_bar.toml", tet10_bar_case()), 1e-10,
                                 {"history.csv"});
}

// The same bar of tet4 cells with a nearly incompressible law (ν = 0.49): their dilatation is
// averaged over the nodes, so an element reaches the nodes of the cells around it, across the
// processes' parts.
TEST_F(CliParallel, ANearlyIncompressibleTet4BarGivesTheOneProcessHistory) {
  std::string text = tet10_bar_case();
  text.replace(text.find("cell = \"tet10\""), 14, "cell = \"tet4\"");
  text.replace(text.find("nu = 0.3"), 8, "nu = 0.49");
  expect_the_one_process_results(write_file("tet4_bar.toml", text), 1e-10, {"history.csv"});
}

TEST_F(CliParallel, ATet10BarRestartedOnTwoProcessesContinuesTheOneProcessRun) {
  const History h = expect_a_two_process_restart_to_continue(
      write_file("tet10_bar.toml", tet10_bar_case()), 4, 1, 0.5);
  EXPECT_FALSE(h.columns.empty());
}

TEST_F(CliParallel, AnExplicitTet10BarGivesTheOneProcessHistory) {
  // the tet10 bar in a dynamic-explicit analysis: its cells' multipliers solved by MUMPS on the
  // processes, the loads on its tri6 faces and probes (2 ms, loaded within 1 ms)
  std::string text = tet10_bar_case();
  text.erase(text.find("[[output.average]]"));
  text.replace(text.find("nu = 0.3"), 8, "nu = 0.3\ndensity = 1e-9");
  text.replace(text.find("[[0.0, 0.0], [1.0, 1.0]]"), 24, "[[0.0, 0.0], [1e-3, 1.0]]");
  text.replace(text.find("end_time = 1.0\ndt = 0.25"), 24,
               "end_time = 2e-3\n[analysis]\ntype = \"dynamic-explicit\"");
  text.replace(text.find("interval = 0.25"), 15, "interval = 2.5e-4");
  expect_the_one_process_results(write_file("tet10_explicit.toml", text), 1e-10, {"history.csv"});
}

/// A cube of `cell` cells (a box split) of a biphasic or triphasic `material`, fixed on one face,
/// the opposite face in a bath at 0.01 MPa gauge pressure (and 0.015 M of NaCl for the triphasic
/// one), with a probe at the free corner.
std::string mixture_families_case(const char* cell, const char* material) {
  return fmt::format(R"(
[[mesh.box]]
name = "cube"
size = [1.0, 1.0, 1.0]
divisions = [3, 3, 2]
cell = "{}"
material = "tissue"

[materials.tissue]
type = "{}"
phi_s0 = 0.25
permeability = 1.07e-3
{}
[materials.tissue.solid]
type = "saint-venant-kirchhoff"
E = 0.3
nu = 0.0

[curves.ramp]
points = [[0.0, 0.0], [1.0, 1.0]]

[[boundary.bath]]
surface = "cube.xmax"
{}
pressure = 0.01
curve = "ramp"

[[boundary.fixed]]
set = "cube.xmin"
components = ["x", "y", "z"]

[time]
end_time = 200.0
dt = 0.5
dt_max = 50.0

[[output.probe]]
name = "corner"
point = [1.0, 1.0, 1.0]
)",
                     cell, material,
                     std::string(material) == "triphasic"
                         ? "fixed_charge = 2e-4\nd_plus = 5e-4\nd_minus = 8e-4"
                         : "",
                     std::string(material) == "triphasic" ? "concentration = 1.5e-5" : "");
}

TEST_F(CliParallel, ATriphasicCubeOfWedgesGivesTheOneProcessHistory) {
  expect_the_one_process_results(
      write_file("wedges.toml", mixture_families_case("penta6", "triphasic")), 1e-10,
      {"history.csv"});
}

TEST_F(CliParallel, ABiphasicCubeOfTet10CellsGivesTheOneProcessHistory) {
  expect_the_one_process_results(
      write_file("tet10.toml", mixture_families_case("tet10", "biphasic")), 1e-10, {"history.csv"});
}

TEST_F(CliParallel, TheKrylovBackendIsRefusedWithOneErrorLine) {
  std::string text = read_text(kExamples / "cantilever" / "cantilever.toml");
  text += "\n[solver]\nlinear_solver = \"krylov\"\n";
  ASSERT_EQ(count_of(text, "[solver]"), 1u) << "the example has no [solver] of its own";
  const Result r =
      mpirun(2, {"run", write_file("krylov.toml", text).string(), "-o", output().string()});
  EXPECT_EQ(r.exit_code, kInvalidInput) << r;
  const std::vector<std::string> errors = error_lines(r.err);
  ASSERT_EQ(errors.size(), 1u) << r;
  EXPECT_TRUE(contains(errors[0], "krylov")) << r;
}

TEST_F(CliParallel, AFrictionalBlockDraggedOnSeveralProcessesGivesTheOneProcessHistory) {
  // the block of the friction test pressed by a rigid plate and dragged 0.5 mm over a fixed
  // base (every slave node sticking, then slipping at the Coulomb limit)
  std::string text = read_text(kData / "friction_block.toml");
  const std::string push = "x = { force = 0.03, curve = \"push\" }";
  ASSERT_NE(text.find(push), std::string::npos);
  text.replace(text.find(push), push.size(), "x = { displacement = 0.5, curve = \"push\" }");
  expect_the_one_process_history(write_file("drag.toml", text), 1e-10);
}

} // namespace
} // namespace trifem::cli_test
