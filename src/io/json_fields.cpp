#include "io/json_fields.hpp"

#include <cmath>
#include <cstdint>
#include <sstream>

#include "common/limits.hpp"

namespace nineball::io {

using nlohmann::json;

std::string shortened(const std::string& s, std::size_t keep) {
  // Long strings are cut so that one bad value or key cannot flood the message.
  return s.size() > keep ? s.substr(0, keep) + "..." : s;
}

std::string quote(const std::string& s) {
  // Invalid UTF-8 (say, from a cut string) is replaced rather than thrown on.
  return json(shortened(s)).dump(-1, ' ', false, json::error_handler_t::replace);
}

std::string formatNumber(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool Bounds::contains(double v) const {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Bounds::requirement() const {
  std::string low, high;
  if (std::isfinite(lo)) low = (lo_open ? "> " : ">= ") + formatNumber(lo);
  if (std::isfinite(hi)) high = (hi_open ? "< " : "<= ") + formatNumber(hi);
  if (low.empty() && high.empty()) return "must be finite";
  if (high.empty()) return "must be " + low;
  if (low.empty()) return "must be " + high;
  return "must be " + low + " and " + high;
}

void refuse(const std::string& path, const std::string& reason) {
  throw ParseError{path + ": " + reason};
}

std::string describe(const json& v) {
  switch (v.type()) {
    case json::value_t::object:
      return "an object";
    case json::value_t::array:
      return "an array";
    case json::value_t::string: {
      return "string " + quote(v.get_ref<const std::string&>());
    }
    default:
      return v.dump();
  }
}

std::string member(const std::string& parent, const std::string& key) {
  return parent.empty() ? shortened(key) : parent + "." + shortened(key);
}

std::string element(const std::string& parent, std::size_t i) {
  return parent + "[" + std::to_string(i) + "]";
}

void expectObject(const json& v, const std::string& path) {
  if (!v.is_object()) refuse(path, "expected an object, found " + describe(v));
}

void allowOnly(const json& obj, const std::string& path, std::initializer_list<const char*> keys,
               const char* what) {
  for (const auto& item : obj.items()) {
    bool known = false;
    for (const char* k : keys) known = known || item.key() == k;
    if (known) continue;
    std::string list;
    for (const char* k : keys) list += (list.empty() ? "" : ", ") + std::string(k);
    refuse(member(path, item.key()), std::string(what) + " (expected one of: " + list + ")");
  }
}

const json& required(const json& obj, const std::string& path, const char* key) {
  const auto it = obj.find(key);
  if (it == obj.end()) refuse(member(path, key), "required field missing");
  return *it;
}

const json* optional(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it == obj.end() ? nullptr : &*it;
}

double number(const json& v, const std::string& path, Bounds bounds) {
  if (!v.is_number()) refuse(path, "expected a number, found " + describe(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) refuse(path, "must be finite");
  if (!bounds.contains(d)) refuse(path, bounds.requirement() + ", found " + describe(v));
  return d;
}

int integer(const json& v, const std::string& path, int lo, int hi) {
  if (!v.is_number_integer()) refuse(path, "expected an integer, found " + describe(v));
  bool in_range = false;
  if (v.is_number_unsigned()) {
    // Unsigned values can exceed every int64: compare them as unsigned.
    const auto u = v.get<std::uint64_t>();
    in_range = hi >= 0 && u <= static_cast<std::uint64_t>(hi) &&
               (lo <= 0 || u >= static_cast<std::uint64_t>(lo));
  } else {
    const auto i = v.get<std::int64_t>();
    in_range = i >= lo && i <= hi;
  }
  if (!in_range) {
    refuse(path, "must be >= " + std::to_string(lo) + " and <= " + std::to_string(hi) + ", found " +
                     describe(v));
  }
  return static_cast<int>(v.get<std::int64_t>());
}

std::string text(const json& v, const std::string& path) {
  if (!v.is_string()) refuse(path, "expected a string, found " + describe(v));
  return v.get<std::string>();
}

}  // namespace nineball::io
