#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

// How messages travel between two nineballs: each is a 4-byte big-endian length and that many
// bytes of UTF-8 JSON. A length of 0 or past kMaxMessageBytes breaks the stream.
namespace nineball::net {

/// The port a host listens on unless told otherwise.
constexpr unsigned short kDefaultPort = 47047;
/// The protocol spoken; a peer of another version is refused at the handshake.
constexpr int kProtocolVersion = 1;
/// The largest message either side accepts: a welcome carrying a rack's 500 turns fits.
constexpr std::size_t kMaxMessageBytes = 256 * 1024;

/// The build's name: version, commit, compiler and build type. Two builds of another name may
/// simulate differently, so a peer of another name is refused.
std::string buildId();

/// `payload` with its length in front.
std::string framed(const std::string& payload);

/// Cuts a byte stream into messages. Bytes go in as they arrive; whole messages come out.
class FrameReader {
 public:
  /// Appends received bytes. False (with `why`) once the stream cannot be a message stream:
  /// a length of 0 or past kMaxMessageBytes.
  bool feed(const char* data, std::size_t size, std::string& why);
  /// The next whole message, if one has arrived.
  std::optional<std::string> next();
  /// Bytes received that are not yet a whole message.
  std::size_t buffered() const { return buffer_.size() - read_; }

 private:
  bool checkLength(std::string& why) const;

  std::string buffer_;
  std::size_t read_ = 0;  // bytes of buffer_ already handed out
};

/// Where a host listens (IPv4, as SFML speaks it).
struct Address {
  std::string host;
  unsigned short port = kDefaultPort;
};

/// Reads "HOST", "HOST:PORT" or ":PORT"; nothing (with `why`) for a port outside 1-65535 or an
/// empty host.
std::optional<Address> parseAddress(const std::string& text, std::string& why);
/// "HOST:PORT", as parseAddress reads it back.
std::string addressText(const Address& a);
/// Reads a port number 1-65535.
std::optional<unsigned short> parsePort(const std::string& text, std::string& why);

}  // namespace nineball::net
