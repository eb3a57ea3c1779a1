#include "window/screens/screen_stack.hpp"

#include <algorithm>

namespace nineball::window {

std::size_t ScreenStack::lowestInSight() const {
  for (std::size_t i = screens_.size(); i-- > 0;) {
    if (screens_[i]->covers()) return i;
  }
  return 0;
}

void ScreenStack::event(const sf::Event& event) {
  if (!screens_.empty()) screens_.back()->event(event);
}

void ScreenStack::update(double seconds) {
  if (screens_.empty()) return;
  const std::size_t lowest = lowestInSight();
  for (std::size_t i = screens_.size(); i-- > lowest;) {
    screens_[i]->update(seconds, i + 1 == screens_.size());
  }
}

void ScreenStack::draw(sf::RenderTarget& target) {
  if (screens_.empty()) return;
  for (std::size_t i = lowestInSight(); i < screens_.size(); ++i) screens_[i]->draw(target);
}

bool ScreenStack::busy() const {
  if (screens_.empty()) return false;
  for (std::size_t i = lowestInSight(); i < screens_.size(); ++i) {
    if (screens_[i]->busy()) return true;
  }
  return false;
}

void ScreenStack::closeTop() {
  // A screen's closed() may push another (the menu's game starting over the table): it is
  // taken off before it is told.
  std::unique_ptr<Screen> done = std::move(screens_.back());
  screens_.pop_back();
  done->closed();
  changed_ = true;
}

bool ScreenStack::removeFinished() {
  bool removed = false;
  while (!screens_.empty() && screens_.back()->finished()) {
    closeTop();
    removed = true;
  }
  return removed;
}

void ScreenStack::insert(std::size_t at, std::unique_ptr<Screen> screen) {
  screens_.insert(screens_.begin() + static_cast<std::ptrdiff_t>(std::min(at, screens_.size())),
                  std::move(screen));
  changed_ = true;
}

bool ScreenStack::holds(const Screen& screen) const {
  return std::any_of(screens_.begin(), screens_.end(),
                     [&](const std::unique_ptr<Screen>& s) { return s.get() == &screen; });
}

void ScreenStack::remove(const Screen& screen) {
  const auto it =
      std::find_if(screens_.begin(), screens_.end(),
                   [&](const std::unique_ptr<Screen>& s) { return s.get() == &screen; });
  if (it == screens_.end()) return;
  std::unique_ptr<Screen> done = std::move(*it);
  screens_.erase(it);
  done->closed();
  changed_ = true;
}

void ScreenStack::closeDownTo(std::size_t keep) {
  while (screens_.size() > keep) closeTop();
}

}  // namespace nineball::window
