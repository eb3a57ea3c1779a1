// The joiner's seat tokens kept for a restarted window: per host, bounded, and nothing taken from
// a file that does not hold one.
#include "window/seat_token_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "net/handshake.hpp"

namespace nineball::window {
namespace {

class SeatTokenFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("nineball-seat-" + std::to_string(getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    path_ = (dir_ / "online_seat.json").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  std::string path_;
};

TEST_F(SeatTokenFile, ATokenIsKeptForItsHostOnly) {
  EXPECT_EQ(loadSeatToken(path_, "10.0.0.7:47047"), "");
  const std::string a = net::makeSeatToken();
  const std::string b = net::makeSeatToken();
  keepSeatToken(path_, "10.0.0.7:47047", a);
  keepSeatToken(path_, "10.0.0.8:5000", b);
  EXPECT_EQ(loadSeatToken(path_, "10.0.0.7:47047"), a);
  EXPECT_EQ(loadSeatToken(path_, "10.0.0.8:5000"), b);
  EXPECT_EQ(loadSeatToken(path_, "10.0.0.9:47047"), "");
  keepSeatToken(path_, "10.0.0.7:47047", b);
  EXPECT_EQ(loadSeatToken(path_, "10.0.0.7:47047"), b);
  for (int i = 0; i < 40; ++i) keepSeatToken(path_, "h" + std::to_string(i) + ":1", a);
  EXPECT_LT(std::filesystem::file_size(path_), 4000u) << "the file grew with every host";
  EXPECT_EQ(loadSeatToken(path_, "h39:1"), a);
}

TEST_F(SeatTokenFile, AFileThatHoldsNoTokenGivesNone) {
  for (const char* text : {"", "[]", "{\"seats\": 3}", "{\"seats\": {\"h:1\": 7}}",
                           "{\"seats\": {\"h:1\": \"not a token\"}}", "\x01\x02 not json"}) {
    std::ofstream(path_) << text;
    EXPECT_EQ(loadSeatToken(path_, "h:1"), "") << text;
  }
  EXPECT_EQ(loadSeatToken("", "h:1"), "");
}

}  // namespace
}  // namespace nineball::window
