// SPDX-License-Identifier: MIT
// The linear-solver backends give the same converged answers: every quasi-static example (but
// the two-minute sliding_layers, whose coarse form runs in the verification suite; the columns
// and the indentation through their first steps) is run with
// UMFPACK, with MUMPS (also reusing factorizations) and with the Krylov backend (PETSc): every
// history column must agree to 1e-8 of the largest magnitude of its unit in the history (a column
// that is zero in exact arithmetic, a lateral displacement, is compared with the displacements),
// and the Newton iterations to within one per step. Bad PETSc settings are input errors naming the
// key.
#include "cli_harness.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <sstream>

namespace trifem::cli_test {
namespace {

/// `text` (a case file) with [solver] linear_solver set to `backend` (and no
/// reuse_factorization of its own).
std::string with_backend(std::string text, const std::string& backend) {
  const std::string line = "linear_solver = \"" + backend + "\"\n";
  const auto solver = text.find("\n[solver]\n");
  if (solver == std::string::npos)
    return text + "\n[solver]\n" + line;
  for (const std::string key : {"linear_solver", "reuse_factorization"}) {
    const auto old = text.find("\n" + key, solver);
    if (old != std::string::npos && old < text.find("\n[", solver + 1))
      text.erase(old + 1, text.find('\n', old + 1) - old);
  }
  return text.insert(solver + 10, line);
}

/// The integer after `"key": ` in a summary.json (-1 if absent).
long summary_integer(const fs::path& summary, const std::string& key) {
  const std::string text = read_text(summary);
  const auto at = text.find("\"" + key + "\": ");
  return at == std::string::npos ? -1 : std::stol(text.substr(at + key.size() + 4));
}

class CliSolvers : public Cli {
protected:
  /// Runs the example `name` with `backend`, each text of `edits` in its case file replaced by
  /// its value; the history.csv path (empty on failure).
  fs::path run_example(const std::string& name, const std::string& backend,
                       const std::map<std::string, std::string>& edits = {}) const {
    // "mumps+reuse": MUMPS with reuse_factorization (single-precision factorizations, or with
    // "+double" double-precision ones); "krylov+amg": the multigrid preconditioner;
    // "krylov...+drained": the drained Schur approximation
    const bool reuse = backend.starts_with("mumps+reuse"), amg = backend.starts_with("krylov+amg"),
               drained = backend.ends_with("+drained");
    std::string text = with_backend(read_text(kExamples / name / (name + ".toml")),
                                    reuse                           ? "mumps"
                                    : backend.starts_with("krylov") ? "krylov"
                                                                    : backend);
    if (reuse)
      text.insert(text.find("\n[solver]\n") + 10, "reuse_factorization = true\n");
    if (backend == "mumps+reuse+double")
      text.insert(text.find("\n[solver]\n") + 10, "factorization_precision = \"double\"\n");
    if (amg)
      text.insert(text.find("\n[solver]\n") + 10, "preconditioner = \"amg\"\n");
    if (drained)
      text.insert(text.find("\n[solver]\n") + 10, "schur_approximation = \"drained\"\n");
    for (const auto& [from, to] : edits) {
      const auto at = text.find(from);
      EXPECT_NE(at, std::string::npos) << name << " has no text " << from;
      if (at != std::string::npos)
        text.replace(at, from.size(), to);
    }
    const std::string mesh = "\nfile = \""; // a mesh file beside the example
    if (const auto at = text.find(mesh); at != std::string::npos)
      text.insert(at + mesh.size(), (kExamples / name).string() + "/");
    const fs::path file = write_file(name + "_" + backend + ".toml", text);
    const fs::path out = output() / backend;
    const Result r = trifem({"-q", "run", file.string(), "-o", out.string()});
    EXPECT_EQ(r.exit_code, kSuccess) << r;
    return out / "history.csv";
  }

