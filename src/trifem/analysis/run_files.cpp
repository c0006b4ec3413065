// SPDX-License-Identifier: MIT
#include "trifem/analysis/run_files.hpp"

#include "trifem/core/error.hpp"
#include "trifem/core/interrupt.hpp"
#include "trifem/io/vtu_writer.hpp"

#include <sys/resource.h>

#include <csignal>
#include <mutex>
#include <regex>

namespace trifem::analysis {

namespace fs = std::filesystem;

namespace {

/// The summary file of the run under way on this process, empty when there is none.
struct OpenSummary {
  std::mutex mutex;
  fs::path file;
  nlohmann::json header;
};

OpenSummary& open_summary() {
  static OpenSummary s;
  return s;
}

/// Rewrites the open summary with `status` and `failure`, if there is one (never throws).
void close_summary(const std::string& status, const std::string& failure) noexcept {
  OpenSummary& s = open_summary();
  const std::lock_guard lock(s.mutex);
  if (s.file.empty())
    return;
  try {
    nlohmann::json j = s.header;
    j["status"] = status;
    j["failure"] = failure;
    j["peak_memory_mb"] = peak_memory_mb();
    write_summary_file(s.file, j);
  } catch (...) { // the disk may be full: "running" stays, as for a killed process
  }
  s.file.clear();
}

const char* signal_name(int sig) {
  return sig == SIGINT ? "SIGINT" : sig == SIGTERM ? "SIGTERM" : "a signal";
}

} // namespace

bool is_result_file_name(const std::string& name) {
  static const std::regex pattern(
      R"((results\.pvd|surfaces\.pvd|surfaces_\d{4,}\.vtu|history\.csv|history_step\d+\.csv|)"
      R"(summary\.json|run\.log|)"
      R"(volume_\d{4,}\.vtu|volume_\d{4,}\.pvtu|volume_\d{4,}_\d+\.vtu|contact\d+\.pvd|contact\d+_\d{4,}\.vtu|)"
      R"(contact\d+_surface_\d{4,}\.csv|restart_\d{4,}\.bin)(\.tmp)?)");
  return std::regex_match(name, pattern);
}

void start_output_directory(const fs::path& directory, const io::CaseSpec& spec) {
  std::error_code ec;
  fs::create_directories(directory, ec);
  TRIFEM_CHECK_OUTPUT(!ec, "cannot create the output directory {}: {}", directory.string(),
                      ec.message());
  for (const fs::directory_entry& entry : fs::directory_iterator(directory, ec)) {
    if (!entry.is_regular_file() || !is_result_file_name(entry.path().filename().string()))
      continue;
    fs::remove(entry.path(), ec);
    TRIFEM_CHECK_OUTPUT(!ec, "cannot remove the earlier result file {}: {}", entry.path().string(),
                        ec.message());
  }
  TRIFEM_CHECK_OUTPUT(!ec, "cannot read the output directory {}: {}", directory.string(),
                      ec.message());
  const nlohmann::json header = summary_header(spec, "running", "");
  write_summary_file(directory / "summary.json", header);
  {
    OpenSummary& open = open_summary();
    const std::lock_guard lock(open.mutex);
    open.file = directory / "summary.json";
    open.header = header;
  }
  interrupt::set_notice([](int sig) {
    // rewritten by the run's own summary if it ends cleanly (at its next poll)
    close_summary("interrupted",
                  fmt::format("stopped by {}; the results up to the last accepted step are kept",
                              signal_name(sig)));
  });
}

void write_final_summary(const fs::path& file, const nlohmann::json& summary) {
  interrupt::set_notice(nullptr);
  {
    OpenSummary& open = open_summary();
    const std::lock_guard lock(open.mutex);
    open.file.clear();
  }
  write_summary_file(file, summary);
}

void abandon_summary(const std::string& why) noexcept {
  interrupt::set_notice(nullptr);
  close_summary("failed", why);
}

void write_summary_file(const fs::path& file, const nlohmann::json& summary) {
  io::write_file_atomically(file, [&](std::ostream& out) { out << summary.dump(2) << '\n'; });
}

double peak_memory_mb() {
  rusage usage{};
  if (getrusage(RUSAGE_SELF, &usage) != 0)
    return 0.0;
  return static_cast<double>(usage.ru_maxrss) / 1024.0; // Linux: kilobytes
}

nlohmann::json summary_header(const io::CaseSpec& spec, const std::string& status,
                              const std::string& failure) {
  nlohmann::json j;
  j["trifem_version"] = TRIFEM_VERSION;
  j["case"] = spec.file.string();
  j["status"] = status;
  j["failure"] = failure;
  j["peak_memory_mb"] = peak_memory_mb(); // of rank 0 on several processes
  return j;
}

} // namespace trifem::analysis
