#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace nineball {

/// The place in a registry (models, engines: each entry with a `name`) of the entry named
/// `name`, or nothing.
template <typename Def>
std::optional<std::size_t> placeNamed(const std::vector<Def>& registry, const std::string& name) {
  for (std::size_t i = 0; i < registry.size(); ++i) {
    if (name == registry[i].name) return i;
  }
  return std::nullopt;
}

/// Every name of a registry, in its order.
template <typename Def>
std::vector<std::string> namesOf(const std::vector<Def>& registry) {
  std::vector<std::string> out;
  out.reserve(registry.size());
  for (const Def& d : registry) out.emplace_back(d.name);
  return out;
}

/// The names as a message lists them: "a", "a or b", "a, b or c" (`last` "and" for "a, b and
/// c").
inline std::string listed(const std::vector<std::string>& names, const char* last = "or") {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? std::string(" ") + last + " " : std::string(", ");
    out += names[i];
  }
  return out;
}

/// True when `list` holds `name`.
inline bool holds(const std::vector<std::string>& list, const std::string& name) {
  for (const std::string& s : list) {
    if (s == name) return true;
  }
  return false;
}

}  // namespace nineball
