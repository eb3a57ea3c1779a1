#include "nineball/table.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "common/limits.hpp"

namespace nineball {
namespace {

// How far past the mouth line the ball's centre travels before it drops, and the size of the
// hole, as fractions/offsets that put the slate hole where a real pocket's shelf ends.
constexpr double kCornerShelf = 0.02;
constexpr double kSideShelf = 0.005;
constexpr double kDropRadiusOfMouth = 0.45;
// The jaw faces run this far from the jaw point into the pocket (about a cushion's depth).
constexpr double kJawLength = 0.05;
// Chord of the polygon that stands for the pocket cup's round back.
constexpr double kCupChord = 0.015;

struct PocketFrame {
  PocketId id;
  Vec2 jaw_a, jaw_b, outward;
  bool corner;
};

// The pockets in clockwise order from the top-left corner (y up), each with the jaw met
// first along that walk: a pool table's six, or none.
std::vector<PocketFrame> pocketFrames(const TableDef& d) {
  if (!d.pockets) return {};
  const double hx = d.length / 2.0, hy = d.width / 2.0;
  const double c = d.corner_pocket / std::sqrt(2.0);
  const double s = d.side_pocket / 2.0;
  const double r = 1.0 / std::sqrt(2.0);
  return {
      {PocketId::TopLeft, {-hx, hy - c}, {-hx + c, hy}, {-r, r}, true},
      {PocketId::TopSide, {-s, hy}, {s, hy}, {0.0, 1.0}, false},
      {PocketId::TopRight, {hx - c, hy}, {hx, hy - c}, {r, r}, true},
      {PocketId::BottomRight, {hx, -hy + c}, {hx - c, -hy}, {r, -r}, true},
      {PocketId::BottomSide, {s, -hy}, {-s, -hy}, {0.0, -1.0}, false},
      {PocketId::BottomLeft, {-hx + c, -hy}, {-hx, -hy + c}, {-r, -r}, true},
  };
}

// A table without pockets: the four cushion noses, clockwise from the top-left corner.
std::vector<Vec2> cornerLoop(const TableDef& d) {
  const double hx = d.length / 2.0, hy = d.width / 2.0;
  return {{-hx, hy}, {hx, hy}, {hx, -hy}, {-hx, -hy}};
}

Vec2 nearestOnSegment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return a + ab * t;
}

Vec2 nearestOnArc(Vec2 p, const CushionArc& arc) {
  const Vec2 d = p - arc.centre;
  const double distance = length(d);
  if (distance > 0.0 && arc.covers(d)) return arc.centre + d * (arc.radius / distance);
  return length(p - arc.start) <= length(p - arc.end) ? arc.start : arc.end;
}

// Calls visit(nearest point) for every piece of the cushion: each straight edge of the loop,
// and each knuckle as its arc rather than the chords that stand for it in the loop.
template <class Visit>
void forEachPiece(const TableGeometry& t, Vec2 p, Visit visit) {
  const auto& loop = t.cushion_loop;
  std::size_t k = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    while (k < t.arcs.size() && t.arcs[k].last <= i) ++k;
    if (k < t.arcs.size() && i >= t.arcs[k].first) continue;  // a chord of arc k
    visit(nearestOnSegment(p, loop[i], loop[(i + 1) % loop.size()]));
  }
  for (const CushionArc& arc : t.arcs) visit(nearestOnArc(p, arc));
}

Vec2 leftOf(Vec2 v) {
  return {-v.y, v.x};
}

