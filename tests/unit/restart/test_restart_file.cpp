// SPDX-License-Identifier: MIT
// Restart files (format 3) read in-process, from a file written in the second step of a
// two-step biphasic case (so it holds offsets, released reactions and element histories):
// - the intact file restores the written state, step and histories exactly;
// - 1000 random single-byte corruptions and every truncation are rejected, each with an
//   InputError whose message starts with the file's path;
// - values damaged consistently (checksum resealed, as another program could write them) are
//   rejected by the checks behind the checksum, with what is wrong;
// - a file of another case names the part of the case that differs, while the settings that do
//   not change the state (title, output, solver, time steps, end of the run) are accepted.
#include "restart_file_layout.hpp"
#include "trifem/analysis/restart.hpp"
#include "trifem/analysis/run.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/case_reader.hpp"
#include "trifem/linalg/linear_solver.hpp"
#include "trifem/model/model.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace trifem {
namespace {

namespace fs = std::filesystem;
using test::get;
using test::put;
using test::reseal;
using test::restart_layout;
using test::RestartLayout;

/// `text` with its one occurrence of `from` replaced by `to`.
std::string replaced(std::string_view text, std::string_view from, std::string_view to) {
  std::string out(text);
  const auto at = out.find(from);
  if (at == std::string::npos || out.find(from, at + 1) != std::string::npos)
    throw std::invalid_argument("the case text has not exactly one '" + std::string(from) + "'");
  return out.replace(at, from.size(), to);
}

/// The two-step case of tests/cli/data/restart_steps.toml with a biphasic tissue: a block
/// pressed down (step 1), then released over 0.5 s while its top is sheared relative to the
/// pressed state (step 2). A restart file of step 2 holds the offsets of the relative condition,
/// the released reactions and the mixture's element histories.
std::string case_text() {
  std::ifstream in(fs::path(TRIFEM_SOURCE_DIR) / "tests" / "cli" / "data" / "restart_steps.toml");
  const std::string solid{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return replaced(solid, "type = \"neo-hookean\"\nE = 1.0\nnu = 0.3\n",
                  "type = \"biphasic\"\nphi_s0 = 0.2\npermeability = 1.0e-3\n"
                  "[materials.tissue.solid]\ntype = \"neo-hookean\"\nE = 1.0\nnu = 0.3\n");
}

constexpr double kWrittenAfter = 1.5; ///< the file is written at the first step after this

io::CaseSpec spec_of(std::string_view text) {
  return io::parse_case(text, "restart_case.toml");
}

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_bytes(const fs::path& file, std::string_view bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// The histories of the model's terms that have one, in problem order.
std::vector<std::vector<double>> histories_of(const model::Model& model) {
  std::vector<std::vector<double>> out;
  for (const auto& t : model.problem->terms())
    if (!t->history().empty())
      out.push_back(t->history());
  return out;
}

/// What the run held when it wrote the file.
struct Written {
  analysis::Resume resume;
  std::vector<double> state;
  int active_step = -1;
  std::vector<std::vector<Real>> offsets;
  std::vector<std::pair<Index, Real>> released;
  std::vector<std::vector<double>> histories;
};

/// Runs `spec` as `trifem run` does and writes `file` at the first step after kWrittenAfter.
Written run_and_write(const io::CaseSpec& spec, const fs::path& file) {
  const std::unique_ptr<model::Model> model = model::build_model(spec);
  solver::NewtonSolver newton(analysis::newton_settings(spec.solver),
                              linalg::make_linear_solver(spec.solver.linear_solver));
  analysis::StepState steps = analysis::start_steps(*model);
  solver::Linearization initial;
  model->problem->linearize(initial, false);
  const solver::StepController* controller = nullptr;
  std::optional<Written> written;
  const solver::RunReport report = analysis::run_steps(
      spec, *model, steps, newton,
      [&](const solver::StepInfo& info) {
        if (written || info.time <= kWrittenAfter)
          return;
        const analysis::Resume resume{info.time, controller->dt(), info.step};
        analysis::write_restart(file, spec, *model, steps, resume);
        const Vector& x = model->problem->state();
        written = Written{resume,         {x.data(), x.data() + x.size()},
                          steps.active,   steps.offsets,
                          steps.released, histories_of(*model)};
      },
      [&](const solver::StepController& c) { controller = &c; });
  if (!report.success || !written)
    throw std::runtime_error("the restart case did not run: " + report.failure);
  return *written;
}

/// Every restart file test works in its own directory with the file of the run of case_text().
class RestartFile : public testing::Test {
protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("trifem_test_restart_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    spec_ = new io::CaseSpec(spec_of(case_text()));
    written_ = new Written(run_and_write(*spec_, file()));
    bytes_ = new std::string(read_bytes(file()));
  }
  static void TearDownTestSuite() {
    delete spec_;
    delete written_;
    delete bytes_;
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  static fs::path file() { return dir_ / "restart.bin"; }
  static fs::path damaged() { return dir_ / "damaged.bin"; }

  /// The message of the InputError with which reading `bytes` (as damaged()) into a fresh model
  /// of `spec` fails, checked to start with the file's path; nullopt if the file is accepted.
  static std::optional<std::string> rejection(const std::string& bytes,
                                              const io::CaseSpec& spec = *spec_) {
    write_bytes(damaged(), bytes);
    return rejection_of(damaged(), spec);
  }

  static std::optional<std::string> rejection_of(const fs::path& file, const io::CaseSpec& spec) {
    const std::unique_ptr<model::Model> model = model::build_model(spec);
    try {
      analysis::StepState steps;
      analysis::read_restart(file, spec, *model, steps);
      return std::nullopt;
    } catch (const InputError& e) {
      const std::string message = e.what();
      EXPECT_TRUE(message.starts_with(file.string() + ": ")) << message;
      return message;
    }
  }

  static fs::path dir_;
  static io::CaseSpec* spec_;
  static Written* written_;
  static std::string* bytes_;
};

fs::path RestartFile::dir_;
io::CaseSpec* RestartFile::spec_ = nullptr;
Written* RestartFile::written_ = nullptr;
std::string* RestartFile::bytes_ = nullptr;

TEST_F(RestartFile, HoldsEverySectionOfAStateInALaterStep) {
  const RestartLayout l = restart_layout(*bytes_);
  EXPECT_EQ(get<std::int64_t>(*bytes_, RestartLayout::kVersion), analysis::kRestartFormat);
  EXPECT_EQ(get<std::int64_t>(*bytes_, l.active_step), 1);
  ASSERT_EQ(l.offsets.size(), 1u);
  EXPECT_EQ(get<std::int64_t>(*bytes_, l.offsets[0]), 9) << "the 3 x 3 top nodes' x";
  EXPECT_EQ(get<std::int64_t>(*bytes_, l.released_count), 9) << "the top nodes' z reactions";
  ASSERT_EQ(l.histories.size(), 1u);
  EXPECT_EQ(get<std::int64_t>(*bytes_, l.histories[0]), 6 * 8) << "6 numbers per mixture cell";
}

TEST_F(RestartFile, AnIntactFileRestoresTheWrittenStateExactly) {
  const std::unique_ptr<model::Model> model = model::build_model(*spec_);
  analysis::StepState steps;
  const analysis::Resume resume = analysis::read_restart(file(), *spec_, *model, steps);
  EXPECT_EQ(resume.time, written_->resume.time);
  EXPECT_EQ(resume.dt, written_->resume.dt);
  EXPECT_EQ(resume.steps, written_->resume.steps);
  const Vector& x = model->problem->state();
  EXPECT_EQ(std::vector<double>(x.data(), x.data() + x.size()), written_->state);
  EXPECT_EQ(steps.active, written_->active_step);
  EXPECT_EQ(steps.offsets, written_->offsets);
  EXPECT_EQ(steps.released, written_->released);
  EXPECT_EQ(histories_of(*model), written_->histories);
}

TEST_F(RestartFile, EverySingleByteCorruptionIsRejected) {
  constexpr int kCorruptions = 1000;
  std::mt19937_64 random(20261128);
  std::uniform_int_distribution<std::size_t> position(0, bytes_->size() - 1);
  std::uniform_int_distribution<int> flip(1, 255); // XOR with 1..255: always another byte
  std::map<std::string, int> by_check;             // what rejected them, for the report below
  int rejected = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kCorruptions; ++i) {
    std::string bytes = *bytes_;
    const std::size_t at = position(random);
    bytes[at] = static_cast<char>(static_cast<unsigned char>(bytes[at]) ^ flip(random));
    ASSERT_NE(bytes, *bytes_);
    if (const auto message = rejection(bytes)) {
      ++rejected;
      ++by_check[message->substr(damaged().string().size() + 2, 40)];
    } else {
      ADD_FAILURE() << "the file with byte " << at << " changed was accepted";
    }
  }
  EXPECT_EQ(rejected, kCorruptions);
  std::cout << rejected << " of " << kCorruptions << " single-byte corruptions of a "
            << bytes_->size() << "-byte file rejected in "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s; messages:\n";
  for (const auto& [message, count] : by_check)
    std::cout << "  " << count << " x " << message << "...\n";
}

TEST_F(RestartFile, EveryTruncationIsRejected) {
  std::size_t rejected = 0;
  for (std::size_t size = 0; size < bytes_->size(); ++size)
    if (rejection(bytes_->substr(0, size)))
      ++rejected;
    else
      ADD_FAILURE() << "the file truncated to " << size << " bytes was accepted";
  EXPECT_EQ(rejected, bytes_->size());
}

/// A consistently damaged file: `edit` changes the bytes (with the layout of the intact file),
/// then the header is resealed unless `keep_header`.
struct Damage {
  std::string what;
  std::function<void(std::string&, const RestartLayout&)> edit;
  std::string expected; ///< a fragment of the message
  bool keep_header = false;
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Removes `values` numbers after the length field at `at` and lowers the length by as many.
void shorten(std::string& bytes, std::size_t at, std::int64_t values) {
  const auto n = get<std::int64_t>(bytes, at);
  put<std::int64_t>(bytes, at, n - values);
  bytes.erase(at + 8 + 8 * static_cast<std::size_t>(n - values),
              8 * static_cast<std::size_t>(values));
}

TEST_F(RestartFile, ConsistentlyDamagedValuesAreRejectedWithWhatIsWrong) {
  const Index held = model::build_model(*spec_)->case_conditions.at(0).dofs.at(0);
  const std::vector<Damage> damages = {
      {"time 0", [](auto& b, auto&) { put(b, RestartLayout::kTime, 0.0); }, "its time is t = 0 s"},
      {"time NaN", [](auto& b, auto&) { put(b, RestartLayout::kTime, kNaN); },
       "its time is t = nan s"},
      {"time at the end", [](auto& b, auto&) { put(b, RestartLayout::kTime, 2.0); },
       "nothing is left to run"},
      {"time beyond the end", [](auto& b, auto&) { put(b, RestartLayout::kTime, 1e300); },
       "nothing is left to run"},
      {"dt NaN", [](auto& b, auto&) { put(b, RestartLayout::kDt, kNaN); },
       "its next time step is nan s"},
      {"dt 0", [](auto& b, auto&) { put(b, RestartLayout::kDt, 0.0); },
       "its next time step is 0 s"},
      {"steps -1", [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kSteps, -1); },
       "its step count is -1"},
      {"state length 2^29",
       [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kStateLength, 1 << 29); },
       "the state vector gives 536870912 entries where the"},
      {"state length -1",
       [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kStateLength, -1); },
       "the state vector gives -1 entries"},
      {"state one value short", [](auto& b, auto&) { shorten(b, RestartLayout::kStateLength, 1); },
       "degrees of freedom"},
      {"state value NaN", [](auto& b, auto&) { put(b, RestartLayout::kStateLength + 8, kNaN); },
       "value 1 of the state vector is nan"},
      {"active step 1 instead of 2",
       [](auto& b, auto& l) { put<std::int64_t>(b, l.active_step, 0); },
       "is in analysis step 1 'press', which runs from t = 0 to 1 s"},
      {"active step 3", [](auto& b, auto& l) { put<std::int64_t>(b, l.active_step, 2); },
       "analysis step 3 as the active one but the case has 2 [[step]] tables"},
      {"no active step", [](auto& b, auto& l) { put<std::int64_t>(b, l.active_step, -1); },
       "no active analysis step but the case has 2 [[step]] tables"},
      {"two conditions", [](auto& b, auto& l) { put<std::int64_t>(b, l.offsets[0] - 8, 2); },
       "has 2 conditions, the case's has 1"},
      {"offsets emptied", [](auto& b, auto& l) { shorten(b, l.offsets[0], 9); },
       "holds 0 offsets for step[2].boundary.prescribed"},
      {"offsets one short", [](auto& b, auto& l) { shorten(b, l.offsets[0], 1); },
       "holds 8 offsets for step[2].boundary.prescribed"},
      {"offset NaN", [](auto& b, auto& l) { put(b, l.offsets[0] + 8, kNaN); },
       "value 1 of the offsets of a step condition is nan"},
      {"released count 2^40",
       [](auto& b, auto& l) { put<std::int64_t>(b, l.released_count, std::int64_t{1} << 40); },
       "the number of released reactions gives 1099511627776 entries"},
      {"released DOF 1e9",
       [](auto& b, auto& l) { put<std::int64_t>(b, l.released_count + 8, 1'000'000'000); },
       "released reaction 1 is"},
      {"released DOF -5", [](auto& b, auto& l) { put<std::int64_t>(b, l.released_count + 8, -5); },
       "released reaction 1 is"},
      {"released DOF held by the case",
       [held](auto& b, auto& l) { put<std::int64_t>(b, l.released_count + 8, held); },
       "released reaction 1 is"},
      {"released DOF repeated",
       [](auto& b, auto& l) {
         put(b, l.released_count + 24, get<std::int64_t>(b, l.released_count + 8));
       },
       "released reaction 2 is"},
      {"released force NaN", [](auto& b, auto& l) { put(b, l.released_count + 16, kNaN); },
       "released reaction 1 is nan"},
      {"history one value short", [](auto& b, auto& l) { shorten(b, l.histories[0], 1); },
       "holds 47 values for term history 1, this case's model needs 48"},
      {"history value inf",
       [](auto& b, auto& l) {
         put(b, l.histories[0] + 8, std::numeric_limits<double>::infinity());
       },
       "value 1 of a term history is inf"},
      {"two histories", [](auto& b, auto& l) { put<std::int64_t>(b, l.histories_count, 2); },
       "has 2 term histories, this case's model has 1"},
      {"one velocity",
       [](auto& b, auto& l) {
         put<std::int64_t>(b, l.velocity, 1);
         b.insert(l.velocity + 8, 8, '\0');
       },
       "invalid restart file: it holds 1 velocities, this case's model has"},
      {"an explicit integrator's state in a quasi-static step",
       [](auto& b, auto& l) {
         put<std::int64_t>(b, l.integrator, 1);
         b.append(8, '\0');
       },
       "holds 1 values of the explicit integrator's state, its analysis step needs 0"},
      {"bytes after the end", [](auto& b, auto&) { b.append(8, '\0'); },
       "8 bytes after its last entry"},
      {"magic", [](auto& b, auto&) { b[3] = 'X'; }, "not a trifem restart file", true},
      {"format 1", [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kVersion, 1); },
       "was written by an older trifem (restart format 1); this trifem reads format 3", true},
      {"format 2", [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kVersion, 2); },
       "was written by an older trifem (restart format 2); this trifem reads format 3", true},
      {"format 4", [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kVersion, 4); },
       "has format 4, this trifem reads format 3", true},
      {"other byte order",
       [](auto& b, auto&) { put<std::int64_t>(b, RestartLayout::kVersion, std::int64_t{2} << 56); },
       "other byte order", true},
      {"payload size + 1",
       [](auto& b, auto&) {
         put(b, RestartLayout::kPayloadSize, get<std::int64_t>(b, RestartLayout::kPayloadSize) + 1);
       },
       "truncated or damaged", true},
      {"checksum", [](auto& b, auto&) { b[RestartLayout::kChecksum] ^= 1; },
       "is damaged: its checksum does not match its contents", true},
      {"one state value", [](auto& b, auto&) { b[RestartLayout::kStateLength + 12] ^= 4; },
       "is damaged: its checksum does not match its contents", true},
  };
  const RestartLayout layout = restart_layout(*bytes_);
  for (const Damage& d : damages) {
    SCOPED_TRACE(d.what);
    std::string bytes = *bytes_;
    d.edit(bytes, layout);
    if (!d.keep_header)
      reseal(bytes);
    const std::optional<std::string> message = rejection(bytes);
    ASSERT_TRUE(message) << "accepted";
    EXPECT_NE(message->find(d.expected), std::string::npos) << *message;
  }
}

