#include "window/window_placement.hpp"

#include <gtest/gtest.h>

using nineball::window::centredOnDesktop;

TEST(WindowPlacement, AWindowSmallerThanTheDesktopIsCentred) {
  EXPECT_EQ(centredOnDesktop({1280, 800}, {1920, 1080}), sf::Vector2i(320, 140));
  EXPECT_EQ(centredOnDesktop({1920, 1080}, {1920, 1080}), sf::Vector2i(0, 0));
}

TEST(WindowPlacement, AWindowLargerThanTheDesktopKeepsItsTopLeftCornerOnIt) {
  EXPECT_EQ(centredOnDesktop({1280, 800}, {1024, 768}), sf::Vector2i(0, 0));
  EXPECT_EQ(centredOnDesktop({800, 900}, {1024, 768}), sf::Vector2i(112, 0));
}
