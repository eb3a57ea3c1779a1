// The framing of online play's messages (a 4-byte big-endian length, then the JSON) and the
// reading of a host's address and port.
#include "net/wire.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace nineball::net {
namespace {

// Feeds `bytes` to `reader` in one piece, expecting it to be taken.
void feedAll(FrameReader& reader, const std::string& bytes) {
  std::string why;
  ASSERT_TRUE(reader.feed(bytes.data(), bytes.size(), why)) << why;
}

std::vector<std::string> drain(FrameReader& reader) {
  std::vector<std::string> out;
  while (auto m = reader.next()) out.push_back(*m);
  return out;
}

// A length prefix alone, as a peer could send it.
std::string lengthPrefix(std::uint32_t n) {
  return {static_cast<char>(n >> 24), static_cast<char>((n >> 16) & 0xff),
          static_cast<char>((n >> 8) & 0xff), static_cast<char>(n & 0xff)};
}

TEST(Wire, FramedPutsTheLengthBigEndianInFront) {
  const std::string f = framed(std::string(258, 'x'));
  ASSERT_EQ(f.size(), 262u);
  EXPECT_EQ(f.substr(0, 4), std::string("\x00\x00\x01\x02", 4));
  EXPECT_EQ(f.substr(4), std::string(258, 'x'));
}

TEST(Wire, AMessageSplitByteByByteComesOutWholeOnceItsLastByteArrives) {
  const std::string message = R"({"type":"hello","name":"Ann"})";
  const std::string bytes = framed(message);
  FrameReader reader;
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    EXPECT_FALSE(reader.next().has_value()) << "a message out after " << i << " bytes";
    std::string why;
    ASSERT_TRUE(reader.feed(&bytes[i], 1, why)) << "byte " << i << ": " << why;
  }
  const auto out = reader.next();
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(*out, message);
  EXPECT_FALSE(reader.next().has_value());
  EXPECT_EQ(reader.buffered(), 0u);
}

TEST(Wire, SeveralMessagesInOneFeedComeOutInOrder) {
  FrameReader reader;
  feedAll(reader, framed("{\"a\":1}") + framed("[]") + framed(std::string(1000, 'z')) +
                      framed("{\"b\":2}").substr(0, 5));
  const auto out = drain(reader);
  ASSERT_EQ(out.size(), 3u);
  EXPECT_EQ(out[0], "{\"a\":1}");
  EXPECT_EQ(out[1], "[]");
  EXPECT_EQ(out[2], std::string(1000, 'z'));
  // The fourth is cut: its first byte waits for the rest.
  EXPECT_EQ(reader.buffered(), 5u);
  feedAll(reader, framed("{\"b\":2}").substr(5));
  ASSERT_EQ(drain(reader), std::vector<std::string>{"{\"b\":2}"});
}

TEST(Wire, ManyMessagesThroughOneReaderKeepItsBufferBounded) {
  // The reader drops what it has handed out, so a long link does not grow it without end.
  FrameReader reader;
  const std::string bytes = framed(std::string(10000, 'm'));
  for (int i = 0; i < 200; ++i) {
    // Split off-centre, so the buffer is never empty between feeds.
    feedAll(reader, bytes.substr(0, 7));
    ASSERT_EQ(drain(reader).size(), 0u);
    feedAll(reader, bytes.substr(7) + bytes.substr(0, 3));
    ASSERT_EQ(drain(reader).size(), 1u);
    feedAll(reader, bytes.substr(3));
    ASSERT_EQ(drain(reader).size(), 1u);
  }
  EXPECT_EQ(reader.buffered(), 0u);
}

TEST(Wire, AZeroLengthIsRefused) {
  FrameReader reader;
  std::string why;
  const std::string zero = lengthPrefix(0);
  EXPECT_FALSE(reader.feed(zero.data(), zero.size(), why));
  EXPECT_EQ(why, "an empty message");
  EXPECT_FALSE(reader.next().has_value());
}

