// SPDX-License-Identifier: MIT
#include "trifem/analysis/restart.hpp"

#include "trifem/analysis/explicit_step.hpp"
#include "trifem/analysis/restart_fingerprint.hpp"
#include "trifem/core/error.hpp"
#include "trifem/io/vtu_writer.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>

namespace trifem::analysis {
namespace {

constexpr char kMagic[16] = "trifem restart";
constexpr std::size_t kVersionAt = 16;     // int64
constexpr std::size_t kPayloadSizeAt = 24; // int64: bytes after the header
constexpr std::size_t kChecksumAt = 32;    // uint64
constexpr std::size_t kHeaderBytes = 40;

/// What to do about a file that is not what the case needs.
constexpr std::string_view kUseTheWritingCase = "restart with the case that wrote the file";
constexpr std::string_view kUseAnotherFile =
    "restart from another restart file of the run, or run the case again";

/// FNV-1a 64 of the header without the checksum field, then of the payload: any change of one
/// byte outside the checksum field changes it.
std::uint64_t checksum_of(std::string_view file_bytes) {
  Fnv1a64 hash;
  hash.add(file_bytes.data(), kChecksumAt);
  hash.add(file_bytes.data() + kHeaderBytes, file_bytes.size() - kHeaderBytes);
  return hash.value();
}

/// `v` with its bytes in the opposite order.
std::uint64_t byte_swapped(std::uint64_t v) {
  std::uint64_t out = 0;
  for (int i = 0; i < 8; ++i, v >>= 8)
    out = (out << 8) | (v & 0xff);
  return out;
}

template <class T>
T load(std::string_view bytes, std::size_t at) {
  T v;
  std::memcpy(&v, bytes.data() + at, sizeof v);
  return v;
}

template <class T>
void store(std::string& bytes, std::size_t at, T v) {
  std::memcpy(bytes.data() + at, &v, sizeof v);
}

/// Appends numbers and arrays to the bytes of a file (native byte order), after room for the
/// header.
class PayloadWriter {
public:
  PayloadWriter() : bytes_(kHeaderBytes, '\0') {}
  void integer(std::int64_t v) { raw(&v, sizeof v); }
  void number(double v) { raw(&v, sizeof v); }
  void numbers(const double* v, std::size_t n) {
    integer(static_cast<std::int64_t>(n));
    raw(v, n * sizeof(double));
  }
  void raw(const void* p, std::size_t bytes) { bytes_.append(static_cast<const char*>(p), bytes); }
  /// The whole file: the header (magic, version, payload size, checksum) filled in.
  std::string& sealed() {
    std::memcpy(bytes_.data(), kMagic, sizeof kMagic);
    store<std::int64_t>(bytes_, kVersionAt, kRestartFormat);
    store<std::int64_t>(bytes_, kPayloadSizeAt,
                        static_cast<std::int64_t>(bytes_.size() - kHeaderBytes));
    store<std::uint64_t>(bytes_, kChecksumAt, checksum_of(bytes_));
    return bytes_;
  }

private:
  std::string bytes_;
};

/// Reads numbers and arrays from a payload whose checksum has been verified. Every length is
/// checked against the bytes left before anything is allocated; every failure is an
/// InputError naming the file.
class PayloadReader {
public:
  PayloadReader(std::string_view payload, const std::string& file)
      : payload_(payload), file_(file) {}

  std::int64_t integer(std::string_view what) { return value<std::int64_t>(what); }
  std::uint64_t hash(std::string_view what) { return value<std::uint64_t>(what); }
  double number(std::string_view what) { return value<double>(what); }

  /// A count of items of `item_bytes` each, at most as many as the bytes left can hold.
  std::size_t count(std::string_view what, std::size_t item_bytes) {
    const std::int64_t n = integer(what);
    const std::size_t fit = left() / item_bytes;
    TRIFEM_CHECK(n >= 0 && static_cast<std::uint64_t>(n) <= fit,
                 "{}: invalid restart file: {} gives {} entries where the {} bytes left hold at "
                 "most {} ({})",
                 file_, what, n, left(), fit, kUseAnotherFile);
    return static_cast<std::size_t>(n);
  }

