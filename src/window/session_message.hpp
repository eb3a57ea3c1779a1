#pragma once

#include <string>

#include "render/hud_state.hpp"

namespace nineball::window {

/// The HUD's message line as the session keeps it: what the last shot gave, a refusal, a saved
/// screenshot; its tone; and whether it is a refused cue-ball placement, which a placement that
/// succeeds then clears. No SFML.
class SessionMessage {
 public:
  const std::string& text() const { return text_; }
  render::Tone tone() const { return tone_; }
  /// Replaces the line.
  void say(const std::string& text, render::Tone tone = render::Tone::Info) {
    text_ = text;
    tone_ = tone;
    placement_refused_ = false;
  }
  /// Says why the cue ball may not stand where it was put.
  void refusePlacement(const std::string& why) {
    say(why, render::Tone::Warning);
    placement_refused_ = true;
  }
  /// The cue ball stands where it may: a refusal said before is out of date.
  void placementTaken() {
    if (placement_refused_) say("");
    placement_refused_ = false;
  }
  /// Empties the line as a shot begins (its tone stays until the next message).
  void clear() { text_.clear(); }
  /// A new rack's line: empty and plain.
  void clearPlain() {
    text_.clear();
    tone_ = render::Tone::Info;
  }

 private:
  std::string text_;
  render::Tone tone_ = render::Tone::Info;
  bool placement_refused_ = false;  // the line is a refused cue-ball placement
};

}  // namespace nineball::window
