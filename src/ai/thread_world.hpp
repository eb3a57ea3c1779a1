#pragma once

#include <cstdint>

#include "nineball/engine.hpp"

namespace nineball::ai {

/// A new owner's number for worldForThisThread (an evaluator or a judge of one position).
std::uint64_t newWorldOwner();

/// This thread's world for `owner`, empty: made for the first call of an owner on a thread,
/// reset on the next ones. Building the table for each of thousands of candidates cost a
/// twentieth of the search; a reset engine is a new one to the bit, so which thread ran a
/// candidate changes nothing.
Engine& worldForThisThread(std::uint64_t owner, const TableDef& table, const PhysicsParams& physics,
                           const StepParams& step);

}  // namespace nineball::ai