// Appends a knuckle to the loop: from `start` counter-clockwise round `centre` through `turn`
// to `end`, sampled in chords; the arc itself is kept in g.arcs. Its ends are passed as the
// points the straight pieces on either side end at, so that they are the same vertices.
void addKnuckle(TableGeometry& g, Vec2 start, Vec2 end, Vec2 centre, double rho, double turn) {
  CushionArc arc;
  arc.centre = centre;
  arc.radius = rho;
  const Vec2 from = start - centre;
  const double a0 = std::atan2(from.y, from.x);
  arc.start = start;
  arc.end = end;
  arc.first = g.cushion_loop.size();
  const int pieces = std::max(2, static_cast<int>(std::ceil(turn / arcChordAngle(rho))));
  g.cushion_loop.push_back(arc.start);
  for (int k = 1; k < pieces; ++k) {
    g.cushion_loop.push_back(centre + fromAngle(a0 + turn * k / pieces) * rho);
  }
  g.cushion_loop.push_back(arc.end);
  arc.last = g.cushion_loop.size() - 1;
  g.arcs.push_back(arc);
}

}  // namespace

double arcChordAngle(double radius) {
  // A chord spanning angle a lies radius (1 - cos(a / 2)) behind the arc at its middle.
  return 2.0 * std::acos(std::max(-1.0, 1.0 - kArcChordError / radius));
}

bool CushionArc::covers(Vec2 d) const {
  return cross(start - centre, d) >= 0.0 && cross(d, end - centre) >= 0.0;
}

TableDef TableDef::carom() {
  TableDef t;
  t.length = 2.84;
  t.width = 1.42;
  t.pockets = false;
  return t;
}

TableDef TableDef::caromSmall() {
  TableDef t = carom();
  t.length = 2.10;
  t.width = 1.05;
  return t;
}

TableDef TableDef::snooker() {
  TableDef t;
  // WPBSA Official Rules, section 1 (a): the playing area within the cushion faces measures
  // 11 ft 8 1/2 in x 5 ft 10 in (3569 x 1778 mm), +-13 mm.
  t.length = 3.569;
  t.width = 1.778;
  // The openings follow the WPBSA's templates, which are not public (rule 1 (c) (ii)). The
  // published approximations: a corner opening of about 3.5 in (89 mm), a middle one of
  // about 4.1-4.3 in (here 4.2 in, 107 mm); jaw faces at 142-145 degrees to the nose at the
  // corners and 100-104 at the middle (polymorvic/deep-peep-snooker src/utils/const.py, which
  // also gives the corner mouth as 89 mm): the middles of those ranges.
  t.corner_pocket = 0.0889;
  t.side_pocket = 0.1067;
  t.corner_jaw_deg = 143.5;
  t.side_jaw_deg = 102.0;
  // The knuckles: tailuge/billiards (src/view/pocketgeometry.ts) rounds its snooker jaws with
  // radii of 0.62 R at the corners and 0.4 R at the middles; R = 26.25 mm.
  t.corner_jaw_radius = 0.0163;
  t.side_jaw_radius = 0.0105;
  t.marks = TableMarks::Snooker;
  return t;
}

TableDef TableDef::snookerTenFoot() {
  TableDef t = snooker();
  // The same proportions at 10/12 the size: every length, the angles unchanged.
  constexpr double kScale = 10.0 / 12.0;
  for (double* v : {&t.length, &t.width, &t.corner_pocket, &t.side_pocket, &t.corner_jaw_radius,
                    &t.side_jaw_radius}) {
    *v *= kScale;
  }
  return t;
}

namespace {

struct NamedTable {
  const char* name;
  TableDef (*make)();
};

// The one list of named tables: a name here is known everywhere a table is read.
const std::vector<NamedTable>& namedTables() {
  static const std::vector<NamedTable> tables{{"9ft", &TableDef::nineFoot},
                                              {"8ft", &TableDef::eightFoot},
                                              {"7ft", &TableDef::sevenFoot},
                                              {"carom", &TableDef::carom},
                                              {"carom-small", &TableDef::caromSmall},
                                              {"snooker", &TableDef::snooker},
                                              {"snooker-10ft", &TableDef::snookerTenFoot}};
  return tables;
}

}  // namespace

std::optional<TableDef> TableDef::named(const std::string& name) {
  for (const NamedTable& t : namedTables()) {
    if (name == t.name) return t.make();
  }
  return std::nullopt;
}

std::vector<std::string> TableDef::names() {
  std::vector<std::string> out;
  for (const NamedTable& t : namedTables()) out.emplace_back(t.name);
  return out;
}

