// A host (or joiner) of `nineball online` run in a thread of the test, on a free loopback
// port, its result waited for with a bound: what the live protocol tests talk to.
#pragma once

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <thread>

#include "io/match_json.hpp"
#include "net/free_port.hpp"
#include "net/online_rack.hpp"

namespace nineball::net_test {

using nineball::testing::freePort;

using net::OnlineRackOptions;
using net::OnlineRackResult;
using net::playOnlineRack;

inline io::MatchScript scriptOf(const std::string& text) {
  auto parsed = io::parseMatchScript(text);
  if (const auto* e = std::get_if<io::ParseError>(&parsed)) {
    ADD_FAILURE() << e->message;
    return {};
  }
  return std::get<io::MatchScript>(parsed);
}

// A rack played in a thread; its result comes back through a future, waited on with a bound.
// A rack still on when the test is done is asked to end (as Ctrl-C asks it) and waited for: a
// thread left running past the test would outlive the logger it writes to, and the sanitizers
// then hang the program's exit.
class RackThread {
 public:
  explicit RackThread(OnlineRackOptions o)
      : options_(std::make_shared<OnlineRackOptions>(std::move(o))) {
    if (options_->quit == nullptr) options_->quit = &own_quit_;
    auto promise = std::make_shared<std::promise<OnlineRackResult>>();
    future_ = promise->get_future();
    thread_ = std::thread([options = options_, promise] {
      try {
        promise->set_value(playOnlineRack(*options));
      } catch (...) {
        promise->set_exception(std::current_exception());
      }
    });
  }
  ~RackThread() { stop(); }
  RackThread(const RackThread&) = delete;
  RackThread& operator=(const RackThread&) = delete;

  bool finished() const {
    return future_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
  }
  // The result, or nothing when the rack is still on after `seconds` (it is then stopped).
  std::optional<OnlineRackResult> result(double seconds) {
    if (future_.wait_for(std::chrono::duration<double>(seconds)) != std::future_status::ready) {
      stop();
      return std::nullopt;
    }
    thread_.join();
    return future_.get();
  }

 private:
  void stop() {
    if (!thread_.joinable()) return;
    // The flag is the test's own or this one's, never a const object: it may be raised here.
    const_cast<std::atomic<bool>*>(options_->quit)->store(true);
    if (future_.wait_for(std::chrono::seconds(30)) == std::future_status::ready) {
      thread_.join();
    } else {
      thread_.detach();  // a rack deaf to the flag: left to its own limits
    }
  }

  std::atomic<bool> own_quit_{false};

 private:
  std::shared_ptr<OnlineRackOptions> options_;
  std::future<OnlineRackResult> future_;
  std::thread thread_;
};

}  // namespace nineball::net_test
