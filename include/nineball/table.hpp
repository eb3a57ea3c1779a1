#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "nineball/pocket_id.hpp"
#include "nineball/vec2.hpp"

namespace nineball {

/// Which lines and spots are drawn on a table's cloth (table_markings.hpp).
enum class TableMarks {
  Pool,     ///< the head string and the foot spot
  Snooker,  ///< the baulk line, the D and the six colour spots
};

/// Size of a table's playing surface and its pocket mouths, in metres. Origin at the centre,
/// x along the length, y across. The cushion noses lie on x = +-length/2 and y = +-width/2.
struct TableDef {
  double length = 2.54;           ///< between the long-axis cushion noses (9 ft table)
  double width = 1.27;            ///< between the short-axis cushion noses
  double corner_pocket = 0.116;   ///< corner mouth, jaw point to jaw point (WPA 114-117 mm)
  double side_pocket = 0.129;     ///< side mouth, jaw point to jaw point (WPA 127-130 mm)
  double corner_jaw_deg = 142.0;  ///< angle between cushion nose and jaw face (WPA 142 +-1)
  double side_jaw_deg = 104.0;    ///< the same for the side pockets (WPA 103-104)
  /// Radius of the knuckle through which the cushion nose turns into a corner pocket's jaw
  /// (a snooker table's rounded jaw); 0 is a sharp jaw point, as on a pool table. The mouth
  /// above is then measured between the points where nose and jaw lines would meet.
  double corner_jaw_radius = 0.0;
  double side_jaw_radius = 0.0;  ///< the same for the side (middle) pockets
  /// False for a table without pockets (carom): four straight cushions, and the pocket
  /// fields above are not read.
  bool pockets = true;
  TableMarks marks = TableMarks::Pool;

  static TableDef nineFoot() { return {}; }
  static TableDef eightFoot() { return {2.34, 1.17}; }
  static TableDef sevenFoot() { return {1.98, 0.99}; }
  /// A carom match table (UMB: 2.84 x 1.42 m between the cushion noses), no pockets.
  static TableDef carom();
  /// A small carom table (2.10 x 1.05 m), no pockets.
  static TableDef caromSmall();
  /// A snooker table (WPBSA: 3569 x 1778 mm between the cushion noses), rounded jaws.
  static TableDef snooker();
  /// A 10 ft snooker table: the full-size table's proportions at 10/12 the size.
  static TableDef snookerTenFoot();
  /// A table by the name scenes, scripts and --table give it (names()); nothing for another.
  static std::optional<TableDef> named(const std::string& name);
  /// Every named table, pool's first: "9ft", "8ft", "7ft", "carom", "carom-small", "snooker",
  /// "snooker-10ft".
  static std::vector<std::string> names();
};

/// "top-left", "top-side", ... (top = +y, right = +x).
const char* pocketName(PocketId id);
std::optional<PocketId> pocketFromName(const std::string& name);

/// One pocket as built: the mouth between its two jaw points, and the drop circle. A ball
/// is pocketed once its centre is inside the drop circle.
struct Pocket {
  PocketId id = PocketId::TopLeft;
  Vec2 jaw_a;  ///< first jaw point met going clockwise round the table
  Vec2 jaw_b;  ///< second jaw point
  /// Where the straight cushion noses end at this pocket: the jaw points themselves, or for a
  /// rounded jaw the start of its knuckle (jaw_a and jaw_b are then where the nose and jaw
  /// lines would meet).
  Vec2 nose_a;
  Vec2 nose_b;
  Vec2 outward;  ///< unit vector from the mouth into the pocket
  Vec2 drop_centre;
  double drop_radius = 0.0;
};

/// A rounded jaw (knuckle): the cushion nose turning through a circular arc into the jaw. The
/// cushion loop holds it sampled finely (loop[first] .. loop[last], short chords that lie
/// within kArcChordError behind the arc), for Box2D and the pictures; the contact search and
/// the cushion helpers below use the arc itself.
struct CushionArc {
  Vec2 centre;
  double radius = 0.0;
  Vec2 start, end;  ///< its ends, counter-clockwise round the centre (the loop's order)
  std::size_t first = 0, last = 0;  ///< indices of start and end in the cushion loop
  /// True when the direction d from the centre lies within the arc's span (at most 180 deg).
  bool covers(Vec2 d) const;
};

/// How far (m) the chords that stand for a knuckle in the cushion loop lie behind the arc.
constexpr double kArcChordError = 2e-6;
/// The angle (rad) each of those chords spans on a knuckle of this radius.
double arcChordAngle(double radius);

/// The table as the physics builds it: one clockwise loop of cushion vertices (rails, angled
/// jaws and the pocket cups behind them) and its pockets (a pool table's six; the engines take
/// any number, none included).
struct TableGeometry {
  TableDef def;
  std::vector<Vec2> cushion_loop;
  std::vector<Pocket> pockets;
  std::vector<CushionArc> arcs;  ///< the rounded jaws, in loop order (none on a pool table)

  /// Head string (x of the line behind which the cue ball is placed for the break).
  double headStringX() const { return -def.length / 4.0; }
  /// Foot spot, where the apex ball of the rack sits.
  Vec2 footSpot() const { return {def.length / 4.0, 0.0}; }

  /// True when a ball of radius r centred at c lies inside the cushions, touches no cushion
  /// segment, and is not already over a pocket.
  bool ballFits(Vec2 c, double r) const;
  /// True when the point is inside the cushion loop.
  bool insideLoop(Vec2 p) const;
  /// The pocket whose drop circle holds the point, if any.
  std::optional<PocketId> pocketAt(Vec2 p) const;
};

/// How deep a ball of radius r at c sinks into the cushion loop (m; 0 or less when clear).
double cushionSink(const TableGeometry& table, Vec2 c, double r);

/// Where a ball of radius r at c is once lifted straight out of the cushions it sinks into.
Vec2 outOfCushions(const TableGeometry& table, Vec2 c, double r);

/// Empty when a table can hold balls of radius r: every rail at least a ball's diameter long
/// between its pockets, and jaws and cups that cross nothing. Else why not, naming the table.
std::optional<std::string> checkTable(const TableDef& def, double r);

/// Builds the cushion loop and pockets. `ball_radius` sets how deep the pocket cups are.
TableGeometry buildTable(const TableDef& def, double ball_radius);

/// The cushion loop's points from a pocket's first nose end to its second: the knuckles (if
/// rounded), the jaw faces and the cup, as the pictures of the table draw them.
std::vector<Vec2> pocketOutline(const TableGeometry& table, const Pocket& pocket);

/// The straight cushion noses, clockwise from the top-left: from one pocket's second nose end
/// to the next pocket's first, or a table's four sides when it has no pockets.
std::vector<std::pair<Vec2, Vec2>> cushionNoses(const TableGeometry& table);
/// The cloth's outline: the ends of every cushion nose, clockwise.
std::vector<Vec2> clothOutline(const TableGeometry& table);

}  // namespace nineball
