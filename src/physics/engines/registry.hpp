#pragma once

#include <memory>
#include <string>
#include <vector>

#include "nineball/engine.hpp"

namespace nineball::physics {

/// An engine as makeEngine and the scene reader know it.
struct EngineDef {
  /// As scenes name it ("step": {"engine": name}).
  const char* name = "";
  std::unique_ptr<Engine> (*make)(const TableDef& table, const PhysicsParams& physics,
                                  const StepParams& step) = nullptr;
  /// The fields of "step" it reads beyond max_time (a scene that sets one it does not read is
  /// refused, naming the engines that do).
  std::vector<std::string> reads;
  /// What it lacks that those fields are for, for that message ("has no time step").
  const char* lacks = "";
};

/// Every engine, in the order EngineKind::names() gives. One line of registry.cpp an engine.
const std::vector<EngineDef>& engines();

}  // namespace nineball::physics
