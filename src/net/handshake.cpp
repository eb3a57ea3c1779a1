#include "net/handshake.hpp"

#include <cctype>
#include <random>

namespace nineball::net {

Hello helloFrom(const std::string& name, const std::string& code, const std::string& token,
                const Seat& player) {
  Hello h;
  h.protocol = kProtocolVersion;
  h.build = buildId();
  h.name = cleanName(name);
  h.code = code.substr(0, kMostCodeChars);
  h.token = token;
  h.player = player;
  return h;
}

namespace {

// No 0/O, 1/I/L: a code read out over the phone is typed right.
constexpr char kCodeAlphabet[] = "23456789ABCDEFGHJKMNPQRSTUVWXYZ";

// Equal strings, compared in a time that does not say how much of a guess was right.
bool sameSecret(const std::string& a, const std::string& b) {
  if (a.size() != b.size() || a.empty()) return false;
  unsigned char diff = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    diff |= static_cast<unsigned char>(a[i] ^ b[i]);
  }
  return diff == 0;
}

std::optional<std::string> mismatch(int protocol, const std::string& build) {
  if (protocol != kProtocolVersion) {
    return "the other side speaks protocol " + std::to_string(protocol) + ", this one " +
           std::to_string(kProtocolVersion);
  }
  if (build != buildId()) {
    // The reason first: a refusal is cut to what the other side reads, and long build names
    // (a sanitizer build's) would push it out.
    return "both players need the same build (its physics could differ): the other side runs " +
           cleanText(build, 80) + ", this one " + buildId();
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
                    const Lockstep& lockstep, const std::string& token) {
  Welcome w;
  w.protocol = kProtocolVersion;
  w.build = buildId();
  w.name = cleanName(name);
  w.match = match;
  w.race = race;
  w.turns = lockstep.turns();
  w.hashes = lockstep.hashes();
  w.token = token;
  return w;
}

std::string makeJoinCode() {
  std::random_device source;
  std::uniform_int_distribution<std::size_t> pick(0, sizeof kCodeAlphabet - 2);
  std::string code;
  for (int i = 0; i < 8; ++i) {
    if (i == 4) code += '-';
    code += kCodeAlphabet[pick(source)];
  }
  return code;
}

std::string makeSeatToken() {
  std::random_device source;
  std::uniform_int_distribution<int> digit(0, 15);
  std::string token;
  for (std::size_t i = 0; i < kSeatTokenChars; ++i) token += "0123456789abcdef"[digit(source)];
  return token;
}

std::string normalCode(const std::string& code) {
  std::string out;
  for (char c : code) {
    if (c == '-' || c == ' ') continue;
    out += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  }
  return out;
}

bool codeMatches(const std::string& typed, const std::string& code) {
  return sameSecret(normalCode(typed), normalCode(code));
}

bool tokenMatches(const std::string& offered, const std::string& token) {
  return sameSecret(offered, token);
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