TEST_F(RestartFile, AChangedFingerprintNamesThePartThatDiffers) {
  const std::vector<std::string> parts = {
      "mesh",          "degrees of freedom", "materials",      "boundary conditions",
      "contact pairs", "rigid bodies",       "analysis steps", "analysis options"};
  ASSERT_EQ(parts.size(), RestartLayout::kFingerprintParts);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    SCOPED_TRACE(parts[i]);
    std::string bytes = *bytes_;
    bytes[RestartLayout::kFingerprint + 8 * i] ^= 1;
    reseal(bytes);
    const std::optional<std::string> message = rejection(bytes);
    ASSERT_TRUE(message) << "accepted";
    EXPECT_NE(message->find("the restart file was written for another case (it differs from this "
                            "case in its " +
                            parts[i] + "): restart with the case that wrote the file"),
              std::string::npos)
        << *message;
  }
}

/// A case like case_text() with one change, and the parts of the fingerprint a restart names.
struct OtherCase {
  std::string what;
  std::string from, to;
  std::string named; ///< "(it differs from this case in its <named>)"
};

TEST_F(RestartFile, ACaseThatDiffersInWhatTheStateDependsOnIsNamed) {
  const std::vector<OtherCase> others = {
      {"E x 100", "E = 1.0", "E = 100.0", "materials"},
      {"nu", "nu = 0.3", "nu = 0.25", "materials"},
      {"permeability", "permeability = 1.0e-3", "permeability = 2.0e-3", "materials"},
      {"other geometry, same DOF count", "size = [1.0, 1.0, 1.0]", "size = [3.0, 3.0, 0.5]",
       "mesh"},
      {"another fixed condition", "[curves.ramp]",
       "[[boundary.fixed]]\nset = \"block.xmin\"\ncomponents = [\"y\"]\n\n[curves.ramp]",
       "degrees of freedom and boundary conditions"},
      {"another curve", "[2.0, 2.0]]", "[2.0, 3.0]]", "boundary conditions"},
      {"another step load", "value = -0.1", "value = -0.2", "analysis steps"},
      {"another release time", "release_time = 0.5", "release_time = 0.25", "analysis steps"},
      {"another step start", "end_time = 1.0", "end_time = 1.25", "analysis steps"},
      {"lumped flux mass", "[[mesh.box]]", "[analysis]\nflux_mass = \"lumped\"\n\n[[mesh.box]]",
       "analysis options"},
  };
  for (const OtherCase& o : others) {
    SCOPED_TRACE(o.what);
    const io::CaseSpec other = spec_of(replaced(case_text(), o.from, o.to));
    const std::optional<std::string> message = rejection_of(file(), other);
    ASSERT_TRUE(message) << "accepted";
    EXPECT_NE(message->find("written for another case (it differs from this case in its " +
                            o.named + ")"),
              std::string::npos)
        << *message;
  }
}

TEST_F(RestartFile, SettingsThatDoNotChangeTheStateAreNotPartOfTheFingerprint) {
  const std::vector<OtherCase> others = {
      {"title", "restart steps case", "another title", ""},
      {"output", "[output]\ninterval = 0.25", "[output]\ninterval = 0.5\nvtu = false", ""},
      {"solver", "[[mesh.box]]",
       "[solver]\nresidual_tolerance = 1e-10\nlinear_solver = \"sparselu\"\n\n[[mesh.box]]", ""},
      {"time steps", "dt = 0.25\nrelease_time", "dt = 0.1\nrelease_time", ""},
      {"a later end of the run", "end_time = 2.0", "end_time = 3.0", ""},
  };
  for (const OtherCase& o : others) {
    SCOPED_TRACE(o.what);
    const io::CaseSpec other = spec_of(replaced(case_text(), o.from, o.to));
    const std::unique_ptr<model::Model> model = model::build_model(other);
    analysis::StepState steps;
    EXPECT_NO_THROW(analysis::read_restart(file(), other, *model, steps));
    const Vector& x = model->problem->state();
    EXPECT_EQ(std::vector<double>(x.data(), x.data() + x.size()), written_->state);
  }
}

} // namespace
} // namespace trifem