  /// An array of finite numbers: its length, then its values.
  std::vector<double> numbers(std::string_view what) {
    std::vector<double> v(count(what, sizeof(double)));
    if (!v.empty())
      std::memcpy(v.data(), payload_.data() + at_, v.size() * sizeof(double));
    at_ += v.size() * sizeof(double);
    const auto bad = std::find_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); });
    TRIFEM_CHECK(bad == v.end(), "{}: invalid restart file: value {} of {} is {} ({})", file_,
                 bad - v.begin() + 1, what, *bad, kUseAnotherFile);
    return v;
  }

  std::size_t left() const { return payload_.size() - at_; }

private:
  template <class T>
  T value(std::string_view what) {
    TRIFEM_CHECK(left() >= sizeof(T), "{}: invalid restart file: it ends before {} ({})", file_,
                 what, kUseAnotherFile);
    const T v = load<T>(payload_, at_);
    at_ += sizeof(T);
    return v;
  }

  std::string_view payload_;
  std::size_t at_ = 0;
  const std::string& file_;
};

/// The terms with a history, in problem order (stateless ones are skipped: the loads added
/// when a step begins may differ in number between a run and its restart).
std::vector<physics::Term*> stateful_terms(const model::Model& model) {
  std::vector<physics::Term*> out;
  for (const auto& t : model.problem->terms())
    if (!t->history().empty())
      out.push_back(t.get());
  return out;
}

void write_step(PayloadWriter& w, const StepState& step) {
  w.integer(step.active);
  if (step.active < 0)
    return;
  w.integer(static_cast<std::int64_t>(step.offsets.size()));
  for (const auto& o : step.offsets)
    w.numbers(o.data(), o.size());
  w.integer(static_cast<std::int64_t>(step.released.size()));
  for (const auto& [dof, force] : step.released) {
    w.integer(dof);
    w.number(force);
  }
}

/// The bytes of `file`: as many as the file has, so a damaged length field cannot make the
/// reader allocate more.
std::string read_file(const std::filesystem::path& file, const std::string& name) {
  std::error_code ec;
  TRIFEM_CHECK(std::filesystem::is_regular_file(file, ec),
               "{}: cannot open the restart file (no such file, or not a regular file)", name);
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  std::ifstream in(file, std::ios::binary);
  TRIFEM_CHECK(!ec && in, "{}: cannot open the restart file", name);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(size));
  TRIFEM_CHECK(in.gcount() == static_cast<std::streamsize>(size),
               "{}: cannot read the restart file", name);
  return bytes;
}

[[noreturn]] void throw_truncated(const std::string& name, std::size_t size, std::string_view why) {
  throw InputError(fmt::format("{}: the restart file is truncated or damaged: it has {} bytes, {} "
                               "({})",
                               name, size, why, kUseAnotherFile));
}

void check_magic(std::string_view bytes, const std::string& name) {
  TRIFEM_CHECK(!bytes.empty(), "{}: not a trifem restart file (the file is empty)", name);
  const std::size_t compared = std::min(bytes.size(), sizeof kMagic);
  TRIFEM_CHECK(std::memcmp(bytes.data(), kMagic, compared) == 0, "{}: not a trifem restart file",
               name);
  if (bytes.size() < kHeaderBytes)
    throw_truncated(name, bytes.size(),
                    fmt::format("less than the {}-byte header of a restart file", kHeaderBytes));
}

void check_version(std::string_view bytes, const std::string& name) {
  const auto version = load<std::int64_t>(bytes, kVersionAt);
  if (version == kRestartFormat)
    return;
  TRIFEM_CHECK(version < 1 || version > kRestartFormat,
               "{}: the restart file was written by an older trifem (restart format {}); this "
               "trifem reads format {}: continue the run with the trifem that wrote it, or run "
               "the case again with --write-restart",
               name, version, kRestartFormat);
  const auto swapped = static_cast<std::int64_t>(byte_swapped(static_cast<std::uint64_t>(version)));
  TRIFEM_CHECK(swapped < 1 || swapped > kRestartFormat,
               "{}: the restart file was written on a machine of the other byte order; restart "
               "files are read on machines of the byte order that wrote them",
               name);
  throw InputError(fmt::format("{}: the restart file has format {}, this trifem reads format {} "
                               "(a newer trifem wrote it, or it is damaged): continue the run "
                               "with the trifem that wrote it",
                               name, version, kRestartFormat));
}

