#include "io/standing_json.hpp"

#include <string>

#include "io/json_fields.hpp"
#include "io/parse_error.hpp"

namespace nineball::io {
namespace {

using nlohmann::json;

rules::Player parseSide(const json& v, const std::string& path) {
  const std::string name = text(v, path);
  if (name != "A" && name != "B") refuse(path, "expected \"A\" or \"B\", found " + quote(name));
  return name == "A" ? rules::Player::A : rules::Player::B;
}

std::optional<rules::Group> parseGroup(const json& v, const std::string& path) {
  if (v.is_null()) return std::nullopt;
  const std::string name = text(v, path);
  if (name == "solids") return rules::Group::Solids;
  if (name == "stripes") return rules::Group::Stripes;
  refuse(path, "expected \"solids\", \"stripes\" or null, found " + quote(name));
}

rules::Group otherGroup(rules::Group g) {
  return g == rules::Group::Solids ? rules::Group::Stripes : rules::Group::Solids;
}

// {"A": n, "B": n}, either left out as 0.
void parsePair(const json& v, const std::string& path, int hi, int (&out)[2]) {
  expectObject(v, path);
  allowOnly(v, path, {"A", "B"}, "unknown player");
  if (const json* p = optional(v, "A")) out[0] = integer(*p, member(path, "A"), 0, hi);
  if (const json* p = optional(v, "B")) out[1] = integer(*p, member(path, "B"), 0, hi);
}

// {"A": group, "B": group}: one given, the other takes the other group.
rules::Groups parseGroups(const json& v) {
  const std::string path = "groups";
  expectObject(v, path);
  allowOnly(v, path, {"A", "B"}, "unknown player");
  rules::Groups g;
  if (const json* p = optional(v, "A")) g.a = parseGroup(*p, member(path, "A"));
  if (const json* p = optional(v, "B")) g.b = parseGroup(*p, member(path, "B"));
  if (g.a && !g.b && !optional(v, "B")) g.b = otherGroup(*g.a);
  if (g.b && !g.a && !optional(v, "A")) g.a = otherGroup(*g.b);
  if (g.a.has_value() != g.b.has_value() || (g.a && *g.a == *g.b)) {
    refuse(path, "each player takes the group the other does not (or both null: open)");
  }
  return g;
}

}  // namespace

std::optional<RackStanding> parseStanding(const json& doc) {
  bool any = false;
  for (const char* key : kStandingKeys) any = any || optional(doc, key) != nullptr;
  if (!any) return std::nullopt;
  RackStanding s;
  if (const json* p = optional(doc, "shooter")) s.shooter = parseSide(*p, "shooter");
  if (const json* p = optional(doc, "ball_in_hand")) {
    if (!p->is_boolean()) refuse("ball_in_hand", "expected true or false, found " + describe(*p));
    s.ball_in_hand = p->get<bool>();
  }
  // Three consecutive fouls lose a rack: a rack still in play carries at most two.
  if (const json* p = optional(doc, "fouls")) parsePair(*p, "fouls", 2, s.fouls);
  if (const json* p = optional(doc, "groups")) s.groups = parseGroups(*p);
  if (const json* p = optional(doc, "score")) parsePair(*p, "score", 100000, s.score);
  return s;
}

}  // namespace nineball::io
