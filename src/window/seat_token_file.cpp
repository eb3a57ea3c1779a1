#include "window/seat_token_file.hpp"

#include <nlohmann/json.hpp>

#include "common/log.hpp"
#include "net/protocol.hpp"
#include "window/settings.hpp"
#include "window/state_file.hpp"

namespace nineball::window {
namespace {

// Hosts remembered at once: the file stays small whatever is joined.
constexpr std::size_t kMostHosts = 16;

// {"seats": {"HOST:PORT": "token", ...}}, or an empty object when there is none to read.
nlohmann::json readSeats(const std::string& path) {
  std::string text;
  std::string why;
  if (path.empty() || !readStateFile(path, text, why)) return nlohmann::json::object();
  nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (!j.is_object() || !j.contains("seats") || !j["seats"].is_object()) {
    return nlohmann::json::object();
  }
  return j["seats"];
}

}  // namespace

std::string seatTokenPath() {
  return xdgFile("XDG_CONFIG_HOME", ".config", "online_seat.json");
}

std::string loadSeatToken(const std::string& path, const std::string& address) {
  const nlohmann::json seats = readSeats(path);
  const auto t = seats.find(address);
  if (t == seats.end() || !t->is_string() || !net::isSeatToken(t->get<std::string>())) return "";
  return t->get<std::string>();
}

void keepSeatToken(const std::string& path, const std::string& address, const std::string& token) {
  nlohmann::json seats = readSeats(path);
  while (seats.size() >= kMostHosts && !seats.contains(address)) seats.erase(seats.begin());
  seats[printable(address)] = token;
  std::string why;
  const nlohmann::json j = {{"seats", seats}};
  if (!saveStateFile(path, j.dump(2) + "\n", "no home for the seat token", why)) {
    logger("online")->warn("the seat token is not kept: {}", why);
  }
}

}  // namespace nineball::window
