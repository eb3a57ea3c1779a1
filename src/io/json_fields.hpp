#pragma once

#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "common/limits.hpp"
#include "io/parse_error.hpp"

// Typed access to the fields of a JSON document. Every function takes the path of the value
// it reads and throws ParseError{"<path>: <reason>"} when the value does not fit.
namespace nineball::io {

/// The range a number must lie in; an open end excludes its limit.
struct Bounds {
  double lo = -std::numeric_limits<double>::infinity();
  bool lo_open = false;
  double hi = std::numeric_limits<double>::infinity();
  bool hi_open = false;

  /// Any finite number.
  static Bounds any() { return {}; }
  /// (0, hi].
  static Bounds positive(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, true, hi, false};
  }
  /// [0, hi].
  static Bounds nonNegative(double hi = std::numeric_limits<double>::infinity()) {
    return {0.0, false, hi, false};
  }
  /// [lo, hi].
  static Bounds closed(double lo, double hi) { return {lo, false, hi, false}; }

  bool contains(double v) const;
  /// "must be > 0 and <= 100".
  std::string requirement() const;
};

/// Throws ParseError{path + ": " + reason}.
[[noreturn]] void refuse(const std::string& path, const std::string& reason);

/// The string cut to `keep` characters, with "..." when cut.
std::string shortened(const std::string& s, std::size_t keep = limits::kMaxQuotedChars);
/// The string as a JSON literal ("abc" with its quotes, escaped), cut as by shortened().
std::string quote(const std::string& s);
/// A number as short as it reads: 100, 0.5, 1e+06.
std::string formatNumber(double v);

/// How a value reads in a message: `string "abc"`, `null`, `1.5`, `an object`.
std::string describe(const nlohmann::json& v);

/// "parent.key", or "key" at the root.
std::string member(const std::string& parent, const std::string& key);
/// "parent[i]".
std::string element(const std::string& parent, std::size_t i);

/// Refuses anything but an object.
void expectObject(const nlohmann::json& v, const std::string& path);
/// Refuses the first key of the object that is not listed, as "<path>.<key>: <what> (expected
/// one of: ...)".
void allowOnly(const nlohmann::json& obj, const std::string& path,
               std::initializer_list<const char*> keys, const char* what = "unknown field");
/// The member `key` of the object, refused as "<path>.<key>: required field missing".
const nlohmann::json& required(const nlohmann::json& obj, const std::string& path, const char* key);
/// The member `key` of the object, or nullptr.
const nlohmann::json* optional(const nlohmann::json& obj, const char* key);

/// A finite JSON number (integer or not) within the bounds.
double number(const nlohmann::json& v, const std::string& path, Bounds bounds = Bounds::any());
/// A JSON integer (3.0 is refused) in [lo, hi].
int integer(const nlohmann::json& v, const std::string& path, int lo, int hi);
/// A JSON string.
std::string text(const nlohmann::json& v, const std::string& path);

}  // namespace nineball::io
