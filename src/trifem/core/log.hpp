// SPDX-License-Identifier: MIT
// Logging: a thin wrapper around spdlog so that modules do not configure sinks themselves.
#pragma once

#include <spdlog/spdlog.h>
#include <string>

namespace trifem::log {

/// Verbosity of the console log.
enum class Level { Silent, Quiet, Normal, Verbose };

/// Configures the global console logger (called once by the application).
void configure(Level level);

/// Adds a plain-text log file sink (e.g. results/run.log); every later message also goes there.
/// OutputError if the file cannot be opened.
void add_file(const std::string& path);

using spdlog::debug;
using spdlog::error;
using spdlog::info;
using spdlog::warn;

} // namespace trifem::log
