#include "window/seat_token_file.hpp"

#include <nlohmann/json.hpp>

#include "common/log.hpp"
#include "net/protocol.hpp"
#include "window/settings.hpp"
#include "window/state_file.hpp"

namespace nineball::window {

std::string seatTokenPath() {
  return xdgFile("XDG_CONFIG_HOME", ".config", "online_seat.json");
}

std::string loadSeatToken(const std::string& path, const std::string& address) {
  std::string text;
  std::string why;
  if (path.empty() || !readStateFile(path, text, why)) return "";
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object()) return "";
  const auto a = j.find("address");
  const auto t = j.find("token");
  if (a == j.end() || t == j.end() || !a->is_string() || !t->is_string()) return "";
  if (a->get<std::string>() != address || !net::isSeatToken(t->get<std::string>())) return "";
  return t->get<std::string>();
}

void keepSeatToken(const std::string& path, const std::string& address, const std::string& token) {
  const nlohmann::json j = {{"address", printable(address)}, {"token", token}};
  std::string why;
  if (!saveStateFile(path, j.dump(2) + "\n", "no home for the seat token", why)) {
    logger("online")->warn("the seat token is not kept: {}", why);
  }
}

}  // namespace nineball::window