/// Magic, version, size and checksum: nothing else of the file is looked at before these pass.
void check_header(std::string_view bytes, const std::string& name) {
  check_magic(bytes, name);
  check_version(bytes, name);
  const auto payload = load<std::int64_t>(bytes, kPayloadSizeAt);
  const std::size_t present = bytes.size() - kHeaderBytes;
  if (payload < 0)
    throw_truncated(name, bytes.size(), fmt::format("its header gives a size of {}", payload));
  if (static_cast<std::uint64_t>(payload) != present)
    throw_truncated(name, bytes.size(),
                    fmt::format("its header says {} bytes",
                                kHeaderBytes + static_cast<std::uint64_t>(payload)));
  TRIFEM_CHECK(load<std::uint64_t>(bytes, kChecksumAt) == checksum_of(bytes),
               "{}: the restart file is damaged: its checksum does not match its contents ({})",
               name, kUseAnotherFile);
}

/// InputError naming the parts of the case fingerprint that differ from the file's.
void check_fingerprint(PayloadReader& r, const CaseFingerprint& expected, const std::string& name) {
  std::vector<std::string_view> differing;
  for (std::size_t i = 0; i < kCaseParts; ++i)
    if (r.hash("the case fingerprint") != expected[i])
      differing.push_back(case_part_name(static_cast<CasePart>(i)));
  if (differing.empty())
    return;
  std::string parts(differing.front());
  for (std::size_t i = 1; i < differing.size(); ++i)
    parts += fmt::format("{}{}", i + 1 == differing.size() ? " and " : ", ", differing[i]);
  throw InputError(fmt::format("{}: the restart file was written for another case (it differs "
                               "from this case in its {}): {}",
                               name, parts, kUseTheWritingCase));
}

/// Time, next step and step count, checked against the run of the case.
Resume read_resume(PayloadReader& r, const io::CaseSpec& spec, const std::string& name) {
  Resume resume;
  resume.time = r.number("the time");
  resume.dt = r.number("the time step");
  const std::int64_t steps = r.integer("the step count");
  TRIFEM_CHECK(std::isfinite(resume.time) && resume.time > 0.0,
               "{}: invalid restart file: its time is t = {} s; a restart state is at a time "
               "after the start of the run ({})",
               name, resume.time, kUseAnotherFile);
  TRIFEM_CHECK(
      resume.time < spec.time.end_time * (1.0 - 1e-10),
      "{}: the restart state is at t = {} s, at or after the end of the run (time.end_time = "
      "{} s): nothing is left to run",
      name, resume.time, spec.time.end_time);
  TRIFEM_CHECK(std::isfinite(resume.dt) && resume.dt > 0.0,
               "{}: invalid restart file: its next time step is {} s, not a positive number ({})",
               name, resume.dt, kUseAnotherFile);
  TRIFEM_CHECK(steps >= 0 && steps <= INT_MAX,
               "{}: invalid restart file: its step count is {} ({})", name, steps, kUseAnotherFile);
  resume.steps = static_cast<int>(steps);
  return resume;
}

/// The state vector: one finite value per DOF of the model.
std::vector<double> read_state(PayloadReader& r, const model::Model& model,
                               const std::string& name) {
  const std::vector<double> x = r.numbers("the state vector");
  const auto dofs = static_cast<std::size_t>(model.dofs.num_dofs());
  TRIFEM_CHECK(x.size() == dofs,
               "{}: the restart file was written for a model with {} degrees of freedom, this "
               "case has {} ({})",
               name, x.size(), dofs, kUseTheWritingCase);
  return x;
}

/// The index of the active step, consistent with the case's steps and with the time.
int read_active_step(PayloadReader& r, const model::Model& model, const Resume& resume,
                     Real end_time, const std::string& name) {
  const std::int64_t k = r.integer("the active analysis step");
  const auto n = static_cast<std::int64_t>(model.steps.size());
  if (n == 0) {
    TRIFEM_CHECK(k == -1,
                 "{}: the restart file is in analysis step {} but the case has no [[step]] "
                 "tables ({})",
                 name, k + 1, kUseTheWritingCase);
    return -1;
  }
  TRIFEM_CHECK(k != -1,
               "{}: the restart file has no active analysis step but the case has {} [[step]] "
               "tables ({})",
               name, n, kUseTheWritingCase);
  TRIFEM_CHECK(k >= 0 && k < n,
               "{}: the restart file gives analysis step {} as the active one but the case has "
               "{} [[step]] tables ({})",
               name, k + 1, n, kUseTheWritingCase);
  const model::ModelStep& step = model.steps[static_cast<std::size_t>(k)];
  const Real tol = 1e-10 * std::max(1.0, end_time);
  const bool last = k + 1 == n;
  TRIFEM_CHECK(resume.time >= step.start_time - tol && (last || resume.time <= step.end_time + tol),
               "{}: the restart file is not consistent: its state at t = {} s is in analysis "
               "step {} '{}', which runs from t = {} to {} s ({})",
               name, resume.time, k + 1, step.name, step.start_time, step.end_time,
               kUseAnotherFile);
  return static_cast<int>(k);
}

