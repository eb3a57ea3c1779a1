#pragma once

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace nineball {

/// One entry of a registry, chosen by the name the registry declares for it: a cushion model, a
/// ball-ball model, an engine. `Kind` derives from it, names what it is (`kWhat`, for messages),
/// says how to read its registry (`registrySize()`, `registryName(i)`, defined beside the
/// registry's list) and adds what only its kind knows.
template <class Kind>
class NamedChoice {
 public:
  /// The one of that name; std::invalid_argument for a name the registry does not hold.
  static Kind named(const std::string& name) {
    if (auto k = fromName(name)) return *k;
    throw std::invalid_argument(std::string("no ") + Kind::kWhat + " named \"" + name + "\"");
  }
  /// The one of that name, or nothing.
  static std::optional<Kind> fromName(const std::string& name) {
    for (std::size_t i = 0; i < Kind::registrySize(); ++i) {
      if (name == Kind::registryName(i)) return Kind(i);
    }
    return std::nullopt;
  }
  /// Every name, in the registry's order.
  static std::vector<std::string> names() {
    std::vector<std::string> out;
    for (std::size_t i = 0; i < Kind::registrySize(); ++i) out.emplace_back(Kind::registryName(i));
    return out;
  }

  /// The name it declares in the registry.
  const char* name() const { return Kind::registryName(index_); }
  /// Its place in the registry.
  std::size_t index() const { return index_; }

  bool operator==(const NamedChoice& o) const { return index_ == o.index_; }
  bool operator!=(const NamedChoice& o) const { return index_ != o.index_; }

 protected:
  explicit NamedChoice(std::size_t index) : index_(index) {}

 private:
  std::size_t index_;
};

}  // namespace nineball
