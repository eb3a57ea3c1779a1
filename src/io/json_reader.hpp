#pragma once

#include <nlohmann/json.hpp>
#include <string_view>

#include "io/parse_error.hpp"

namespace nineball::io {

/// Parses strict JSON (no comments, no trailing text). Throws ParseError for empty input, a
/// syntax error, a number too large for a double ("balls[0].x: number 1e999 is out of range") or a
/// key given twice in one object ("balls[1].x: duplicate key"); the last two name the field.
nlohmann::json readJson(std::string_view text);

/// Empties `v` from its leaves up, eight levels deep: nlohmann's destructor allocates a stack
/// as long as the array it frees, and out of memory a throw from a destructor would abort the
/// process. A document dismantled first is freed with no memory to spare.
void dismantle(nlohmann::json& v);

}  // namespace nineball::io
