#include "net/handshake.hpp"

namespace nineball::net {

Hello helloFrom(const std::string& name) {
  return Hello{kProtocolVersion, buildId(), cleanName(name)};
}

namespace {

std::optional<std::string> mismatch(int protocol, const std::string& build) {
  if (protocol != kProtocolVersion) {
    return "the other side speaks protocol " + std::to_string(protocol) + ", this one " +
           std::to_string(kProtocolVersion);
  }
  if (build != buildId()) {
    return "the other side runs " + build + ", this one " + buildId() +
           ": both players need the same build (its physics could differ)";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> refusalOf(const Hello& hello) {
  return mismatch(hello.protocol, hello.build);
}

std::optional<std::string> refusalOf(const Welcome& welcome) {
  return mismatch(welcome.protocol, welcome.build);
}

Welcome welcomeFrom(const std::string& name, const nlohmann::json& match, const Race& race,
                    const Lockstep& lockstep) {
  Welcome w;
  w.protocol = kProtocolVersion;
  w.build = buildId();
  w.name = cleanName(name);
  w.match = match;
  w.race = race;
  w.turns = lockstep.turns();
  w.hashes = lockstep.hashes();
  return w;
}

std::optional<MatchSetup> setupOf(const Welcome& welcome, std::string& why) {
  nlohmann::json script = welcome.match;
  if (script.contains("turns") || script.contains("players")) {
    why = "match: carries \"turns\" or \"players\"";
    return std::nullopt;
  }
  script["turns"] = nlohmann::json::array();
  const io::MatchScriptResult parsed = io::parseMatchScript(script.dump());
  if (const auto* error = std::get_if<io::ParseError>(&parsed)) {
    why = "match." + error->message;
    return std::nullopt;
  }
  return std::get<io::MatchScript>(parsed).setup;
}

nlohmann::json matchPart(const nlohmann::json& script) {
  nlohmann::json match = script;
  match.erase("turns");
  match.erase("players");
  return match;
}

}  // namespace nineball::net