  /// Runs the example `name` with UMFPACK and with every PETSc backend: the same history to
  /// 1e-8 of each unit's scale, and the same Newton iterations within one in every step (an
  /// iterative solve to Newton's forcing term may take one more or one fewer).
  /// `edits`: as for run_example.
  void expect_petsc_backends_give_the_umfpack_history(
      const std::string& name, const std::vector<std::string>& backends,
      const std::map<std::string, std::string>& edits = {}) const {
    SCOPED_TRACE(name);
    const History umfpack = read_history(run_example(name, "umfpack", edits));
    ASSERT_GT(umfpack.names.size(), 1u);
    for (const std::string& backend : backends) {
      SCOPED_TRACE(backend);
      const History other = read_history(run_example(name, backend, edits));
      expect_the_same_history(umfpack, other, 1e-8, {"iterations"});
      const auto column = std::find(umfpack.names.begin(), umfpack.names.end(), "iterations");
      ASSERT_NE(column, umfpack.names.end());
      const auto c = static_cast<std::size_t>(column - umfpack.names.begin());
      ASSERT_EQ(other.columns[c].size(), umfpack.columns[c].size());
      for (std::size_t step = 0; step < umfpack.columns[c].size(); ++step)
        EXPECT_LE(std::abs(other.columns[c][step] - umfpack.columns[c][step]), 1.0)
            << "step " << step + 1;
      // the same Newton iterations per step, within one per step
      const fs::path direct = output() / "umfpack" / "summary.json";
      const fs::path summary = output() / backend / "summary.json";
      const long steps = summary_integer(direct, "steps");
      ASSERT_GT(steps, 0);
      EXPECT_GT(summary_integer(summary, "peak_memory_mb"), 1); // the process's peak RSS
      // an iterative solve counts its iterations (at least one per Newton iteration)
      const long newton = summary_integer(summary, "newton_iterations");
      if (backend == "mumps")
        EXPECT_EQ(summary_integer(summary, "linear_iterations"), 0);
      else
        EXPECT_GE(summary_integer(summary, "linear_iterations"), newton);
    }
  }
};

TEST_F(CliSolvers, PetscBackendsGiveTheUmfpackHistoryOnEveryExample) {
  // the columns under their platen's ramp: the confined one through the whole 50 s ramp (20 of
  // its 400 steps), the contact one through half of it (10 of 80 steps)
  const std::map<std::string, std::map<std::string, std::string>> edits = {
      {"confined_column",
       {{"end_time = 1000.0", "end_time = 50.0"},
        {"times = [5.0, 25.0, 50.0, 100.0, 200.0, 500.0, 1000.0]", "times = [5.0, 25.0, 50.0]"}}},
      {"contact_column",
       {{"end_time = 200.0", "end_time = 25.0"},
        {"times = [5.0, 25.0, 50.0, 100.0, 200.0]", "times = [5.0, 25.0]"}}}};
  for (const std::string name : {"biphasic_creep", "cantilever", "confined_column",
                                 "contact_column", "contact_patch", "free_swelling"})
    expect_petsc_backends_give_the_umfpack_history(
        name,
        {"mumps", "mumps+reuse", "mumps+reuse+double", "krylov", "krylov+amg",
         "krylov+amg+drained"},
        edits.contains(name) ? edits.at(name) : std::map<std::string, std::string>{});
}

TEST_F(CliSolvers, PetscBackendsGiveTheUmfpackHistoryOnTheIndentationExample) {
  // 3-D, contact, rigid body; the multigrid preconditioner is not yet efficient on contact
  // (docs/theory/solvers.md §4). The indentation and the first 35 s of the relaxation (13 of
  // the 20 steps; the whole run took 5 min in the two-job suite): the contact and its fluid
  // boundary change in every step up to there.
  expect_petsc_backends_give_the_umfpack_history(
      "indentation", {"mumps", "mumps+reuse", "krylov", "krylov+drained"},
      {{"end_time = 1000.0", "end_time = 45.0"},
       {"times = [2.0, 5.0, 10.0, 100.0, 1000.0]", "times = [2.0, 5.0, 10.0, 45.0]"}});
}

TEST_F(CliSolvers, MumpsFactorizesAgainWhenItsWorkspaceEstimateIsTooSmall) {
  // the confined column as a 6 x 6 x 24 block (6 383 equations): MUMPS's first factorization
  // runs out of its estimated workspace (INFOG(1) = -9, pivots delayed on the saddle-point
  // rows); the backend must factorize again with a larger ICNTL(14), not fail the run
  std::string text = read_text(kExamples / "confined_column" / "confined_column.toml");
  for (const auto& [from, to] : std::vector<std::pair<std::string, std::string>>{
           {"divisions = [1, 1, 10]", "divisions = [6, 6, 24]"},
           {"end_time = 1000.0", "end_time = 12.5"}}) {
    ASSERT_NE(text.find(from), std::string::npos) << from;
    text.replace(text.find(from), from.size(), to);
  }
  text.erase(text.find("\ntimes = "),
             text.find('\n', text.find("\ntimes = ") + 1) - text.find("\ntimes = "));
  std::map<std::string, History> histories;
  for (const std::string backend : {"mumps", "sparselu"}) {
    const fs::path out = output() / backend;
    const Result r = trifem(
        {"run", write_file("block_" + backend + ".toml", with_backend(text, backend)).string(),
         "-o", out.string()});
    ASSERT_EQ(r.exit_code, kSuccess) << r;
    if (backend == "mumps") {
      EXPECT_NE(r.out.find("factorizing again with ICNTL(14)"), std::string::npos) << r.out;
    }
    histories[backend] = read_history(out / "history.csv");
  }
  expect_the_same_history(histories.at("sparselu"), histories.at("mumps"), 1e-8);
}

/// The triphasic block of docs/performance.md (1 mm cube, bottom fixed and impermeable, the top
/// compressed; `cells`^3 cells, from the prestressed Donnan state) with the friction mass
/// lumped, two steps of 2.5 s; `solver` is the body of its [solver] table.
std::string lumped_block(int cells, const std::string& solver) {
  const std::string n = std::to_string(cells);
  return "title = \"triphasic block\"\n[[mesh.box]]\nname = \"b\"\nsize = [1.0, 1.0, 1.0]\n"
         "divisions = [" +
         n + ", " + n + ", " + n +
         "]\nmaterial = \"cartilage\"\n"
         "[materials.cartilage]\ntype = \"triphasic\"\nphi_s0 = 0.25\npermeability = 1.07e-3\n"
         "fixed_charge = 2.0e-4\nd_plus = 5.0e-4\nd_minus = 8.0e-4\n"
         "[materials.cartilage.solid]\ntype = \"saint-venant-kirchhoff\"\nE = 0.3\nnu = 0.0\n"
         "[electrochemistry]\nT = 298.0\nbath_concentration = 1.5e-4\n"
         "[curves.ramp]\npoints = [[0.0, 0.0], [50.0, 1.0]]\n"
         "[[boundary.fixed]]\nset = \"b.zmin\"\n"
         "[[boundary.impermeable]]\nset = \"b.zmin\"\nnormal = \"z\"\n"
         "[[boundary.prescribed]]\nset = \"b.zmax\"\ncomponent = \"z\"\nvalue = -0.05\n"
         "curve = \"ramp\"\n"
         "[analysis]\ninitial_state = \"donnan-prestressed\"\nflux_mass = \"lumped\"\n"
         "[time]\nend_time = 5.0\ndt = 2.5\n[output]\nvtu = false\n[solver]\n" +
         solver;
}

TEST_F(CliSolvers, DrainedApproximationOfALumpedFluxMassGivesTheUmfpackHistoryInFewIterations) {
  // with the friction mass lumped the drained approximation's transport block is exact but
  // for the undrained coupling (docs/theory/solvers.md §3): few FGMRES iterations per Newton
  // iteration, and the answers of the direct solve
  std::map<std::string, History> histories;
  for (const auto& [name, solver] : std::vector<std::pair<std::string, std::string>>{
           {"umfpack", "linear_solver = \"umfpack\"\n"},
           {"krylov", "linear_solver = \"krylov\"\npreconditioner = \"amg\"\n"
                      "schur_approximation = \"drained\"\n"}}) {
    const fs::path out = output() / name;
    const Result r =
        trifem({"run", write_file("block_" + name + ".toml", lumped_block(6, solver)).string(),
                "-o", out.string()});
    ASSERT_EQ(r.exit_code, kSuccess) << r;
    histories[name] = read_history(out / "history.csv");
  }
  expect_the_same_history(histories.at("umfpack"), histories.at("krylov"), 1e-8, {"iterations"});
  const fs::path summary = output() / "krylov" / "summary.json";
  const long newton = summary_integer(summary, "newton_iterations");
  ASSERT_GT(newton, 0);
  const long linear = summary_integer(summary, "linear_iterations");
  std::cout << "FGMRES iterations per Newton iteration: " << double(linear) / double(newton)
            << "\n";
  EXPECT_LE(linear, 15 * newton); // 9-12 measured on this block from 8^3 to 30^3 cells
}

TEST_F(CliSolvers, UnknownPetscOptionIsNamed) {
  const std::string text = with_backend(read_text(kExamples / "cantilever" / "cantilever.toml"),
                                        "mumps\"\npetsc_options = \"-mat_mumps_icntl_99x 3");
  expect_invalid_input(write_file("typo.toml", text),
                       {"solver.petsc_options", "-mat_mumps_icntl_99x 3", "does not know or use"});
}

TEST_F(CliSolvers, PetscOptionsOfANonPetscBackendAreRejected) {
  const std::string text = with_backend(read_text(kExamples / "cantilever" / "cantilever.toml"),
                                        "umfpack\"\npetsc_options = \"-ksp_type gmres");
  expect_invalid_input(write_file("umfpack.toml", text),
                       {"solver.petsc_options", "linear_solver = \"umfpack\"", "(line "});
}

} // namespace
} // namespace trifem::cli_test
