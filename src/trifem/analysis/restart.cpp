// SPDX-License-Identifier: MIT
#include "trifem/analysis/restart.hpp"

#include "trifem/core/error.hpp"
#include "trifem/model/steps.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>

namespace trifem::analysis {
namespace {

constexpr char kMagic[16] = "trifem restart";
constexpr std::int64_t kVersion = 1;

/// Sequential binary writer of numbers and arrays (native byte order).
class Writer {
public:
  explicit Writer(std::ofstream& out) : out_(out) {}
  void integer(std::int64_t v) { raw(&v, sizeof v); }
  void number(double v) { raw(&v, sizeof v); }
  void numbers(const double* v, std::size_t n) {
    integer(static_cast<std::int64_t>(n));
    raw(v, n * sizeof(double));
  }
  void raw(const void* p, std::size_t bytes) {
    out_.write(static_cast<const char*>(p), static_cast<std::streamsize>(bytes));
  }

private:
  std::ofstream& out_;
};

/// The matching reader; every read past the end is an InputError naming the file.
class Reader {
public:
  Reader(std::ifstream& in, std::string file) : in_(in), file_(std::move(file)) {}
  std::int64_t integer() {
    std::int64_t v = 0;
    raw(&v, sizeof v);
    return v;
  }
  double number() {
    double v = 0.0;
    raw(&v, sizeof v);
    return v;
  }
  std::vector<double> numbers(std::size_t limit) {
    const std::int64_t n = integer();
    TRIFEM_CHECK(n >= 0 && static_cast<std::size_t>(n) <= limit,
                 "{}: corrupt restart file (an array of {} values where at most {} fit)", file_, n,
                 limit);
    std::vector<double> v(static_cast<std::size_t>(n));
    raw(v.data(), v.size() * sizeof(double));
    return v;
  }
  void raw(void* p, std::size_t bytes) {
    in_.read(static_cast<char*>(p), static_cast<std::streamsize>(bytes));
    TRIFEM_CHECK(in_.gcount() == static_cast<std::streamsize>(bytes),
                 "{}: the restart file is truncated", file_);
  }

private:
  std::ifstream& in_;
  std::string file_;
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

void write_step(Writer& w, const model::Model& model) {
  w.integer(model.active_step);
  if (model.active_step < 0)
    return;
  const model::ModelStep& step = model.steps[model.active_step];
  w.integer(static_cast<std::int64_t>(step.offsets.size()));
  for (const auto& o : step.offsets)
    w.numbers(o.data(), o.size());
  w.integer(static_cast<std::int64_t>(step.released.size()));
  for (const auto& [dof, force] : step.released) {
    w.integer(dof);
    w.number(force);
  }
}

void read_step(Reader& r, const std::string& file, model::Model& model, std::size_t limit) {
  const std::int64_t k = r.integer();
  TRIFEM_CHECK(k >= -1 && k < static_cast<std::int64_t>(model.steps.size()),
               "{}: the restart file is in analysis step {} but the case has {} [[step]] tables",
               file, k + 1, model.steps.size());
  if (k < 0)
    return;
  model::ModelStep restored = model.steps[k];
  const std::int64_t conditions = r.integer();
  TRIFEM_CHECK(conditions == static_cast<std::int64_t>(restored.conditions.size()),
               "{}: step {} of the restart file has {} conditions, the case's has {}", file, k + 1,
               conditions, restored.conditions.size());
  restored.offsets.clear();
  for (std::int64_t i = 0; i < conditions; ++i)
    restored.offsets.push_back(r.numbers(limit));
  const std::int64_t released = r.integer();
  TRIFEM_CHECK(released >= 0 && static_cast<std::size_t>(released) <= limit,
               "{}: corrupt restart file", file);
  restored.released.clear();
  for (std::int64_t i = 0; i < released; ++i) {
    const auto dof = static_cast<Index>(r.integer());
    restored.released.emplace_back(dof, r.number());
  }
  model::activate_step(model, static_cast<std::size_t>(k), &restored);
}

} // namespace

void write_restart(const std::filesystem::path& file, const model::Model& model,
                   const Resume& resume) {
  auto temporary = file;
  temporary += ".tmp";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      throw OutputError(fmt::format("cannot write the restart file {}", temporary.string()));
    Writer w(out);
    w.raw(kMagic, sizeof kMagic);
    w.integer(kVersion);
    w.number(resume.time);
    w.number(resume.dt);
    w.integer(resume.steps);
    const Vector& x = model.problem->state();
    w.numbers(x.data(), static_cast<std::size_t>(x.size()));
    write_step(w, model);
    const auto terms = stateful_terms(model);
    w.integer(static_cast<std::int64_t>(terms.size()));
    for (const physics::Term* t : terms) {
      const std::vector<double> h = t->history();
      w.numbers(h.data(), h.size());
    }
    if (!out.flush())
      throw OutputError(fmt::format("cannot write the restart file {}", temporary.string()));
  }
  std::error_code ec;
  std::filesystem::rename(temporary, file, ec);
  if (ec)
    throw OutputError(
        fmt::format("cannot write the restart file {}: {}", file.string(), ec.message()));
}

Resume read_restart(const std::filesystem::path& file, model::Model& model) {
  const std::string name = file.string();
  std::ifstream in(file, std::ios::binary);
  TRIFEM_CHECK(in, "{}: cannot open the restart file", name);
  Reader r(in, name);
  char magic[sizeof kMagic] = {};
  r.raw(magic, sizeof magic);
  TRIFEM_CHECK(std::memcmp(magic, kMagic, sizeof kMagic) == 0, "{}: not a trifem restart file",
               name);
  const std::int64_t version = r.integer();
  TRIFEM_CHECK(version == kVersion, "{}: restart file version {} (this trifem reads version {})",
               name, version, kVersion);
  Resume resume;
  resume.time = r.number();
  resume.dt = r.number();
  resume.steps = static_cast<int>(r.integer());
  const auto dofs = static_cast<std::size_t>(model.dofs.num_dofs());
  const std::vector<double> x = r.numbers(std::max<std::size_t>(dofs, 1u << 30));
  TRIFEM_CHECK(x.size() == dofs,
               "{}: the restart file was written for a model with {} degrees of freedom, this "
               "case has {} (restart with the case that wrote it)",
               name, x.size(), dofs);
  model.problem->set_time(resume.time);
  model.problem->set_state(Eigen::Map<const Vector>(x.data(), static_cast<Index>(x.size())));
  read_step(r, name, model, std::max<std::size_t>(dofs, 1u << 30));
  const auto terms = stateful_terms(model);
  const std::int64_t count = r.integer();
  TRIFEM_CHECK(count == static_cast<std::int64_t>(terms.size()),
               "{}: the restart file has {} term histories, this case's model has {}", name, count,
               terms.size());
  for (physics::Term* t : terms) {
    const std::vector<double> h = r.numbers(dofs * 16 + 1024);
    try {
      t->restore_history(h);
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: {}", name, e.what()));
    }
  }
  return resume;
}

} // namespace trifem::analysis
