#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "nineball/table.hpp"
#include "physics/model/motion.hpp"

namespace nineball::physics {

/// The cushion loop as the contact search needs it: each segment with its inward normal, the
/// corners that stick out into the table (jaw points), which a ball can meet head on, and the
/// rounded jaws (knuckles) as arcs, in place of the chords that stand for them in the loop.
struct Cushions {
  struct Segment {
    Vec2 a, b;
    Vec2 along;   ///< unit, a to b
    Vec2 inward;  ///< unit normal into the table
    double length;
  };
  std::vector<Segment> segments;
  std::vector<Vec2> corners;
  /// A convex arc of the cushion (a knuckle): a ball of radius R touches it when its centre
  /// is R + radius from the centre, in a direction within the arc's span (a corner is the
  /// case radius 0, every direction).
  struct Arc {
    Vec2 centre;
    double radius;
    Vec2 from, to;  ///< unit directions from the centre to its ends, counter-clockwise
    /// True when the direction d from the centre lies within the span.
    bool covers(Vec2 d) const { return cross(from, d) >= 0.0 && cross(d, to) >= 0.0; }
  };
  std::vector<Arc> arcs;

  /// A grid over the loop, so that a search looks only at what is near: each cell lists the
  /// segments, then the corners (numbered after the segments), then the arcs (numbered after
  /// the corners) whose bounding box, grown by
  /// kGridReach, overlaps it, in order. A search that may reach further than kGridReach, or
  /// starts off the grid, looks at everything.
  static constexpr double kGridReach = 0.15;  ///< m: a piece's travel and a ball's radius
  static constexpr double kGridCell = 0.1;    ///< m
  Vec2 grid_min;
  int grid_nx = 0, grid_ny = 0;
  std::vector<int> cell_start;  ///< cell c's items are items[cell_start[c] .. cell_start[c + 1])
  std::vector<int> items;

  static Cushions of(const TableGeometry& table);
  /// Cushions::of, built once for each cushion loop a process meets (the last few are kept)
  /// and shared. Safe from any thread.
  static std::shared_ptr<const Cushions> sharedOf(const TableGeometry& table);
  /// The grid cell holding p, or nothing off the grid.
  std::optional<int> cellOf(Vec2 p) const;

 private:
  void buildGrid();
};

/// Where a path meets a cushion: the clock value and the unit normal from the cushion to the
/// ball's centre.
struct CushionHit {
  double s = 0.0;
  Vec2 normal;
};

/// The first clock value in [0, horizon] at which two balls on paths a and b are `distance`
/// apart and closing. Balls already touching count only if they close faster than
/// kMinClosingSpeed (slower: they rest against each other).
std::optional<double> ballContact(const Path& a, const Path& b, double distance, double horizon);

/// A ball's height on its path: z0 + vz s + accel s^2 / 2 (accel -g in the air, 0 on the cloth).
struct Height {
  double z0 = 0.0;
  double vz = 0.0;
  double accel = 0.0;
};

/// ballContact for balls of which one at least is in the air: the first time in [0, horizon]
/// at which their centres are `distance` apart in space and closing (time is the clock: the
/// air is only flown over the cloths whose clock is the time).
std::optional<double> ballContactInAir(const Path& a, Height za, const Path& b, Height zb,
                                       double distance, double horizon);

/// The first clock value in [0, horizon] at which a ball of `radius` on the path touches a
/// cushion segment, corner or arc while moving into it.
std::optional<CushionHit> cushionContact(const Path& path, double radius, const Cushions& cushions,
                                         double horizon);

/// The normals (into the table) of every face, corner and arc a ball of `radius` at p touches.
std::vector<Vec2> touchingNormals(Vec2 p, double radius, const Cushions& cushions);

/// The first clock value in [0, horizon] at which the path's point enters the circle.
std::optional<double> circleEntry(const Path& path, Vec2 centre, double radius, double horizon);

/// How far a path can get from its start within the horizon.
double reach(const Path& path, double horizon);

}  // namespace nineball::physics
