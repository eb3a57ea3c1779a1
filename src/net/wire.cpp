#include "net/wire.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>

namespace nineball::net {
namespace {

constexpr std::size_t kLengthBytes = 4;

std::size_t lengthAt(const std::string& b, std::size_t at) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < kLengthBytes; ++i) {
    n = (n << 8) | static_cast<unsigned char>(b[at + i]);
  }
  return n;
}

}  // namespace

std::string buildId() {
  return "nineball " NINEBALL_VERSION " (" NINEBALL_COMMIT ", " NINEBALL_COMPILER
         ", " NINEBALL_BUILD_TYPE ")";
}

std::string framed(const std::string& payload) {
  const std::size_t n = payload.size();
  std::string out;
  out.reserve(kLengthBytes + n);
  for (int shift = 24; shift >= 0; shift -= 8) {
    out.push_back(static_cast<char>((n >> shift) & 0xff));
  }
  out += payload;
  return out;
}

bool FrameReader::checkLength(std::string& why) const {
  // Every length received is checked, not only the first: a bad one behind whole messages in
  // the same packet would otherwise wait, unread, until the peer sent more (or forever).
  for (std::size_t at = read_; buffer_.size() - at >= kLengthBytes;) {
    const std::size_t n = lengthAt(buffer_, at);
    if (n == 0) {
      why = "an empty message";
      return false;
    }
    if (n > kMaxMessageBytes) {
      why = "a message of " + std::to_string(n) + " bytes (at most " +
            std::to_string(kMaxMessageBytes) + ")";
      return false;
    }
    if (buffer_.size() - at - kLengthBytes < n) break;
    at += kLengthBytes + n;
  }
  return true;
}

bool FrameReader::feed(const char* data, std::size_t size, std::string& why) {
  if (read_ > 0 && read_ == buffer_.size()) {
    buffer_.clear();
    read_ = 0;
  }
  buffer_.append(data, size);
  return checkLength(why);
}

std::optional<std::string> FrameReader::next() {
  if (buffered() < kLengthBytes) return std::nullopt;
  const std::size_t n = lengthAt(buffer_, read_);
  if (n == 0 || n > kMaxMessageBytes || buffered() < kLengthBytes + n) return std::nullopt;
  std::string message = buffer_.substr(read_ + kLengthBytes, n);
  read_ += kLengthBytes + n;
  if (read_ > kMaxMessageBytes) {
    buffer_.erase(0, read_);
    read_ = 0;
  }
  return message;
}

std::optional<unsigned short> parsePort(const std::string& text, std::string& why) {
  if (text.empty() || text.size() > 5 || !std::all_of(text.begin(), text.end(), [](char c) {
        return std::isdigit(static_cast<unsigned char>(c));
      })) {
    why = "the port \"" + text.substr(0, 16) + "\" is not a number from 1 to 65535";
    return std::nullopt;
  }
  const long port = std::stol(text);
  if (port < 1 || port > 65535) {
    why = "the port " + text + " is outside 1-65535";
    return std::nullopt;
  }
  return static_cast<unsigned short>(port);
}

std::string addressText(const Address& a) {
  return a.host + ":" + std::to_string(a.port);
}

std::optional<Address> parseAddress(const std::string& text, std::string& why) {
  Address a;
  const std::size_t colon = text.rfind(':');
  a.host = colon == std::string::npos ? text : text.substr(0, colon);
  if (colon != std::string::npos) {
    const auto port = parsePort(text.substr(colon + 1), why);
    if (!port) return std::nullopt;
    a.port = *port;
  }
  if (a.host.empty()) {
    why = "no host in \"" + text.substr(0, 64) + "\" (expected HOST or HOST:PORT)";
    return std::nullopt;
  }
  if (a.host.size() > 253) {
    why = "the host name is longer than 253 characters";
    return std::nullopt;
  }
  return a;
}

}  // namespace nineball::net
