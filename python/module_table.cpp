// The table and rack calls of `nineball._core`: a scene's table as the physics builds it, and
// a game's standard rack on it.
#include <pybind11/pybind11.h>

#include <optional>
#include <string>

#include "module_parts.hpp"
#include "nineball/rules.hpp"
#include "nineball/scenes.hpp"
#include "nineball/table.hpp"

namespace nineball::python {
namespace {

py::list point(Vec2 p) {
  py::list xy;
  xy.append(p.x);
  xy.append(p.y);
  return xy;
}

}  // namespace

// The table of a scene (its "table" and "physics"; no balls needed) as the physics builds it.
py::dict tableGeometry(py::handle scene) {
  const Scene s = parse(scene, "");
  const TableGeometry t = buildTable(s.table, s.physics.ball_radius);
  py::dict out;
  out["length"] = t.def.length;
  out["width"] = t.def.width;
  out["ball_radius"] = s.physics.ball_radius;
  out["pockets_on"] = t.def.pockets;
  out["corner_pocket"] = t.def.corner_pocket;
  out["side_pocket"] = t.def.side_pocket;
  py::list pockets;
  for (const Pocket& p : t.pockets) {
    py::dict one;
    one["id"] = pocketName(p.id);
    one["jaw_a"] = point(p.jaw_a);
    one["jaw_b"] = point(p.jaw_b);
    one["outward"] = point(p.outward);
    one["drop_centre"] = point(p.drop_centre);
    one["drop_radius"] = p.drop_radius;
    pockets.append(one);
  }
  out["pockets"] = pockets;
  py::list loop;
  for (Vec2 v : t.cushion_loop) loop.append(point(v));
  out["cushion_loop"] = loop;
  out["head_string_x"] = t.headStringX();
  out["foot_spot"] = point(t.footSpot());
  out["head_spot"] = point({t.headStringX(), 0.0});
  out["centre_spot"] = point({0.0, 0.0});
  return out;
}

// The standard rack of `game` on the scene's table, seeded as the game seeds it.
py::list rackOf(const std::string& game_name, std::uint64_t seed, py::handle scene) {
  const std::optional<rules::Game> game = rules::gameFromName(game_name);
  if (!game) throw py::value_error("game: unknown game \"" + game_name + "\"");
  const Scene s = parse(scene, "");
  py::list balls;
  for (const BallState& b : rackFor(*game, s.table, s.physics.ball_radius, seed)) {
    py::dict one;
    one["id"] = b.id;
    one["x"] = b.pos.x;
    one["y"] = b.pos.y;
    balls.append(one);
  }
  return balls;
}

}  // namespace nineball::python
