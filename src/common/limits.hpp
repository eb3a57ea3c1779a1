#pragma once

#include <cstddef>

/// The ranges every input is held to, each from the physics of a pool table or from what the
/// solver can hold exactly. Parsing, validation, the stress test and the fuzz test all read
/// them from here, so that what is accepted is what is tested.
namespace nineball::limits {

/// m: 1-10 cm takes in every cue sport's ball (snooker 26 mm, pool 28.6 mm, carom 30.8 mm,
/// Russian 34 mm) with room on both sides.
constexpr double kMinBallRadius = 0.01;
constexpr double kMaxBallRadius = 0.1;
/// kg: 10 g-1 kg (a snooker ball is 142 g, a carom ball 210 g). The ratio of 100 between the
/// lightest and heaviest ball is what any kiss can amplify a speed by.
constexpr double kMinBallMass = 0.01;
constexpr double kMaxBallMass = 1.0;
/// m/s: just above the fastest power breaks measured (11-13 m/s), which no cue exceeds, so
/// that the paper's own worked impulse (13.3 m/s) still runs.
constexpr double kMaxSpeed = 14.0;
/// m, the highest a scene may set a ball above the cloth ("z"): far above any jump.
constexpr double kMaxBallHeight = 2.0;
/// m/s: R |w| of a strike at the ball's very edge at the top speed (w = 5 v b / 2 R^2, b = R).
constexpr double kMaxSurfaceSpeed = 2.5 * kMaxSpeed;

/// The speed-dependent cushion's restitution curve e(V) = base + slope V + quadratic V^2: a
/// slope of 1 s/m (or a quadratic term of 1 s^2/m^2) moves e across its whole range [0, 1] in
/// 1 m/s, four times the steepest published fit (Han 2005: 0.257 s/m, -0.044 s^2/m^2).
constexpr double kMaxRestitutionSlope = 1.0;
constexpr double kMaxRestitutionQuadratic = 1.0;
/// s: a ball stays in a cushion for milliseconds; 0.1 s, ten times the default, would join
/// cushions a ball meets a slow roll apart.
constexpr double kMaxCushionContactTime = 0.1;
/// m: a struck ball this near a cushion counts as frozen to it at most (a fifth of a pool
/// ball's radius); further off, the ball travels to the cushion as a contact of its own.
constexpr double kMaxFrozenTolerance = 0.006;

/// m: twice a 12 ft snooker table; beyond it the float coordinates Box2D keeps lose the
/// micrometres the contact search works in.
constexpr double kMaxTableLength = 10.0;
/// Each rail between two pockets is at least a ball's diameter long, so that a ball can rest
/// against it; the table's width follows from it (two corner mouths and a rail).
constexpr double kMinRailInDiameters = 1.0;

/// Box2D units per metre. Below 10 a ball's radius is less than 60 times Box2D's linear slop
/// (5 mm of units) and the chain's skin; above 1000 a table's corner lies 1,270 units out,
/// where a float keeps only 0.1 mm of units and every piece is 1.5 mm long.
constexpr double kMinScale = 10.0;
constexpr double kMaxScale = 1000.0;
/// So a ball is at least 0.1 Box2D units in radius (20 times the linear slop).
constexpr double kMinBallUnits = kMinBallRadius * kMinScale;
/// 1/s: the base step rate. Every piece already ends at the next event, so a finer rate adds
/// cost and no accuracy; 2000 Hz is the plain baseline's rate.
constexpr double kMinHz = 1.0;
constexpr double kMaxHz = 2000.0;
/// s: the longest run, with "until" or to rest.
constexpr double kMaxSimTime = 3600.0;

/// The work one run may do: contacts resolved and pieces stepped. A run that reaches either
/// stops there with a partial result (exit status 3), never silently.
constexpr long kMaxEvents = 2'000'000;
constexpr long kMaxPieces = 20'000'000;

/// A trace's rate (samples per second per ball) and its size in all (balls x instants): at the
/// bound a result is 196 MB of JSON (91 MB compact) and its run peaks under 1 GB of memory,
/// whatever the run; a run that would need more keeps its earliest instants.
constexpr double kMinTraceHz = 1.0;
constexpr double kMaxTraceHz = 10000.0;
constexpr std::size_t kMaxTraceSamples = 1'000'000;

/// Input sizes: balls in a scene, bytes in a document, characters of a key quoted in a message.
constexpr std::size_t kMaxBalls = 200;
constexpr std::size_t kMaxInputBytes = 4u << 20;
constexpr std::size_t kMaxQuotedChars = 40;

/// Recorded shots (`nineball fit`, `calibrate`): a file of them, and one ball's samples. 182
/// three-cushion shots tracked at 50 Hz are about 10 MB of JSON; a ball tracked at 1000 Hz
/// for ten minutes is 600,000 samples.
constexpr std::size_t kMaxRecordingBytes = 256u << 20;
constexpr std::size_t kMaxRecordedSamples = 1'000'000;

}  // namespace nineball::limits
