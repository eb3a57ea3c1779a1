#pragma once

#include "nineball/engine.hpp"
#include "physics/model/search_work.hpp"

// What the library's own engines show beyond the public Engine: the arcs a trace is sampled
// from, and the work of the event search. Implementation, kept out of include/nineball.
namespace nineball::physics {

class ArcLog;

/// Implemented by every engine makeEngine makes, beside Engine.
class EngineInternals {
 public:
  virtual ~EngineInternals() = default;
  /// Keeps every arc each ball follows from here on, for a trace (call before addBall).
  virtual void logArcs() = 0;
  /// The arcs kept since logArcs(), or null.
  virtual const ArcLog* arcLog() const = 0;
  virtual SearchWork searchWork() const = 0;
};

/// The internals of an engine makeEngine made; throws std::logic_error for any other.
EngineInternals& internals(Engine& engine);
const EngineInternals& internals(const Engine& engine);

}  // namespace nineball::physics
