#pragma once

#include <vector>

#include "nineball/ball.hpp"
#include "nineball/rules.hpp"

namespace nineball::rules {

// Nine-ball and ten-ball under WPA rules share their fouls: the lowest ball first, a pot or
// a rail after contact, and on the break the lowest ball first and a pot or four to a rail.

/// The ball on in a rotation game: the lowest numbered on the table (0 when none is left).
int lowestOnTable(const RackState& s);

/// The foul of a rotation shot (None when legal). `on` is the lowest ball on the table.
Foul rotationFoul(const RackState& s, const ShotSummary& shot, const std::vector<int>& pocketed,
                  int on, bool push_out);

/// Counts a foul, or clears the count after a legal shot; a third foul in a row turns the
/// verdict's foul into ThreeFouls.
void countFoul(RackState& s, Verdict& v);

/// The object balls that left the table this shot (every ball in shot.off_table but `cue`).
std::vector<int> jumpedObjectBalls(const ShotSummary& shot, int cue);

/// Object balls jumped off the table stay off, but the game ball, which is spotted (WPA
/// nine-ball and ten-ball: "jumped object balls are not re-spotted, except the 9 / the 10").
void jumpedStayOff(RackState& s, Verdict& v, const ShotSummary& shot, int game_ball);

/// The ball that wins a rotation rack: `wanted` (the 9, the 10), or in a custom layout without
/// it the highest number on the table.
int rotationGameBall(const std::vector<int>& on_table, int wanted);

}  // namespace nineball::rules