const char* pocketName(PocketId id) {
  switch (id) {
    case PocketId::TopLeft:
      return "top-left";
    case PocketId::TopSide:
      return "top-side";
    case PocketId::TopRight:
      return "top-right";
    case PocketId::BottomRight:
      return "bottom-right";
    case PocketId::BottomSide:
      return "bottom-side";
    case PocketId::BottomLeft:
      return "bottom-left";
  }
  return "?";
}

std::optional<PocketId> pocketFromName(const std::string& name) {
  for (int i = 0; i < kPocketCount; ++i) {
    const auto id = static_cast<PocketId>(i);
    if (name == pocketName(id)) return id;
  }
  return std::nullopt;
}

TableGeometry buildTable(const TableDef& def, double ball_radius) {
  TableGeometry g;
  g.def = def;
  const auto frames = pocketFrames(def);
  if (frames.empty()) {
    g.cushion_loop = cornerLoop(def);
    return g;
  }
  const std::size_t count = frames.size();
  g.pockets.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const PocketFrame& f = frames[i];
    const PocketFrame& prev = frames[(i + count - 1) % count];
    const PocketFrame& next = frames[(i + 1) % count];
    // Rail directions arriving at jaw a and leaving jaw b, walking clockwise.
    const Vec2 rail_in = normalized(f.jaw_a - prev.jaw_b);
    const Vec2 rail_out = normalized(next.jaw_a - f.jaw_b);
    const double turn = degToRad(180.0 - (f.corner ? def.corner_jaw_deg : def.side_jaw_deg));
    // Outside the table is on the left of a clockwise walk: jaw a turns left off its rail,
    // jaw b is the mirror image, reached walking back out of the pocket.
    const Vec2 jaw_a_dir = rotated(rail_in, turn);
    const Vec2 jaw_b_dir = rotated(-rail_out, -turn);
    const double jaw_len = std::max(kJawLength, 1.2 * ball_radius);
    const Vec2 qa = f.jaw_a + jaw_a_dir * jaw_len;
    const Vec2 qb = f.jaw_b + jaw_b_dir * jaw_len;

    const double mouth = length(f.jaw_b - f.jaw_a);
    Pocket& p = g.pockets[i];
    p.id = f.id;
    p.jaw_a = f.jaw_a;
    p.jaw_b = f.jaw_b;
    p.outward = f.outward;
    p.drop_radius = kDropRadiusOfMouth * mouth;
    const double shelf = f.corner ? kCornerShelf : kSideShelf;
    p.drop_centre = (f.jaw_a + f.jaw_b) * 0.5 + f.outward * (shelf + p.drop_radius);

    const double rho = f.corner ? def.corner_jaw_radius : def.side_jaw_radius;
    p.nose_a = f.jaw_a;
    p.nose_b = f.jaw_b;
    if (rho > 0.0) {
      // The knuckle: tangent to the nose and to the jaw face, the nose turning left (clockwise
      // walk, outside on the left) through `turn` round a centre inside the cushion.
      const double tangent = rho * std::tan(0.5 * turn);
      p.nose_a = f.jaw_a - rail_in * tangent;
      addKnuckle(g, p.nose_a, f.jaw_a + jaw_a_dir * tangent, p.nose_a + leftOf(rail_in) * rho, rho,
                 turn);
    } else {
      g.cushion_loop.push_back(f.jaw_a);
    }
    g.cushion_loop.push_back(qa);
    // The cup: clockwise round the drop centre from qa to qb, the long way (behind the hole).
    const Vec2 da = qa - p.drop_centre, db = qb - p.drop_centre;
    const double a0 = std::atan2(da.y, da.x);
    double a1 = std::atan2(db.y, db.x);
    while (a1 >= a0) a1 -= 2.0 * kPi;
    const double ra = length(da), rb = length(db);
    const double sweep = a0 - a1;
    const int pieces =
        std::max(4, static_cast<int>(std::ceil(sweep * std::max(ra, rb) / kCupChord)));
    for (int k = 1; k < pieces; ++k) {
      const double u = static_cast<double>(k) / pieces;
      const double radius = ra + (rb - ra) * u;
      g.cushion_loop.push_back(p.drop_centre + fromAngle(a0 - sweep * u) * radius);
    }
    g.cushion_loop.push_back(qb);
    if (rho > 0.0) {
      // Jaw b's knuckle, walked from the jaw face out onto the next rail: again a left turn.
      const double tangent = rho * std::tan(0.5 * turn);
      p.nose_b = f.jaw_b + rail_out * tangent;
      const Vec2 on_jaw = f.jaw_b + jaw_b_dir * tangent;
      addKnuckle(g, on_jaw, p.nose_b, p.nose_b + leftOf(rail_out) * rho, rho, turn);
    } else {
      g.cushion_loop.push_back(f.jaw_b);
    }
  }
  return g;
}