/// Per DOF: held by a condition of the case or of `step` (a released reaction is not).
std::vector<char> held_in_step(const model::Model& model, const model::ModelStep& step) {
  std::vector<char> held(static_cast<std::size_t>(model.dofs.num_dofs()), 0);
  for (const auto* conditions : {&model.case_conditions, &step.conditions})
    for (const dofs::DirichletCondition& c : *conditions)
      for (const Index d : c.dofs)
        held[static_cast<std::size_t>(d)] = 1;
  return held;
}

/// The offsets of the step's conditions: as many as each relative condition has DOFs, none
/// for the others.
void read_offsets(PayloadReader& r, const model::ModelStep& step, StepState& out, std::size_t k,
                  const std::string& name) {
  const std::int64_t conditions = r.integer("the number of step conditions");
  TRIFEM_CHECK(conditions == static_cast<std::int64_t>(step.conditions.size()),
               "{}: analysis step {} of the restart file has {} conditions, the case's has {} ({})",
               name, k + 1, conditions, step.conditions.size(), kUseTheWritingCase);
  out.offsets.clear();
  for (std::size_t i = 0; i < step.conditions.size(); ++i) {
    std::vector<double> offsets = r.numbers("the offsets of a step condition");
    const std::size_t expected = step.relative[i] ? step.conditions[i].dofs.size() : 0;
    TRIFEM_CHECK(offsets.size() == expected,
                 "{}: invalid restart file: it holds {} offsets for {} (analysis step {}), which "
                 "needs {} ({})",
                 name, offsets.size(), step.keys[i], k + 1, expected, kUseAnotherFile);
    out.offsets.push_back(std::move(offsets));
  }
}

/// The reactions released when the step began: DOFs of the model, ascending, free in the step,
/// finite forces; none unless the step releases gradually.
void read_released(PayloadReader& r, const model::Model& model, const model::ModelStep& step,
                   StepState& out, std::size_t k, const std::string& name) {
  const std::size_t count =
      r.count("the number of released reactions", sizeof(std::int64_t) + sizeof(double));
  TRIFEM_CHECK(count == 0 || step.release_time > 0.0,
               "{}: invalid restart file: it holds {} released reactions for analysis step {}, "
               "which releases none gradually (release_time = {} s) ({})",
               name, count, k + 1, step.release_time, kUseAnotherFile);
  const std::vector<char> held = held_in_step(model, step);
  const std::int64_t dofs = model.dofs.num_dofs();
  out.released.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const std::int64_t dof = r.integer("a released degree of freedom");
    const double force = r.number("a released reaction");
    const std::int64_t previous = i == 0 ? -1 : out.released.back().first;
    TRIFEM_CHECK(dof > previous && dof < dofs && !held[static_cast<std::size_t>(dof)] &&
                     std::isfinite(force),
                 "{}: invalid restart file: released reaction {} is {} on degree of freedom {}, "
                 "not a finite force on a free degree of freedom of this model's {} in "
                 "ascending order ({})",
                 name, i + 1, force, dof, dofs, kUseAnotherFile);
    out.released.emplace_back(static_cast<Index>(dof), force);
  }
}

/// The histories of the model's stateful `terms`, each as long as the term's own.
std::vector<std::vector<double>> read_histories(PayloadReader& r,
                                                const std::vector<physics::Term*>& terms,
                                                const std::string& name) {
  const std::int64_t count = r.integer("the number of term histories");
  TRIFEM_CHECK(count == static_cast<std::int64_t>(terms.size()),
               "{}: the restart file has {} term histories, this case's model has {} ({})", name,
               count, terms.size(), kUseTheWritingCase);
  std::vector<std::vector<double>> histories;
  for (std::size_t i = 0; i < terms.size(); ++i) {
    histories.push_back(r.numbers("a term history"));
    const std::size_t expected = terms[i]->history().size();
    TRIFEM_CHECK(histories.back().size() == expected,
                 "{}: the restart file holds {} values for term history {}, this case's model "
                 "needs {} ({})",
                 name, histories.back().size(), i + 1, expected, kUseTheWritingCase);
  }
  return histories;
}

