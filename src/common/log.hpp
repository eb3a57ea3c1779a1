#pragma once

#include <spdlog/spdlog.h>

#include <memory>
#include <string>

namespace nineball {

/// A named logger ("physics", "sim", "app", ...) writing to stderr; created on first use with
/// the level set by setLogLevel (warn until then: quiet by default).
std::shared_ptr<spdlog::logger> logger(const std::string& name);

/// The physics' logger ("physics"), looked up once and kept: its calls sit on the simulation's
/// hot paths (an event each), where logger()'s lock would serialise threads simulating side by
/// side.
spdlog::logger& physicsLogger();

/// Sets the level of every nineball logger, present and future. Returns false for an unknown
/// level name (trace, debug, info, warn, error, critical, off).
bool setLogLevel(const std::string& level);

}  // namespace nineball
