// The capture driver: who runs the window's frames (a person, a picture run, a benchmark) and
// the tests' environment variables, read from an injected environment.
#include "window/capture_driver.hpp"

#include <gtest/gtest.h>

#include <map>
#include <sstream>

#include "window/online_play.hpp"

namespace nineball::window {
namespace {

CaptureDriver::Environment table(std::map<std::string, std::string> values) {
  return [values = std::move(values)](const char* name) -> const char* {
    const auto found = values.find(name);
    return found == values.end() ? nullptr : found->second.c_str();
  };
}

app::GameOptions picture(std::optional<long> frames = std::nullopt) {
  app::GameOptions o;
  o.screenshot = "shot.png";
  o.frames = frames;
  return o;
}

TEST(CaptureDriver, TheOptionsChooseWhoRunsTheFrames) {
  app::GameOptions person;
  EXPECT_EQ(CaptureDriver(person, table({})).mode(), CaptureDriver::Mode::Person);
  EXPECT_EQ(CaptureDriver(person, table({})).frameLimit(), -1);
  EXPECT_EQ(CaptureDriver(picture(), table({})).mode(), CaptureDriver::Mode::Picture);
  EXPECT_EQ(CaptureDriver(picture(), table({})).frameLimit(), 1);
  EXPECT_EQ(CaptureDriver(picture(30), table({})).frameLimit(), 30);
  app::GameOptions bench;
  bench.frames = 200;
  const CaptureDriver b(bench, table({}));
  EXPECT_EQ(b.mode(), CaptureDriver::Mode::Benchmark);
  EXPECT_FALSE(b.benchmarkDone(199));
  EXPECT_TRUE(b.benchmarkDone(200));
  EXPECT_FALSE(CaptureDriver(picture(200), table({})).benchmarkDone(200));
  EXPECT_TRUE(b.breaksForDemo());
  EXPECT_FALSE(CaptureDriver(picture(), table({})).breaksForDemo());
}

TEST(CaptureDriver, APictureRunStepsFixedFramesAndAPersonTheClock) {
  EXPECT_DOUBLE_EQ(CaptureDriver(picture(), table({})).frameSeconds(0.5), 1.0 / 60.0);
  const CaptureDriver person(app::GameOptions{}, table({}));
  EXPECT_DOUBLE_EQ(person.frameSeconds(0.02), 0.02);
  EXPECT_DOUBLE_EQ(person.frameSeconds(3.0), 0.25);  // a stall counts as a quarter second
}

TEST(CaptureDriver, MenuKeysAreTypedOnlyIntoAPictureRun) {
  const auto env = table({{"NINEBALL_MENU_KEYS", "down,right,,enter"}});
  std::ostringstream err;
  int status = 0;
  const auto keys = CaptureDriver(picture(), env).typedMenuKeys(err, status);
  ASSERT_TRUE(keys);
  EXPECT_EQ(*keys, (std::vector<MenuKey>{MenuKey::Down, MenuKey::Right, MenuKey::Enter}));
  EXPECT_FALSE(CaptureDriver(picture(), env).picturesMenu(true));
  EXPECT_TRUE(CaptureDriver(picture(), table({})).picturesMenu(true));
  EXPECT_FALSE(CaptureDriver(picture(), table({})).picturesMenu(false));
  const auto none = CaptureDriver(app::GameOptions{}, env).typedMenuKeys(err, status);
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());  // a person types their own
  EXPECT_FALSE(CaptureDriver(app::GameOptions{}, table({})).picturesMenu(true));
}

TEST(CaptureDriver, AWordThatNamesNoKeyIsRefused) {
  std::ostringstream err;
  int status = 0;
  const auto keys = CaptureDriver(picture(), table({{"NINEBALL_MENU_KEYS", "down,jump"}}))
                        .typedMenuKeys(err, status);
  EXPECT_FALSE(keys);
  EXPECT_EQ(status, 2);
  EXPECT_NE(err.str().find("NINEBALL_MENU_KEYS: \"jump\""), std::string::npos) << err.str();
}

TEST(CaptureDriver, APictureRunOnlineWaitsBoundedAndAPersonAsLongAsTheyLike) {
  OnlineConfig config;
  CaptureDriver(app::GameOptions{}, table({{"NINEBALL_ONLINE_WAIT", "3"}}))
      .boundOnlineWaits(config);
  EXPECT_EQ(config.wait_s, OnlineConfig{}.wait_s);
  EXPECT_EQ(config.stall_s, OnlineConfig{}.stall_s);
  CaptureDriver(picture(), table({})).boundOnlineWaits(config);
  EXPECT_EQ(config.wait_s, 60.0);
  EXPECT_EQ(config.rejoin_s, 20.0);
  EXPECT_EQ(config.stall_s, 60.0);
  CaptureDriver(picture(), table({{"NINEBALL_ONLINE_WAIT", "3"}})).boundOnlineWaits(config);
  EXPECT_EQ(config.wait_s, 3.0);
  CaptureDriver(picture(), table({{"NINEBALL_ONLINE_WAIT", "0"}})).boundOnlineWaits(config);
  EXPECT_EQ(config.wait_s, 1.0);  // at least a second
  CaptureDriver(picture(), table({{"NINEBALL_ONLINE_WAIT", "9999"}})).boundOnlineWaits(config);
  EXPECT_EQ(config.wait_s, 600.0);
}

TEST(CaptureDriver, AnUnwritablePictureIsRefusedBeforeAWindowOpens) {
  std::ostringstream err;
  app::GameOptions o = picture();
  o.screenshot = "/nonexistent-dir/shot.png";
  EXPECT_EQ(CaptureDriver(o, table({})).refuseBeforeWindow(err), 2);
  EXPECT_NE(err.str().find("--screenshot"), std::string::npos);
  EXPECT_FALSE(CaptureDriver(app::GameOptions{}, table({})).refuseBeforeWindow(err));
}

}  // namespace
}  // namespace nineball::window
