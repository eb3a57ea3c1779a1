#include <algorithm>
#include <cstdio>

#include "render/cue_stick_shape.hpp"
#include "window/online_play.hpp"

// What the window shows of an online game: who controls the table, the banner, the status.
namespace nineball::window {

std::string clockText(double seconds) {
  const int s = std::max(0, static_cast<int>(seconds + 0.999));
  char text[16];
  std::snprintf(text, sizeof text, "%d:%02d", s / 60, s % 60);
  return text;
}

std::string OnlinePlay::joinLine() const {
  return "nineball --join " + net::localAddress() + ":" + std::to_string(config_.address.port) +
         " --code " + config_.code;
}

// --- what the window shows ---

bool OnlinePlay::controls(const GameSession& session) const {
  const Phase phase = session.phase();
  if (phase != Phase::Aiming && phase != Phase::PushOutChoice) return false;
  return config_.scripted || !ourMove(session);
}

bool OnlinePlay::showsCue() const {
  return peer_aiming_;
}

double OnlinePlay::pull() const {
  return std::clamp(peer_power_, 0.0, 1.0) * render::CueStickShape::kMaxPull;
}

std::string OnlinePlay::banner() const {
  switch (stage()) {
    case Stage::Waiting:
      if (config_.side == net::Side::Host) {
        return "Waiting for a friend to join: " + joinLine() + "  (Esc cancels)";
      }
      return "Connecting to " + net::addressText(config_.address) + "..." +
             (why_.empty() ? std::string() : " (" + why_ + ")");
    case Stage::Handshake:
      return "Connected: greeting the other side...";
    case Stage::Lost: {
      const std::string left = clockText(peer_->rejoinLeft());
      return config_.side == net::Side::Host
                 ? "Connection lost - waiting for " + peer_name_ + " to rejoin (" + left + ")"
                 : "Connection lost - reconnecting to " + peer_name_ + " (" + left + ")";
    }
    case Stage::Over:
      return why_ + " (Esc leaves)";
    case Stage::Playing:
      break;
  }
  return "";
}

std::string OnlinePlay::status(const GameSession& session) const {
  // Before the game began, the lobby over the table says how the link stands.
  if (!started() && stage() != Stage::Over) return "Waiting for the online game to begin...";
  if (stage() != Stage::Playing) return banner();
  if (pending_ || (driver_.begun() && !driver_.settled())) {
    return "Waiting for " + peer_name_ + "'s table to agree...";
  }
  if (local_finished_) return "Your script is over: the rack ends here.";
  if (ourMove(session)) return "Your script plays your turn...";
  if (session.phase() == Phase::PushOutChoice) return peer_name_ + " decides...";
  return peer_aiming_ ? peer_name_ + " is aiming..." : peer_name_ + "'s turn...";
}

bool OnlinePlay::finished(const GameSession& session) const {
  if (session.phase() == Phase::Rolling || pending_ || !inbox_.empty()) return false;
  if (local_finished_ || peer_finished_) return true;
  return driver_.settled() && session.match().rack().over();
}

}  // namespace nineball::window