TEST(Wire, ABadLengthBehindAGoodMessageInTheSameFeedIsRefusedAtOnce) {
  // A peer that sends a good message and a broken length in one packet, then goes quiet, is
  // refused on that packet, not left waiting on the silence timeout.
  for (std::uint32_t n : {0u, static_cast<std::uint32_t>(kMaxMessageBytes + 1)}) {
    FrameReader reader;
    std::string why;
    const std::string bytes = framed("{}") + framed("[1]") + lengthPrefix(n);
    EXPECT_FALSE(reader.feed(bytes.data(), bytes.size(), why)) << n;
    EXPECT_FALSE(why.empty());
  }
}

TEST(Wire, ABadLengthArrivingAfterAGoodMessageIsRefused) {
  FrameReader reader;
  feedAll(reader, framed("{}"));
  ASSERT_EQ(drain(reader), std::vector<std::string>{"{}"});
  std::string why;
  const std::string zero = lengthPrefix(0);
  EXPECT_FALSE(reader.feed(zero.data(), zero.size(), why));
  EXPECT_EQ(why, "an empty message");
}

TEST(Wire, ALengthPastTheBoundIsRefusedBeforeItsBytesArrive) {
  for (std::uint32_t n :
       {static_cast<std::uint32_t>(kMaxMessageBytes + 1), 0x7fffffffu, 0xffffffffu}) {
    FrameReader reader;
    std::string why;
    const std::string prefix = lengthPrefix(n);
    EXPECT_FALSE(reader.feed(prefix.data(), prefix.size(), why)) << n;
    EXPECT_NE(why.find("a message of " + std::to_string(n) + " bytes"), std::string::npos) << why;
    EXPECT_FALSE(reader.next().has_value());
  }
}

TEST(Wire, ALengthOfExactlyTheBoundIsTaken) {
  FrameReader reader;
  feedAll(reader, framed(std::string(kMaxMessageBytes, 'q')));
  const auto out = reader.next();
  ASSERT_TRUE(out.has_value());
  EXPECT_EQ(out->size(), kMaxMessageBytes);
}

TEST(Wire, APortIsANumberFromOneTo65535) {
  std::string why;
  EXPECT_EQ(parsePort("1", why), 1);
  EXPECT_EQ(parsePort("47047", why), 47047);
  EXPECT_EQ(parsePort("65535", why), 65535);
  for (const char* bad :
       {"", "0", "65536", "99999", "123456", "-1", "+80", " 80", "80 ", "8O", "0x50", "1e3"}) {
    why.clear();
    EXPECT_FALSE(parsePort(bad, why).has_value()) << bad;
    EXPECT_NE(why.find("port"), std::string::npos) << bad << ": " << why;
  }
}

TEST(Wire, AnAddressIsAHostWithAnOptionalPort) {
  std::string why;
  const auto plain = parseAddress("192.168.1.20", why);
  ASSERT_TRUE(plain.has_value());
  EXPECT_EQ(plain->host, "192.168.1.20");
  EXPECT_EQ(plain->port, kDefaultPort);

  const auto with_port = parseAddress("example.org:5000", why);
  ASSERT_TRUE(with_port.has_value());
  EXPECT_EQ(with_port->host, "example.org");
  EXPECT_EQ(with_port->port, 5000);
}

TEST(Wire, AnAddressWithoutAHostOrWithABadPortIsRefusedByName) {
  std::string why;
  EXPECT_FALSE(parseAddress("", why).has_value());
  EXPECT_NE(why.find("no host"), std::string::npos) << why;
  EXPECT_FALSE(parseAddress(":5000", why).has_value());
  EXPECT_NE(why.find("no host"), std::string::npos) << why;
  EXPECT_FALSE(parseAddress("host:", why).has_value());
  EXPECT_NE(why.find("port"), std::string::npos) << why;
  EXPECT_FALSE(parseAddress("host:70000", why).has_value());
  EXPECT_NE(why.find("65535"), std::string::npos) << why;
  EXPECT_FALSE(parseAddress(std::string(254, 'h'), why).has_value());
  EXPECT_NE(why.find("253"), std::string::npos) << why;
}

}  // namespace
}  // namespace nineball::net
