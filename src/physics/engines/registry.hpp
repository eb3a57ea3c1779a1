#pragma once

#include <memory>
#include <optional>
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
  /// Its own settings on this table that it cannot run, as a message naming the field (what
  /// Box2D would assert on); null for an engine that can run any.
  std::optional<std::string> (*check)(const TableGeometry& table, const StepParams& step) = nullptr;
};

/// Every engine, in the order EngineKind::names() gives. One line of registry.cpp an engine.
const std::vector<EngineDef>& engines();

}  // namespace nineball::physics