namespace {

// Proper crossing of segments ab and cd (touching at a shared end does not count).
bool segmentsCross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a);
  const double d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
  return ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0)) &&
         ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0));
}

std::string metres(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g m", v);
  return text;
}

}  // namespace

namespace {

bool sameTable(const TableDef& a, const TableDef& b) {
  return a.length == b.length && a.width == b.width && a.corner_pocket == b.corner_pocket &&
         a.side_pocket == b.side_pocket && a.corner_jaw_deg == b.corner_jaw_deg &&
         a.side_jaw_deg == b.side_jaw_deg && a.pockets == b.pockets &&
         a.corner_jaw_radius == b.corner_jaw_radius && a.side_jaw_radius == b.side_jaw_radius;
}

std::optional<std::string> checkTableOnce(const TableDef& def, double r);

}  // namespace

std::optional<std::string> checkTable(const TableDef& def, double r) {
  // A stream of scenes (sim --jsonl, the planner's positions) checks the same table again and
  // again; crossing every segment of its loop with every other is a tenth of a break's time.
  struct Last {
    bool valid = false;
    TableDef def;
    double r = 0.0;
    std::optional<std::string> answer;
  };
  thread_local Last last;
  if (last.valid && last.r == r && sameTable(last.def, def)) return last.answer;
  last.answer = checkTableOnce(def, r);
  last.def = def;
  last.r = r;
  last.valid = true;
  return last.answer;
}

namespace {

std::optional<std::string> checkTableOnce(const TableDef& def, double r) {
  if (!def.pockets) return std::nullopt;  // four straight cushions cross nothing
  for (auto [name, rho] : {std::pair{"corner_jaw_radius", def.corner_jaw_radius},
                           std::pair{"side_jaw_radius", def.side_jaw_radius}}) {
    if (!(rho >= 0.0 && rho < def.width / 2.0)) {
      return std::string("table: ") + name + " is " + metres(rho) +
             ", not a knuckle radius (0, a sharp jaw, or up to half the width)";
    }
  }
  const double jaw_len = std::max(kJawLength, 1.2 * r);
  // How far along the nose and along the jaw face a knuckle reaches from where they meet.
  const double corner_knuckle =
      def.corner_jaw_radius * std::tan(0.5 * degToRad(180.0 - def.corner_jaw_deg));
  const double side_knuckle =
      def.side_jaw_radius * std::tan(0.5 * degToRad(180.0 - def.side_jaw_deg));
  if (corner_knuckle >= jaw_len || side_knuckle >= jaw_len) {
    return "table: a knuckle runs past the end of its jaw face (" + metres(jaw_len) +
           " long): make the jaw radius smaller";
  }
  const double rail = 2.0 * r * limits::kMinRailInDiameters;
  const double corner_cut = def.corner_pocket / std::sqrt(2.0) + corner_knuckle;
  const double short_rail = def.width - 2.0 * corner_cut;
  if (short_rail < rail) {
    return "table: the end rails between the corner pockets are " + metres(short_rail) +
           " long, less than a ball's diameter (" + metres(rail) +
           "): widen the table or narrow the corner pockets";
  }
  const double long_rail = def.length / 2.0 - corner_cut - def.side_pocket / 2.0 - side_knuckle;
  if (long_rail < rail) {
    return "table: the side rails between a corner and a side pocket are " + metres(long_rail) +
           " long, less than a ball's diameter (" + metres(rail) +
           "): lengthen the table or narrow the pockets";
  }
  const TableGeometry g = buildTable(def, r);
  const auto& loop = g.cushion_loop;
  const std::size_t n = loop.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (segmentsCross(loop[i], loop[(i + 1) % n], loop[j], loop[(j + 1) % n])) {
        return std::string(
                   "table: the pocket jaws and cups cross each other or the rails (jaw "
                   "faces are ") +
               metres(jaw_len) +
               " long): widen the mouths or bring the jaw angles further from 180 degrees";
      }
    }
  }
  return std::nullopt;
}

}  // namespace

