#include "common/log.hpp"

#include <spdlog/sinks/stdout_color_sinks.h>

#include <mutex>

namespace nineball {
namespace {

std::mutex& registryMutex() {
  static std::mutex m;
  return m;
}

spdlog::level::level_enum& currentLevel() {
  static spdlog::level::level_enum level = spdlog::level::warn;
  return level;
}

}  // namespace

std::shared_ptr<spdlog::logger> logger(const std::string& name) {
  std::lock_guard<std::mutex> lock(registryMutex());
  const std::string full = "nineball." + name;
  if (auto existing = spdlog::get(full)) return existing;
  auto created = spdlog::stderr_color_mt(full);
  created->set_level(currentLevel());
  created->set_pattern("[%n] %l: %v");
  return created;
}

spdlog::logger& physicsLogger() {
  static const std::shared_ptr<spdlog::logger> kept = logger("physics");
  return *kept;
}

bool setLogLevel(const std::string& level) {
  const auto parsed = spdlog::level::from_str(level);
  // from_str maps anything unknown to "off", so only accept "off" when it was asked for.
  if (parsed == spdlog::level::off && level != "off") return false;
  std::lock_guard<std::mutex> lock(registryMutex());
  currentLevel() = parsed;
  spdlog::apply_all([parsed](const std::shared_ptr<spdlog::logger>& l) { l->set_level(parsed); });
  return true;
}

}  // namespace nineball
