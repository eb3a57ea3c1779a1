#include "window/online_start.hpp"

#include <string>

#include "net/wire.hpp"

namespace nineball::window {

OnlineConfig onlineConfigFromOptions(const app::GameOptions& options, const GameStart& start) {
  OnlineConfig config;
  config.side = options.host_port ? net::Side::Host : net::Side::Joiner;
  if (config.side == net::Side::Host) {
    config.address.port = *options.host_port;
  } else {
    std::string why;
    config.address = *net::parseAddress(options.join, why);  // checked with the options
  }
  config.name = options.name;
  config.code = options.code;
  config.match = start.online_match;
  config.scripted = !options.script.empty();
  config.script = start.turns;
  return config;
}

std::optional<OnlineConfig> onlineConfigFromMenu(MenuModel::Outcome outcome,
                                                 const Settings& settings,
                                                 const MatchSetup& setup) {
  if (outcome != MenuModel::Outcome::Host && outcome != MenuModel::Outcome::Join) {
    return std::nullopt;
  }
  OnlineConfig config;
  if (outcome == MenuModel::Outcome::Host) {
    config.side = net::Side::Host;
    config.address.port = net::kDefaultPort;
    config.match = onlineMatchOf(setup);
  } else {
    std::string why;
    config.side = net::Side::Joiner;
    config.address = net::parseAddress(settings.join_address, why).value_or(net::Address{});
    config.code = settings.join_code;
  }
  // The name typed on the menu's main screen (seat 1), as a game at this computer uses it.
  config.name = settings.last.names[0];
  return config;
}

}  // namespace nineball::window