bool TableGeometry::insideLoop(Vec2 p) const {
  bool inside = false;
  const std::size_t n = cushion_loop.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Vec2 a = cushion_loop[i], b = cushion_loop[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) {
      inside = !inside;
    }
  }
  return inside;
}

bool TableGeometry::ballFits(Vec2 c, double r) const {
  if (!insideLoop(c) || pocketAt(c)) return false;
  // A ball exactly frozen to a cushion is on the table: allow rounding of the input.
  constexpr double kTouchTolerance = 1e-7;
  bool clear = true;
  forEachPiece(*this, c, [&](Vec2 nearest) {
    if (length(c - nearest) < r - kTouchTolerance) clear = false;
  });
  return clear;
}

double cushionSink(const TableGeometry& t, Vec2 c, double r) {
  double sink = 0.0;
  forEachPiece(t, c, [&](Vec2 nearest) { sink = std::max(sink, r - length(c - nearest)); });
  return sink;
}

Vec2 outOfCushions(const TableGeometry& t, Vec2 c, double r) {
  // A ball in a wedge is lifted off one face onto the other: a few passes settle it.
  for (int pass = 0; pass < 4; ++pass) {
    double deepest = 0.0;
    Vec2 lift;
    forEachPiece(t, c, [&](Vec2 nearest) {
      const double gap = length(c - nearest);
      // A centre on the face itself has no side to be lifted to.
      if (r - gap > deepest && gap > 0.0) {
        deepest = r - gap;
        lift = (c - nearest) * (deepest / gap);
      }
    });
    if (deepest <= 0.0) break;
    c += lift;
  }
  return c;
}

std::optional<PocketId> TableGeometry::pocketAt(Vec2 p) const {
  for (const Pocket& pk : pockets) {
    if (length(p - pk.drop_centre) < pk.drop_radius) return pk.id;
  }
  return std::nullopt;
}

std::vector<std::pair<Vec2, Vec2>> cushionNoses(const TableGeometry& table) {
  std::vector<std::pair<Vec2, Vec2>> noses;
  const auto& pk = table.pockets;
  if (pk.empty()) {
    const auto& loop = table.cushion_loop;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      noses.emplace_back(loop[i], loop[(i + 1) % loop.size()]);
    }
    return noses;
  }
  for (std::size_t i = 0; i < pk.size(); ++i)
    noses.emplace_back(pk[i].nose_b, pk[(i + 1) % pk.size()].nose_a);
  return noses;
}

std::vector<Vec2> clothOutline(const TableGeometry& table) {
  std::vector<Vec2> outline;
  for (const auto& [a, b] : cushionNoses(table)) {
    outline.push_back(a);
    outline.push_back(b);
  }
  return outline;
}

std::vector<Vec2> pocketOutline(const TableGeometry& table, const Pocket& pocket) {
  std::vector<Vec2> out;
  const auto& loop = table.cushion_loop;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    if (loop[i] != pocket.nose_a) continue;
    for (std::size_t k = i; k < i + loop.size(); ++k) {
      out.push_back(loop[k % loop.size()]);
      if (loop[k % loop.size()] == pocket.nose_b) break;
    }
    break;
  }
  return out;
}

}  // namespace nineball