/// The velocity (none, or one value per DOF) and the explicit integrator's state (none, or as
/// many values as ExplicitStep::state_size of this model, in a dynamic-explicit step only).
void read_motion(PayloadReader& r, const io::CaseSpec& spec, const model::Model& model, int k,
                 Resume& resume, const std::string& name) {
  const std::vector<double> v = r.numbers("the velocity");
  const auto dofs = static_cast<std::size_t>(model.dofs.num_dofs());
  TRIFEM_CHECK(v.empty() || v.size() == dofs,
               "{}: invalid restart file: it holds {} velocities, this case's model has {} "
               "degrees of freedom ({})",
               name, v.size(), dofs, kUseTheWritingCase);
  resume.velocity = Eigen::Map<const Vector>(v.data(), static_cast<Index>(v.size()));
  resume.integrator = r.numbers("the explicit integrator's state");
  const bool in_explicit_step =
      k >= 0 ? spec.steps[static_cast<std::size_t>(k)].is_explicit() : spec.is_explicit();
  const std::size_t expected = in_explicit_step ? ExplicitStep::state_size(model) : 0;
  TRIFEM_CHECK(resume.integrator.size() == expected,
               "{}: invalid restart file: it holds {} values of the explicit integrator's state, "
               "{} analysis step needs {} ({})",
               name, resume.integrator.size(), in_explicit_step ? "its dynamic-explicit" : "its",
               expected, kUseTheWritingCase);
}

} // namespace

void write_restart(const std::filesystem::path& file, const io::CaseSpec& spec,
                   const model::Model& model, const StepState& step, const Resume& resume) {
  PayloadWriter w;
  for (const std::uint64_t part : case_fingerprint(spec, model))
    w.raw(&part, sizeof part);
  w.number(resume.time);
  w.number(resume.dt);
  w.integer(resume.steps);
  const Vector& x = model.problem->state();
  w.numbers(x.data(), static_cast<std::size_t>(x.size()));
  write_step(w, step);
  const auto terms = stateful_terms(model);
  w.integer(static_cast<std::int64_t>(terms.size()));
  for (const physics::Term* t : terms) {
    const std::vector<double> h = t->history();
    w.numbers(h.data(), h.size());
  }
  w.numbers(resume.velocity.data(), static_cast<std::size_t>(resume.velocity.size()));
  w.numbers(resume.integrator.data(), resume.integrator.size());
  const std::string& bytes = w.sealed();
  io::write_file_atomically(file, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

Resume read_restart(const std::filesystem::path& file, const io::CaseSpec& spec,
                    model::Model& model, StepState& steps) {
  const std::string name = file.string();
  const std::string bytes = read_file(file, name);
  check_header(bytes, name);
  PayloadReader r(std::string_view(bytes).substr(kHeaderBytes), name);
  check_fingerprint(r, case_fingerprint(spec, model), name);
  Resume resume = read_resume(r, spec, name);
  const std::vector<double> x = read_state(r, model, name);
  const int k = read_active_step(r, model, resume, spec.time.end_time, name);
  std::optional<StepState> step;
  if (k >= 0) {
    step.emplace();
    const model::ModelStep& described = model.steps[static_cast<std::size_t>(k)];
    read_offsets(r, described, *step, static_cast<std::size_t>(k), name);
    read_released(r, model, described, *step, static_cast<std::size_t>(k), name);
  }
  const std::vector<physics::Term*> terms = stateful_terms(model); // before the step adds any
  const std::vector<std::vector<double>> histories = read_histories(r, terms, name);
  read_motion(r, spec, model, k, resume, name);
  TRIFEM_CHECK(r.left() == 0, "{}: invalid restart file: {} bytes after its last entry ({})", name,
               r.left(), kUseAnotherFile);

  // everything checked: the model takes the state
  model.problem->set_time(resume.time);
  model.problem->set_state(Eigen::Map<const Vector>(x.data(), static_cast<Index>(x.size())));
  if (step)
    activate_step(model, static_cast<std::size_t>(k), steps, &*step);
  for (std::size_t i = 0; i < terms.size(); ++i) {
    try {
      terms[i]->restore_history(histories[i]);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
  }
  return resume;
}

} // namespace trifem::analysis
