// SPDX-License-Identifier: MIT
#include "trifem/core/log.hpp"

#include "trifem/core/error.hpp"

#include <spdlog/sinks/basic_file_sink.h>
#include <spdlog/sinks/stdout_color_sinks.h>

namespace trifem::log {

void configure(Level level) {
  auto logger = spdlog::stdout_color_mt("trifem");
  logger->set_pattern("%v");
  switch (level) {
  case Level::Silent: // the processes of a parallel run other than rank 0
    logger->set_level(spdlog::level::off);
    break;
  case Level::Quiet:
    logger->set_level(spdlog::level::warn);
    break;
  case Level::Normal:
    logger->set_level(spdlog::level::info);
    break;
  case Level::Verbose:
    logger->set_level(spdlog::level::debug);
    break;
  }
  spdlog::set_default_logger(logger);
}

void add_file(const std::string& path) {
  std::shared_ptr<spdlog::sinks::basic_file_sink_mt> sink;
  try {
    sink = std::make_shared<spdlog::sinks::basic_file_sink_mt>(path, true);
  } catch (const spdlog::spdlog_ex& e) {
    throw OutputError(fmt::format("cannot write the log file {}: {}", path, e.what()));
  }
  sink->set_pattern("%v");
  sink->set_level(spdlog::level::debug);
  spdlog::default_logger()->sinks().push_back(sink);
  spdlog::default_logger()->flush_on(spdlog::level::info);
}

} // namespace trifem::log
