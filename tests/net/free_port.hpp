#pragma once

// A loopback port for a test's host: the system's pick, let go again (another process could
// take it in between; the system hands out ports in turn, so that is rare).
#include <SFML/Network/TcpListener.hpp>

namespace nineball::testing {

/// A port nobody listens on now; 0 when none could be had.
inline unsigned short freePort() {
  sf::TcpListener probe;
  if (probe.listen(sf::Socket::AnyPort) != sf::Socket::Done) return 0;
  const unsigned short port = probe.getLocalPort();
  probe.close();
  return port;
}

}  // namespace nineball::testing
