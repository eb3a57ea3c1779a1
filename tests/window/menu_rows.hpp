#pragma once

#include <string>

#include "window/menu.hpp"

namespace nineball::window {

/// The index of the menu's row of that label, or -1.
inline int rowNamed(const MenuModel& m, const std::string& label) {
  const auto rows = m.rows();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (rows[i].label == label) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace nineball::window
